#ifndef fgimpact_compliance_h
#define fgimpact_compliance_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plate_model.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The compliance of a matrix A (the effective matrix K + a0 M of a
   * Newmark step, or K of a static problem) at the contact DoFs: for the
   * unit loads g_j the responses c_j = A^{-1} g_j (m solves with the
   * factorized A) and the dense Delassus matrix C_ij = g_i^T c_j (m/N),
   * symmetric positive definite.  The responses of the first
   * n_responses DoFs are kept if asked for (one vector per DoF: the
   * back-substitution u -= sum lambda_j c_j costs no solve); the others
   * are left empty (size 0).  Collective.
   */
  void
  compute_compliance(
    EffectiveMatrixSolver                      &solver,
    const PlateModel                           &plate,
    const std::vector<types::global_dof_index> &dofs,
    FullMatrix<double>                         &C,
    std::vector<TrilinosWrappers::MPI::Vector> *responses,
    const std::size_t n_responses = static_cast<std::size_t>(-1));

  /// The response c = A^{-1} g of one unit load at `dof` (the solver
  /// factorized A).  Collective.
  void
  compute_response(EffectiveMatrixSolver         &solver,
                   const PlateModel              &plate,
                   const types::global_dof_index  dof,
                   TrilinosWrappers::MPI::Vector &c);

  /**
   * The plate's largest static compliance e_i^T K^{-1} e_i (m/N) over the
   * contact DoFs, or over 8 of them spread over the list when it is longer
   * (a resolved contact's candidates, sorted by their distance from the
   * impact point: the compliance varies slowly over the patch); one
   * factorization of K.  For Time integration/End time = auto.
   * Collective.
   */
  double
  largest_static_compliance(
    const PlateModel                           &plate,
    const EffectiveMatrixSolver::Parameters    &solver_parameters,
    const std::vector<types::global_dof_index> &dofs);
} // namespace fgimpact

#endif
