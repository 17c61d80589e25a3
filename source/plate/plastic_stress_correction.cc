// The plastic part of the probes' stresses (plastic_stress_correction.h).

#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/material/plasticity.h>
#include <fgimpact/plate/plastic_stress_correction.h>
#include <fgimpact/plate/stress_recovery.h>

namespace fgimpact
{
  PlasticStressCorrection::PlasticStressCorrection(const PlateModel &plate)
    : plate(plate)
  {}



  void
  PlasticStressCorrection::add_point(
    const DoFHandler<3>::active_cell_iterator      &cell,
    const Point<3>                                 &unit_point,
    const std::vector<std::pair<unsigned, double>> &weights,
    const unsigned int                              planes)
  {
    const auto         &fe = plate.get_fe();
    const Quadrature<3> point(std::vector<Point<3>>{unit_point});
    FEValues<3>         fe_values(plate.get_mapping(),
                          fe,
                          point,
                          update_gradients | update_quadrature_points);
    fe_values.reinit(cell);
    PropertyInterpolator properties(fe.base_element(0),
                                    point.get_points(),
                                    plate.get_material());
    std::vector<double>  E, nu, rho;
    properties.values(cell, E, nu, rho);

    Record                               record{cell->active_cell_index(),
                  unit_point,
                  E[0],
                  nu[0],
                  fe_values.quadrature_point(0)[2],
                  planes,
                  weights,
                  {},
                  {},
                  {}};
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    cell->get_dof_indices(dofs);
    const auto mean_div = plate.mean_divergence(cell);
    for (unsigned int i = 0; i < dofs.size(); ++i)
      {
        record.local_index.push_back(static_cast<int>(dofs[i]));
        record.strain.push_back(
          PlateModel::shape_strain(fe_values, i, 0, mean_div));
      }
    records.push_back(std::move(record));
  }



  void
  PlasticStressCorrection::set_plasticity(const PlasticPlate &plastic)
  {
    plasticity = &plastic;
    u_ghosted.reinit(plate.locally_owned_dofs(),
                     plate.locally_relevant_dofs(),
                     plate.get_mpi_communicator());
    // The global DoFs of the records as local indices of u_ghosted.
    const auto &map = u_ghosted.trilinos_vector().Map();
    for (auto &record : records)
      for (auto &index : record.local_index)
        index = map.LID(static_cast<TrilinosWrappers::types::int_type>(index));
  }



  void
  PlasticStressCorrection::set_prestress(const InitialStress &initial)
  {
    prestressed = true;
    std::vector<SymmetricTensor<2, 3>> eps0;
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (auto &record : records)
          if (record.active_index == cell->active_cell_index())
            {
              FEValues<3> fe_values(plate.get_mapping(),
                                    plate.get_fe(),
                                    Quadrature<3>(record.unit_point),
                                    update_gradients |
                                      update_quadrature_points);
              fe_values.reinit(cell);
              initial.strain(fe_values, cell, eps0);
              record.eps0 = eps0[0];
            }
  }



  void
  PlasticStressCorrection::add_to(const TrilinosWrappers::MPI::Vector &u,
                                  std::vector<double>                 &local,
                                  const unsigned int                   stride,
                                  const unsigned int offset) const
  {
    if (!plasticity)
      return;
    const double *const values = importer.import(u, u_ghosted);
    for (const auto &record : records)
      {
        SymmetricTensor<2, 3> eps;
        for (unsigned int i = 0; i < record.strain.size(); ++i)
          eps += values[record.local_index[i]] * record.strain[i];
        if (prestressed)
          eps += record.eps0; // the total mechanical strain
        const PlasticState state =
          plasticity->plastic_state(record.active_index, record.unit_point);
        const SymmetricTensor<2, 3> elastic =
          HookeLaw::stress(record.E, record.nu, eps);
        const SymmetricTensor<2, 3> carried = J2Plasticity::admissible_stress(
          HookeLaw::stress(record.E, record.nu, eps - state.plastic_strain),
          plasticity->yield_stress(record.z, state.equivalent_plastic_strain));
        const SymmetricTensor<2, 3> difference = carried - elastic;
        for (const auto &[slot, factor] : record.weights)
          for (unsigned int s = 0; s < 6; ++s)
            if (!odd_under_reflection(s, record.planes))
              local[slot * stride + offset + s] +=
                factor *
                difference[stress_component[s][0]][stress_component[s][1]];
      }
  }
} // namespace fgimpact
