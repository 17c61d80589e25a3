#include <deal.II/dofs/dof_tools.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/lac/lapack_full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/rigid_modes.h>

#include <algorithm>
#include <array>
#include <map>
#include <tuple>

namespace fgimpact
{
  namespace
  {
    using Motion = std::array<double, 6>;

    /// Component c of the six unit motions at p (relative to the centre,
    /// scaled): translations t_x, t_y, t_z, then rotations e_k x p.
    Motion
    motion_row(const Point<3> &p, const unsigned int c)
    {
      Motion row = {};
      row[c]     = 1.;
      for (unsigned int k = 0; k < 3; ++k)
        {
          const unsigned int k1 = (k + 1) % 3, k2 = (k + 2) % 3;
          row[3 + k] = (c == k1 ? -p[k2] : c == k2 ? p[k1] : 0.);
        }
      return row;
    }

    /// The six unit motions as ghosted vectors on the plate's DoFs: a
    /// constraint's entries may lie off this rank's cells (an immovable
    /// side's column), where only their owner knows the support point.
    std::array<TrilinosWrappers::MPI::Vector, 6>
    motion_vectors(const PlateModel &plate,
                   const Point<3>   &centre,
                   const double      size)
    {
      const DoFHandler<3>                        &dh = plate.get_dof_handler();
      std::map<types::global_dof_index, Point<3>> points;
      DoFTools::map_dofs_to_support_points(plate.get_mapping(), dh, points);
      std::array<IndexSet, 3> component_dofs;
      for (unsigned int c = 0; c < 3; ++c)
        {
          ComponentMask mask(3, false);
          mask.set(c, true);
          component_dofs[c] = DoFTools::extract_dofs(dh, mask);
        }
      std::array<TrilinosWrappers::MPI::Vector, 6> motions;
      for (unsigned int m = 0; m < 6; ++m)
        {
          TrilinosWrappers::MPI::Vector owned;
          plate.initialize_vector(owned);
          for (const auto dof : plate.locally_owned_dofs())
            {
              unsigned int c = 0;
              while (c < 2 && !component_dofs[c].is_element(dof))
                ++c;
              owned(dof) =
                motion_row(Point<3>((points.at(dof) - centre) / size), c)[m];
            }
          owned.compress(VectorOperation::insert);
          motions[m].reinit(plate.locally_owned_dofs(),
                            plate.locally_relevant_dofs(),
                            plate.get_mpi_communicator());
          motions[m] = owned;
        }
      return motions;
    }

    /// The Gram matrix of the constraints' residuals on the six motions,
    /// summed over the ranks.
    FullMatrix<double>
    constraint_gram(const PlateModel &plate,
                    const Point<3>   &centre,
                    const double      size)
    {
      const std::array<TrilinosWrappers::MPI::Vector, 6> motions =
        motion_vectors(plate, centre, size);
      const auto row_of = [&](const types::global_dof_index dof) {
        Motion row;
        for (unsigned int m = 0; m < 6; ++m)
          row[m] = motions[m](dof);
        return row;
      };
      const AffineConstraints<double> &constraints = plate.get_constraints();
      std::vector<double>              gram(36, 0.);
      for (const auto dof : plate.locally_owned_dofs())
        if (constraints.is_constrained(dof))
          {
            Motion r = row_of(dof);
            if (const auto *entries = constraints.get_constraint_entries(dof))
              for (const auto &[j, w] : *entries)
                {
                  const Motion rj = row_of(j);
                  for (unsigned int m = 0; m < 6; ++m)
                    r[m] -= w * rj[m];
                }
            for (unsigned int m = 0; m < 6; ++m)
              for (unsigned int n = 0; n < 6; ++n)
                gram[6 * m + n] += r[m] * r[n];
          }
      std::vector<double> sums(36);
      Utilities::MPI::sum(ArrayView<const double>(gram),
                          plate.get_mpi_communicator(),
                          ArrayView<double>(sums));
      FullMatrix<double> matrix(6, 6);
      for (unsigned int m = 0; m < 6; ++m)
        for (unsigned int n = 0; n < 6; ++n)
          matrix(m, n) = sums[6 * m + n];
      return matrix;
    }
  } // namespace



  namespace
  {
    /// The bounding box of the modelled part: its low and high corners,
    /// the centre and the largest extent (m).
    struct PartBox
    {
      Point<3> lo, hi, centre;
      double   size;

      /// Corner k (bit d: the high side in direction d).
      Point<3>
      corner(const unsigned int k) const
      {
        return Point<3>(k & 1 ? hi[0] : lo[0],
                        k & 2 ? hi[1] : lo[1],
                        k & 4 ? hi[2] : lo[2]);
      }
    };

    /// The free motions: the eigenvectors of the constraints' Gram matrix
    /// with (numerically) zero eigenvalue.
    std::vector<Motion>
    free_motions(const PlateModel &plate, const PartBox &box)
    {
      LAPACKFullMatrix<double> gram(6, 6);
      gram = constraint_gram(plate, box.centre, box.size);
      FullMatrix<double> eigenvectors;
      Vector<double>     eigenvalues;
      gram.compute_eigenvalues_symmetric(-1.,
                                         1e-12 * std::max(1., gram.l1_norm()),
                                         1e-14,
                                         eigenvalues,
                                         eigenvectors);
      std::vector<Motion> free;
      for (unsigned int k = 0; k < eigenvalues.size(); ++k)
        {
          Motion x;
          for (unsigned int m = 0; m < 6; ++m)
            x[m] = eigenvectors(m, k);
          free.push_back(x);
        }
      return free;
    }

    /// The corner component that the free motions move most: (corner,
    /// component, each motion's value there).
    std::tuple<Point<3>, unsigned int, std::vector<double>>
    best_pin(const std::vector<Motion> &free, const PartBox &box)
    {
      double              best = 0;
      Point<3>            best_point;
      unsigned int        best_c = 0;
      std::vector<double> best_values;
      for (unsigned int k = 0; k < 8; ++k)
        for (unsigned int c = 0; c < 3; ++c)
          {
            const Motion row =
              motion_row(Point<3>((box.corner(k) - box.centre) / box.size), c);
            std::vector<double> values;
            double              norm = 0;
            for (const Motion &x : free)
              {
                double v = 0;
                for (unsigned int m = 0; m < 6; ++m)
                  v += row[m] * x[m];
                values.push_back(v);
                norm += v * v;
              }
            if (norm > best + 1e-12)
              best = norm, best_point = box.corner(k), best_c = c,
              best_values = values;
          }
      AssertThrow(best > 1e-12, ExcInternalError());
      return {best_point, best_c, best_values};
    }

    /// The motions that keep the pin fixed: each minus its share of the
    /// one that moves the pin most (values: each motion's value there).
    std::vector<Motion>
    motions_fixing(const std::vector<Motion> &free,
                   const std::vector<double> &values)
    {
      const auto pivot = static_cast<unsigned int>(
        std::max_element(values.begin(),
                         values.end(),
                         [](double a, double b) {
                           return std::abs(a) < std::abs(b);
                         }) -
        values.begin());
      std::vector<Motion> kept;
      for (unsigned int k = 0; k < free.size(); ++k)
        if (k != pivot)
          {
            Motion x = free[k];
            for (unsigned int m = 0; m < 6; ++m)
              x[m] -= values[k] / values[pivot] * free[pivot][m];
            kept.push_back(x);
          }
      return kept;
    }
  } // namespace



  std::vector<types::global_dof_index>
  rigid_motion_pins(const PlateModel &plate)
  {
    const auto bounding = GridTools::compute_bounding_box(
      plate.get_dof_handler().get_triangulation());
    PartBox box;
    box.lo     = bounding.get_boundary_points().first;
    box.hi     = bounding.get_boundary_points().second;
    box.centre = 0.5 * (box.lo + box.hi);
    box.size   = std::max(
      {box.hi[0] - box.lo[0], box.hi[1] - box.lo[1], box.hi[2] - box.lo[2]});
    std::vector<Motion>                  free = free_motions(plate, box);
    std::vector<types::global_dof_index> pins;
    // Greedy: the corner component that the motions not yet removed move
    // most, then those motions projected off it.
    while (!free.empty())
      {
        const auto [point, component, values] = best_pin(free, box);
        pins.push_back(plate.nearest_vertex_dof(point, component).first);
        free = motions_fixing(free, values);
      }
    return pins;
  }
} // namespace fgimpact
