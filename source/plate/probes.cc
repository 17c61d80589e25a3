#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/plate/probes.h>

namespace fgimpact
{
  namespace
  {
    constexpr unsigned int voigt[6][2] =
      {{0, 0}, {1, 1}, {2, 2}, {1, 2}, {0, 2}, {0, 1}};
  }



  std::vector<std::pair<DoFHandler<3>::active_cell_iterator, Point<3>>>
  locally_owned_cells_containing(const PlateModel &plate,
                                 const Point<3>   &location)
  {
    std::vector<std::pair<DoFHandler<3>::active_cell_iterator, Point<3>>> cells;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const double tolerance = 1e-10 * cell->diameter();
          bool         inside    = true;
          for (unsigned int d = 0; d < 3; ++d)
            inside = inside && location[d] >= cell->vertex(0)[d] - tolerance &&
                     location[d] <= cell->vertex(7)[d] + tolerance;
          if (inside)
            cells.emplace_back(
              cell,
              GeometryInfo<3>::project_to_unit_cell(
                plate.get_mapping().transform_real_to_unit_cell(cell,
                                                                location)));
        }
    return cells;
  }



  std::vector<std::pair<types::global_dof_index, double>>
  owned_nonzeros(const PlateModel                    &plate,
                 const TrilinosWrappers::MPI::Vector &vector)
  {
    std::vector<std::pair<types::global_dof_index, double>> list;
    for (const auto dof : plate.locally_owned_dofs())
      if (vector(dof) != 0.)
        list.emplace_back(dof, vector(dof));
    return list;
  }



  double
  local_dot(const DofWeights &w, const TrilinosWrappers::MPI::Vector &x)
  {
    double sum = 0;
    for (const auto &[dof, weight] : w)
      sum += weight * x(dof);
    return sum;
  }



  std::array<DofWeights, 3>
  displacement_weights(const PlateModel  &plate,
                       const Point<3>    &location,
                       const std::string &outside)
  {
    const MPI_Comm     comm  = plate.get_mpi_communicator();
    const auto        &fe    = plate.get_fe();
    const auto         cells = locally_owned_cells_containing(plate, location);
    const unsigned int n_cells =
      Utilities::MPI::sum(static_cast<unsigned int>(cells.size()), comm);
    AssertThrow(n_cells > 0, ExcMessage(outside));
    auto                                 w = weight_vectors<3>(plate);
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &[cell, unit_point] : cells)
      {
        cell->get_dof_indices(dofs);
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          w[fe.system_to_component_index(i).first](dofs[i]) +=
            fe.shape_value(i, unit_point) / n_cells;
      }
    return owned_weights(plate, w);
  }



  PointProbe::PointProbe(const PlateModel &plate, const Point<3> &location)
    : point(location)
    , mpi_communicator(plate.get_mpi_communicator())
    , displacement_weights(
        fgimpact::displacement_weights(plate,
                                       location,
                                       "A probe point lies outside the plate."))
    , plastic_correction(plate)
  {
    const auto &fe = plate.get_fe();

    const auto         cells = locally_owned_cells_containing(plate, location);
    const unsigned int n_adjacent_cells =
      Utilities::MPI::sum(static_cast<unsigned int>(cells.size()),
                          mpi_communicator);
    // Q_p stress is discontinuous across cells: the average over all
    // cells that contain the point.
    const double w = 1. / n_adjacent_cells;

    // The weights of the 6 stress components.
    auto                                 weights = weight_vectors<6>(plate);
    std::vector<types::global_dof_index> local_dofs(fe.n_dofs_per_cell());

    for (const auto &[cell, unit_point] : cells)
      {
        const Quadrature<3> quadrature(std::vector<Point<3>>{unit_point});
        FEValues<3>         fe_values(plate.get_mapping(),
                              fe,
                              quadrature,
                              update_values | update_gradients);
        fe_values.reinit(cell);
        cell->get_dof_indices(local_dofs);
        plastic_correction.add_point(cell, unit_point, {{0u, w}});
        std::vector<double>  E, nu, rho;
        PropertyInterpolator properties(fe.base_element(0),
                                        quadrature.get_points(),
                                        plate.get_material());
        properties.values(cell, E, nu, rho);
        const auto mean_div = plate.mean_divergence(cell);
        const auto modes    = plate.mode_shape_strains(cell, {unit_point});
        for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
          {
            // The stress of this shape function (with its incompatible
            // modes' strain): the weights of the 6 independent components.
            const SymmetricTensor<2, 3> sigma = HookeLaw::stress(
              E[0],
              nu[0],
              PlateModel::shape_strain(fe_values, i, 0, mean_div) +
                modes[0][i]);
            for (unsigned int s = 0; s < 6; ++s)
              {
                const double value = sigma[voigt[s][0]][voigt[s][1]];
                if (value != 0.)
                  weights[s](local_dofs[i]) += w * value;
              }
          }
      }

    stress_weights = owned_weights(plate, weights);
  }



  template <std::size_t N>
  std::array<double, N>
  PointProbe::apply(const std::array<Weights, N>        &weights,
                    const TrilinosWrappers::MPI::Vector &u) const
  {
    // Local sums over the owned DoFs, then one all-reduce for all N.
    std::array<double, N> local{}, global;
    for (std::size_t k = 0; k < N; ++k)
      local[k] = local_dot(weights[k], u);
    Utilities::MPI::sum(ArrayView<const double>(local),
                        mpi_communicator,
                        ArrayView<double>(global));
    return global;
  }



  Tensor<1, 3>
  PointProbe::displacement(const TrilinosWrappers::MPI::Vector &u) const
  {
    const auto   values = apply(displacement_weights, u);
    Tensor<1, 3> d;
    for (unsigned int c = 0; c < 3; ++c)
      d[c] = values[c];
    return d;
  }



  SymmetricTensor<2, 3>
  PointProbe::stress(const TrilinosWrappers::MPI::Vector &u) const
  {
    auto values = apply(stress_weights, u);
    if (plastic_correction.active())
      {
        std::vector<double> local(6, 0.), global(6);
        plastic_correction.add_to(u, local, 0, 0);
        Utilities::MPI::sum(ArrayView<const double>(local),
                            mpi_communicator,
                            ArrayView<double>(global));
        for (unsigned int s = 0; s < 6; ++s)
          values[s] += global[s];
      }
    SymmetricTensor<2, 3> sigma;
    for (unsigned int s = 0; s < 6; ++s)
      sigma[voigt[s][0]][voigt[s][1]] = values[s];
    // (Not + 0 without one: a -0 stays -0 in the printed columns.)
    return has_prestress ? sigma + prestress : sigma;
  }
} // namespace fgimpact
