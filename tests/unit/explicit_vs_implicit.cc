// The explicit path (central difference, lumped mass, automatic stable
// step) against the implicit one (average acceleration, consistent mass,
// dt = 0.5 us) on a small mesh: peak contact force within 1 %, contact
// duration within 1 %; and the explicit run conserves energy.
// Also: a time step above the stability limit is refused.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <test_tools.h>

namespace fgimpact_unit_tests::explicit_vs_implicit
{

  using namespace fgimpact;

  using fgimpact_tests::run_impact;

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const ImpactResults              implicit_run =
      run_impact("subsection Time integration\n set Time step = 0.5e-6\nend\n");
    const ImpactResults explicit_run =
      run_impact("subsection Time integration\n set Scheme = explicit\n"
                 " set Time step = 0\nend\n");

    const double dF = std::abs(
      explicit_run.peak_contact_force / implicit_run.peak_contact_force - 1);
    const double dT = std::abs(
      explicit_run.contact_duration / implicit_run.contact_duration - 1);
    bool ok = dF < 0.01 && dT < 0.01 && explicit_run.max_energy_drift < 5e-3;
    std::printf("explicit vs implicit peak force within 1 %%: %s\n",
                dF < 0.01 ? "yes" : "NO");
    std::printf("explicit vs implicit contact duration within 1 %%: %s\n",
                dT < 0.01 ? "yes" : "NO");
    std::printf("explicit energy drift below 0.5 %%: %s\n",
                explicit_run.max_energy_drift < 5e-3 ? "yes" : "NO");

    // 2 us is about twice the stability limit on this mesh (1.0 us).
    bool refused = false;
    try
      {
        run_impact("subsection Time integration\n set Scheme = explicit\n"
                   " set Time step = 2e-6\nend\n");
      }
    catch (const ExceptionBase &e)
      {
        std::ostringstream message;
        e.print_info(message);
        refused = message.str().find("exceeds the stability limit") !=
                  std::string::npos;
      }
    ok = ok && refused;
    std::printf("unstable explicit time step refused: %s\n",
                refused ? "yes" : "NO");
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::explicit_vs_implicit
