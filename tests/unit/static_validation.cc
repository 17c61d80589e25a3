// Static validation against the exact 3D elasticity solution
// (tests/exact/plate_exact.h, an independent state-space solver): the
// simply supported homogeneous and n = 1 graded plates under the pressure
// q0 sin(pi x/a) sin(pi y/b).
//  - Q1: mid-plane centre deflection error under uniform refinement in all
//    three directions, observed order of convergence (expected 2);
//  - Q2: within 0.5 % of exact on a 20 x 10 x 4 mesh;
//  - B-bar (Finite element/Volumetric strain = cell mean) on a nearly
//    incompressible homogeneous plate (nu = 0.499), where the pointwise
//    brick locks: order 2 and within 1 % on 40 x 20 x 8, and the pointwise
//    brick's error at least 5 x as large there.
// Set FGIMPACT_VERBOSE=1 to print the numbers.

#include <deal.II/base/mpi.h>

#include <fgimpact/analysis/static_analysis.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exact/plate_exact.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::static_validation
{

  using namespace fgimpact;

  namespace
  {
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;

    /// FE mid-plane centre deflection (m, downward) for q0 = 1 MPa.
    double
    fe_deflection(const double       n,
                  const unsigned int degree,
                  const unsigned int nx,
                  const unsigned int ny,
                  const unsigned int nz,
                  const PropertyMode mode            = PropertyMode::graded,
                  const double       nu              = 0.3,
                  const bool         mean_dilatation = false)
    {
      const auto c = fgimpact_tests::make_plate(
        nx, ny, nz, degree, n, mode, 0.02, MPI_COMM_WORLD, nu, mean_dilatation);
      const auto                       &plate = *c.plate;
      StaticAnalysis::Parameters        sp;
      EffectiveMatrixSolver::Parameters lp;
      lp.type = EffectiveMatrixSolver::Type::cholmod;
      StaticAnalysis analysis(sp, lp, plate, Point<2>(0.1, 0.05));
      analysis.solve();
      return analysis.get_results().deflection[1];
    }


    /// Q1 with the cell's mean dilatation (B-bar) against the pointwise
    /// brick on a homogeneous plate with nu = 0.499 (kappa / mu = 500).
    bool
    nearly_incompressible()
    {
      const double nu = 0.499;
      const double exact =
        -fgimpact_exact::static_sinusoidal(
           fgimpact_exact::homogeneous_plate(70e9, 2707., nu), 1e6, 1, 1)
           .W(0.01);
      std::printf("homogeneous plate, nu = 0.499, exact mid-plane deflection "
                  "%.4f um\n",
                  exact * 1e6);
      double bbar[3], pointwise[3];
      for (unsigned int l = 0; l < 3; ++l)
        {
          const unsigned int k = 1u << l;
          bbar[l]              = std::abs(
            fe_deflection(
              0., 1, 10 * k, 5 * k, 2 * k, PropertyMode::graded, nu, true) /
              exact -
            1);
          pointwise[l] = std::abs(
            fe_deflection(
              0., 1, 10 * k, 5 * k, 2 * k, PropertyMode::graded, nu, false) /
              exact -
            1);
          if (verbose)
            std::fprintf(stderr,
                         "  Q1 %ux%ux%u: B-bar error %.3e, pointwise %.3e\n",
                         10 * k,
                         5 * k,
                         2 * k,
                         bbar[l],
                         pointwise[l]);
        }
      const double order    = std::log2(bbar[1] / bbar[2]);
      const bool   order_ok = std::abs(order - 2.) < 0.2;
      const bool   close    = bbar[2] < 1e-2;
      const bool   locks    = pointwise[2] > 5. * bbar[2];
      std::printf("  Q1 B-bar observed order of convergence 2 +- 0.2: %s; "
                  "within 1 %% on 40 x 20 x 8: %s; the pointwise brick's "
                  "error at least 5 x B-bar's there: %s\n",
                  order_ok ? "yes" : "NO",
                  close ? "yes" : "NO",
                  locks ? "yes" : "NO");
      return order_ok && close && locks;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    for (const double n : {0., 1.})
      {
        // n = 0 is pure metal: the homogeneous plate.
        const fgimpact_exact::Plate exact_plate =
          fgimpact_exact::power_law_plate(n);
        const double exact =
          -fgimpact_exact::static_sinusoidal(exact_plate, 1e6, 1, 1).W(0.01);
        std::printf("%s plate, exact mid-plane deflection %.4f um\n",
                    n == 0 ? "homogeneous (n = 0)" : "graded n = 1",
                    exact * 1e6);

        double       previous = 0;
        double       order    = 0;
        unsigned int level    = 0;
        for (const unsigned int k : {1u, 2u, 4u})
          {
            const double error =
              std::abs(fe_deflection(n, 1, 10 * k, 5 * k, 2 * k) / exact - 1);
            if (level > 0)
              order = std::log2(previous / error);
            if (verbose)
              std::fprintf(stderr,
                           "  Q1 %ux%ux%u: error %.3e order %.3f\n",
                           10 * k,
                           5 * k,
                           2 * k,
                           error,
                           order);
            previous = error;
            ++level;
          }
        const bool order_ok = std::abs(order - 2.) < 0.2;
        std::printf("  Q1 observed order of convergence 2 +- 0.2: %s\n",
                    order_ok ? "yes" : "NO");

        const double q2_error =
          std::abs(fe_deflection(n, 2, 20, 10, 4) / exact - 1);
        if (verbose)
          std::fprintf(stderr, "  Q2 20x10x4: error %.3e\n", q2_error);
        const bool q2_ok = q2_error < 5e-3;
        std::printf("  Q2 20 x 10 x 4 within 0.5 %%: %s\n",
                    q2_ok ? "yes" : "NO");
        ok = ok && order_ok && q2_ok;
      }
    ok = nearly_incompressible() && ok;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::static_validation
