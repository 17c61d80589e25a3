// The memory of Accuracy = converged (issue 24), on the default scene with
// the resolved sphere:
//  (1) the resolved contact's part of the resource estimate: the
//      candidates it expects (the top nodes within 1.5 times the expected
//      contact radius plus two elements) against the count the level-5
//      run found (summary n_contact_candidates), within 15 %;
//  (2) the refusal: under an address-space limit (RLIMIT_AS of this
//      process, raised again after) that leaves room for levels 4 and 5
//      by the estimate but not for level 6 (End time = auto: two factors),
//      a converged run with an unreachable tolerance stops before level 6
//      is built, with one
//      message naming the tolerance, the level and RLIMIT_AS; level 5's
//      summary.txt is complete and there is no level-6 directory.
// The machine-dependent numbers go to stderr with FGIMPACT_VERBOSE=1.

#include <deal.II/base/mpi.h>

#include <fgimpact/material/material.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/problem/resources.h>
#include <fgimpact/problem/scene.h>
#include <fgimpact/problem/symmetry.h>
#include <fgimpact/study/simulator.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <malloc.h>
#include <sstream>
#include <sys/resource.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::converged_memory
{

  using namespace fgimpact;

  namespace
  {
    const std::string default_prm = FGIMPACT_SOURCE_DIR "/prm/default.prm";

    /// The default scene with the resolved sphere (the quarter: Symmetry =
    /// auto, as users run it), short, into ./out.
    std::string
    settings(const std::string &more)
    {
      return "subsection Geometry\n set Symmetry = auto\nend\n"
             "subsection Contact\n set Model = resolved sphere\nend\n"
             "subsection Linear solver\n set Type = cholmod\nend\n"
             "subsection Output\n set Directory = out\n set VTU interval = 0\n"
             " set Log interval = 0\n set Print timing = false\nend\n" +
             more;
    }

    Parameters
    parameters_of(const std::string &text)
    {
      const InputFile  input(default_prm,
                            InputFile(default_prm).expanded() + "\n" + text);
      ParameterHandler prm;
      Parameters       p;
      read_run_parameters(input, {}, prm, p);
      return p;
    }

    /// The resource estimate of the run at `levels` contact refinement
    /// levels.
    ResourceEstimate
    estimate_at(const unsigned int levels)
    {
      const Parameters                 p    = parameters_of(settings(
        "subsection Geometry\n set Contact refinement levels = " +
        std::to_string(levels) +
        "\nend\nsubsection Time integration\n set End time = auto\nend\n"));
      const SymmetricPart              part = resolve_symmetry(p);
      const PlateGeometry              geometry(p.geometry, part.cut);
      const FunctionallyGradedMaterial material(p.material,
                                                geometry.thickness());
      const Scene                      scene(p, material, geometry.share());
      return estimate_resources(p, contact_refinement_of(p, scene));
    }

    /// VmSize of this process (bytes).
    double
    mapped()
    {
      std::ifstream in("/proc/self/status");
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind("VmSize:", 0) == 0)
          return 1024. * std::atof(line.c_str() + 7);
      return 0;
    }

    bool
    report(const char *what, const bool pass)
    {
      std::printf("%s: %s\n", what, pass ? "yes" : "NO");
      return pass;
    }

    bool
    has(const std::string &text, const std::string &part)
    {
      return text.find(part) != std::string::npos;
    }
  } // namespace



  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;
    bool       ok      = true;

    // (1) Level 5 for 2 us (also the warm-up of (2): threads, libraries).
    fgimpact_tests::remove_output("out");
    const ImpactResults level5 =
      fgimpact_tests::run_quietly(
        default_prm,
        settings("subsection Geometry\n set Contact refinement levels = 5\n"
                 "end\nsubsection Time integration\n set End time = 2e-6\n"
                 "end\n"))
        .results;
    const ResourceEstimate e5 = estimate_at(5), e6 = estimate_at(6);
    const double ratio = e5.n_candidates / level5.n_contact_candidates;
    std::printf("(1) level 5: %u candidates, %.0f estimated (ratio %.3f)\n",
                level5.n_contact_candidates,
                e5.n_candidates,
                ratio);
    ok &= report("(1) the estimated candidates within 15 % of the run's",
                 std::abs(ratio - 1.) < 0.15);

    // (2) The sanitizers reserve terabytes of address space: no limit there.
    if (std::getenv("FGIMPACT_SANITIZED") != nullptr)
      {
        std::printf("(2) skipped under the sanitizers\n");
        std::printf("%s\n", ok ? "all checks passed" : "FAILED");
        return ok ? 0 : 1;
      }
    malloc_trim(0);
    const double now = mapped();
    // Half-way between what level 5 and level 6 need by the estimate.
    const double room = 0.5 * (e5.total(true) + e6.total(true));
    if (verbose)
      std::fprintf(stderr,
                   "mapped %.3f GB; estimates: level 5 %.3f GB, level 6 %.3f "
                   "GB; limit %.3f GB\n",
                   now * 1e-9,
                   e5.total(true) * 1e-9,
                   e6.total(true) * 1e-9,
                   (now + room) * 1e-9);
    struct rlimit old_limit, limit;
    getrlimit(RLIMIT_AS, &old_limit);
    limit.rlim_cur = static_cast<rlim_t>(now + room);
    limit.rlim_max = old_limit.rlim_max;
    setrlimit(RLIMIT_AS, &limit);
    fgimpact_tests::remove_output("out");
    std::string message;
    try
      {
        fgimpact_tests::run_quietly(
          default_prm,
          settings("set Accuracy = converged\nset Accuracy tolerance = 1e-4\n"
                   "subsection Time integration\n set End time = auto\nend\n"));
      }
    catch (const std::exception &e)
      {
        // One line: deal.II's message wraps the text.
        std::istringstream words(e.what());
        for (std::string word; words >> word;)
          message += word + ' ';
      }
    setrlimit(RLIMIT_AS, &old_limit);
    if (verbose)
      std::fprintf(stderr, "%s\n", message.c_str());
    const auto level5_summary =
      fgimpact_tests::read_summary("out/convergence/level_5/summary.txt");
    ok &= report(
      "(2) refused before level 6, naming the tolerance, the level "
      "and RLIMIT_AS",
      has(message, "Accuracy tolerance = 0.010 %") &&
        has(message, "not reached by level 5") &&
        has(message,
            "level 6 on 40x20x4 does not fit (raise Accuracy tolerance)") &&
        has(message, "RLIMIT_AS"));
    ok &= report("(2) level 5's summary.txt complete, no level 6 directory",
                 level5_summary.count("wall_time_s") == 1 &&
                   !std::filesystem::exists("out/convergence/level_6"));
    std::printf("%s\n", ok ? "all checks passed" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::converged_memory
