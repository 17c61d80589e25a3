#include <deal.II/lac/lapack_full_matrix.h>

#include <fgimpact/analysis/modal_analysis.h>
#include <fgimpact/analysis/thermal_buckling.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/stop_signals.h>

#include <cmath>
#include <limits>

namespace fgimpact
{
  namespace
  {
    /// Rayleigh-Ritz: (Y^T G Y) q = mu (Y^T K Y) q, X = Y Q for the
    /// largest mu first; returns the mu in that order.
    std::vector<double>
    buckling_ritz(const TrilinosWrappers::SparseMatrix             &K,
                  const TrilinosWrappers::SparseMatrix             &G,
                  const std::vector<TrilinosWrappers::MPI::Vector> &Y,
                  TrilinosWrappers::MPI::Vector                    &tmp,
                  std::vector<TrilinosWrappers::MPI::Vector>       &X)
    {
      const unsigned int       p = Y.size();
      LAPACKFullMatrix<double> Gr(p, p), Kr(p, p);
      for (unsigned int j = 0; j < p; ++j)
        {
          G.vmult(tmp, Y[j]);
          for (unsigned int i = 0; i <= j; ++i)
            Gr(i, j) = Gr(j, i) = Y[i] * tmp;
          K.vmult(tmp, Y[j]);
          for (unsigned int i = 0; i <= j; ++i)
            Kr(i, j) = Kr(j, i) = Y[i] * tmp;
        }
      // A vector the pre-stress does not reach (G X = 0 there) is zero:
      // a unit diagonal keeps the projected K definite (its mu is 0).
      for (unsigned int j = 0; j < p; ++j)
        if (Kr(j, j) == 0.)
          Kr(j, j) = 1.;
      std::vector<Vector<double>> q(p, Vector<double>(p));
      Gr.compute_generalized_eigenvalues_symmetric(Kr, q);
      std::vector<double> mu(p);
      for (unsigned int j = 0; j < p; ++j)
        {
          // LAPACK's order is ascending: the largest first here.
          const unsigned int k = p - 1 - j;
          mu[j]                = Gr.eigenvalue(k).real();
          X[j]                 = 0.;
          for (unsigned int i = 0; i < p; ++i)
            X[j].add(q[k](i), Y[i]);
        }
      return mu;
    }
  } // namespace



  BucklingResult
  thermal_buckling_factor(const TrilinosWrappers::SparseMatrix &K,
                          const TrilinosWrappers::SparseMatrix &K_sigma,
                          EffectiveMatrixSolver                &K_solver,
                          const PlateModel                     &plate)
  {
    // G = -K_sigma: positive where the pre-stress compresses.
    TrilinosWrappers::SparseMatrix G;
    G.copy_from(K_sigma);
    G *= -1.;
    BucklingResult result;
    if (G.linfty_norm() == 0.) // no pre-stress (a free plate, Delta T = 0)
      {
        result.factor = std::numeric_limits<double>::infinity();
        return result;
      }
    const unsigned int                         p = 8;
    std::vector<TrilinosWrappers::MPI::Vector> X, Y;
    subspace_start_block(plate, p, X, Y);
    TrilinosWrappers::MPI::Vector tmp;
    plate.initialize_vector(tmp);
    double mu_old = 0.;
    for (result.iterations = 1; result.iterations <= 300; ++result.iterations)
      {
        throw_if_stop_signal(plate.get_mpi_communicator(),
                             "during the thermal buckling solve");
        for (unsigned int j = 0; j < p; ++j)
          {
            G.vmult(tmp, X[j]);
            K_solver.solve(Y[j], tmp);
          }
        const double mu = buckling_ritz(K, G, Y, tmp, X).front();
        if (result.iterations > 1 &&
            std::abs(mu - mu_old) <= 1e-10 * std::abs(mu))
          {
            result.factor =
              mu > 0. ? 1. / mu : std::numeric_limits<double>::infinity();
            return result;
          }
        mu_old = mu;
      }
    AssertThrow(false,
                ExcNumericalFailure(
                  "the thermal buckling solve did not converge in 300 "
                  "subspace iterations; set Thermal/Geometric stiffness = "
                  "false or refine Geometry/Subdivisions."));
    return result;
  }
} // namespace fgimpact
