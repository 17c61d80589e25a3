// Newmark time convergence on the full impact (n = 1, V0 = 1 m/s, 20 x 10
// x 2 mesh): dt = 0.2, 0.1, 0.05 us.  Smooth functionals of the solution,
// the impulse int F dt and the contact duration, converge at order 2.  The
// peak force rides on the contact node's high-frequency oscillation (a
// local mode of period ~ 4 us on this mesh), so it shows no clean order at
// these step sizes; its changes are checked to be below 1e-4 relative
// (the mesh dependence of the peak force is ~10 %, doc/mesh_study.md).
// Set FGIMPACT_VERBOSE=1 to print the numbers.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/simulator.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <test_tools.h>

using namespace fgimpact;

namespace
{
  ImpactResults
  run(const double dt)
  {
    std::ostringstream settings;
    settings << "subsection Geometry\n set Subdivisions x = 20\n"
             << " set Subdivisions y = 10\n set Subdivisions z = 2\nend\n"
             << "subsection Time integration\n set Time step = " << dt
             << "\n set End time = 130e-6\nend\n"
             << "subsection Newton\n set Tolerance = 1e-12\nend\n";
    return fgimpact_tests::run_impact(settings.str());
  }
} // namespace

int
main(int argc, char **argv)
{
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;

  const ImpactResults r[3] = {run(0.2e-6), run(0.1e-6), run(0.05e-6)};
  auto order = [](const double a, const double b, const double c) {
    return std::log2(std::abs(a - b) / std::abs(b - c));
  };
  const double p_impulse = order(r[0].impulse, r[1].impulse, r[2].impulse);
  const double p_duration =
    order(r[0].contact_duration, r[1].contact_duration, r[2].contact_duration);
  const double dF =
    std::max(std::abs(r[0].peak_contact_force / r[1].peak_contact_force - 1),
             std::abs(r[1].peak_contact_force / r[2].peak_contact_force - 1));
  if (verbose)
    for (const auto &x : r)
      std::fprintf(stderr,
                   "impulse %.12e duration %.6f us peak %.5f N\n",
                   x.impulse,
                   x.contact_duration * 1e6,
                   x.peak_contact_force);
  if (verbose)
    std::fprintf(stderr,
                 "orders: impulse %.3f, duration %.3f; peak change %.2e\n",
                 p_impulse,
                 p_duration,
                 dF);

  const bool ok_i = p_impulse > 1.5 && p_impulse < 3.;
  const bool ok_d = p_duration > 1.5 && p_duration < 3.;
  const bool ok_f = dF < 1e-4;
  std::printf("impulse converges at order 2 (1.5 < p < 3): %s\n",
              ok_i ? "yes" : "NO");
  std::printf("contact duration converges at order 2 (1.5 < p < 3): %s\n",
              ok_d ? "yes" : "NO");
  std::printf("peak force changes below 1e-4 relative: %s\n",
              ok_f ? "yes" : "NO");
  std::printf("%s\n",
              ok_i && ok_d && ok_f ? "all checks passed" :
                                     "SOME CHECKS FAILED");
  return ok_i && ok_d && ok_f ? 0 : 1;
}
