#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/cell_matrices.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/plate/thermal_load.h>

#include <limits>

namespace fgimpact
{
  namespace
  {
    /// The quadrature, FEValues and graded properties of the thermal
    /// step's cell integrals (those of the stiffness: QGauss(p + 1)).
    struct CellValues
    {
      explicit CellValues(const PlateModel &plate)
        : quadrature(plate.get_fe().degree + 1)
        , fe_values(plate.get_mapping(),
                    plate.get_fe(),
                    quadrature,
                    update_gradients | update_quadrature_points |
                      update_JxW_values)
        , properties(plate.get_fe().base_element(0),
                     quadrature.get_points(),
                     plate.get_material())
      {}

      const QGauss<3>      quadrature;
      FEValues<3>          fe_values;
      PropertyInterpolator properties;
    };
  } // namespace



  void
  assemble_thermal_load(const PlateModel              &plate,
                        const TemperatureProfile      &temperature,
                        TrilinosWrappers::MPI::Vector &rhs)
  {
    const FESystem<3>                   &fe = plate.get_fe();
    CellValues                           values(plate);
    const QGauss<3>                     &quadrature    = values.quadrature;
    FEValues<3>                         &fe_values     = values.fe_values;
    PropertyInterpolator                &properties    = values.properties;
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>                       cell_f(dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<double>                  E, nu, rho;
    plate.initialize_vector(rhs);
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          properties.values(cell, E, nu, rho);
          const ArrayView<const double> mean_div = plate.mean_divergence(cell);
          cell_f                                 = 0;
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            {
              // C e I = (3 lambda + 2 mu) e I (Pa).
              const double stress =
                (3. * HookeLaw::lambda(E[q], nu[q]) +
                 2. * HookeLaw::mu(E[q], nu[q])) *
                temperature.thermal_strain(fe_values.quadrature_point(q)[2]);
              for (unsigned int i = 0; i < dofs_per_cell; ++i)
                {
                  const double div_i =
                    mean_div.size() > 0 ?
                      mean_div[i] :
                      fe_values.shape_grad(
                        i, q)[fe.system_to_component_index(i).first];
                  cell_f[i] += stress * div_i * fe_values.JxW(q);
                }
            }
          cell->get_dof_indices(local_dofs);
          plate.get_constraints().distribute_local_to_global(cell_f,
                                                             local_dofs,
                                                             rhs);
        }
    rhs.compress(VectorOperation::add);
  }



  namespace
  {
    /// sigma0 = C eps0 at the quadrature points of one cell.
    void
    prestress(const InitialStress                       &initial,
              const FEValues<3>                         &fe_values,
              const DoFHandler<3>::active_cell_iterator &cell,
              const PropertyInterpolator                &properties,
              std::vector<SymmetricTensor<2, 3>>        &sigma0)
    {
      initial.strain(fe_values, cell, sigma0);
      std::vector<double> E, nu, rho;
      properties.values(cell, E, nu, rho);
      for (unsigned int q = 0; q < sigma0.size(); ++q)
        sigma0[q] = HookeLaw::stress(E[q], nu[q], sigma0[q]);
    }
  } // namespace



  void
  assemble_geometric_stiffness(const PlateModel               &plate,
                               const InitialStress            &initial,
                               TrilinosWrappers::SparseMatrix &K_sigma)
  {
    const FESystem<3>                   &fe = plate.get_fe();
    CellValues                           values(plate);
    FEValues<3>                         &fe_values  = values.fe_values;
    PropertyInterpolator                &properties = values.properties;
    const unsigned int                   n          = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_K(n, n);
    std::vector<types::global_dof_index> dofs(n);
    std::vector<SymmetricTensor<2, 3>>   sigma0;
    K_sigma.reinit(plate.sparsity_pattern());
    const AffineConstraints<double> &constraints = plate.get_constraints();
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          prestress(initial, fe_values, cell, properties, sigma0);
          cell_K = 0;
          add_geometric_cell_matrix(fe_values, sigma0, cell_K);
          cell->get_dof_indices(dofs);
          constraints.distribute_local_to_global(cell_K, dofs, K_sigma);
        }
    K_sigma.compress(VectorOperation::add);
    for (const auto dof : plate.locally_owned_dofs())
      if (constraints.is_constrained(dof))
        K_sigma.set(dof, dof, 0.);
    K_sigma.compress(VectorOperation::insert);
  }
} // namespace fgimpact
