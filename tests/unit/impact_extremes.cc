// Stability and scaling at the extremes (issue 3), each with an expected
// behaviour:
//  - V0 = 0.01 and 20 m/s in the rigid-plate limit: the peak force scales as
//    V0^(6/5) (Hertz on a half-space), ratio within 1 %;
//  - dt = 0.01 us and 20 us (average acceleration is unconditionally
//    stable): no blow-up (at 20 us the energy error stays below the
//    second-order bound (pi dt / T_contact)^2), the ball leaves;
//  - a ball 100x heavier and 100x lighter: energy balance within 0.5 % and
//    the ball leaves.
// Set FGIMPACT_VERBOSE=1 to print the numbers.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <test_tools.h>

namespace fgimpact_unit_tests::impact_extremes
{

  using namespace fgimpact;

  namespace
  {
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;

    ImpactResults
    run(const std::string &settings)
    {
      const ImpactResults r = fgimpact_tests::run_impact(settings);
      if (verbose)
        std::fprintf(stderr,
                     "F %.6g N, contact %.6g us, V_dep %.6g, drift %.3e, "
                     "impacts %u, steps %u\n",
                     r.peak_contact_force,
                     r.contact_duration * 1e6,
                     r.departure_velocity,
                     r.max_energy_drift,
                     r.n_impacts,
                     r.n_time_steps);
      return r;
    }

    bool
    report(const char *what, const bool pass)
    {
      std::printf("%s: %s\n", what, pass ? "yes" : "NO");
      return pass;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    // Rigid-plate limit (plate 1000x stiffer, contact stiffness of the 70 GPa
    // half-space): F_max ~ V0^(6/5).
    const std::string rigid =
      "subsection Material\n set Metal Young's modulus = 70e12\n"
      " set Ceramic Young's modulus = 70e12\n set Ceramic density = 2707\nend\n"
      "subsection Contact\n set Contact stiffness = 1.25615e10\nend\n"
      "subsection Newton\n set Tolerance = 1e-12\nend\n";
    // Contact times: ~122 us / V0^(1/5): 3.2x longer at 0.01 m/s, 0.55x at 20.
    const ImpactResults slow =
      run(rigid + "subsection Impactor\n set Initial velocity = 0.01\nend\n"
                  "subsection Time integration\n set Time step = 2e-6\n"
                  " set End time = 500e-6\nend\n");
    const ImpactResults fast =
      run(rigid + "subsection Impactor\n set Initial velocity = 20\nend\n"
                  "subsection Time integration\n set Time step = 0.25e-6\n"
                  " set End time = 100e-6\nend\n");
    const double ratio = fast.peak_contact_force / slow.peak_contact_force;
    ok &= report("V0 = 0.01 -> 20 m/s, rigid plate: peak force ratio = "
                 "2000^(6/5) within 1 %",
                 std::abs(ratio / std::pow(2000., 1.2) - 1) < 0.01);

    // Time steps far apart.
    const ImpactResults tiny =
      run("subsection Time integration\n set Time step = 0.01e-6\n"
          " set End time = 150e-6\nend\n");
    ok &= report("dt = 0.01 us: energy drift below 5 %, ball leaves",
                 tiny.max_energy_drift < 0.05 && tiny.departure_velocity > 0);
    const ImpactResults huge =
      run("subsection Time integration\n set Time step = 20e-6\n"
          " set End time = 600e-6\nend\n");
    // With ~6 steps in contact the second-order error is of the size
    // (omega dt)^2, omega = pi / T_contact: the energy error must stay below
    // that bound (no growth), the solution finite, and the ball must leave.
    const double bound = std::pow(M_PI * 20e-6 / tiny.contact_duration, 2);
    ok &=
      report("dt = 20 us (6 steps in contact): no blow-up, energy error "
             "below (pi dt / T_contact)^2, ball leaves",
             std::isfinite(huge.peak_contact_force) &&
               huge.max_energy_drift < bound && huge.departure_velocity > 0);
    ok &= report("dt = 20 us peak force within 10 % of dt = 0.01 us",
                 std::abs(huge.peak_contact_force / tiny.peak_contact_force -
                          1) < 0.1);

    // Impactor mass x100 and /100 (7800 kg/m^3 -> 780000 and 78).
    const ImpactResults heavy =
      run("subsection Impactor\n set Density = 780000\nend\n"
          "subsection Time integration\n set Time step = 2e-6\n"
          " set End time = 4000e-6\nend\n");
    ok &= report("ball 100x heavier: energy within 0.5 %, ball leaves",
                 heavy.max_energy_drift < 5e-3 && heavy.departure_velocity > 0);
    const ImpactResults light =
      run("subsection Impactor\n set Density = 78\nend\n"
          "subsection Time integration\n set Time step = 0.1e-6\n"
          " set End time = 100e-6\nend\n");
    ok &= report("ball 100x lighter: energy within 0.5 %, ball leaves",
                 light.max_energy_drift < 5e-3 && light.departure_velocity > 0);

    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::impact_extremes
