// A thin plate, h/a = 0.01 (0.2 x 0.1 x 0.002 m, homogeneous, simply
// supported, sinusoidal load), against the exact 3D solution: the 8-node
// brick (Q1) locks in bending with one element through the thickness
// (-86 % with elements 5x longer than thick; still -32 % with cubic
// elements, 22x the DoFs); the remedy is Q2 (-0.4 % with one element
// through the thickness on the coarse mesh).
// Set FGIMPACT_VERBOSE=1 to print the numbers.

#include <deal.II/base/mpi.h>

#include <fgimpact/analysis/static_analysis.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exact/plate_exact.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::thin_plate_locking
{

  using namespace fgimpact;

  namespace
  {
    const double h = 0.002;

    double
    error(const double       exact,
          const unsigned int degree,
          const unsigned int nx,
          const unsigned int ny,
          const unsigned int nz)
    {
      const auto c = fgimpact_tests::make_plate(
        nx, ny, nz, degree, 0., PropertyMode::graded, h);
      const auto                       &plate = *c.plate;
      EffectiveMatrixSolver::Parameters lp;
      lp.type = EffectiveMatrixSolver::Type::cholmod;
      StaticAnalysis analysis(StaticAnalysis::Parameters(),
                              lp,
                              plate,
                              Point<2>(0.1, 0.05));
      analysis.solve();
      const double e = analysis.get_results().deflection[1] / exact - 1;
      if (std::getenv("FGIMPACT_VERBOSE"))
        std::fprintf(stderr,
                     "Q%u %ux%ux%u (%u DoFs): error %+.4e\n",
                     degree,
                     nx,
                     ny,
                     nz,
                     plate.n_dofs(),
                     e);
      return e;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const double                     exact =
      -fgimpact_exact::static_sinusoidal(
         fgimpact_exact::homogeneous_plate(70e9, 2707., 0.3, 0.2, 0.1, h),
         1e6,
         1,
         1)
         .W(h / 2);

    bool ok     = true;
    auto report = [&](const char *what, const bool pass) {
      std::printf("%s: %s\n", what, pass ? "yes" : "NO");
      ok = ok && pass;
    };
    report("Q1, 20 x 10 x 1 (elements 5x longer than thick): locks, deflection "
           "more than 50 % too small",
           error(exact, 1, 20, 10, 1) < -0.5);
    report("Q1, 100 x 50 x 1 (cubic elements, 22x the DoFs): still more than "
           "20 % too stiff",
           error(exact, 1, 100, 50, 1) < -0.2);
    report("Q2, 20 x 10 x 1: within 1 %",
           std::abs(error(exact, 2, 20, 10, 1)) < 0.01);
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::thin_plate_locking
