// Output/Fields = acceleration: the VTU field acceleration_m_s2 of an
// impact run is the time stepper's acceleration.  Read back from the
// files (base64, zlib stored blocks with Output/VTU compression = none),
// every snapshot pair n, n+1 (VTU interval 1) must satisfy the average
// acceleration rule v_{n+1} - v_n = dt/2 (a_n + a_{n+1}) at every output
// point, with the velocity field velocity_m_s written beside it (float32
// data: to 1e-5 of the largest velocity change), and the mid-plane
// centre's a_z must equal probes.csv's mid_az_m_s2.  A wrong vector in the
// field (the velocity, the displacement, a stale copy) fails both.

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::vtu_acceleration
{

  using namespace dealii;
  using fgimpact_tests::read_array;

  namespace
  {
    const double dt = 2e-6; // s

    std::string
    snapshot(const unsigned int n)
    {
      return "out/vtu/solution_" + Utilities::int_to_string(n, 5) + ".0.vtu";
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    fgimpact_tests::remove_output("out");
    fgimpact_tests::run_quietly(
      "",
      "subsection Geometry\n set Subdivisions x = 10\n set Subdivisions y = 6\n"
      " set Subdivisions z = 2\nend\n"
      "subsection Time integration\n set Time step = 2e-6\n"
      " set End time = 40e-6\nend\n"
      "subsection Output\n set Directory = out\n set Log interval = 0\n"
      " set Print timing = false\n set VTU interval = 1\n"
      " set VTU compression = none\n"
      " set Fields = displacement, velocity, acceleration\nend\n");

    // (1) The average acceleration rule between consecutive snapshots.
    double worst = 0, scale = 0;
    for (unsigned int n = 0; n < 20; ++n)
      {
        const auto v0 = read_array(snapshot(n), "velocity_m_s");
        const auto v1 = read_array(snapshot(n + 1), "velocity_m_s");
        const auto a0 = read_array(snapshot(n), "acceleration_m_s2");
        const auto a1 = read_array(snapshot(n + 1), "acceleration_m_s2");
        AssertThrow(v0.size() == a0.size() && v1.size() == a1.size() &&
                      v0.size() == v1.size() && !v0.empty(),
                    ExcMessage("field sizes differ"));
        for (std::size_t k = 0; k < v0.size(); ++k)
          {
            const double dv = double(v1[k]) - double(v0[k]);
            scale           = std::max(scale, std::abs(dv));
            worst           = std::max(worst,
                             std::abs(dv - 0.5 * dt * (double(a0[k]) + a1[k])));
          }
      }
    const bool rule = worst < 1e-5 * scale && scale > 0;
    // The verdict: the residual is float32 rounding, its digits the CPU's.
    std::printf("v_{n+1} - v_n = dt/2 (a_n + a_{n+1}) at every point of 20 "
                "snapshot pairs: largest residual / largest change below "
                "1e-5: %s\n",
                rule ? "yes" : "NO");

    // (2) The mid-plane centre (0.1, 0.05, 0.01) m against probes.csv at
    // t = 20 us (step 10).
    const auto        points = read_array(snapshot(10), "acceleration_m_s2");
    const std::string file   = snapshot(10);
    const std::vector<float> coordinates = fgimpact_tests::read_points(file);
    double                   a_z         = std::nan("");
    for (std::size_t k = 0; 3 * k + 2 < coordinates.size(); ++k)
      if (std::abs(coordinates[3 * k] - 0.1) < 1e-6 &&
          std::abs(coordinates[3 * k + 1] - 0.05) < 1e-6 &&
          std::abs(coordinates[3 * k + 2] - 0.01) < 1e-6)
        a_z = points[3 * k + 2];
    std::ifstream probes("out/probes.csv");
    std::string   header, line;
    std::getline(probes, header);
    const auto columns = Utilities::split_string_list(header, ',');
    const auto column =
      std::find(columns.begin(), columns.end(), "mid_az_m_s2") -
      columns.begin();
    double probe = std::nan("");
    while (std::getline(probes, line))
      {
        const auto cells = Utilities::split_string_list(line, ',');
        if (std::abs(std::stod(cells[0]) - 20.) < 1e-9)
          probe = std::stod(cells[column]);
      }
    const bool same = std::abs(a_z - probe) <= 0.05 + 1e-6 * std::abs(probe);
    std::printf("mid-plane centre at t = 20 us: VTU a_z = %.1f m/s^2, "
                "probes.csv mid_az = %.1f m/s^2: %s\n",
                a_z,
                probe,
                same ? "yes" : "NO");
    const bool ok = rule && same;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::vtu_acceleration
