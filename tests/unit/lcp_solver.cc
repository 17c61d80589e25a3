// The contact LCP solver (primal-dual active set with a projected
// Gauss-Seidel fallback) against an independent solution: every active set
// enumerated for small random SPD matrices (the unique solution is the one
// set whose lambda >= 0 and g >= 0), and the solution's KKT conditions
// for a large Delassus-like matrix; warm starts from the exact set take one
// iteration.

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/contact/complementarity.h>

#include <cmath>
#include <cstdio>
#include <random>

namespace fgimpact_unit_tests::lcp_solver
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    /// A random SPD matrix B B^T + m I/10 and a q with mixed signs.
    void
    random_problem(const unsigned int  m,
                   std::mt19937       &rng,
                   FullMatrix<double> &A,
                   Vector<double>     &q)
    {
      std::uniform_real_distribution<double> u(-1., 1.);
      FullMatrix<double>                     B(m, m);
      for (unsigned int i = 0; i < m; ++i)
        for (unsigned int j = 0; j < m; ++j)
          B(i, j) = u(rng);
      A.reinit(m, m);
      B.mTmult(A, B);
      for (unsigned int i = 0; i < m; ++i)
        A(i, i) += 0.1 * m;
      q.reinit(m);
      for (unsigned int i = 0; i < m; ++i)
        q[i] = u(rng);
    }

    /// All 2^m active sets: lambda_A = -A_AA^{-1} q_A; the feasible one.
    Vector<double>
    enumerate(const FullMatrix<double> &A, const Vector<double> &q)
    {
      const unsigned int m = q.size();
      for (unsigned int mask = 0; mask < (1u << m); ++mask)
        {
          std::vector<unsigned int> set;
          for (unsigned int j = 0; j < m; ++j)
            if (mask & (1u << j))
              set.push_back(j);
          const unsigned int k = set.size();
          Vector<double>     lambda(m);
          if (k > 0)
            {
              FullMatrix<double> block(k, k), inverse(k, k);
              Vector<double>     rhs(k), x(k);
              for (unsigned int i = 0; i < k; ++i)
                {
                  rhs[i] = -q[set[i]];
                  for (unsigned int j = 0; j < k; ++j)
                    block(i, j) = A(set[i], set[j]);
                }
              inverse.invert(block); // Gauss-Jordan: not Cholesky
              inverse.vmult(x, rhs);
              for (unsigned int i = 0; i < k; ++i)
                lambda[set[i]] = x[i];
            }
          Vector<double> g(m);
          A.vmult(g, lambda);
          g += q;
          bool feasible = true;
          for (unsigned int j = 0; j < m; ++j)
            if (lambda[j] < -1e-12 || g[j] < -1e-12)
              feasible = false;
          if (feasible)
            return lambda;
        }
      return Vector<double>();
    }
  } // namespace

  int
  test_main(int, char **)
  {
    std::mt19937 rng(20261123);
    bool         ok = true;

    // Verdicts, not the numbers: the errors are round-off of LAPACK's
    // Cholesky (its digits depend on the CPU and the BLAS kernel), and an
    // iteration count may change with it; the active set's convergence
    // (without the projected Gauss-Seidel fallback) is what matters.
    std::printf("random SPD, m   max |lambda - enumerated| / max lambda < "
                "1e-10   active set converged (no fallback)   penetration < "
                "1e-12\n");
    for (const unsigned int m : {3u, 6u, 9u, 12u})
      for (unsigned int trial = 0; trial < 3; ++trial)
        {
          FullMatrix<double> A;
          Vector<double>     q, lambda;
          random_problem(m, rng, A, q);
          std::vector<bool>    active;
          const LcpStatistics  s     = solve_lcp(A, q, lambda, active);
          const Vector<double> exact = enumerate(A, q);
          Vector<double>       diff(lambda);
          diff -= exact;
          const double error =
            diff.linfty_norm() / std::max(exact.linfty_norm(), 1e-300);
          std::printf("%2u  %s   %s   %s\n",
                      m,
                      error < 1e-10 ? "yes" : "NO",
                      s.used_fallback ? "NO" : "yes",
                      s.penetration < 1e-12 ? "yes" : "NO");
          ok = ok && error < 1e-10 && !s.used_fallback && s.penetration < 1e-12;
        }

    // A Delassus-like matrix: the compliance of a 1D chain of springs on an
    // elastic foundation (dense, SPD, decaying off the diagonal) pressed by a
    // parabolic punch; KKT conditions checked directly.
    const unsigned int m = 300;
    FullMatrix<double> A(m, m);
    Vector<double>     q(m), lambda, g(m);
    for (unsigned int i = 0; i < m; ++i)
      {
        for (unsigned int j = 0; j < m; ++j)
          A(i, j) = 1e-9 * std::exp(-std::abs(double(i) - double(j)) / 10.);
        const double r = (i - 150.) / 100.;
        q[i]           = 1e-6 * (r * r - 0.3);
      }
    std::vector<bool>   active;
    const LcpStatistics s = solve_lcp(A, q, lambda, active);
    A.vmult(g, lambda);
    g += q;
    double       worst_g = 0, worst_complementarity = 0;
    unsigned int n_active = 0;
    for (unsigned int j = 0; j < m; ++j)
      {
        worst_g = std::max(worst_g, -g[j]);
        worst_complementarity =
          std::max(worst_complementarity, std::abs(lambda[j] * g[j]));
        n_active += (lambda[j] > 0.);
        ok = ok && lambda[j] >= 0.;
      }
    const bool feasible      = worst_g < 1e-12 * q.linfty_norm(),
               complementary = worst_complementarity <
                               1e-12 * lambda.linfty_norm() * q.linfty_norm();
    std::printf("Delassus-like, m = %u: %u active, fallback %s, max "
                "penetration / |q| < 1e-12: %s, max |lambda g| / (|lambda| "
                "|q|) < 1e-12: %s\n",
                m,
                n_active,
                s.used_fallback ? "yes" : "no",
                feasible ? "yes" : "NO",
                complementary ? "yes" : "NO");
    ok = ok && !s.used_fallback && feasible && complementary;

    // Warm start from the converged set: one iteration.
    const LcpStatistics again = solve_lcp(A, q, lambda, active);
    std::printf("warm start from the solution's set: %u iteration(s)\n",
                again.iterations);
    ok = ok && again.iterations == 1;

    // Columns on demand (the resolved contact's compliance): the chain
    // seen from the punch's tip, nearest first, solved with a matrix whose
    // columns are copied from A in blocks of 64 as the LCP asks for them.
    // The forces must be bitwise those of the whole matrix, from the blocks
    // that reach the active set only.
    {
      FullMatrix<double> B(m, m), partial(m, m);
      Vector<double>     p(m), whole, lazy;
      for (unsigned int i = 0; i < m; ++i)
        {
          for (unsigned int j = 0; j < m; ++j)
            B(i, j) = 1e-9 * std::exp(-std::abs(double(i) - double(j)) / 10.);
          p[i] = 1e-6 * (std::pow(i / 100., 2) - 0.3);
        }
      std::vector<bool> set_whole, set_lazy;
      solve_lcp(B, p, whole, set_whole);
      unsigned int        valid   = 0;
      const ColumnRequest request = [&](const unsigned int n) {
        for (; valid < std::min(m, (n + 63) / 64 * 64); ++valid)
          for (unsigned int i = 0; i < m; ++i)
            partial(i, valid) = B(i, valid);
        return valid;
      };
      const LcpStatistics t =
        solve_lcp(partial, p, lazy, set_lazy, 50, request);
      unsigned int n_active = 0, farthest = 0;
      double       difference = 0;
      for (unsigned int j = 0; j < m; ++j)
        {
          difference = std::max(difference, std::abs(lazy[j] - whole[j]));
          if (whole[j] > 0.)
            {
              ++n_active;
              farthest = j;
            }
        }
      std::printf("columns on demand, m = %u: %u active (farthest %u), %u "
                  "columns asked for, lambda bitwise lambda_whole: %s, "
                  "fallback %s\n",
                  m,
                  n_active,
                  farthest,
                  valid,
                  difference == 0. ? "yes" : "NO",
                  t.used_fallback ? "yes" : "no");
      ok = ok && difference == 0. && valid == (farthest + 64) / 64 * 64 &&
           valid < m && set_lazy == set_whole && !t.used_fallback;
    }

    std::printf("%s\n", ok ? "OK" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::lcp_solver
