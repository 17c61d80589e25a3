// The rigid-plate limit: with the plate 1000x stiffer (same density) and the
// contact stiffness of the original law, the impact must reproduce the
// closed-form Hertz impact on a rigid half-space (Goldsmith):
//   alpha_max = (5 m V0^2 / (4 K))^(2/5),  F_max = K alpha_max^(3/2),
//   T_contact = 2.94328 alpha_max / V0,
// each to < 1 %; the ball leaves with the impact speed (e = 1).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <test_tools.h>

namespace fgimpact_unit_tests::rigid_plate_limit
{

  using namespace fgimpact;

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

    // Closed form inputs, computed here independently of the program:
    // a homogeneous 70 GPa, nu = 0.3 plate, R = 15 mm steel ball.
    const double R = 0.015, rho_i = 7800, V0 = 1.;
    const double m = 4. / 3. * M_PI * R * R * R * rho_i;
    const double K = 4. / 3. * 70e9 / (1 - 0.09) * std::sqrt(R);

    const double alpha_max = std::pow(5 * m * V0 * V0 / (4 * K), 0.4);
    const double F_max     = K * std::pow(alpha_max, 1.5);
    const double T_c       = 2.94328 * alpha_max / V0;

    char K_string[64];
    std::snprintf(K_string, sizeof(K_string), "%.17g", K);

    const ImpactResults r =
      fgimpact_tests::run_quietly(
        "",
        std::string("subsection Geometry\n set Subdivisions x = 10\n"
                    " set Subdivisions y = 6\n set Subdivisions z = 2\nend\n"
                    "subsection Material\n set Metal Young's modulus = 70e12\n"
                    " set Ceramic Young's modulus = 70e12\n"
                    " set Ceramic density = 2707\nend\n"
                    "subsection Contact\n set Contact stiffness = ") +
          K_string +
          "\nend\n"
          "subsection Time integration\n set Time step = 0.5e-6\n set End time = 200e-6\nend\n"
          "subsection Newton\n set Tolerance = 1e-12\nend\n"
          "subsection Output\n set Directory = out\n set Log interval = 0\n"
          " set Print timing = false\nend\n")
        .results;

    bool ok    = true;
    auto check = [&](const char *what, const double value, const double exact) {
      const double e    = std::abs(value / exact - 1);
      const bool   pass = e < 0.01;
      ok                = ok && pass;
      std::printf("%-28s closed form %10.4f, within 1 %%: %s\n",
                  what,
                  exact,
                  pass ? "yes" : "NO");
    };
    std::printf("rigid half-space, m = %.5f kg, K = %.5e N/m^1.5:\n", m, K);
    check("peak force (N)", r.peak_contact_force, F_max);
    check("max indentation (um)", r.max_indentation * 1e6, alpha_max * 1e6);
    check("contact duration (us)", r.contact_duration * 1e6, T_c * 1e6);
    check("departure velocity (m/s)", r.departure_velocity, V0);
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::rigid_plate_limit
