#ifndef fgimpact_thermal_buckling_h
#define fgimpact_thermal_buckling_h

#include <deal.II/lac/trilinos_sparse_matrix.h>

#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plate_model.h>

namespace fgimpact
{
  using namespace dealii;

  /// The thermal buckling factor and how it was found.
  struct BucklingResult
  {
    /// The smallest lambda > 0 with K + lambda K_sigma singular; +inf if
    /// the pre-stress nowhere softens the plate (tension, or none).
    double       factor     = 0.;
    unsigned int iterations = 0;
  };

  /**
   * The linear (eigenvalue) buckling of a pre-stress: K phi = lambda (-K_sigma)
   * phi, by subspace iteration on K^{-1} (-K_sigma) with a block of 8 and
   * Rayleigh-Ritz on (Y^T (-K_sigma) Y, Y^T K Y), whose largest eigenvalue
   * mu gives lambda = 1/mu (Bathe's subspace iteration for buckling), to a
   * relative change of 1e-10.  K_solver holds K factorized (or K with the
   * free rigid-body motions pinned).  Collective.
   */
  BucklingResult
  thermal_buckling_factor(const TrilinosWrappers::SparseMatrix &K,
                          const TrilinosWrappers::SparseMatrix &K_sigma,
                          EffectiveMatrixSolver                &K_solver,
                          const PlateModel                     &plate);
} // namespace fgimpact

#endif
