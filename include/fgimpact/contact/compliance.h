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

  /// Unit loads solved together in the compliance's blocked solves (and
  /// the granularity of columns computed on demand).
  constexpr unsigned int compliance_block_size = 64;

  /**
   * The compliance of a matrix A (the effective matrix K + a0 M of a
   * Newmark step, or K of a static problem) at the contact DoFs: for the
   * unit loads g_j the responses c_j = A^{-1} g_j (m solves with the
   * factorized A) and the dense Delassus matrix C_ij = g_i^T c_j (m/N),
   * symmetric positive definite.  Collective.
   */
  void
  compute_compliance(EffectiveMatrixSolver                      &solver,
                     const PlateModel                           &plate,
                     const std::vector<types::global_dof_index> &dofs,
                     FullMatrix<double>                         &C);

  /**
   * A stored unit response c_j: its locally owned entries (m/N, in the
   * order of the plate's distributed vectors), in double or, for a
   * contact whose columns are computed on demand (the resolved one, with
   * hundreds of candidates; ImplicitNewmarkStepper), in single precision.  It
   * only corrects the plate's displacement, u -= sum lambda_j c_j; the contact
   * solve uses the compliance C, kept in double.  At level 7 of the default
   * scene a resolved contact's 384 stored responses took 291 MB in double, 24 %
   * over the plate's own peak; a float's relative round-off, 6e-8, is
   * far below the contact's Newton tolerance (1e-3 of the indentation)
   * and the discretization errors.  The point contacts (one or two
   * responses) keep double: their outputs stay bitwise.
   */
  class StoredResponse
  {
  public:
    explicit StoredResponse(const bool single_precision = false)
      : single_precision(single_precision)
    {}

    /// Store [begin, end) (m/N), narrowed to float if single precision.
    template <typename Iterator>
    void
    assign(const Iterator begin, const Iterator end)
    {
      if (single_precision)
        narrow.assign(begin, end);
      else
        wide.assign(begin, end);
    }

    bool
    empty() const
    {
      return narrow.empty() && wide.empty();
    }

    std::size_t
    size() const
    {
      return single_precision ? narrow.size() : wide.size();
    }

    bool
    single() const
    {
      return single_precision;
    }

    const float *
    single_data() const
    {
      return narrow.data();
    }

    const double *
    double_data() const
    {
      return wide.data();
    }

  private:
    bool                single_precision;
    std::vector<float>  narrow;
    std::vector<double> wide;
  };

  /**
   * Columns [first, last) of the compliance C (m x m, the rest left as
   * they are), and if `responses` is given (m vectors) the responses c_j
   * of these columns, one each (the back-substitution
   * u -= sum lambda_j c_j then costs no solve).  With cholmod on one
   * rank in blocks of compliance_block_size unit loads counted from
   * `first`: a caller that asks for whole blocks from 0 gets bitwise the
   * columns of compute_compliance(), whatever the order it asks in.
   * Collective.
   */
  void
  compute_compliance_columns(EffectiveMatrixSolver                      &solver,
                             const PlateModel                           &plate,
                             const std::vector<types::global_dof_index> &dofs,
                             const unsigned int                          first,
                             const unsigned int                          last,
                             FullMatrix<double>                         &C,
                             std::vector<StoredResponse> *responses);

  /**
   * x += sum_k w_k y_k over the locally owned entries, four terms per
   * pass over x (in blocks of rows that stay in cache): the separate
   * axpys read and wrote all of x once per term (at level 7 of the
   * default scene about 300 terms of 95k entries a step).  Measured
   * alone on that size: 8.5 ms against 14.3 ms.  Every entry gets its
   * terms in the axpys' order and as x + w y (a float y widened to
   * double), so with double responses the sum is bitwise theirs.
   */
  void
  add_weighted_responses(TrilinosWrappers::MPI::Vector             &x,
                         const std::vector<double>                 &w,
                         const std::vector<const StoredResponse *> &y);

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
