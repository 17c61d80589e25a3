// Shared by the kill-and-resume tests (checkpoint_resume.cc on one MPI
// rank, checkpoint_resume_mpi.cc on two): run the executable as a process,
// kill it with SIGKILL at a pseudo-random step, resume it, and compare its
// history.csv and summary.txt with an uninterrupted run's.

#ifndef fgimpact_tests_checkpoint_resume_h
#define fgimpact_tests_checkpoint_resume_h

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <test_tools.h>
#include <thread>
#include <tuple>
#include <unistd.h>
#include <utility>
#include <vector>

namespace checkpoint_test
{
  namespace fs = std::filesystem;

  using fgimpact_tests::read_text;

  inline std::vector<std::string>
  lines_of(const std::string &text)
  {
    std::vector<std::string> lines;
    std::istringstream       in(text);
    std::string              line;
    while (std::getline(in, line))
      lines.push_back(line);
    return lines;
  }

  /// A fixed-seed generator (the same kill points on every machine).
  struct Lcg
  {
    unsigned long long state;
    unsigned int
    next(const unsigned int n)
    {
      state = state * 6364136223846793005ull + 1442695040888963407ull;
      return static_cast<unsigned int>((state >> 33) % n);
    }

    /// A kill point: at least 20 + [0, range) history rows, then a delay
    /// of [0, 20) ms (drawn in this order, in separate statements).
    std::pair<unsigned int, unsigned int>
    kill_point(const unsigned int range)
    {
      const unsigned int rows = 20 + next(range);
      return {rows, next(20)};
    }
  };

  /// Start fgimpact (on n_ranks ranks through mpiexec if > 1) with args;
  /// stdout and stderr to log_file.
  inline pid_t
  start(const std::vector<std::string> &args,
        const unsigned int              n_ranks,
        const std::string              &log_file)
  {
    std::vector<std::string> command;
    if (n_ranks > 1)
      command = {"mpiexec", "-n", std::to_string(n_ranks)};
    command.push_back(FGIMPACT_EXECUTABLE);
    command.insert(command.end(), args.begin(), args.end());
    std::fflush(stdout);
    const pid_t pid = fork();
    if (pid == 0)
      {
        if (!std::freopen(log_file.c_str(), "w", stdout) ||
            !std::freopen(log_file.c_str(), "a", stderr))
          _exit(127);
        std::vector<char *> argv;
        for (auto &arg : command)
          argv.push_back(arg.data());
        argv.push_back(nullptr);
        execvp(argv[0], argv.data());
        _exit(127);
      }
    return pid;
  }

  /// The exit status of a finished run (-signal if killed).
  inline int
  wait_for(const pid_t pid)
  {
    int status = 0;
    waitpid(pid, &status, 0);
    return WIFEXITED(status) ? WEXITSTATUS(status) : -WTERMSIG(status);
  }

  inline int
  run(const std::vector<std::string> &args,
      const unsigned int              n_ranks,
      const std::string              &log_file)
  {
    return wait_for(start(args, n_ranks, log_file));
  }

  /// Rows of history.csv on disk (without the header).
  /// The thermal environment both resume tests run (issue 42):
  /// temperature-dependent constituents, immovable sides, a conduction
  /// field 300-600 K and the geometric stiffness in K.
  inline std::string
  thermal_environment()
  {
    return "subsection Material\n set Metal material = SUS304\n set "
           "Ceramic material = Si3N4\nend\n"
           "subsection Boundary conditions\n set In-plane edges = "
           "immovable\nend\n"
           "subsection Thermal\n set Temperature field = conduction\n "
           "set Bottom temperature = 600\n set Geometric stiffness = "
           "true\nend\n";
  }



  inline unsigned int
  history_rows(const std::string &directory)
  {
    const std::string text = read_text(directory + "/history.csv");
    unsigned int      n    = 0;
    for (const char c : text)
      n += (c == '\n');
    return n > 0 ? n - 1 : 0;
  }

  /**
   * Kill the run (mpiexec and its ranks: the process group) with SIGKILL
   * once history.csv holds at least `rows` rows, plus `delay_ms`, so that
   * the kill falls anywhere between two checkpoints.  Returns whether the
   * run was killed before it finished.
   */
  inline bool
  run_and_kill(const std::vector<std::string> &args,
               const unsigned int              n_ranks,
               const std::string              &directory,
               const unsigned int              rows,
               const unsigned int              delay_ms)
  {
    fs::remove_all(directory);
    std::fflush(stdout);
    const pid_t pid = start(args, n_ranks, directory + ".log");
    setpgid(pid, pid); // also from the parent: no race with exec
    for (unsigned int i = 0; i < 60000 && history_rows(directory) < rows; ++i)
      {
        int status = 0;
        if (waitpid(pid, &status, WNOHANG) == pid)
          return false; // finished (or failed) before the kill
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
      }
    std::this_thread::sleep_for(std::chrono::milliseconds(delay_ms));
    kill(-pid, SIGKILL);
    kill(pid, SIGKILL);
    return wait_for(pid) == -SIGKILL && !fs::exists(directory + "/summary.txt");
  }

  /// Lines of summary.txt that depend on the wall clock (or are the
  /// provenance comments): not compared.
  inline bool
  clock_dependent(const std::string &line)
  {
    for (const std::string key : {"#",
                                  "setup_s ",
                                  "factorization_s ",
                                  "time_loop_s ",
                                  "time_per_step_ms ",
                                  "output_s ",
                                  "wall_time_s "})
      if (line.rfind(key, 0) == 0)
        return true;
    return false;
  }

  struct Comparison
  {
    unsigned int history_lines = 0, history_differing = 0;
    unsigned int summary_lines = 0, summary_differing = 0;
    /// Every other output file (probes.csv, the PVD and VTU files): how
    /// many, and how many differ (in content but deal.II's date line, or
    /// present in one directory only).
    unsigned int files = 0, files_differing = 0;
    bool         same_length = false;

    /// Every file the same, none missing.
    bool
    identical() const
    {
      return same_length && history_differing == 0 && summary_differing == 0 &&
             files > 0 && files_differing == 0;
    }

    /// The counts, as the cases print them.
    std::string
    text() const
    {
      char line[256];
      std::snprintf(line,
                    sizeof(line),
                    "history.csv %u lines, %u differing; summary.txt %u lines "
                    "compared, %u differing; %u other files (probes.csv, "
                    "PVD, VTU, manifests), %u differing",
                    history_lines,
                    history_differing,
                    summary_lines,
                    summary_differing,
                    files,
                    files_differing);
      return line;
    }
  };

  /// The output files compared besides history.csv and summary.txt:
  /// not the log (timings), the parameter files (the directory's name),
  /// report.html (made from the files compared here, with the run's
  /// provenance and wall-clock time), the checkpoints and the lock.
  inline std::set<std::string>
  other_outputs(const std::string &directory)
  {
    std::set<std::string> names;
    for (const auto &entry : fs::directory_iterator(directory))
      {
        const std::string name = entry.path().filename().string();
        if (entry.is_regular_file() && name != "history.csv" &&
            name != "summary.txt" && name != "log.txt" &&
            name != "parameters.prm" && name != "input.prm" &&
            name != "report.html" &&
            (name[0] != '.' || name == ".fgimpact.files"))
          names.insert(name);
      }
    // The VTU files and their manifest, in their folder.
    if (fs::is_directory(directory + "/vtu"))
      for (const auto &entry : fs::directory_iterator(directory + "/vtu"))
        if (entry.is_regular_file())
          names.insert("vtu/" + entry.path().filename().string());
    return names;
  }

  /// A file's lines but deal.II's "generated ... on <date>" comment; a
  /// manifest's (.fgimpact.files) as the set it is: a resumed run lists a
  /// snapshot its killed predecessor wrote where the predecessor did.
  inline std::vector<std::string>
  dated_lines(const std::string &file)
  {
    if (fs::path(file).filename() == ".fgimpact.files")
      {
        const auto                  lines = lines_of(read_text(file));
        const std::set<std::string> set(lines.begin(), lines.end());
        return std::vector<std::string>(set.begin(), set.end());
      }
    // summary.json: as summary.txt, without its provenance object and
    // the wall-clock keys.
    const bool json =
      file.size() >= 12 && file.substr(file.size() - 12) == "summary.json";
    bool                     provenance = false;
    std::vector<std::string> kept;
    for (const auto &line : lines_of(read_text(file)))
      {
        if (json && line.rfind("  \"provenance\"", 0) == 0)
          provenance = true;
        const bool skip =
          provenance ||
          (json && line.size() > 3 &&
           clock_dependent(line.substr(3, line.find('"', 3) - 3) + " "));
        if (provenance && line.rfind("  }", 0) == 0)
          provenance = false;
        if (!skip &&
            line.find("generated by the deal.II library") == std::string::npos)
          kept.push_back(line);
      }
    return kept;
  }

  /// Compare history.csv byte for byte (as lines) and summary.txt except
  /// its clock-dependent lines.
  inline Comparison
  compare(const std::string &reference, const std::string &resumed)
  {
    Comparison c;
    const auto h1 = lines_of(read_text(reference + "/history.csv"));
    const auto h2 = lines_of(read_text(resumed + "/history.csv"));
    c.same_length = read_text(reference + "/history.csv").size() ==
                      read_text(resumed + "/history.csv").size() &&
                    h1.size() == h2.size();
    c.history_lines = h1.size();
    for (std::size_t i = 0; i < std::max(h1.size(), h2.size()); ++i)
      c.history_differing +=
        (i >= h1.size() || i >= h2.size() || h1[i] != h2[i]);
    std::vector<std::string> s1, s2;
    for (const auto &line : lines_of(read_text(reference + "/summary.txt")))
      if (!clock_dependent(line))
        s1.push_back(line);
    for (const auto &line : lines_of(read_text(resumed + "/summary.txt")))
      if (!clock_dependent(line))
        s2.push_back(line);
    c.summary_lines = s1.size();
    for (std::size_t i = 0; i < std::max(s1.size(), s2.size()); ++i)
      c.summary_differing +=
        (i >= s1.size() || i >= s2.size() || s1[i] != s2[i]);
    c.same_length = c.same_length && s1.size() == s2.size() && s1.size() > 20 &&
                    h1.size() > 50;
    const auto names          = other_outputs(reference),
               resumed_names  = other_outputs(resumed);
    std::set<std::string> all = names;
    all.insert(resumed_names.begin(), resumed_names.end());
    for (const auto &name : all)
      {
        ++c.files;
        c.files_differing +=
          (!names.count(name) || !resumed_names.count(name) ||
           dated_lines(reference + "/" + name) !=
             dated_lines(resumed + "/" + name));
      }
    return c;
  }

  /**
   * One case: prm text (without Output/Directory), an uninterrupted run,
   * then a run killed at kill_point (Lcg::kill_point()) and resumed;
   * prints the differing lines (must be 0) and returns whether all holds.
   */
  inline bool
  kill_and_resume(const std::string                           &name,
                  const std::string                           &prm,
                  const unsigned int                           n_ranks,
                  const std::pair<unsigned int, unsigned int> &kill_point)
  {
    const auto [rows, delay_ms] = kill_point;
    const std::string reference = "ref_" + name, killed = "killed_" + name;
    {
      std::ofstream out(name + ".prm");
      out << prm << "subsection Output\n set Directory = " << reference
          << "\n set Log interval = 0\n set Print timing = false\nend\n";
    }
    fs::remove_all(reference);
    const int reference_exit =
      run({name + ".prm"}, n_ranks, reference + ".log");
    const bool was_killed =
      run_and_kill({name + ".prm", "-s", "Output/Directory=" + killed},
                   n_ranks,
                   killed,
                   rows,
                   delay_ms);
    const int resume_exit =
      run({"--resume", killed}, n_ranks, killed + ".resume.log");
    const Comparison c = compare(reference, killed);
    std::printf("%s on %u MPI rank%s, SIGKILL after >= %u history rows: "
                "killed before the end %s, resumed (exit %d); %s\n",
                name.c_str(),
                n_ranks,
                n_ranks > 1 ? "s" : "",
                rows,
                was_killed ? "yes" : "NO",
                resume_exit,
                c.text().c_str());
    const bool ok =
      reference_exit == 0 && was_killed && resume_exit == 0 && c.identical();
    if (!ok)
      std::printf("  reference exit %d; resume log:\n%s\n",
                  reference_exit,
                  read_text(killed + ".resume.log").c_str());
    return ok;
  }
} // namespace checkpoint_test

#endif
