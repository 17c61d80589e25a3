// The same problem on 1 and on 2 MPI ranks gives the same numbers
// (issue 5). Every rank first solves each problem alone (MPI_COMM_SELF, the
// one-rank reference: CHOLMOD), then both ranks solve it together
// (MPI_COMM_WORLD: the distributed MUMPS chosen by 'auto', or CG + AMG).
//  - The default scene (prm/default.prm, 40 x 20 x 4, End time = auto:
//    158 steps, the automatic end decided alike on both ranks): every
//    column of the time history equal to 1e-8 relative to the column's
//    largest magnitude, with the direct solver and with CG + AMG at a
//    relative residual of 1e-12 (over the contact, 150 us).
//  - The same scene (150 us) with the impact point moved so that the contact
//  node
//    is owned by rank 0 instead of rank 1: both owners are exercised.
//  - A plastic face (Material/Plasticity = J2) under the resolved sphere
//    (level 3, 150 us): the plastic state summed over the ranks' cells.
//  - A static point load and the lowest six natural frequencies (20 x 10
//    x 4): equal to 1e-10 and 1e-9 relative.
// Set FGIMPACT_VERBOSE=1 to print the differences.

#include <deal.II/base/mpi.h>

#include <fgimpact/analysis/modal_analysis.h>
#include <fgimpact/analysis/static_analysis.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <test_tools.h>

namespace fgimpact_unit_tests::mpi_consistency
{

  using namespace fgimpact;

  namespace
  {
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;

    struct Run
    {
      ImpactResults                    results;
      std::vector<std::vector<double>> history;
    };

    /// prm/default.prm with `overrides`, quiet, on the given communicator.
    Run
    run_default_scene(const std::string &overrides,
                      const std::string &directory,
                      const MPI_Comm     communicator)
    {
      const auto output = fgimpact_tests::run_quietly(
        std::string(FGIMPACT_SOURCE_DIR) + "/prm/default.prm",
        "subsection Output\n set Directory = " + directory +
          "\n set VTU interval = 0\n"
          " set Log interval = 0\nend\n"
          "subsection Geometry\n set Symmetry = none\nend\n" +
          overrides,
        communicator,
        /*keep_history=*/true);
      return {output.results, output.history};
    }

    using fgimpact_tests::history_difference;
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const unsigned int rank  = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD);
    const unsigned int ranks = Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    const std::string  self  = "out/serial_rank" + std::to_string(rank);
    bool               ok    = true;
    auto               say   = [&](const char *text) {
      if (rank == 0)
        std::printf("%s", text);
    };
    char line[300];

    std::snprintf(line, sizeof(line), "%u MPI ranks\n", ranks);
    say(line);

    // 1. The default scene: direct solvers, and CG + AMG over the contact.
    struct Case
    {
      const char *name;
      std::string overrides;
    };
    const std::vector<Case> cases = {
      {"default scene, direct solver", ""},
      {"default scene, CG + AMG (tolerance 1e-12, 150 us)",
       "subsection Linear solver\n set Type = cg\n set Preconditioner = amg\n"
       " set Tolerance = 1e-12\nend\n"
       "subsection Time integration\n set End time = 150e-6\nend\n"},
      {"impact point (0.05, 0.025) m, direct solver, 150 us",
       "subsection Impactor\n set Impact point x = 0.05\n"
       " set Impact point y = 0.025\nend\n"
       "subsection Time integration\n set End time = 150e-6\nend\n"},
      {"plastic face (J2), resolved sphere, level 3, 150 us",
       "subsection Contact\n set Model = resolved sphere\nend\n"
       "subsection Material\n set Plasticity = J2\nend\n"
       "subsection Geometry\n set Contact refinement levels = 3\nend\n"
       "subsection Time integration\n set End time = 150e-6\nend\n"}};
    for (const auto &c : cases)
      {
        // The one-rank reference always uses the direct solver.
        const bool        cg = c.overrides.find("cg") != std::string::npos;
        const std::string reference_overrides =
          cg ? std::string("subsection Time integration\n set End time = "
                           "150e-6\nend\n") :
               c.overrides;
        const Run one =
          run_default_scene(reference_overrides, self, MPI_COMM_SELF);
        const Run all =
          run_default_scene(c.overrides, "out/parallel", MPI_COMM_WORLD);
        const double difference =
          history_difference(all.history, one.history); // one: the reference
        const bool equal = difference < 1e-8;
        ok               = ok && equal;
        if (verbose && rank == 0)
          std::fprintf(stderr,
                       "%s: max relative history difference %.3e, peak "
                       "force %.6f vs %.6f N\n",
                       c.name,
                       difference,
                       one.results.peak_contact_force,
                       all.results.peak_contact_force);
        // The peak force to 1e-6 relative: CG's result is exact only to its
        // tolerance, and its iterations (and the distributed MUMPS's
        // round-off) depend on the CPU.
        std::snprintf(line,
                      sizeof(line),
                      "%s: %zu rows x %zu columns, contact node owned by rank "
                      "%u of %u; peak force %.2f N; every column equal to "
                      "1e-8: %s\n",
                      c.name,
                      all.history.size(),
                      all.history[0].size(),
                      all.results.contact_node_owner,
                      all.results.n_mpi_ranks,
                      all.results.peak_contact_force,
                      equal ? "yes" : "NO");
        say(line);
      }

    // 2. Static point load and modal analysis on 20 x 10 x 4.
    {
      EffectiveMatrixSolver::Parameters solver;
      StaticAnalysis::Parameters        sp;
      sp.load = StaticAnalysis::Load::point;
      std::array<double, 3> deflection[2];
      std::vector<double>   frequency[2];
      for (unsigned int k = 0; k < 2; ++k)
        {
          const MPI_Comm comm = (k == 0 ? MPI_COMM_SELF : MPI_COMM_WORLD);
          const auto     c    = fgimpact_tests::make_plate(
            20, 10, 4, 1, 1., PropertyMode::graded, 0.02, comm);
          StaticAnalysis analysis(sp, solver, *c.plate, Point<2>(0.1, 0.05));
          analysis.solve();
          for (unsigned int j = 0; j < 3; ++j)
            deflection[k][j] = analysis.get_results().deflection[j];

          ModalAnalysis::Parameters mp;
          mp.tolerance = 1e-13;
          ModalAnalysis modal(mp, solver, *c.plate);
          modal.solve();
          for (const auto &mode : modal.get_modes())
            frequency[k].push_back(mode.frequency);
        }
      double static_difference = 0, modal_difference = 0;
      for (unsigned int j = 0; j < 3; ++j)
        static_difference =
          std::max(static_difference,
                   std::abs(deflection[1][j] - deflection[0][j]) /
                     std::abs(deflection[0][j]));
      for (unsigned int j = 0; j < frequency[0].size(); ++j)
        modal_difference =
          std::max(modal_difference,
                   std::abs(frequency[1][j] - frequency[0][j]) /
                     frequency[0][j]);
      const bool static_equal = static_difference < 1e-10;
      const bool modal_equal  = modal_difference < 1e-9;
      ok                      = ok && static_equal && modal_equal;
      if (verbose && rank == 0)
        std::fprintf(stderr,
                     "static: max relative difference %.3e; modal: %.3e\n",
                     static_difference,
                     modal_difference);
      std::snprintf(line,
                    sizeof(line),
                    "static point load 20x10x4: mid-plane deflection %.5f um, "
                    "bottom/mid/top equal to 1e-10: %s\n"
                    "modal 20x10x4: f1 = %.3f Hz, %zu frequencies equal to "
                    "1e-9: %s\n",
                    deflection[1][1] * 1e6,
                    static_equal ? "yes" : "NO",
                    frequency[1][0],
                    frequency[1].size(),
                    modal_equal ? "yes" : "NO");
      say(line);
    }

    say(ok ? "OK\n" : "FAILED\n");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::mpi_consistency
