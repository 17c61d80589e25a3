#include <deal.II/base/quadrature.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/probes.h>

#include <limits>

namespace fgimpact
{
  InitialStress::InitialStress(const PlateModel                    &plate,
                               const TemperatureProfile            &temperature,
                               const TrilinosWrappers::MPI::Vector &u0)
    : plate(plate)
    , profile(temperature)
    , u0(u0)
  {}



  void
  InitialStress::strain(const FEValues<3>                         &fe_values,
                        const DoFHandler<3>::active_cell_iterator &cell,
                        std::vector<SymmetricTensor<2, 3>>        &eps0) const
  {
    const unsigned int                     n_q = fe_values.n_quadrature_points;
    std::vector<std::vector<Tensor<1, 3>>> gradients(
      n_q, std::vector<Tensor<1, 3>>(3));
    fe_values.get_function_gradients(u0, gradients);
    eps0.assign(n_q, SymmetricTensor<2, 3>());
    for (unsigned int q = 0; q < n_q; ++q)
      for (unsigned int c = 0; c < 3; ++c)
        for (unsigned int d = c; d < 3; ++d)
          eps0[q][c][d] = 0.5 * (gradients[q][c][d] + gradients[q][d][c]);
    plate.apply_mean_dilatation(cell, u0, eps0); // B-bar
    for (unsigned int q = 0; q < n_q; ++q)
      eps0[q] -= profile.thermal_strain(fe_values.quadrature_point(q)[2]) *
                 unit_symmetric_tensor<3>();
  }



  SymmetricTensor<2, 3>
  InitialStress::stress_at(const Point<3> &location) const
  {
    const auto cells = locally_owned_cells_containing(plate, location);
    SymmetricTensor<2, 3>              sum;
    const FESystem<3>                 &fe = plate.get_fe();
    std::vector<SymmetricTensor<2, 3>> eps0;
    std::vector<double>                E, nu, rho;
    for (const auto &[cell, unit_point] : cells)
      {
        const Quadrature<3> point(unit_point);
        FEValues<3>         fe_values(plate.get_mapping(),
                              fe,
                              point,
                              update_gradients | update_quadrature_points);
        fe_values.reinit(cell);
        strain(fe_values, cell, eps0);
        PropertyInterpolator(fe.base_element(0),
                             {unit_point},
                             plate.get_material())
          .values(cell, E, nu, rho);
        sum += HookeLaw::stress(E[0], nu[0], eps0[0]);
      }
    const MPI_Comm     comm = plate.get_mpi_communicator();
    const unsigned int n =
      Utilities::MPI::sum(static_cast<unsigned int>(cells.size()), comm);
    if (n == 0)
      return SymmetricTensor<2, 3>() * std::numeric_limits<double>::quiet_NaN();
    SymmetricTensor<2, 3> total;
    for (unsigned int i = 0; i < 3; ++i)
      for (unsigned int j = i; j < 3; ++j)
        total[i][j] = Utilities::MPI::sum(sum[i][j], comm) / n;
    return total;
  }
} // namespace fgimpact
