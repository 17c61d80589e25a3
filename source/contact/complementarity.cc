#include <deal.II/base/exceptions.h>

#include <deal.II/lac/lapack_full_matrix.h>

#include <fgimpact/contact/complementarity.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  namespace
  {
    /// lambda_A = -A_AA^{-1} q_A (Cholesky), lambda = 0 off the set.
    void
    solve_active_block(const FullMatrix<double>        &A,
                       const Vector<double>            &q,
                       const std::vector<unsigned int> &set,
                       Vector<double>                  &lambda)
    {
      lambda               = 0.;
      const unsigned int k = set.size();
      if (k == 0)
        return;
      LAPACKFullMatrix<double> block(k, k);
      Vector<double>           rhs(k);
      for (unsigned int i = 0; i < k; ++i)
        {
          rhs[i] = -q[set[i]];
          for (unsigned int j = 0; j < k; ++j)
            block(i, j) = A(set[i], set[j]);
        }
      block.set_property(LAPACKSupport::symmetric);
      block.compute_cholesky_factorization();
      block.solve(rhs);
      for (unsigned int i = 0; i < k; ++i)
        lambda[set[i]] = rhs[i];
    }



    /// Projected Gauss-Seidel to a relative change of 1e-14: converges for
    /// any SPD A (it is coordinate descent on the convex QP); false if
    /// 100,000 sweeps did not get there.
    bool
    projected_gauss_seidel(const FullMatrix<double> &A,
                           const Vector<double>     &q,
                           Vector<double>           &lambda)
    {
      const unsigned int m = q.size();
      for (unsigned int sweep = 0; sweep < 100000; ++sweep)
        {
          double change = 0, size = 0;
          for (unsigned int i = 0; i < m; ++i)
            {
              double g = q[i];
              for (unsigned int j = 0; j < m; ++j)
                g += A(i, j) * lambda[j];
              const double updated = std::max(0., lambda[i] - g / A(i, i));
              change    = std::max(change, std::abs(updated - lambda[i]));
              size      = std::max(size, updated);
              lambda[i] = updated;
            }
          if (change <= 1e-14 * size)
            return true;
        }
      return false;
    }
  } // namespace



  namespace
  {
    /// The indices j with active[j], ascending.
    std::vector<unsigned int>
    indices_of(const std::vector<bool> &active)
    {
      std::vector<unsigned int> set;
      for (unsigned int j = 0; j < active.size(); ++j)
        if (active[j])
          set.push_back(j);
      return set;
    }

    /// The semismooth Newton update of the active set (c = 1 in consistent
    /// units is irrelevant: on the set g = 0, off it lambda = 0); whether
    /// it changed.
    bool
    update_active_set(const Vector<double> &lambda,
                      const Vector<double> &g,
                      std::vector<bool>    &active)
    {
      bool changed = false;
      for (unsigned int j = 0; j < active.size(); ++j)
        {
          const bool now = active[j] ? (lambda[j] > 0.) : (g[j] < 0.);
          // A node that left with lambda < 0 is at g > 0 next time; a node
          // with g exactly 0 and lambda exactly 0 stays where it is.
          changed   = changed || now != active[j];
          active[j] = now;
        }
      return changed;
    }
  } // namespace



  LcpStatistics
  solve_lcp(const FullMatrix<double> &A,
            const Vector<double>     &q,
            Vector<double>           &lambda,
            std::vector<bool>        &active,
            const unsigned int        max_iterations,
            const ColumnRequest      &columns)
  {
    const unsigned int m = q.size();
    AssertDimension(A.m(), m);
    AssertDimension(A.n(), m);
    lambda.reinit(m);
    if (active.size() != m)
      active.assign(m, false);

    unsigned int valid   = (columns ? columns(0) : m);
    const auto   require = [&](const unsigned int n) {
      if (n > valid)
        valid = columns(n);
    };

    LcpStatistics  statistics;
    Vector<double> g(m);
    bool           converged = false;
    for (unsigned int it = 1; it <= max_iterations && !converged; ++it)
      {
        const std::vector<unsigned int> set = indices_of(active);
        if (!set.empty())
          require(set.back() + 1);
        solve_active_block(A, q, set, lambda);
        A.vmult(g, lambda);
        g += q;
        statistics.iterations = it;

        converged = !update_active_set(lambda, g, active);
      }

    if (!converged)
      {
        statistics.used_fallback = true;
        require(m);
        for (unsigned int j = 0; j < m; ++j)
          lambda[j] = std::max(0., lambda[j]);
        statistics.converged = projected_gauss_seidel(A, q, lambda);
        for (unsigned int j = 0; j < m; ++j)
          active[j] = (lambda[j] > 0.);
        A.vmult(g, lambda);
        g += q;
      }

    for (unsigned int j = 0; j < m; ++j)
      statistics.penetration = std::max(statistics.penetration, -g[j]);
    return statistics;
  }
} // namespace fgimpact
