// A write that fails on one MPI rank only (its VTU piece of step 10 is a
// link to /dev/full, a full disk) stops both ranks at the same step, never
// a hang: exit code 2, one line from rank 0 naming the failing rank's file,
// summary.txt with status = failed, and history.csv complete up to that
// step.  Then a write that fails on rank 0 alone before the time loop
// (history.csv, whose header rank 0 writes while rank 1 goes on towards
// the collective output of step 0): both ranks stop with exit code 2, one
// line naming history.csv, summary.txt with status = failed after 0 steps.
// Runs `mpiexec -n 2 fgimpact` as the mpirun=2 tests do.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::mpi_output_failure
{

  namespace fs = std::filesystem;

  namespace
  {
    using fgimpact_tests::read_text;

    /// Run `mpiexec -n 2 fgimpact` on a small plate into dir (extra output
    /// settings appended); the exit code, 124 for a hang (timeout).
    int
    run_two_ranks(const std::string &dir, const std::string &output_settings)
    {
      {
        std::ofstream prm("failure.prm");
        prm << "subsection Geometry\n set Subdivisions x = 4\n set "
               "Subdivisions y = 2\n set Subdivisions z = 1\nend\n"
               "subsection Output\n set Directory = "
            << dir << "\n"
            << output_settings
            << " set Log interval = 0\n set Print timing = false\nend\n";
      }
      const std::string command =
        std::string("timeout 300 mpiexec -n 2 ") + FGIMPACT_EXECUTABLE +
        " failure.prm > failure.stdout 2> failure.stderr";
      const int status = std::system(command.c_str());
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    /// The last of fgimpact's lines on stderr (mpiexec adds its own
    /// notice) and how many there were.
    std::string
    our_line(unsigned int &n_ours)
    {
      std::istringstream err(read_text("failure.stderr"));
      std::string        line, ours;
      n_ours = 0;
      while (std::getline(err, line))
        if (line.rfind("fgimpact: ", 0) == 0)
          {
            ++n_ours;
            ours = line;
          }
      return ours;
    }

    /// history.csv on rank 0 alone is /dev/full: the header cannot be
    /// written before the time loop.
    bool
    history_fails_on_rank_0()
    {
      const std::string dir = "failure_history";
      fs::remove_all(dir);
      fs::create_directories(dir);
      fs::create_symlink("/dev/full", dir + "/history.csv");
      const int         exit_code = run_two_ranks(dir, "");
      unsigned int      n_ours;
      const std::string ours     = our_line(n_ours);
      const bool        no_hang  = exit_code != 124;
      const bool        exit_two = exit_code == 2;
      const bool        named =
        n_ours == 1 && ours.find("history.csv") != std::string::npos;
      const std::string summary = read_text(dir + "/summary.txt");
      const bool        failed =
        summary.find("status = failed") != std::string::npos &&
        summary.find("n_time_steps = 0\n") != std::string::npos;
      std::printf(
        "history.csv full on rank 0 before the time loop: no hang %s, "
        "exit code 2 %s, one line naming history.csv %s, summary.txt "
        "status = failed after 0 steps %s\n",
        no_hang ? "yes" : "NO",
        exit_two ? "yes" : "NO",
        named ? "yes" : "NO",
        failed ? "yes" : "NO");
      const bool ok = no_hang && exit_two && named && failed;
      if (!ok)
        std::printf("  exit code %d, stderr: %s\n  summary:\n%s\n",
                    exit_code,
                    read_text("failure.stderr").c_str(),
                    summary.c_str());
      return ok;
    }
  } // namespace



  int
  test_main(int, char **)
  {
    const std::string dir = "failure_out";
    fs::remove_all(dir);
    fs::create_directories(dir);
    // The whole plate from a quarter: rank 1 writes the pieces 2 and 3 (two
    // per rank); the first of them cannot be written.
    fs::create_directories(dir + "/vtu");
    fs::create_symlink("/dev/full", dir + "/vtu/solution_00010.2.vtu");
    // A hang would be ended by timeout (exit code 124).
    const int  exit_code = run_two_ranks(dir, " set VTU interval = 5\n");
    const bool no_hang   = exit_code != 124;
    const bool exit_two  = exit_code == 2;

    unsigned int      n_ours;
    const std::string ours = our_line(n_ours);
    std::string       line;
    const bool        one_line = n_ours == 1;
    const bool named = ours.find("solution_00010.2.vtu") != std::string::npos;

    const std::string summary = read_text(dir + "/summary.txt");
    const bool        failed =
      summary.find("status = failed") != std::string::npos &&
      summary.find("n_time_steps = 10\n") != std::string::npos;
    // history.csv: the header and the rows of steps 0..10, all complete.
    const std::string  history = read_text(dir + "/history.csv");
    std::istringstream rows(history);
    std::getline(rows, line);
    const auto   fields   = std::count(line.begin(), line.end(), ',');
    unsigned int n_rows   = 0;
    bool         complete = !history.empty() && history.back() == '\n';
    while (std::getline(rows, line))
      {
        ++n_rows;
        complete =
          complete && std::count(line.begin(), line.end(), ',') == fields;
      }
    complete                = complete && n_rows == 11;
    const bool no_temporary = !fs::exists(dir + "/solution.pvd.tmp") &&
                              !fs::exists(dir + "/summary.txt.tmp");

    std::printf(
      "disk full on rank 1 only: no hang %s, exit code 2 %s, one line "
      "%s, names rank 1's file %s\n",
      no_hang ? "yes" : "NO",
      exit_two ? "yes" : "NO",
      one_line ? "yes" : "NO",
      named ? "yes" : "NO");
    std::printf("summary.txt status = failed after step 10 %s, history.csv "
                "rows 0..10 complete %s, no temporary file %s\n",
                failed ? "yes" : "NO",
                complete ? "yes" : "NO",
                no_temporary ? "yes" : "NO");
    bool ok = no_hang && exit_two && one_line && named && failed && complete &&
              no_temporary;
    if (!ok)
      std::printf("  exit code %d, stderr: %s\n  summary:\n%s\n",
                  exit_code,
                  read_text("failure.stderr").c_str(),
                  summary.c_str());
    ok = history_fails_on_rank_0() && ok;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::mpi_output_failure
