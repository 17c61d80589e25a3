// The fields of a locally refined impact run, read back from the files a
// user opens (VTU snapshots, probes.csv, summary.txt), must be those of
// the conforming finite element solution.  The scene: prm/default.prm
// (quarter plate) with Contact/Model = resolved sphere and 3 contact
// refinement levels, 60 us (the peak force is at 56 us), a snapshot every
// 10 steps.
//  1. At every hanging vertex (the midpoint of an edge or the centre of a
//     face of a coarser neighbour: found from the cells' boxes in the VTU,
//     not from the library), in every snapshot and in every cell that has
//     it as a vertex, the displacement, velocity, acceleration and the
//     recovered sigma_zz equal the interpolation of the coarser cell's
//     corners (float32 data: to 1e-6 of the field's largest magnitude).
//     Before constraints were distributed, u = v = a = 0 there.
//  2. The recovered sigma_zz within 5 mm of the impact point is bounded by
//     the largest contact pressure of summary.txt times 1.15 (the nodal
//     average of a Q1 field at a surface node under a contact whose radius
//     spans 2-3 elements; measured 1.047).
//  3. A probe (Output/Probe points) on the top-face hanging vertex that
//     moves most equals a probe 1e-9 m beside it (probes.csv, every row;
//     u, v printed to 1e-6 um and m/s).
// The same output on 1 and 2 MPI ranks (each rank writes its VTU piece).

#include <deal.II/base/mpi.h>
#include <deal.II/base/utilities.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <hanging_check.h>
#include <map>
#include <set>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::hanging_fields
{

  using namespace dealii;

  namespace
  {
    using namespace fgimpact_tests::hanging;

    /// summary.txt's value of key.
    double
    summary_value(const std::string &key)
    {
      std::ifstream in("out/summary.txt");
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind(key + " = ", 0) == 0)
          return std::stod(line.substr(key.size() + 3));
      return std::nan("");
    }

    std::string
    scene(const std::string &probes)
    {
      return "subsection Contact\n set Model = resolved sphere\nend\n"
             "subsection Geometry\n set Contact refinement levels = 3\nend\n"
             "subsection Time integration\n set End time = 60e-6\nend\n"
             "subsection Output\n set Directory = out\n set Log interval = 0\n"
             " set Print timing = false\n set VTU interval = 10\n"
             " set VTU compression = none\n set Mirror symmetric part = false\n"
             " set Fields = displacement, velocity, acceleration, stress\n"
             " set Probe points = " +
             probes + "\nend\n";
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    fgimpact_tests::remove_output("out");
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    const std::string prm = FGIMPACT_SOURCE_DIR "/prm/default.prm";
    const double      h   = 0.02; // m
    bool              ok  = true;

    fgimpact_tests::run_quietly(prm, scene(""));
    // 1. Hanging vertices in the snapshots at 0, 10, ..., 60 us.
    HangingCheck check;
    double       min_sigma_zz = 0;
    if (root)
      for (unsigned int step = 0; step <= 60; step += 10)
        {
          const auto cells = read_snapshot("out", step, n_ranks);
          check_hanging(cells, h, check);
          for (const auto &cell : cells)
            for (const auto &p : cell)
              if (std::hypot(p.x[0] - 0.1, p.x[1] - 0.05, p.x[2] - h) < 5e-3)
                min_sigma_zz = std::min(min_sigma_zz, p.f[9]);
        }
    if (root)
      {
        std::printf("1. %zu hanging vertices, %u (vertex, fine cell) pairs in "
                    "7 snapshots; largest |value - interpolation of the coarse "
                    "cell| / largest |value|:\n",
                    check.vertices.size(),
                    check.n_checked);
        bool hanging_ok = check.vertices.size() > 100;
        for (unsigned int f = 0; f < n_fields; ++f)
          {
            // The verdict only: the difference is float32 rounding and
            // round-off, whose digits depend on the CPU.
            const double error = check.largest[f] / check.scale[f];
            const bool   good  = error < 1e-6;
            std::printf("   %-18s < 1e-6: %s\n",
                        field_names[f],
                        good ? "yes" : "NO");
            hanging_ok = hanging_ok && good;
          }
        ok = ok && hanging_ok;

        // 2. sigma_zz near the ball against the contact pressure.
        const double p_max = summary_value("max_contact_pressure_MPa");
        const bool   bounded =
          -min_sigma_zz <= 1.15 * p_max && -min_sigma_zz > 0.5 * p_max;
        std::printf("2. recovered sigma_zz within 5 mm of the impact point: "
                    "min %.0f MPa; largest contact pressure %.0f MPa; ratio "
                    "%.3f (within 0.5 .. 1.15: %s)\n",
                    min_sigma_zz,
                    p_max,
                    -min_sigma_zz / p_max,
                    bounded ? "yes" : "NO");
        ok = ok && bounded;
      }

    // 3. Probes on the top-face hanging vertex that moves most and 1e-9 m
    // beside it (towards the plate's edge x = 0), in m.
    std::array<double, 3> vertex{};
    if (root)
      {
        double largest = -1;
        for (const auto &p : check.top)
          if (std::abs(p.f[2]) > largest)
            {
              largest = std::abs(p.f[2]);
              for (unsigned int d = 0; d < 3; ++d)
                vertex[d] = std::round(p.x[d] * 1e6) * 1e-6; // m, whole um
            }
      }
    vertex = Utilities::MPI::broadcast(MPI_COMM_WORLD, vertex, 0);
    char probes[200];
    std::snprintf(probes,
                  sizeof(probes),
                  "hanging: %.6f, %.6f, %.6f; beside: %.9f, %.6f, %.6f",
                  vertex[0],
                  vertex[1],
                  vertex[2],
                  vertex[0] - 1e-9,
                  vertex[1],
                  vertex[2]);
    fgimpact_tests::run_quietly(prm, scene(probes));
    if (root)
      {
        std::ifstream in("out/probes.csv");
        std::string   line;
        std::getline(in, line);
        const auto header = Utilities::split_string_list(line, ',');
        const auto column = [&](const std::string &name) {
          return std::find(header.begin(), header.end(), name) - header.begin();
        };
        double       largest_u = 0, largest_v = 0, uz_peak = 0;
        unsigned int rows = 0;
        while (std::getline(in, line))
          {
            const auto cells = Utilities::split_string_list(line, ',');
            for (const char *c : {"x", "y", "z"})
              {
                const std::string u = std::string("_u") + c + "_um",
                                  v = std::string("_v") + c + "_m_s";
                largest_u =
                  std::max(largest_u,
                           std::abs(std::stod(cells[column("hanging" + u)]) -
                                    std::stod(cells[column("beside" + u)])));
                largest_v =
                  std::max(largest_v,
                           std::abs(std::stod(cells[column("hanging" + v)]) -
                                    std::stod(cells[column("beside" + v)])));
              }
            uz_peak =
              std::min(uz_peak, std::stod(cells[column("hanging_uz_um")]));
            ++rows;
          }
        const bool same = rows == 61 && largest_u <= 2e-6 && largest_v <= 2e-6;
        // The differences are the last printed digit of probes.csv (round-off
        // decides it): the verdict only.
        std::printf("3. probe on the hanging vertex (%.3f, %.3f, %.3f) mm "
                    "(u_z down to %.4f um) and 1e-9 m beside it, %u rows: "
                    "largest |difference| of u (um) and of v (m/s) <= 2e-6: "
                    "%s\n",
                    vertex[0] * 1e3,
                    vertex[1] * 1e3,
                    vertex[2] * 1e3,
                    uz_peak,
                    rows,
                    same ? "yes" : "NO");
        ok = ok && same;
        std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
      }
    return Utilities::MPI::broadcast(MPI_COMM_WORLD, ok ? 0 : 1, 0);
  }
} // namespace fgimpact_unit_tests::hanging_fields
