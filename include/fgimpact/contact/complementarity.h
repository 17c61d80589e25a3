#ifndef fgimpact_complementarity_h
#define fgimpact_complementarity_h

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <functional>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Columns of a Delassus matrix computed on demand, nearest contact DoF
   * first: columns(n) makes the first n columns of the matrix valid (it
   * writes them into the matrix its caller holds) and returns how many are
   * valid now, at least n.  An empty request: all columns are valid.
   */
  using ColumnRequest = std::function<unsigned int(unsigned int)>;

  /// What solve_lcp() did.
  struct LcpStatistics
  {
    /// Active-set iterations (each one Cholesky solve of the active block).
    unsigned int iterations = 0;
    /// Whether the projected Gauss-Seidel fallback had to finish the job.
    bool used_fallback = false;
    /// False only if the fallback, too, stopped short of its tolerance:
    /// the forces are not the LCP's solution.
    bool converged = true;
    /// The largest penetration max_j (-g_j) left after the solve (m):
    /// lambda >= 0 and lambda_j g_j = 0 hold by construction (on the set
    /// g = 0 to round-off, off it lambda = 0).
    double penetration = 0;
  };

  /**
   * The linear complementarity problem of frictionless unilateral contact
   * with a symmetric positive definite Delassus matrix A (m/N):
   *
   *   g = q + A lambda >= 0,  lambda >= 0,  lambda_j g_j = 0,
   *
   * (g the gaps in m, lambda the contact forces in N).  It is the
   * optimality system of the convex QP min 1/2 l^T A l + q^T l, l >= 0, so
   * it has exactly one solution.
   *
   * Solved by the primal-dual active set method (semismooth Newton on
   * lambda = max(0, lambda - c g), Hintermueller, Ito & Kunisch 2003),
   * warm-started from `active` (the previous time step's set, which is
   * updated): a step solves A_AA lambda_A = -q_A by Cholesky and moves
   * nodes with lambda < 0 out of and nodes with g < 0 into the set; it stops
   * when the set repeats.  PDAS converges in a few iterations for contact
   * Delassus matrices but is not guaranteed for every SPD matrix, so after
   * `max_iterations` the projected Gauss-Seidel method (convergent for any
   * SPD matrix) finishes from the last iterate.
   *
   * Only the columns of the active set enter: A_AA, and the gaps
   * g = q + A_{:A} lambda_A (lambda is 0 off the set).  With `columns`, A's
   * columns are asked for as the set reaches them (all of them before the
   * fallback); a column not yet valid must hold finite values (they are
   * multiplied by lambda_j = 0 exactly, so the result is bitwise that of
   * the whole matrix).
   */
  LcpStatistics
  solve_lcp(const FullMatrix<double> &A,
            const Vector<double>     &q,
            Vector<double>           &lambda,
            std::vector<bool>        &active,
            const unsigned int        max_iterations = 50,
            const ColumnRequest      &columns        = ColumnRequest());
} // namespace fgimpact

#endif
