// Plasticity from a thermal pre-stress (PlasticPlate::set_prestress(),
// issue 42): the initial state's strain at the Gauss points.

#include <deal.II/base/quadrature_lib.h>

#include <fgimpact/plate/plastic_plate.h>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>

namespace fgimpact
{
  void
  PlasticPlate::set_prestress(const InitialStress &initial)
  {
    const QGauss<3> quadrature(plate.get_fe().degree + 1); // as setup()
    FEValues<3>     fe_values(plate.get_mapping(),
                          plate.get_fe(),
                          quadrature,
                          update_gradients | update_quadrature_points);
    prestrain.assign(yield.size(), SymmetricTensor<2, 3>());
    prestrain_dev.assign(table.size(), 0.);
    std::vector<SymmetricTensor<2, 3>> eps0;
    std::pair<double, Point<3>>        largest = {0., Point<3>()};
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned() &&
          cell_of_active[cell->active_cell_index()] >= 0)
        {
          const unsigned int c = cell_of_active[cell->active_cell_index()];
          fe_values.reinit(cell);
          initial.strain(fe_values, cell, eps0);
          for (unsigned int q = 0; q < n_points; ++q)
            {
              const unsigned int k = c * n_points + q;
              prestrain[k]         = eps0[q];
              const double dev     = deviator(eps0[q]).norm();
              prestrain_dev[c]     = std::max(prestrain_dev[c], dev);
              // von Mises = sqrt(3/2) 2 mu |dev eps0| over the yield
              // strength.
              const double ratio = std::sqrt(1.5) * 2. * mu[k] * dev / yield[k];
              if (ratio > largest.first)
                largest = {ratio, position[k]};
            }
        }
    // The largest ratio over the ranks, and where (from its rank).
    const MPI_Comm comm   = plate.get_mpi_communicator();
    prestress_yield.first = Utilities::MPI::max(largest.first, comm);
    const unsigned int owner =
      Utilities::MPI::min(largest.first == prestress_yield.first ?
                            Utilities::MPI::this_mpi_process(comm) :
                            Utilities::MPI::n_mpi_processes(comm),
                          comm);
    prestress_yield.second = largest.second;
    MPI_Bcast(&prestress_yield.second[0], 3, MPI_DOUBLE, owner, comm);
  }



  void
  PlasticPlate::refuse_yielding_prestress() const
  {
    // A state beyond the yield strength would flow plastically in the
    // impact's first time step: a sudden release of elastic energy, a
    // dynamic load the thermal step does not have.  Alike on every rank.
    const auto &[ratio, where] = prestress_yield;
    std::ostringstream text;
    text << std::fixed << std::setprecision(2) << ratio
         << " x the yield strength at (" << where[0] * 1e3 << ", "
         << where[1] * 1e3 << ", " << where[2] * 1e3 << ") mm";
    AssertThrow(!(ratio > 1.),
                ExcMessage("Material/Plasticity = J2: the thermal state's von "
                           "Mises stress reaches " +
                           text.str() +
                           "; the thermal step is elastic and an impact "
                           "starts from an admissible state (a static run "
                           "relaxes it in its first load step; "
                           "doc/thermal.md): lower the Thermal temperatures "
                           "or raise Material/Metal yield strength."));
  }
} // namespace fgimpact
