// Whole-program check on a small mesh: the impact of the paper's ball on the
// n = 1 plate conserves total energy (average-acceleration Newmark) to
// < 0.5 %, and the ball leaves.  Also for a homogeneous plate and a
// re-striking case.  (The impactor's balance int F dt = m (V0 + V_dep) is an
// identity of its update for gamma = 1/2, not a check: not asserted.)

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <test_tools.h>

namespace fgimpact_unit_tests::impact_conservation
{

  using namespace fgimpact;

  using fgimpact_tests::run_impact;

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize           mpi(argc, argv, 1);
    bool                                       ok      = true;
    const std::pair<const char *, std::string> cases[] = {
      {"n = 1, V0 = 1 m/s", ""},
      {"homogeneous plate, V0 = 3 m/s",
       "subsection Material\n set Ceramic Young's modulus = 70e9\n"
       " set Ceramic density = 2707\nend\n"
       "subsection Impactor\n set Initial velocity = 3\nend\n"},
      {"n = 5, 11300 kg/m^3 ball, dt = 2 us",
       "subsection Material\n set Power-law index = 5\nend\n"
       "subsection Impactor\n set Density = 11300\nend\n"
       "subsection Time integration\n set Time step = 2e-6\n set End time = 600e-6\nend\n"}};
    for (const auto &[name, settings] : cases)
      {
        const ImpactResults r      = run_impact(settings);
        const bool          energy = r.max_energy_drift < 5e-3;
        const bool          left =
          std::isfinite(r.departure_velocity) && r.departure_velocity > 0;
        ok = ok && energy && left;
        std::printf("%s:\n  energy drift %.2e, below 0.5 %%: %s\n"
                    "  ball left the plate: %s\n",
                    name,
                    r.max_energy_drift,
                    energy ? "yes" : "NO",
                    left ? "yes" : "NO");
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::impact_conservation
