// Probes anywhere (ProbeSet): the weights that make each probe value a linear
// functional of the fields (displacement, recovered stress, support
// reaction) and their evaluation; the Output/Probe points entry is in
// probe_points.cc.

#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>
#include <deal.II/base/utilities.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/probe_set.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/plate/stress_recovery.h>

#include <algorithm>
#include <cctype>
#include <set>
#include <sstream>

namespace fgimpact
{
  ProbeSet::ProbeSet(const PlateModel              &plate,
                     const std::vector<ProbePoint> &probe_points)
    : mpi_communicator(plate.get_mpi_communicator())
    , weights(probe_points.size())
    , plastic_correction(plate)
  {
    const auto &g = plate.get_geometry();
    for (const auto &point : probe_points)
      {
        names.push_back(point.name);
        points.push_back(point.location(g.length(), g.width(), g.thickness()));
      }
    setup_point_weights(plate);
    setup_stress_weights(plate);
    setup_reaction_weights(plate);
  }



  void
  ProbeSet::setup_point_weights(const PlateModel &plate)
  {
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        const auto w =
          displacement_weights(plate,
                               points[p],
                               std::string("Output/Probe points: '") +
                                 names[p] + "' lies outside the plate.");
        for (unsigned int c = 0; c < 3; ++c)
          weights[p][c] = w[c];
      }
  }



  namespace
  {
    /// The cell of the scalar DoFHandler on the same mesh cell.
    DoFHandler<3>::active_cell_iterator
    scalar_cell(const DoFHandler<3>                       &scalar_dofs,
                const DoFHandler<3>::active_cell_iterator &cell)
    {
      return DoFHandler<3>::active_cell_iterator(
        &scalar_dofs.get_triangulation(),
        cell->level(),
        cell->index(),
        &scalar_dofs);
    }

    /// Ghosted vectors on scalar_dofs: [0] the number of cells (on all
    /// ranks) at each node, [1 + p] the coefficients c_j of point p: its
    /// shape function values N_j(x_p), averaged over the cells that
    /// contain it.
    std::vector<TrilinosWrappers::MPI::Vector>
    recovery_coefficients(const PlateModel            &plate,
                          const DoFHandler<3>         &scalar_dofs,
                          const std::vector<Point<3>> &points)
    {
      const MPI_Comm comm  = plate.get_mpi_communicator();
      const IndexSet owned = scalar_dofs.locally_owned_dofs();
      IndexSet       relevant;
      DoFTools::extract_locally_relevant_dofs(scalar_dofs, relevant);
      const FiniteElement<3>              &scalar_fe = scalar_dofs.get_fe();
      std::vector<types::global_dof_index> sdofs(scalar_fe.n_dofs_per_cell());

      std::vector<TrilinosWrappers::MPI::Vector> sums(1 + points.size());
      for (auto &v : sums)
        v.reinit(owned, relevant, comm, /*vector_writable=*/true);
      for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            scalar_cell(scalar_dofs, cell)->get_dof_indices(sdofs);
            for (const auto dof : sdofs)
              sums[0](dof) += 1.;
          }
      // A hanging node's recovered value is its parents' interpolation
      // (StressRecovery): its coefficient goes to them.
      const AffineConstraints<double> hanging =
        scalar_hanging_constraints(scalar_dofs);
      Vector<double> local(sdofs.size());
      for (unsigned int p = 0; p < points.size(); ++p)
        {
          const auto cells = locally_owned_cells_containing(plate, points[p]);
          const unsigned int n_cells =
            Utilities::MPI::sum(static_cast<unsigned int>(cells.size()), comm);
          for (const auto &[cell, unit_point] : cells)
            {
              scalar_cell(scalar_dofs, cell)->get_dof_indices(sdofs);
              for (unsigned int k = 0; k < sdofs.size(); ++k)
                local[k] = scalar_fe.shape_value(k, unit_point) / n_cells;
              hanging.distribute_local_to_global(local, sdofs, sums[1 + p]);
            }
        }
      std::vector<TrilinosWrappers::MPI::Vector> ghosted(sums.size());
      for (unsigned int k = 0; k < sums.size(); ++k)
        {
          sums[k].compress(VectorOperation::add);
          ghosted[k].reinit(owned, relevant, comm);
          ghosted[k] = sums[k];
        }
      return ghosted;
    }
  } // namespace



  namespace
  {
    /// The probes whose recovered stress reads scalar node `dof`, with
    /// their factor c_j / n_j (ghosted[0]: n_j, ghosted[1 + p]: probe p's
    /// c_j), in the order of the probes.
    std::vector<std::pair<unsigned int, double>>
    probe_factors(const std::vector<TrilinosWrappers::MPI::Vector> &ghosted,
                  const types::global_dof_index                     dof)
    {
      std::vector<std::pair<unsigned int, double>> factors;
      for (unsigned int p = 0; p + 1 < ghosted.size(); ++p)
        if (ghosted[1 + p](dof) != 0.)
          factors.emplace_back(p, ghosted[1 + p](dof) / ghosted[0](dof));
      return factors;
    }

    /// The cut planes a scalar node lies on (dofs_on_cut_planes()).
    unsigned int
    planes_of(const std::map<types::global_dof_index, unsigned int> &cut_planes,
              const types::global_dof_index                          dof)
    {
      const auto cut = cut_planes.find(dof);
      return cut == cut_planes.end() ? 0u : cut->second;
    }

    /// A shape function's stress sigma at a scalar node into the probes'
    /// weights of its DoF: w[p][s](dof) += factor sigma_s.  A node on a
    /// cut plane: the odd shear components of its (whole-plate) average
    /// are zero.
    void
    add_stress_weights(
      const SymmetricTensor<2, 3>                               &sigma,
      const std::vector<std::pair<unsigned int, double>>        &factors,
      const unsigned int                                         planes,
      const types::global_dof_index                              dof,
      std::vector<std::array<TrilinosWrappers::MPI::Vector, 6>> &w)
    {
      for (const auto &[p, factor] : factors)
        for (unsigned int s = 0; s < 6; ++s)
          if (!odd_under_reflection(s, planes))
            w[p][s](dof) +=
              factor * sigma[stress_component[s][0]][stress_component[s][1]];
    }

    /// The probes' factors (probe_factors()) of each scalar node of a
    /// cell; empty if no probe reads any of them.
    std::vector<std::vector<std::pair<unsigned int, double>>>
    cell_probe_factors(
      const std::vector<TrilinosWrappers::MPI::Vector> &ghosted,
      const std::vector<types::global_dof_index>       &sdofs)
    {
      std::vector<std::vector<std::pair<unsigned int, double>>> factors(
        sdofs.size());
      bool needed = false;
      for (unsigned int q = 0; q < sdofs.size(); ++q)
        {
          factors[q] = probe_factors(ghosted, sdofs[q]);
          needed     = needed || !factors[q].empty();
        }
      if (!needed)
        factors.clear();
      return factors;
    }
  } // namespace



  void
  ProbeSet::visit_read_nodes(const PlateModel  &plate,
                             const NodeVisitor &visit) const
  {
    DoFHandler<3> scalar_dofs(plate.get_dof_handler().get_triangulation());
    scalar_dofs.distribute_dofs(plate.get_fe().base_element(0));
    const FiniteElement<3> &scalar_fe = scalar_dofs.get_fe();
    const auto ghosted = recovery_coefficients(plate, scalar_dofs, points);
    const auto cut_planes =
      dofs_on_cut_planes(plate.get_geometry(), scalar_dofs);
    std::vector<types::global_dof_index> sdofs(scalar_fe.n_dofs_per_cell());

    // Each cell's stress at its scalar support points, as in
    // StressRecovery::recover().
    const Quadrature<3>  support(scalar_fe.get_unit_support_points());
    FEValues<3>          fe_values(plate.get_mapping(),
                          plate.get_fe(),
                          support,
                          update_gradients | update_quadrature_points);
    PropertyInterpolator properties(scalar_fe,
                                    support.get_points(),
                                    plate.get_material());
    NodeValues           node;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          scalar_cell(scalar_dofs, cell)->get_dof_indices(sdofs);
          node.factors = cell_probe_factors(ghosted, sdofs);
          if (node.factors.empty())
            continue;
          fe_values.reinit(cell);
          properties.values(cell, node.E, node.nu, node.rho);
          node.planes.resize(sdofs.size());
          for (unsigned int q = 0; q < sdofs.size(); ++q)
            node.planes[q] = planes_of(cut_planes, sdofs[q]);
          visit(cell, fe_values, node);
        }
  }



  void
  ProbeSet::setup_stress_weights(const PlateModel &plate)
  {
    const auto                          &fe = plate.get_fe();
    const HookeLaw                       hooke(plate.get_material());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    std::vector<std::array<TrilinosWrappers::MPI::Vector, 6>> w(points.size());
    for (auto &vectors : w)
      vectors = weight_vectors<6>(plate);
    visit_read_nodes(
      plate,
      [&](const auto        &cell,
          const FEValues<3> &fe_values,
          const NodeValues  &node) {
        cell->get_dof_indices(dofs);
        const auto mean_div = plate.mean_divergence(cell);
        const auto modes =
          plate.mode_shape_strains(cell,
                                   fe_values.get_quadrature().get_points());
        for (unsigned int q = 0; q < node.factors.size(); ++q)
          if (!node.factors[q].empty())
            {
              // The same points for a plastic run's correction.
              plastic_correction.add_point(cell,
                                           fe_values.get_quadrature().point(q),
                                           node.factors[q],
                                           node.planes[q]);
              for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                add_stress_weights(hooke.stress(node.E[q],
                                                node.nu[q],
                                                PlateModel::shape_strain(
                                                  fe_values, i, q, mean_div) +
                                                  modes[q][i]),
                                   node.factors[q],
                                   node.planes[q],
                                   dofs[i],
                                   w);
            }
      });
    for (unsigned int p = 0; p < points.size(); ++p) // weights 3-8
      std::copy_n(owned_weights(plate, w[p]).begin(), 6, &weights[p][3]);
  }



  void
  ProbeSet::set_prestress(const PlateModel &plate, const InitialStress &initial)
  {
    // The recovered stress of the initial state at each probe: the same
    // nodal averages of the cells' C eps0 at their support points.
    std::vector<double>                local(6 * points.size(), 0.);
    std::vector<SymmetricTensor<2, 3>> eps0;
    visit_read_nodes(
      plate,
      [&](const auto        &cell,
          const FEValues<3> &fe_values,
          const NodeValues  &node) {
        initial.strain(fe_values, cell, eps0);
        for (unsigned int q = 0; q < node.factors.size(); ++q)
          for (const auto &[p, factor] : node.factors[q])
            {
              const SymmetricTensor<2, 3> sigma0 =
                HookeLaw::stress(node.E[q], node.nu[q], eps0[q]);
              for (unsigned int s = 0; s < 6; ++s)
                if (!odd_under_reflection(s, node.planes[q]))
                  local[6 * p + s] +=
                    factor *
                    sigma0[stress_component[s][0]][stress_component[s][1]];
            }
      });
    plastic_correction.set_prestress(initial);
    prestress.resize(local.size());
    Utilities::MPI::sum(ArrayView<const double>(local),
                        mpi_communicator,
                        ArrayView<double>(prestress));
  }



  ProbeValues
  ProbeSet::evaluate(const TrilinosWrappers::MPI::Vector &u,
                     const TrilinosWrappers::MPI::Vector &v,
                     const TrilinosWrappers::MPI::Vector &a,
                     const bool                           lumped_mass) const
  {
    const auto &dot = local_dot;
    // Local sums, then one all-reduce: per point u, v, a (3 each) and the
    // stress (6), then the reaction.
    const unsigned int  n = points.size();
    std::vector<double> local(15 * n + 1), global(15 * n + 1);
    for (unsigned int p = 0; p < n; ++p)
      {
        for (unsigned int c = 0; c < 3; ++c)
          {
            local[15 * p + c]     = dot(weights[p][c], u);
            local[15 * p + 3 + c] = dot(weights[p][c], v);
            local[15 * p + 6 + c] = dot(weights[p][c], a);
          }
        for (unsigned int s = 0; s < 6; ++s)
          local[15 * p + 9 + s] = dot(weights[p][3 + s], u);
      }
    plastic_correction.add_to(u, local, 15, 9);
    local[15 * n] = dot(reaction_stiffness, u) +
                    (lumped_mass ? 0. : dot(reaction_mass, a)) +
                    plastic_reaction();
    Utilities::MPI::sum(ArrayView<const double>(local),
                        mpi_communicator,
                        ArrayView<double>(global));

    ProbeValues values;
    for (unsigned int p = 0; p < n; ++p)
      {
        Tensor<1, 3>          d, vel, acc;
        SymmetricTensor<2, 3> sigma;
        for (unsigned int c = 0; c < 3; ++c)
          {
            d[c]   = global[15 * p + c];
            vel[c] = global[15 * p + 3 + c];
            acc[c] = global[15 * p + 6 + c];
          }
        for (unsigned int s = 0; s < 6; ++s)
          sigma[stress_component[s][0]][stress_component[s][1]] =
            prestress.empty() ? global[15 * p + 9 + s] :
                                global[15 * p + 9 + s] + prestress[6 * p + s];
        values.displacement.push_back(d);
        values.velocity.push_back(vel);
        values.acceleration.push_back(acc);
        values.stress.push_back(sigma);
      }
    values.support_reaction_z = global[15 * n];
    return values;
  }



  std::vector<std::pair<std::string, int>>
  ProbeSet::columns() const
  {
    std::vector<std::pair<std::string, int>> list = {{"t_us", 3},
                                                     {"support_reaction_z_N",
                                                      3}};
    static const char *const stress[6] = {"xx", "yy", "zz", "xy", "xz", "yz"};
    for (const auto &name : names)
      {
        for (const char *c : {"x", "y", "z"})
          list.emplace_back(name + "_u" + c + "_um", 6);
        for (const char *c : {"x", "y", "z"})
          list.emplace_back(name + "_v" + c + "_m_s", 6);
        for (const char *c : {"x", "y", "z"})
          list.emplace_back(name + "_a" + c + "_m_s2", 1);
        for (const char *c : stress)
          list.emplace_back(name + "_sigma_" + c + "_MPa", 4);
      }
    return list;
  }



  std::vector<double>
  ProbeSet::row(const double t, const ProbeValues &values) const
  {
    std::vector<double> row = {t * 1e6, values.support_reaction_z};
    for (unsigned int p = 0; p < points.size(); ++p)
      {
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(values.displacement[p][c] * 1e6);
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(values.velocity[p][c]);
        for (unsigned int c = 0; c < 3; ++c)
          row.push_back(values.acceleration[p][c]);
        for (unsigned int s = 0; s < 6; ++s)
          row.push_back(
            values.stress[p][stress_component[s][0]][stress_component[s][1]] *
            1e-6);
      }
    return row;
  }
} // namespace fgimpact
