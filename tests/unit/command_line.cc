// The executable's command line, run as a separate process: an override
// `-s "Section/Entry=value"` gives the same history.csv as editing the
// file, so do the .prm read from standard input and an include resolved
// relative to the including file; --validate checks and writes nothing;
// --version and the provenance lines; one-line errors with "did you mean";
// no argument prints the usage and exits 1; a study from the Study
// subsection (zip, time loop) and --study-case; a tabulated profile
// relative to its .prm in a run and a study.

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::command_line
{

  namespace fs = std::filesystem;

  namespace
  {
    bool all_ok = true;

    /// Run the executable with arguments args (shell words); stdout and
    /// stderr into cli.stdout and cli.stderr; the exit code.
    int
    run(const std::string &args)
    {
      const std::string command = std::string(FGIMPACT_EXECUTABLE) + " " +
                                  args + " > cli.stdout 2> cli.stderr";
      const int status = std::system(command.c_str());
      return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    }

    using fgimpact_tests::read_text;

    void
    write(const std::string &filename, const std::string &text)
    {
      std::ofstream(filename) << text;
    }

    bool
    contains(const std::string &text, const std::string &part)
    {
      return text.find(part) != std::string::npos;
    }

    unsigned int
    n_lines(const std::string &text)
    {
      unsigned int n = 0;
      for (const char c : text)
        n += (c == '\n');
      return n;
    }

    void
    check(const std::string &what, const bool ok)
    {
      all_ok = all_ok && ok;
      std::printf("%s: %s\n", what.c_str(), ok ? "yes" : "NO");
    }

    /// A small, fast impact scene writing into directory `out`.
    std::string
    scene(const std::string &out, const std::string &extra = "")
    {
      return "subsection Geometry\n set Subdivisions x = 10\n"
             " set Subdivisions y = 6\n set Subdivisions z = 2\nend\n"
             "subsection Time integration\n set Time step = 2e-6\n"
             " set End time = 100e-6\nend\n"
             "subsection Output\n set Directory = " +
             out + "\n set Log interval = 0\n set Print timing = false\nend\n" +
             extra;
    }

    /// The largest difference between two CSV files' values, in units of
    /// the last printed digit (0 if identical; 1e9 if the shapes differ).
    double
    csv_difference(const std::string &a, const std::string &b)
    {
      std::istringstream ia(a), ib(b);
      std::string        la, lb;
      double             worst = 0;
      while (std::getline(ia, la))
        {
          if (!std::getline(ib, lb))
            return 1e9;
          std::istringstream fa(la), fb(lb);
          std::string        va, vb;
          while (std::getline(fa, va, ','))
            {
              if (!std::getline(fb, vb, ','))
                return 1e9;
              if (va == vb)
                continue;
              const auto dot = va.find('.');
              const int  decimals =
                dot == std::string::npos ? 0 : int(va.size() - dot - 1);
              char        *end_a = nullptr, *end_b = nullptr;
              const double x = std::strtod(va.c_str(), &end_a),
                           y = std::strtod(vb.c_str(), &end_b);
              if (end_a == va.c_str() || end_b == vb.c_str())
                return 1e9; // differing text (the header)
              worst =
                std::max(worst, std::abs(x - y) * std::pow(10., decimals));
            }
        }
      return std::getline(ib, lb) ? 1e9 : worst;
    }

    /// history.csv of a run, or "" if missing.
    std::string
    history(const std::string &out)
    {
      return read_text(out + "/history.csv");
    }
  } // namespace



  int
  test_main(int, char **)
  {
    for (const char *d : {"cli_base",
                          "cli_edited",
                          "cli_set",
                          "cli_stdin",
                          "cli_include",
                          "cli_validate",
                          "cli_bad",
                          "cli_sub",
                          "cli_probes",
                          "cli_study",
                          "cli_zip",
                          "cli_zip_one",
                          "cli_tab",
                          "cli_tab_study"})
      fs::remove_all(d);
    const std::string velocity_2 =
      "subsection Impactor\n set Initial velocity = 2\nend\n";

    // --version and no arguments.
    {
      const int         code = run("--version");
      const std::string out  = read_text("cli.stdout");
      check("--version exits 0 and names program, commit, deal.II, Trilinos",
            code == 0 && contains(out, "fgimpact ") &&
              contains(out, "git commit ") && contains(out, "deal.II 9.") &&
              contains(out, "Trilinos "));
      const int code_none = run("");
      check("no argument: exit 1 and the usage",
            code_none == 1 && contains(read_text("cli.stderr"), "Usage:"));
    }

    // The base run, the edited file, and the same edit by -s.
    write("cli_base.prm", scene("cli_base"));
    write("cli_edited.prm", scene("cli_edited", velocity_2));
    write("cli_set.prm", scene("cli_set"));
    check("base run exits 0", run("cli_base.prm") == 0);
    check("edited run exits 0", run("cli_edited.prm") == 0);
    check("-s run exits 0",
          run("cli_set.prm -s 'Impactor/Initial velocity=2'") == 0);
    check("-s gives the edited file's history.csv, byte for byte",
          !history("cli_set").empty() &&
            history("cli_set") == history("cli_edited"));
    check("... and it differs from the base run's",
          history("cli_set") != history("cli_base"));
    check("the later of two -s of one entry wins",
          run("cli_set.prm -s 'Impactor/Initial velocity=3' "
              "-s 'Impactor/Initial velocity=2'") == 0 &&
            history("cli_set") == history("cli_edited"));

    // A study through the executable: its case with V0 = 2 m/s equals the
    // separate run of the edited file (the study runs by convolution).
    write("cli_study.prm", scene("cli_study"));
    {
      const int    code = run("cli_study.prm --study 'Impactor/Initial "
                              "velocity=1,2'");
      const double diff =
        csv_difference(read_text("cli_study/case_001/history.csv"),
                       history("cli_edited"));
      // A verdict, not the difference (in units of the last printed digit).
      // The case runs as a convolution (Study/Method = auto), which agrees
      // with the time loop to 1e-11 relative (study_convolution): a value at
      // a rounding boundary may print one unit of its last digit apart.
      std::printf("study case V0 = 2 against the separate run: history.csv "
                  "within one unit of every last printed digit: %s\n",
                  diff <= 1.01 ? "yes" : "NO");
      check("--study: exit 0, study.csv with a header and 2 cases, the case's "
            "history.csv equal to the separate run's",
            code == 0 && n_lines(read_text("cli_study/study.csv")) == 3 &&
              diff <= 1.01);
    }

    // A study from the .prm's Study subsection, two lists zipped, through
    // the time loop: case 1 (V0 = 2 m/s, steel 8900 kg/m^3) equals the
    // separate run of that scene, and --study-case 1 reruns it alone.
    write("cli_zip.prm",
          scene("cli_zip",
                "subsection Study\n set Entries = Impactor/Initial velocity = "
                "1, 2; Impactor/Density = 7800, 8900\n set Combination = zip\n"
                " set Method = time loop\nend\n"));
    write("cli_zip_one.prm",
          scene("cli_zip_one",
                "subsection Impactor\n set Initial velocity = 2\n"
                " set Density = 8900\nend\n"));
    {
      const int    code     = run("cli_zip.prm");
      const int    code_one = run("cli_zip_one.prm");
      const double diff =
        csv_difference(read_text("cli_zip/case_001/history.csv"),
                       history("cli_zip_one"));
      std::printf("Study subsection, zip, time loop: case 1 against the "
                  "separate run: history.csv the same in every printed digit: "
                  "%s\n",
                  diff == 0. ? "yes" : "NO");
      check("Study subsection (zip, time loop): exit 0, 2 cases in study.csv, "
            "case 1 equal to the separate run",
            code == 0 && code_one == 0 &&
              n_lines(read_text("cli_zip/study.csv")) == 3 && diff == 0. &&
              !fs::exists("cli_zip/case_002"));
      const std::string first = history("cli_zip/case_001");
      fs::remove_all("cli_zip/case_001");
      const int rerun = run("cli_zip.prm --study-case 1");
      check("--study-case 1 reruns that case alone, with the same history",
            rerun == 0 && !first.empty() &&
              history("cli_zip/case_001") == first);
    }

    // A study whose second case fails (a time step far longer than the
    // contact: the energy watchdog): the first case completes, the second
    // has a failed summary.txt, study.csv lists both with their status, and
    // the study exits 2 with one line naming the failed case.
    write("cli_fail.prm", scene("cli_fail"));
    {
      const int code =
        run("cli_fail.prm --study 'Time integration/Time step=2e-6,1e-4' "
            "-s 'Time integration/End time=4e-3'");
      const std::string err = read_text("cli.stderr");
      const std::string csv = read_text("cli_fail/study.csv");
      check("a study with a failing case: exit 2, one line naming case_001, "
            "case_000 completed, case_001's summary failed, study.csv lists "
            "both with their status",
            code == 2 && n_lines(err) == 1 && contains(err, "case_001") &&
              contains(read_text("cli_fail/case_000/summary.txt"),
                       "status = completed") &&
              contains(read_text("cli_fail/case_001/summary.txt"),
                       "status = failed") &&
              n_lines(csv) == 3 && contains(csv, ",completed") &&
              contains(csv, ",failed"));
    }
    {
      const int         code = run("cli_fail.prm --study 'Impactor/Initial "
                                   "velocity=1,2' --study 'Impactor/Initial "
                                   "velocity=3'");
      const std::string err  = read_text("cli.stderr");
      check("the same entry twice in a study: exit 1, one line saying so",
            code == 1 && n_lines(err) == 1 && contains(err, "listed twice"));
    }
    // Errors in a study's entries name where the user wrote them: --study on
    // the command line, Study/Entries in the file (not -s).
    {
      const int         code = run("cli_fail.prm --study 'Geometry/Subdivision "
                                   "z=2,4'");
      const std::string err  = read_text("cli.stderr");
      check("a misspelled --study entry: exit 1, one line naming --study and "
            "the closest entry",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "--study 'Geometry/Subdivision z=2'") &&
              contains(err, "Geometry/Subdivisions z") &&
              !contains(err, "-s '"));
    }
    {
      write("cli_entries.prm",
            scene("cli_entries",
                  "subsection Study\n set Entries = Impactor/Initial velocity "
                  "= 1, fast\nend\n"));
      const int         code = run("cli_entries.prm");
      const std::string err  = read_text("cli.stderr");
      check("a bad value in Study/Entries: exit 1, one line naming "
            "Study/Entries and the value",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "Study/Entries 'Impactor/Initial velocity=fast'") &&
              !fs::exists("cli_entries"));
    }
    // A study that varied Output/Directory ran every case into the study's
    // own case_NNN, ignoring the values.
    {
      const int code = run("cli_fail.prm --study 'Output/Directory=cli_d1,"
                           "cli_d2'");
      const std::string err = read_text("cli.stderr");
      check("a study varying Output/Directory: exit 1, one line naming it, "
            "nothing written",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "Output/Directory' cannot vary") &&
              !fs::exists("cli_d1") && !fs::exists("cli_d2"));
    }
    // A NUL byte in a parameter file is refused with its line (deal.II cut
    // the value there: "Directory = a\0b" ran into "a"); a value of
    // 100,000 characters is not echoed as it is: shortened, one short line.
    {
      write("cli_nul.prm",
            scene("cli_nul") + "subsection Impactor\n set Radius = 0.0" +
              std::string(1, '\0') + "1\nend\n");
      const int         code = run("cli_nul.prm");
      const std::string err  = read_text("cli.stderr");
      check("a NUL byte in a value: exit 1, one line naming the file's line "
            "and the NUL byte, the byte not echoed",
            code == 1 && n_lines(err) == 1 && contains(err, "cli_nul.prm") &&
              contains(err, "NUL byte") && err.find('\0') == std::string::npos);
      fs::remove_all("cli_a");
      write("cli_nul_dir.prm", scene("cli_a" + std::string(1, '\0') + "b"));
      const int         dir_code = run("cli_nul_dir.prm");
      const std::string dir_err  = read_text("cli.stderr");
      check("... a NUL byte in Output/Directory: exit 1, one line, no "
            "directory cut at the NUL ('cli_a') written",
            dir_code == 1 && n_lines(dir_err) == 1 &&
              contains(dir_err, "NUL byte") && !fs::exists("cli_a"));
      const int long_code = run(
        "cli_base.prm -s 'Impactor/Radius=" + std::string(100000, 'x') + "'");
      const std::string long_err = read_text("cli.stderr");
      std::printf("a value of 100,000 characters: error line of %zu "
                  "characters\n",
                  long_err.size());
      check("... a value of 100,000 characters: exit 1, one line under 2,000 "
            "characters saying how many were left out",
            long_code == 1 && n_lines(long_err) == 1 &&
              long_err.size() < 2000 &&
              contains(long_err, "characters left out"));
    }

    // The .prm from standard input.
    write("cli_stdin.prm", scene("cli_stdin", velocity_2));
    check("'-' reads standard input: the same history",
          run("- < cli_stdin.prm") == 0 &&
            history("cli_stdin") == history("cli_edited"));

    // An include relative to the including file (run from another directory).
    fs::create_directories("cli_sub/deeper");
    write("cli_sub/deeper/base.prm", scene("cli_include"));
    write("cli_sub/case.prm", "include deeper/base.prm\n" + velocity_2);
    check("include resolved relative to the including file",
          run("cli_sub/case.prm") == 0 &&
            history("cli_include") == history("cli_edited"));
    write("cli_sub/loop.prm", "include loop.prm\n");
    {
      const int         code = run("cli_sub/loop.prm");
      const std::string err  = read_text("cli.stderr");
      check("an include loop: exit 1, one line naming the include",
            code == 1 && n_lines(err) == 1 && contains(err, "include"));
    }

    // A '#' in a path would start a comment in parameters.prm (the path
    // read back would differ, and so would the directory it cleans).
    {
      const int         code = run("cli_base.prm -s 'Output/Directory=cli#x'");
      const std::string err  = read_text("cli.stderr");
      check("'#' in Output/Directory (-s): exit 1, one line naming it, "
            "nothing written",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "Output/Directory") && !fs::exists("cli#x"));
    }

    // A newline in a path breaks every listing of it: refused (a directory
    // "cli_nl\nx" was created and run into).
    {
      const int code =
        run("cli_base.prm -s \"$(printf 'Output/Directory=cli_nl\\nx')\"");
      const std::string err = read_text("cli.stderr");
      check("a newline in Output/Directory (-s): exit 1, one line naming it, "
            "nothing written",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "Output/Directory") && !fs::exists("cli_nl\nx"));
    }
    // --study-case without a study was ignored without a word.
    {
      const int         code = run("cli_base.prm --study-case 0");
      const std::string err  = read_text("cli.stderr");
      check("--study-case without a study: exit 1, one line naming it",
            code == 1 && n_lines(err) == 1 && contains(err, "--study-case"));
    }

    // A tabulated profile given relative to its .prm (run from another
    // directory): found by the run and by a study's cases, and written into
    // parameters.prm as an absolute path (what --resume DIR reads).
    write("cli_sub/profile.csv",
          "# z/h, E (Pa), nu, rho (kg/m^3)\n0, 380e9, 0.3, 3800\n"
          "0.5, 225e9, 0.3, 3253\n1, 70e9, 0.3, 2707\n");
    write("cli_sub/tab.prm",
          scene("cli_tab",
                "subsection Material\n set Gradation = tabulated\n"
                " set Profile file = profile.csv\nend\n"));
    {
      const int         code = run("cli_sub/tab.prm -s 'Impactor/Initial "
                                   "velocity=2'");
      const std::string prm  = read_text("cli_tab/parameters.prm");
      const auto        at   = prm.find("set Profile file");
      const std::string line =
        at == std::string::npos ? "" : prm.substr(at, prm.find('\n', at) - at);
      // "set Profile file = PATH # default: ..."
      std::string path       = line.substr(line.find('=') + 1);
      path                   = path.substr(0, path.find('#'));
      const std::string file = path.substr(path.find_first_not_of(' '),
                                           path.find_last_not_of(' ') -
                                             path.find_first_not_of(' ') + 1);
      check("a Profile file relative to its .prm: the run finds it, and "
            "parameters.prm names it by an absolute path",
            code == 0 && fs::path(file).is_absolute() &&
              fs::equivalent(file, "cli_sub/profile.csv"));
      const int    study_code = run("cli_sub/tab.prm -s 'Output/Directory="
                                    "cli_tab_study' --study 'Impactor/Initial "
                                    "velocity=1,2'");
      const double diff =
        csv_difference(read_text("cli_tab_study/case_001/history.csv"),
                       history("cli_tab"));
      // A convolution case, as above: one unit of a last digit at most.
      std::printf("tabulated study case V0 = 2 against the separate run: "
                  "history.csv within one unit of every last printed digit: "
                  "%s\n",
                  diff <= 1.01 ? "yes" : "NO");
      check("... and so do a study's cases (case V0 = 2 equal to the run)",
            study_code == 0 && diff <= 1.01);
    }

    // Provenance and the log.
    {
      const std::string log     = read_text("cli_set/log.txt");
      const std::string summary = read_text("cli_set/summary.txt");
      check("log.txt starts with the version and has the command line",
            log.rfind("# fgimpact ", 0) == 0 && contains(log, "# command ") &&
              contains(log, "Impactor/Initial velocity=2") &&
              contains(log, "# MPI ranks 1"));
      check("log.txt holds the run's log and names the output directory",
            contains(log, "peak force") &&
              contains(log, "fgimpact: results in cli_set"));
      check("summary.txt starts with '#' provenance lines, then the keys",
            summary.rfind("# fgimpact ", 0) == 0 &&
              contains(summary, "\npeak_contact_force_N = "));
      check("input.prm is the input as given",
            read_text("cli_set/input.prm") == read_text("cli_set.prm") &&
              read_text("cli_include/input.prm") ==
                read_text("cli_sub/case.prm"));
    }

    // --validate: checks, runs nothing, writes nothing.
    write("cli_validate.prm", scene("cli_validate"));
    check("--validate of a good file: exit 0, no output directory",
          run("--validate cli_validate.prm") == 0 &&
            !fs::exists("cli_validate"));
    write("cli_bad.prm",
          scene("cli_bad", "subsection Impactor\n set Radious = 0.01\nend\n"));
    {
      const int         code = run("--validate cli_bad.prm");
      const std::string err  = read_text("cli.stderr");
      check("--validate of a misspelled entry: exit 1, one line, 'did you "
            "mean 'Radius'?'",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "did you mean 'Radius'") && !fs::exists("cli_bad"));
    }
    write("cli_bad.prm",
          scene("cli_bad", "subsection Impacter\n set Radius = 0.01\nend\n"));
    {
      const int         code = run("cli_bad.prm");
      const std::string err  = read_text("cli.stderr");
      check("a misspelled subsection: exit 1, one line, 'did you mean "
            "'Impactor'?'",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "did you mean 'Impactor'") &&
              !fs::exists("cli_bad"));
    }
    {
      const int code = run("cli_base.prm -s 'Impactor/Initial velocty=2'");
      const std::string err = read_text("cli.stderr");
      check("-s with a misspelled path: exit 1, one line, the closest path",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "did you mean 'Impactor/Initial velocity'"));
    }
    {
      const int code = run("cli_base.prm -s 'Impactor/Initial velocity=x'");
      const std::string err = read_text("cli.stderr");
      check("-s with a bad value: exit 1, one line naming the entry",
            code == 1 && n_lines(err) == 1 &&
              contains(err, "Impactor/Initial velocity"));
    }

    // --print-parameters: the allowed values or range before every entry,
    // and the range listed is the one the program enforces.
    {
      const int          code    = run("--print-parameters");
      const std::string  listing = read_text("cli.stdout");
      std::istringstream lines(listing);
      std::string        line, previous, vtu_allowed;
      unsigned int       n_set = 0, n_annotated = 0;
      while (std::getline(lines, line))
        {
          if (line.find_first_not_of(' ') != std::string::npos &&
              line.compare(line.find_first_not_of(' '), 4, "set ") == 0)
            {
              ++n_set;
              n_annotated += contains(previous, "# Allowed: [");
              if (contains(line, "set VTU interval"))
                vtu_allowed = previous;
            }
          previous = line;
        }
      check("--print-parameters: exit 0, every entry preceded by its "
            "allowed values",
            code == 0 && n_set > 50 && n_annotated == n_set);
      write("cli_listing.prm", listing);
      check("... the listing is a valid .prm",
            run("--validate cli_listing.prm") == 0);
      check("... Output/VTU interval listed as 0...100000000, and enforced",
            contains(vtu_allowed,
                     "[Integer range 0...100000000 (inclusive)]") &&
              run("--validate cli_validate.prm -s 'Output/VTU "
                  "interval=100000000'") == 0 &&
              run("--validate cli_validate.prm -s 'Output/VTU "
                  "interval=100000001'") == 1);
    }

    // Output/Probe points through the executable.
    {
      write("cli_probes.prm", scene("cli_probes"));
      const int code = run("cli_probes.prm -s 'Output/Probe points=corner: "
                           "0, 0, 0; q: 0.25a, 0.5b, 0.015'");
      const std::string probes = read_text("cli_probes/probes.csv");
      check("named probes: probes.csv has t_us, support_reaction_z_N, the "
            "named columns and a row per history row",
            code == 0 &&
              contains(probes, "t_us,support_reaction_z_N,corner_ux_um") &&
              contains(probes, "q_sigma_yz_MPa\n") &&
              n_lines(probes) == n_lines(history("cli_probes")));
      const int         outside = run("cli_probes.prm -s 'Output/Probe "
                                      "points=far: 0.25, 0.05, 0.005'");
      const std::string err     = read_text("cli.stderr");
      check("a probe outside the plate: exit 1, one line naming the entry "
            "and the point",
            outside == 1 && n_lines(err) == 1 &&
              contains(err, "Output/Probe points") && contains(err, "'far'"));
      const int bad = run("cli_probes.prm -s 'Output/Probe points=p: 1, 2'");
      check("a probe with two coordinates: exit 1, one line naming the entry",
            bad == 1 && n_lines(read_text("cli.stderr")) == 1 &&
              contains(read_text("cli.stderr"), "Output/Probe points"));
    }
    std::printf("%s\n", all_ok ? "OK" : "FAILED");
    return all_ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::command_line
