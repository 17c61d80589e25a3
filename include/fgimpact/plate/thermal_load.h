#ifndef fgimpact_thermal_load_h
#define fgimpact_thermal_load_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/material/thermal.h>
#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/plate_model.h>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The thermal load of the static thermal step (N): with the thermal
   * strain eps_th = e(z) I, e = alpha(z) (T(z) - T_ref),
   *
   *   f_i = int eps(phi_i) : C eps_th dV = int (3 lambda + 2 mu) e div phi_i dV
   *
   * (with B-bar the cell's mean divergence of phi_i), E and nu as in the
   * stiffness (PropertyInterpolator), e at the quadrature point's z.
   * Assembled through the plate's constraints into rhs (non-ghosted,
   * compressed).
   */
  void
  assemble_thermal_load(const PlateModel              &plate,
                        const TemperatureProfile      &temperature,
                        TrilinosWrappers::MPI::Vector &rhs);


  /**
   * The initial-stress stiffness K_sigma of the pre-stress
   * sigma0 = C eps0 (add_geometric_cell_matrix()), on K's
   * sparsity; the constrained DoFs' rows and columns are zero (not the
   * diagonal that condensation puts there), so that K + K_sigma keeps K's
   * constrained rows.
   */
  void
  assemble_geometric_stiffness(const PlateModel               &plate,
                               const InitialStress            &initial,
                               TrilinosWrappers::SparseMatrix &K_sigma);
} // namespace fgimpact

#endif
