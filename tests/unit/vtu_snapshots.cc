// Snapshots between time steps (Output/Snapshot times and the snapshot at
// the peak force), read back from the files a user opens: solution.pvd,
// vtu/solution_*.0.vtu, vtu/sphere_peak.vtu, history.csv and summary.txt,
// after a Hertz impact on a 10 x 6 x 2 plate with dt = 1 us:
//  (1) solution.pvd lists the regular snapshots (every 20 steps), the
//      requested 0.25 and 37.5 us, and the peak, in time order and each
//      time once (60 us is also a regular snapshot: written once);
//  (2) the peak snapshot's time (sphere.pvd) and summary.txt's
//      time_of_peak_force_us equal, to 0.01 us, the vertex of the parabola
//      through history.csv's largest contact force and its neighbours,
//      computed here from the CSV, and the ball's contact_force_N in
//      sphere_peak.vtu the vertex's force (to 1e-6);
//  (3) the interpolated plate: the top centre node's u_z in the 37.5 us
//      snapshot (cubic Hermite from u and v at 37 and 38 us) against the
//      cubic through history.csv's top_deflection_um at 36, 37, 38 and
//      39 us (both fourth-order in dt), relative to the largest
//      deflection; and the ball's displacement (sphere file) against the
//      cubic through impactor_displacement_um.

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <sstream>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::vtu_snapshots
{

  using namespace dealii;

  namespace
  {
    /// The PVD's timestep values, in the order listed.
    std::vector<double>
    pvd_times(const std::string &file)
    {
      const std::string   text = fgimpact_tests::file_text(file);
      std::vector<double> times;
      for (auto at = text.find("timestep=\""); at != std::string::npos;
           at      = text.find("timestep=\"", at + 1))
        times.push_back(std::stod(text.substr(at + 10)));
      return times;
    }

    /// A number of summary.txt.
    double
    summary_value(const std::string &key)
    {
      std::ifstream in("out/summary.txt");
      for (std::string line; std::getline(in, line);)
        if (line.rfind(key + " = ", 0) == 0)
          return std::stod(line.substr(key.size() + 3));
      AssertThrow(false, ExcMessage(key + " not in summary.txt"));
      return 0;
    }

    /// A column of history.csv (one row per step, dt = 1 us).
    std::vector<double>
    history_column(const std::string &name)
    {
      std::ifstream in("out/history.csv");
      std::string   line;
      std::getline(in, line);
      const auto header = Utilities::split_string_list(line, ',');
      const auto column =
        std::find(header.begin(), header.end(), name) - header.begin();
      std::vector<double> values;
      while (std::getline(in, line))
        values.push_back(
          std::stod(Utilities::split_string_list(line, ',')[column]));
      return values;
    }

    /// The cubic through (k, f[k]) for k = i-1 .. i+2 at i + s.
    double
    cubic(const std::vector<double> &f, const unsigned int i, const double s)
    {
      const double x[4] = {-1., 0., 1., 2.};
      double       sum  = 0;
      for (unsigned int k = 0; k < 4; ++k)
        {
          double l = 1;
          for (unsigned int m = 0; m < 4; ++m)
            if (m != k)
              l *= (s - x[m]) / (x[k] - x[m]);
          sum += l * f[i - 1 + k];
        }
      return sum;
    }

  } // namespace



  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    fgimpact_tests::remove_output("out");
    fgimpact_tests::run_impact(
      "subsection Time integration\n set End time = 100e-6\nend\n"
      "subsection Output\n set VTU interval = 20\n"
      " set Snapshot times = 60e-6, 37.5e-6, 0.25e-6\n"
      " set VTU compression = none\n" // raw data: tests/vtu_reader.h
      " set Fields = displacement, velocity\nend\n");

    // (1) The PVD: regular, requested and peak snapshots in time order.
    const std::vector<double> times    = pvd_times("out/solution.pvd");
    const double              t_peak   = summary_value("time_of_peak_force_us");
    std::vector<double>       expected = {0, 0.25, 20, 37.5, 40, 60, 80, 100};
    expected.insert(std::upper_bound(expected.begin(), expected.end(), t_peak),
                    t_peak);
    bool listed = times.size() == expected.size();
    for (unsigned int k = 0; listed && k < times.size(); ++k)
      listed = std::abs(times[k] - expected[k]) < 0.01;
    std::printf("solution.pvd: %zu snapshots in time order (regular every "
                "20 us, 0.25, 37.5 and the peak at %.4f us; 60 us once): %s\n",
                times.size(),
                t_peak,
                listed ? "yes" : "NO");

    // (2) The peak's time and force, against the parabola through
    // history.csv's largest contact force and its two neighbours, computed
    // here from the CSV (dt = 1 us, one row per step).
    const auto         F = history_column("contact_force_N");
    const unsigned int k =
      std::max_element(F.begin(), F.end()) - F.begin(); // t_k = k us
    const double d      = F[k - 1] - 2 * F[k] + F[k + 1];
    const double t_csv  = k + (F[k - 1] - F[k + 1]) / (2 * d);
    const double F_csv  = F[k] - std::pow(F[k - 1] - F[k + 1], 2) / (8 * d);
    double       t_file = 1e9; // the sphere series' entry nearest the vertex
    for (const double t : pvd_times("out/sphere.pvd"))
      if (std::abs(t - t_csv) < std::abs(t_file - t_csv))
        t_file = t;
    const double F_file =
      fgimpact_tests::ascii_array(fgimpact_tests::file_text(
                                    "out/vtu/sphere_peak.vtu"),
                                  "contact_force_N")[0];
    const double time_error =
      std::max(std::abs(t_file - t_csv), std::abs(t_peak - t_csv));
    const double force_error = std::abs(F_file - F_csv) / F_csv;
    const bool   peak_ok     = time_error < 0.01 && force_error < 1e-6;
    // The vertex from history.csv's rounded forces (to 1e-4 N: its time to
    // about 2e-5 us), and verdicts on the differences, which are rounding.
    std::printf("peak snapshot (sphere.pvd, time_of_peak_force_us) at the "
                "vertex of history.csv's parabola, %.3f us, to 0.01 us: %s; "
                "its contact_force_N %.2f N against the vertex's %.2f N "
                "(relative difference below 1e-6: %s): %s\n",
                t_csv,
                time_error < 0.01 ? "yes" : "NO",
                F_file,
                F_csv,
                force_error < 1e-6 ? "yes" : "NO",
                peak_ok ? "yes" : "NO");

    // (3) The interpolated plate and ball at 37.5 us.
    const std::string file   = "out/vtu/solution_t000037500.0.vtu";
    const auto        points = fgimpact_tests::read_points(file);
    const auto        u  = fgimpact_tests::read_array(file, "displacement_m");
    double            uz = 0;
    for (std::size_t k = 0; 3 * k + 2 < points.size(); ++k)
      if (std::abs(points[3 * k] - 0.1) < 1e-7 &&
          std::abs(points[3 * k + 1] - 0.05) < 1e-7 &&
          std::abs(points[3 * k + 2] - 0.02) < 1e-7)
        uz = u[3 * k + 2];
    const auto   W           = history_column("top_deflection_um");
    const double W_max       = *std::max_element(W.begin(), W.end());
    const double W_ref       = cubic(W, 37, 0.5);
    const double plate_error = std::abs(-uz * 1e6 - W_ref) / W_max;
    const auto   w_ball      = history_column("impactor_displacement_um");
    const double w_ref       = cubic(w_ball, 37, 0.5);
    const double w_file =
      fgimpact_tests::ascii_array(fgimpact_tests::file_text(
                                    "out/vtu/sphere_t000037500.vtu"),
                                  "impactor_displacement_um")[0];
    const double ball_error = std::abs(w_file - w_ref) /
                              *std::max_element(w_ball.begin(), w_ball.end());
    const bool interpolated_ok = plate_error < 2e-3 && ball_error < 1e-4;
    // To 1e-4 um: history.csv has 1e-5 um, and the differences are of
    // that size (verdicts against their limits).
    std::printf("at 37.5 us: top deflection %.4f um (Hermite) against %.4f "
                "um (cubic through history.csv; difference / largest below "
                "2e-3: %s), ball %.4f against %.4f um (below 1e-4: %s): %s\n",
                -uz * 1e6,
                W_ref,
                plate_error < 2e-3 ? "yes" : "NO",
                w_file,
                w_ref,
                ball_error < 1e-4 ? "yes" : "NO",
                interpolated_ok ? "yes" : "NO");
    return listed && peak_ok && interpolated_ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::vtu_snapshots
