// Time integration/End time = auto in whole runs, against the same run with
// a fixed End time (n = 1, the paper's ball at 1 m/s): hertz node on a
// 10 x 6 x 2 plate, implicit and explicit, to 1000 us (the plate free for
// about 850 us after the ball left), and the resolved sphere on the
// default mesh's quarter, 4 levels under the ball, to 600 us.  For each:
//  - the auto run stops well before 1000 us, after the last contact;
//  - its history equals the fixed run's first rows exactly (every column);
//  - in the fixed run the contact force stays 0 after the auto run's stop
//    (the contact does not recur, which the rule claims);
//  - the summary's peak force, contact duration, departure velocity and
//    largest mid-plane deflection are the fixed run's (to 1e-10; the departure
//    velocity is kept to round-off).

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <test_tools.h>

namespace fgimpact_unit_tests::auto_end_time_run
{

  using namespace fgimpact;

  namespace
  {
    fgimpact_tests::RunOutput
    run(const std::string &settings, const std::string &end_time)
    {
      fgimpact_tests::remove_output("out");
      return fgimpact_tests::run_quietly(
        "",
        "subsection Time integration\n set End time = " + end_time +
          "\nend\n"
          "subsection Output\n set Directory = out\n set VTU interval = 0\n"
          " set Log interval = 0\n set Print timing = false\nend\n" +
          settings,
        MPI_COMM_WORLD,
        /*keep_history=*/true);
    }

    double
    relative(const double a, const double b)
    {
      return std::abs(a - b) / std::max(std::abs(b), 1e-300);
    }

    bool
    compare(const std::string &name,
            const std::string &settings,
            const std::string &fixed_end_time)
    {
      const auto  fixed = run(settings, fixed_end_time);
      const auto  autom = run(settings, "auto");
      const auto &hf = fixed.history, &ha = autom.history;
      // Columns: 0 = t (us), 1 = contact force (N).  The departure velocity
      // is the ball's velocity at the end: the Newmark update of a free ball
      // keeps it to round-off (1e-12 relative over 850 steps).
      double t_last_contact = 0;
      for (const auto &row : hf)
        if (row[1] > 0)
          t_last_contact = row[0];
      const double t_stop = ha.back()[0];
      double       prefix = (ha.size() <= hf.size() ? 0. : 1e300);
      for (std::size_t i = 0; i < ha.size() && i < hf.size(); ++i)
        for (std::size_t j = 0; j < ha[i].size(); ++j)
          prefix = std::max(prefix, std::abs(ha[i][j] - hf[i][j]));
      double later = 0;
      for (const auto &row : hf)
        if (row[0] > t_stop)
          later = std::max(later, row[1]);
      const ImpactResults &a = autom.results, &f = fixed.results;
      const double         summary = std::max(
        {relative(a.peak_contact_force, f.peak_contact_force),
                 relative(a.contact_duration, f.contact_duration),
                 relative(a.departure_velocity, f.departure_velocity),
                 relative(a.max_midplane_deflection, f.max_midplane_deflection)});

      const bool ok = t_stop > t_last_contact && t_stop < 500. &&
                      prefix == 0. && later == 0. && summary < 1e-10;
      // Verdicts, not the differences: the summary's are round-off (1e-12),
      // whose digits depend on the CPU and the BLAS kernel.
      std::printf("%s: the last contact in the fixed run at %.3f us, auto "
                  "stopped at %.3f us (%zu of %zu rows); history equal to the "
                  "fixed run's rows: %s; largest contact force after the stop "
                  "in the fixed run %.3f N; summary differences below 1e-10: "
                  "%s: %s\n",
                  name.c_str(),
                  t_last_contact,
                  t_stop,
                  ha.size(),
                  hf.size(),
                  prefix == 0. ? "yes" : "NO",
                  later,
                  summary < 1e-10 ? "yes" : "NO",
                  ok ? "ok" : "FAILED");
      return ok;
    }
  } // namespace



  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const std::string                coarse =
      "subsection Geometry\n set Subdivisions x = 10\n"
      " set Subdivisions y = 6\n set Subdivisions z = 2\nend\n";
    bool ok =
      compare("hertz node, implicit",
              coarse + "subsection Contact\n set Model = hertz node\nend\n",
              "1000e-6");
    ok =
      compare("hertz node, explicit",
              coarse + "subsection Contact\n set Model = hertz node\nend\n"
                       "subsection Time integration\n set Scheme = explicit\n"
                       " set Time step = 0\nend\n",
              "1000e-6") &&
      ok;
    // The default 40 x 20 x 4 mesh's quarter, 4 levels under the ball.
    ok = compare("resolved sphere, quarter",
                 "subsection Geometry\n set Symmetry = quarter\n"
                 " set Contact refinement levels = 4\nend\n"
                 "subsection Contact\n set Model = resolved sphere\nend\n",
                 "600e-6") &&
         ok;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::auto_end_time_run
