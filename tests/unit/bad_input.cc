// The bad-input suite: runs the fgimpact executable as a process on
// malformed, out-of-range and physically meaningless inputs (and a few
// that must run: a byte-order mark, CRLF line ends, a ball that has not
// left by the end time).  For every case it checks the exit code, that
// stderr is one line naming the parameter (or file) at fault, and that the
// output directory holds nothing half-written: for a refused input nothing
// at all; after a run (completed or failed) no temporary file, every row
// of history.csv complete, and a summary.txt with a status and no NaN;
// after a failure (exit code 2, also in set-up) a summary.txt with status
// = failed.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <sys/wait.h>
#include <test_tools.h>
#include <vector>

namespace fgimpact_unit_tests::bad_input
{

  namespace fs = std::filesystem;

  namespace
  {
    // A mesh of 4 x 2 x 1 elements and 20 us: every run takes well under a
    // second.
    const std::string small =
      "subsection Geometry\n set Subdivisions x = 4\n set Subdivisions y = 2\n"
      " set Subdivisions z = 1\nend\nsubsection Output\n set Log interval = 0\n"
      " set Print timing = false\nend\n";
    const std::string short_run =
      "subsection Time integration\n set End time = 20e-6\nend\n";
    const std::string all_free =
      "subsection Boundary conditions\n set Face x min = free\n set Face x max "
      "= free\n set Face y min = free\n set Face y max = free\nend\n";

    enum class Setup
    {
      plain,          // case.prm = prm + Output/Directory
      output_first,   // case.prm = Output/Directory + prm
      bom,            // ... preceded by a UTF-8 byte-order mark
      crlf,           // ... with Windows line ends
      include_crlf,   // case.prm includes a BOM + CRLF file with prm
      directory,      // the parameter "file" is a directory
      dev_zero,       // the parameter file is a link to /dev/zero
      self_include,   // the parameter file includes itself
      mutual_include, // two files include each other
      missing_file,   // the parameter file does not exist
      directory_is_a_file,
      not_empty,       // Overwrite = false into a directory with a file
      stale_files,     // Overwrite = true removes an earlier run's files
      manifest_files,  // ... only those its manifest lists
      user_checkpoint, // a user's file in Output/Directory/checkpoint/
      fifo_profile,    // profile.fifo: a FIFO with no writer
      symlink_loop,    // loop_a -> loop_b -> loop_a
      dev_full         // Output/Directory/<full_file> is a link to /dev/full
    };

    struct Case
    {
      const char *name;
      std::string prm;
      int         exit_code;
      const char *must_name; // in the one line on stderr
      Setup       setup     = Setup::plain;
      const char *full_file = ""; // for Setup::dev_full
    };

    /// Files an earlier run wrote (Overwrite = true removes them).
    std::vector<std::string>
    stale_names()
    {
      return {"solution_99999.0.vtu",
              "solution_99999.12.vtu",
              "solution_99999.pvtu",
              "sphere_99999.vtu",
              "contact_99999.vtu",
              "peak_fields.3.vtu",
              "vtu/solution_00020.1.vtu",
              "vtu/solution_peak.pvtu",
              "vtu/solution_t000037500.0.vtu",
              "vtu/sphere_peak.vtu",
              "summary.txt",
              "history.csv.tmp",
              "checkpoint/rank_0003.bin",
              "checkpoint.old/rank_0000.bin",
              "summary.json",
              // An earlier Accuracy = converged run's levels.
              "convergence.csv",
              "convergence/level_9/summary.txt",
              "convergence/level_9/vtu/solution_00020.0.vtu",
              "convergence/level_9/checkpoint/rank_0000.bin",
              "convergence/base_20x12x4_level_3/summary.txt"};
    }

    /// An earlier run's files that its manifests list (removed), and a
    /// user's files with our exact names that they do not (kept).
    std::vector<std::string>
    listed_names()
    {
      return {"summary.txt",
              "solution_99999.0.vtu",
              "vtu/solution_00020.1.vtu"};
    }

    std::vector<std::string>
    unlisted_names()
    {
      return {"solution_99998.0.vtu",
              "contact_pressure.csv",
              "vtu/solution_00500.0.vtu",
              "vtu/sphere_00500.vtu"};
    }

    /// A user's files beside them, with near-miss names (kept).
    std::vector<std::string>
    decoy_names()
    {
      return {"solution_abc.vtu",
              "solution_1.vtu",
              "solution_final.pvtu",
              "solution_report.vtu",
              "solution_00020.vtu",
              "sphere_mine.vtu",
              "contact_x.vtu",
              "peak_fields.mine.vtu",
              "history.csv.bak",
              "mine/solution_00000.0.vtu",
              "vtu/solution_t37.5.vtu",
              "vtu/notes.txt",
              "convergence/level_8/notes.txt",
              "convergence/base_20x12_level_3/summary.txt"};
    }

    using fgimpact_tests::read_text;

    /// Nothing half-written in dir: no temporary file, every history.csv
    /// row has the header's number of fields and ends with a newline, and
    /// summary.txt has a status and no NaN/Inf.
    bool
    output_is_clean(const std::string &dir)
    {
      if (!fs::is_directory(dir))
        return true;
      for (const auto &entry : fs::directory_iterator(dir))
        if (entry.path().extension() == ".tmp")
          return false;
      // (Regular files only: history.csv may be a link to /dev/full.)
      const std::string history = fs::is_regular_file(dir + "/history.csv") ?
                                    read_text(dir + "/history.csv") :
                                    "";
      if (!history.empty())
        {
          if (history.back() != '\n')
            return false;
          std::istringstream lines(history);
          std::string        line;
          std::getline(lines, line);
          const auto fields = std::count(line.begin(), line.end(), ',');
          while (std::getline(lines, line))
            if (std::count(line.begin(), line.end(), ',') != fields)
              return false;
        }
      if (fs::is_regular_file(dir + "/summary.txt"))
        {
          const std::string summary = read_text(dir + "/summary.txt");
          if (summary.find("status = ") == std::string::npos ||
              summary.find("nan") != std::string::npos ||
              summary.find("inf") != std::string::npos)
            return false;
        }
      return true;
    }

    /// Write the case's files; returns the parameter file's name.
    std::string
    prepare(const Case &c, const std::string &dir)
    {
      const std::string prm =
        c.prm + "subsection Output\n set Directory = " + dir + "\nend\n";
      const auto write = [](const std::string &name, const std::string &text) {
        std::ofstream out(name, std::ios::binary);
        out << text;
      };
      std::string crlf;
      for (const char ch : prm)
        crlf += (ch == '\n') ? std::string("\r\n") : std::string(1, ch);
      switch (c.setup)
        {
          case Setup::bom:
            write("case.prm", "\xEF\xBB\xBF# a BOM\n" + prm);
            return "case.prm";
          case Setup::crlf:
            write("case.prm", crlf);
            return "case.prm";
          case Setup::include_crlf:
            write("included.prm", "\xEF\xBB\xBF" + crlf);
            write("case.prm",
                  "# includes a Windows file\ninclude included.prm\n");
            return "case.prm";
          case Setup::directory:
            fs::create_directories("a_directory.prm");
            return "a_directory.prm";
          case Setup::dev_zero:
            fs::remove("zero.prm");
            fs::create_symlink("/dev/zero", "zero.prm");
            return "zero.prm";
          case Setup::self_include:
            write("self.prm", prm + "include self.prm\n");
            return "self.prm";
          case Setup::mutual_include:
            write("first.prm", "include second.prm\n" + prm);
            write("second.prm", "include first.prm\n");
            return "first.prm";
          case Setup::missing_file:
            return "no_such_file.prm";
          case Setup::output_first:
            write("case.prm",
                  "subsection Output\n set Directory = " + dir + "\nend\n" +
                    c.prm);
            return "case.prm";
          case Setup::directory_is_a_file:
            write(dir, "a file, not a directory\n");
            break;
          case Setup::not_empty:
            fs::create_directories(dir);
            write(dir + "/notes.txt", "someone's file\n");
            break;
          case Setup::dev_full:
            // A full disk: every write to this file fails with ENOSPC.
            fs::create_directories(dir);
            fs::create_symlink("/dev/full", dir + "/" + c.full_file);
            break;
          case Setup::stale_files:
            fs::create_directories(dir + "/checkpoint");
            fs::create_directories(dir + "/checkpoint.old");
            fs::create_directories(dir + "/mine");
            fs::create_directories(dir + "/vtu");
            fs::create_directories(dir + "/convergence/level_9/vtu");
            fs::create_directories(dir + "/convergence/level_9/checkpoint");
            fs::create_directories(dir + "/convergence/level_8");
            fs::create_directories(dir + "/convergence/base_20x12x4_level_3");
            fs::create_directories(dir + "/convergence/base_20x12_level_3");
            // An earlier run's files: removed.
            for (const auto &name : stale_names())
              write(dir + "/" + name, "stale\n");
            // A user's files with near-miss names: kept.
            for (const auto &name : decoy_names())
              write(dir + "/" + name, "mine\n");
            break;
          case Setup::manifest_files:
            fs::create_directories(dir + "/vtu");
            write(dir + "/.fgimpact.files",
                  "summary.txt\nsolution_99999.0.vtu\nhistory.csv\n");
            write(dir + "/vtu/.fgimpact.files", "solution_00020.1.vtu\n");
            for (const auto &name : listed_names())
              write(dir + "/" + name, "stale\n");
            for (const auto &name : unlisted_names())
              write(dir + "/" + name, "mine\n");
            break;
          case Setup::symlink_loop:
            fs::remove("loop_a");
            fs::remove("loop_b");
            fs::create_symlink("loop_b", "loop_a");
            fs::create_symlink("loop_a", "loop_b");
            // The case's Output/Directory last: it wins.
            write("case.prm",
                  "subsection Output\n set Directory = " + dir + "\nend\n" +
                    c.prm);
            return "case.prm";
          case Setup::fifo_profile:
            fs::remove("profile.fifo");
            mkfifo("profile.fifo", 0644);
            break;
          case Setup::user_checkpoint:
            fs::create_directories(dir + "/checkpoint");
            write(dir + "/checkpoint/mydata.bin", "mine\n");
            break;
          default:
            break;
        }
      write("case.prm", prm);
      return "case.prm";
    }
  } // namespace



  namespace
  {
    /// Malformed, out-of-range, inconsistent and meaningless entries.
    std::vector<Case>
    entry_cases()
    {
      return {
        // Malformed and out-of-range entries (exit code 1, nothing written).
        {"missing end",
         "subsection Geometry\n set Length a = 0.2\n",
         1,
         "'end'",
         Setup::output_first},
        {"malformed number",
         "subsection Geometry\n set Length a = 0.2m\nend\n",
         1,
         "Length a"},
        {"out of range",
         "subsection Material\n set Poisson's ratio = 0.7\nend\n",
         1,
         "Poisson's ratio"},
        {"unknown entry",
         "subsection Impactor\n set Radious = 0.01\nend\n",
         1,
         "Radious"},
        {"misspelled subsection",
         "subsection Geometri\n set Length a = 0.2\nend\n",
         1,
         "Geometri"},
        {"negative thickness",
         "subsection Geometry\n set Thickness h = -0.02\nend\n",
         1,
         "Thickness h"},
        {"zero subdivisions",
         "subsection Geometry\n set Subdivisions x = 0\nend\n",
         1,
         "Subdivisions x"},
        {"NaN value",
         "subsection Impactor\n set Initial velocity = nan\nend\n",
         1,
         "Initial velocity"},
        {"inf value",
         "subsection Material\n set Metal Young's modulus = inf\nend\n",
         1,
         "Metal Young's modulus"},
        {"1e400",
         "subsection Impactor\n set Density = 1e400\nend\n",
         1,
         "Density"},
        {"empty value",
         "subsection Material\n set Power-law index =\nend\n",
         1,
         "Power-law index"},
        {"bad selection",
         "subsection Boundary conditions\n set Face x min = pinned\nend\n",
         1,
         "Face x min"},
        {"bad problem type", "set Problem type = dynamic\n", 1, "Problem type"},
        {"bad solver type",
         "subsection Linear solver\n set Type = lu\nend\n",
         1,
         "Type"},
        {"degree 3",
         "subsection Finite element\n set Degree = 3\nend\n",
         1,
         "Degree"},
        // Issue 38: its peak force changes by -0.82 %, then +0.82 %.
        {"the resolved contact on quadratic faces",
         "subsection Finite element\n set Degree = 2\nend\n"
         "subsection Contact\n set Model = resolved sphere\nend\n",
         1,
         "Finite element/Degree"},
        // Issue 38: the modes are condensed from the elastic Q1 stiffness.
        {"incompatible modes on the 27-node brick",
         "subsection Finite element\n set Degree = 2\n"
         " set Incompatible modes = true\nend\n",
         1,
         "Finite element/Incompatible modes"},
        {"incompatible modes on a plastic plate",
         "subsection Finite element\n set Incompatible modes = true\nend\n"
         "subsection Material\n set Plasticity = J2\nend\n"
         "subsection Contact\n set Model = resolved sphere\nend\n",
         1,
         "Finite element/Incompatible modes"},
        {"incompatible modes converged under hertz midplane's point force",
         "set Accuracy = converged\n"
         "subsection Finite element\n set Incompatible modes = true\nend\n"
         "subsection Contact\n set Model = hertz midplane\nend\n",
         1,
         "Finite element/Incompatible modes"},
        {"incompatible modes with a temperature field",
         "subsection Finite element\n set Incompatible modes = true\nend\n"
         "subsection Thermal\n set Temperature field = uniform\n"
         " set Temperature change = 100\nend\n",
         1,
         "Finite element/Incompatible modes"},
        {"adaptive mesh under a point force (hertz node)",
         "subsection Geometry\n set Adaptive refinement cycles = 1\nend\n",
         1,
         "Geometry/Adaptive refinement cycles > 0 needs Contact/Model = "
         "resolved sphere"},
        {"adaptive mesh with Accuracy = converged",
         "set Accuracy = converged\nsubsection Contact\n set Model = resolved "
         "sphere\nend\nsubsection Geometry\n set Adaptive refinement cycles "
         "= 1\nend\n",
         1,
         "Geometry/Adaptive refinement cycles > 0 with Accuracy = converged"},
        {"adaptive mesh in a modal analysis",
         "set Problem type = modal\nsubsection Geometry\n set Adaptive "
         "refinement cycles = 1\nend\n",
         1,
         "Geometry/Adaptive refinement cycles > 0 is for Problem type = "
         "impact"},
        {"adaptive mesh beyond the memory (6 cycles splitting every cell)",
         "subsection Contact\n set Model = resolved sphere\nend\n"
         "subsection Geometry\n set Adaptive refinement cycles = 6\n"
         " set Adaptive refinement fraction = 1\nend\n",
         1,
         "Geometry/Adaptive refinement cycles = 6 with fraction 1: the final "
         "mesh, expected"},
        {"adaptive refinement fraction 0",
         "subsection Geometry\n set Adaptive refinement fraction = 0\nend\n",
         1,
         "Adaptive refinement fraction"},
        {"adaptive estimate without adaptive cycles",
         "subsection Contact\n set Model = resolved sphere\nend\n"
         "subsection Geometry\n set Adaptive refinement estimate = true\nend\n",
         1,
         "Geometry/Adaptive refinement estimate = true needs Adaptive "
         "refinement cycles > 0"},
        // Issue 42: SUS304's cubic law for E turns negative near 1490 K.
        {"a named constituent beyond its temperature law",
         "subsection Material\n set Metal material = SUS304\nend\n"
         "subsection Thermal\n set Temperature field = uniform\n"
         " set Temperature change = 1200\nend\n",
         1,
         "Material/Metal material"},
        // Issue 42: the thermal step is elastic; J2 starts from its state
        // only below the yield strength (-351 MPa here against 275 MPa).
        {"J2 from a thermal state beyond the yield strength",
         small + "subsection Contact\n set Model = resolved sphere\nend\n"
                 "subsection Material\n set Plasticity = J2\n"
                 " set Power-law index = 0\nend\n"
                 "subsection Boundary conditions\n set In-plane edges = "
                 "immovable\nend\n"
                 "subsection Thermal\n set Temperature field = uniform\n"
                 " set Temperature change = 150\nend\n",
         1,
         "Material/Plasticity = J2: the thermal state"},
        {"a named constituent with an exponential gradation",
         "subsection Material\n set Ceramic material = Si3N4\n"
         " set Gradation = exponential\nend\n",
         1,
         "Material/Metal material or Ceramic material"},
        {"negative log interval",
         "subsection Output\n set Log interval = -1\nend\n",
         1,
         "Log interval"},
        {"a snapshot after the End time",
         "subsection Output\n set Snapshot times = 20e-6, 500e-6\nend\n"
         "subsection Time integration\n set End time = 400e-6\nend\n",
         1,
         "Output/Snapshot times"},
        {"a snapshot after the Maximum end time of End time = auto",
         "subsection Output\n set Snapshot times = 20e-6, 5e-3\nend\n"
         "subsection Time integration\n set End time = auto\nend\n",
         1,
         "Maximum end time"},
        {"Accuracy = converged with the paper's hertz node",
         "set Accuracy = converged\n"
         "subsection Contact\n set Model = hertz node\nend\n",
         1,
         "hertz node"},
        {"Accuracy = converged with the explicit scheme",
         "set Accuracy = converged\n"
         "subsection Contact\n set Model = hertz midplane\nend\n"
         "subsection Time integration\n set Scheme = explicit\n"
         " set Time step = 0\nend\n",
         1,
         "Scheme = implicit"},
        {"Accuracy = converged with the ball still in contact at End time",
         "set Accuracy = converged\n"
         "subsection Contact\n set Model = resolved sphere\nend\n"
         "subsection Time integration\n set End time = 40e-6\nend\n",
         2,
         "Time integration/End time"},
        // Issue 40: 1e-6 ran 9 levels for 600 s; refused after 3 levels
        // (7 s) from their observed order.
        {"Accuracy tolerance = 1e-6, out of reach of the contact levels",
         "set Accuracy = converged\nset Accuracy tolerance = 1e-6\n"
         "subsection Contact\n set Model = resolved sphere\nend\n",
         2,
         "cannot be reached"},
        {"End time neither auto nor a number",
         "subsection Time integration\n set End time = later\nend\n",
         1,
         "End time"},
        {"two snapshot times that name one file (the same ns)",
         "subsection Output\n set Snapshot times = 10e-6, 10.0001e-6\nend\n",
         1,
         "Output/Snapshot times"},
        {"a snapshot time that is not a number",
         "subsection Output\n set Snapshot times = 20e-6, soon\nend\n",
         1,
         "Snapshot times"},
        {"bad bool",
         "subsection Output\n set Overwrite = maybe\nend\n",
         1,
         "Overwrite"},
        {"bad accuracy preset", "set Accuracy = ultra\n", 1, "Accuracy"},
        {"zero modes",
         "set Problem type = modal\nsubsection Modal\n set Number of modes = 0\nend\n",
         1,
         "Number of modes"},
        // Inconsistent entries and impossible geometry.
        {"impact point outside the plate",
         "subsection Impactor\n set Impact point x = 0.5\nend\n",
         1,
         "Impact point x"},
        {"impact point on the edge",
         "subsection Impactor\n set Impact point y = 0.1\nend\n",
         1,
         "Impact point y"},
        {"end time shorter than a step",
         "subsection Time integration\n set End time = 1e-7\nend\n",
         1,
         "End time"},
        {"more than 1e8 steps",
         "subsection Time integration\n set End time = 1000\nend\n",
         1,
         "End time"},
        {"implicit with automatic step",
         "subsection Time integration\n set Time step = 0\nend\n",
         1,
         "Time step"},
        {"Newmark gamma 1, beta 1/4",
         "subsection Time integration\n set Newmark gamma = 1\n set Newmark beta = 0.25\nend\n",
         1,
         "Newmark beta"},
        {"Newmark gamma 0.8, beta 0.3",
         "subsection Time integration\n set Newmark gamma = 0.8\n set Newmark beta = 0.3\nend\n",
         1,
         "Newmark beta"},
        {"Newmark gamma below 1/2",
         "subsection Time integration\n set Newmark gamma = 0.4\nend\n",
         1,
         "Newmark gamma"},
        {"explicit step above the stability limit",
         small +
           "subsection Time integration\n set Scheme = explicit\n set Time step = 1e-5\nend\n",
         1,
         "Time step"},
        // Issue 40: the advice named the scheme the run already used, and
        // the failed summary gave the blown-up ball's 3.0 m/s departure.
        {"a 1 um ball: the run blows up, the advice names Hertz's duration",
         small + "subsection Impactor\n set Radius = 1e-6\nend\n",
         2,
         "Hertz's contact lasts about"},
        {"impactor wider than the plate",
         "subsection Impactor\n set Radius = 10\nend\n",
         1,
         "Impactor/Radius"},
        {"static load on a free plate",
         "set Problem type = static\n" + small + all_free,
         1,
         "Boundary conditions/Face x min"},
        {"modal shift 0 on a free plate",
         "set Problem type = modal\n" + small + all_free,
         1,
         "Boundary conditions/Face x min"},
        {"mesh far too large for the memory",
         "subsection Geometry\n set Subdivisions x = 400\n set Subdivisions y = 200\n set Subdivisions z = 40\n set Symmetry = none\nend\n",
         1,
         "Geometry/Subdivisions"},
        {"static, only x faces supported",
         "set Problem type = static\n" + small +
           "subsection Boundary conditions\n set Face y min = free\n set Face y max = free\nend\n",
         1,
         "translation in x"},
        {"static, base simply supported, sides free",
         "set Problem type = static\n" + small + all_free +
           "subsection Boundary conditions\n set Face z min = simply supported\nend\n",
         1,
         "translation in x, translation in y, rotation about the z axis"},
        {"static, one side simply supported",
         "set Problem type = static\n" + small + all_free +
           "subsection Boundary conditions\n set Face x min = simply supported\nend\n",
         1,
         "3 of 6 rigid-body modes free (translation in x, rotation about the "
         "y axis through (0, 50, 10) mm, rotation about the z axis through "
         "(0, 50, 10) mm)"},
        {"plasticity under a point force (hertz node)",
         "subsection Material\n set Plasticity = J2\nend\n",
         1,
         "Material/Plasticity = J2 needs Contact/Model = resolved sphere"},
        {"plasticity with yield strength 0",
         "subsection Material\n set Plasticity = J2\n set Metal yield strength "
         "= 0\nend\nsubsection Contact\n set Model = resolved sphere\nend\n",
         1,
         "Material/Metal yield strength"},
        {"plasticity in a modal analysis",
         "set Problem type = modal\nsubsection Material\n set Plasticity = "
         "J2\nend\n",
         1,
         "Material/Plasticity = J2"},
        {"plasticity under a uniform static pressure",
         "set Problem type = static\nsubsection Static\n set Load = "
         "uniform\nend\nsubsection Material\n set Plasticity = J2\nend\n",
         1,
         "Static/Load = sphere only"},
        {"resolved sphere on a coarse mesh without refinement",
         "subsection Contact\n set Model = resolved sphere\nend\n"
         "subsection Geometry\n set Subdivisions x = 8\n set Subdivisions y = 4\n"
         " set Subdivisions z = 2\n set Contact refinement levels = 0\nend\n"
         "subsection Output\n set Log interval = 0\n set Print timing = false\nend\n" +
           short_run,
         2,
         "Geometry/Contact refinement levels"},
        {"output directory under a file",
         "subsection Output\n set Directory = case.prm/sub\nend\n",
         1,
         "Output/Directory",
         Setup::output_first},
        {"output directory of 5000 characters",
         "subsection Output\n set Directory = " + std::string(5000, 'x') +
           "\nend\n",
         1,
         "Output/Directory",
         Setup::output_first},
        {"output directory through a symbolic-link loop",
         "subsection Output\n set Directory = loop_a/out\nend\n",
         1,
         "Output/Directory",
         Setup::symlink_loop},
        {"profile file is /dev/zero",
         "subsection Material\n set Gradation = tabulated\n set Profile file = /dev/zero\nend\n",
         1,
         "Material/Profile file"},
        {"profile file is a directory",
         "subsection Material\n set Gradation = tabulated\n set Profile file = /tmp\nend\n",
         1,
         "is a directory"},
        {"profile file is a FIFO with no writer",
         "subsection Material\n set Gradation = tabulated\n set Profile file = profile.fifo\nend\n",
         1,
         "not a regular file",
         Setup::fifo_profile},
        {"End time shorter than the automatic explicit step",
         small +
           "subsection Time integration\n set Scheme = explicit\n set Time step = 0\n set End time = 1e-9\nend\n",
         1,
         "Time integration/End time"},
        {"modal: more modes than the mesh has",
         "set Problem type = modal\nsubsection Geometry\n set Subdivisions x = 2\n"
         " set Subdivisions y = 1\n set Subdivisions z = 1\nend\n"
         "subsection Modal\n set Number of modes = 200\nend\n"
         "subsection Output\n set Print timing = false\nend\n",
         2,
         "Modal/Number of modes"}};
    }



    /// Files that are not parameter files, output directories, numerical
    /// failures, full disks, and inputs that must run.
    std::vector<Case>
    file_and_run_cases()
    {
      const std::string newton =
        "subsection Newton\n set Tolerance = 1e-15\n set Max iterations = 1\nend\n";
      return {
        // Files that are not parameter files.
        {"parameter file is a directory",
         "",
         1,
         "a_directory.prm",
         Setup::directory},
        {"parameter file is /dev/zero", "", 1, "zero.prm", Setup::dev_zero},
        {"parameter file includes itself",
         small,
         1,
         "includes itself",
         Setup::self_include},
        {"two files include each other",
         small,
         1,
         "includes itself",
         Setup::mutual_include},
        {"parameter file missing",
         "",
         1,
         "no_such_file.prm",
         Setup::missing_file},
        {"include of a missing file",
         "include not_there.prm\n",
         1,
         "not_there.prm"},
        // Output directories.
        {"unwritable output directory", "", 1, "Output/Directory"},
        {"output directory is a file",
         "",
         1,
         "Output/Directory",
         Setup::directory_is_a_file},
        {"Overwrite = false, directory not empty",
         small + "subsection Output\n set Overwrite = false\nend\n",
         1,
         "Output/Overwrite",
         Setup::not_empty},
        // Numerical failures (exit code 2, one line naming the step or phase).
        {"Newton failure", small + newton, 2, "time step 1 "},
        {"cg capped at 2 iterations in set-up",
         small +
           "subsection Linear solver\n set Type = cg\n set Max iterations = 2\nend\n",
         2,
         "Linear solver/Max iterations"},
        // The check that splits the rest of the plate (about 8 times the
        // DoFs) needs 400-500 cg iterations where the pilot and the final
        // run need 200-250: its failure names the check.
        {"adaptive estimate: cg fails in the rest_of_plate check only",
         "subsection Geometry\n set Symmetry = quarter\n set Subdivisions x "
         "= 20\n set Subdivisions y = 10\n set Subdivisions z = 2\n set "
         "Contact refinement levels = 4\n set Adaptive refinement cycles = "
         "1\n set Adaptive refinement estimate = true\nend\n"
         "subsection Contact\n set Model = resolved sphere\nend\n"
         "subsection Time integration\n set End time = auto\nend\n"
         "subsection Linear solver\n set Type = cg\n set Max iterations = "
         "320\nend\n",
         2,
         "Geometry/Adaptive refinement estimate, check rest_of_plate (the "
         "final run's outputs are complete"},
        {"cg capped at 2 iterations, static",
         "set Problem type = static\n" + small +
           "subsection Linear solver\n set Type = cg\n set Max iterations = 2\nend\n",
         2,
         "static solve"},
        {"modal iteration capped at 1",
         "set Problem type = modal\n" + small +
           "subsection Modal\n set Max iterations = 1\nend\n",
         2,
         "Modal/Max iterations"},
        {"time step longer than the contact",
         small +
           "subsection Time integration\n set Time step = 1e-4\n set End time = 4e-3\nend\n",
         2,
         "Time integration/Time step"},
        {"impactor of 1e-9 kg",
         small + "subsection Impactor\n set Mass = 1e-9\nend\n",
         2,
         "Time integration/Time step"},
        // A full disk (/dev/full) under one output file at a time.
        {"disk full: parameters.prm",
         small,
         2,
         "parameters.prm",
         Setup::dev_full,
         "parameters.prm.tmp"},
        {"disk full: history.csv",
         small,
         2,
         "history.csv",
         Setup::dev_full,
         "history.csv"},
        {"disk full: solution.pvd during the run",
         small + "subsection Output\n set VTU interval = 5\nend\n",
         2,
         "solution.pvd",
         Setup::dev_full,
         "solution.pvd.tmp"},
        {"disk full: summary.txt",
         small,
         2,
         "summary.txt",
         Setup::dev_full,
         "summary.txt.tmp"},
        {"disk full: log.txt", small, 2, "log.txt", Setup::dev_full, "log.txt"},
        // Inputs that run: read normally, with a warning, or with 'none'.
        {"byte-order mark", small + short_run, 0, "", Setup::bom},
        {"Windows line ends", small + short_run, 0, "", Setup::crlf},
        {"included file with BOM and CRLF",
         small + short_run,
         0,
         "",
         Setup::include_crlf},
        {"odd subdivisions, central impact",
         "subsection Geometry\n set Subdivisions x = 5\n set Subdivisions y = 2\n set Subdivisions z = 1\nend\n" +
           short_run,
         0,
         "Subdivisions"},
        {"ball still in contact at the end time", small + short_run, 0, ""},
        {"modal on a 2 x 2 x 1 mesh",
         "set Problem type = modal\nsubsection Geometry\n set Subdivisions x = 2\n"
         " set Subdivisions y = 2\n set Subdivisions z = 1\nend\n"
         "subsection Output\n set Print timing = false\nend\n",
         0,
         ""},
        {"a snapshot time after the automatic end",
         small + "subsection Output\n set Snapshot times = 10e-6, 700e-6\nend\n"
                 "subsection Time integration\n set End time = auto\nend\n",
         0,
         ""},
        {"V0 = 300 m/s: beyond the small-strain model",
         small + "subsection Time integration\n set End time = 60e-6\nend\n"
                 "subsection Impactor\n set Initial velocity = 300\nend\n",
         0,
         ""},
        {"static sphere on a block clamped at its base alone",
         "set Problem type = static\n" + small + all_free +
           "subsection Boundary conditions\n set Face z min = clamped\nend\n"
           "subsection Static\n set Load = sphere\nend\n"
           "subsection Geometry\n set Contact refinement levels = 3\nend\n",
         0,
         ""},
        {"impact point between nodes",
         small + short_run +
           "subsection Impactor\n set Impact point x = 0.0537\nend\n",
         0,
         "Impactor/Impact point"},
        {"time step of 1/8 of the contact",
         small +
           "subsection Time integration\n set Time step = 12e-6\n set End time = 400e-6\nend\n",
         0,
         ""},
        {"a user's file in checkpoint/",
         small + short_run,
         1,
         "checkpoint",
         Setup::user_checkpoint},
        {"Overwrite = true removes stale files",
         small + short_run,
         0,
         "",
         Setup::stale_files},
        {"Overwrite = true removes only what the manifests list",
         small + short_run,
         0,
         "",
         Setup::manifest_files},
        // Snapshot times were in µs until 2026-11: such an input is refused
        // with its value in s.
        {"a snapshot time in us, as before",
         "subsection Output\n set Snapshot times = 50\nend\n"
         "subsection Time integration\n set End time = 400e-6\nend\n",
         1,
         "for 50 us write 5e-05"}};
    }



    /// Run one case; print what it checks; count it.
    bool
    check(const Case        &c,
          const unsigned int i,
          unsigned int      &refused,
          unsigned int      &ran,
          unsigned int      &crashes)
    {
      const std::string dir =
        c.name == std::string("unwritable output directory") ?
          "/proc/fgimpact_cannot_write" :
          "bad_out_" + std::to_string(i);
      fs::remove_all(dir);
      const std::string prm_file = prepare(c, dir);
      const std::string command  = std::string(FGIMPACT_EXECUTABLE) + " " +
                                  prm_file + " > case.stdout 2> case.stderr";
      const int  status    = std::system(command.c_str());
      const int  exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
      const bool crashed   = !WIFEXITED(status) || exit_code > 128;
      crashes += crashed ? 1 : 0;

      const std::string text       = read_text("case.stderr");
      const auto        lines      = std::count(text.begin(), text.end(), '\n');
      const bool        right_code = exit_code == c.exit_code;
      // A refusal or a warning: exactly one line, naming the parameter.
      const bool quiet = c.exit_code == 0 && std::string(c.must_name).empty();
      const bool one_line = quiet ? lines == 0 : lines == 1;
      const bool named    = text.find(c.must_name) != std::string::npos;
      bool       clean    = output_is_clean(dir);
      if (c.exit_code == 1)
        clean =
          clean &&
          (c.setup == Setup::not_empty ?
             !fs::exists(dir + "/history.csv") :
           c.setup == Setup::user_checkpoint ?
             !fs::exists(dir + "/history.csv") &&
               read_text(dir + "/checkpoint/mydata.bin") == "mine\n" :
           c.setup == Setup::directory_is_a_file ? fs::is_regular_file(dir) :
                                                   !fs::exists(dir));
      if (c.exit_code == 2 && std::string(c.name).rfind("a 1 um ball", 0) == 0)
        clean = clean &&
                read_text(dir + "/summary.txt")
                    .find("departure_velocity_m_s = none") != std::string::npos;
      if (c.exit_code == 0)
        {
          // A run that completed; a quantity that does not exist is 'none'.
          const std::string summary = read_text(dir + "/summary.txt");
          clean =
            clean && summary.find("status = completed") != std::string::npos;
          if (c.setup == Setup::stale_files)
            {
              // Exactly the earlier run's files went; every decoy stayed.
              // (summary.txt is this run's again.)
              for (const auto &name : stale_names())
                clean = clean && read_text(dir + "/" + name) != "stale\n";
              for (const auto &name : decoy_names())
                clean = clean && read_text(dir + "/" + name) == "mine\n";
              clean =
                clean && !fs::exists(dir + "/checkpoint.old/rank_0000.bin");
              // An earlier converged run's level without a user's file went.
              clean = clean && !fs::exists(dir + "/convergence/level_9") &&
                      !fs::exists(dir + "/convergence/base_20x12x4_level_3");
            }
          if (c.setup == Setup::manifest_files)
            {
              // The listed files went (summary.txt is this run's again), a
              // user's file with our exact name stayed (issue 40: it was
              // removed).
              for (const auto &name : listed_names())
                clean = clean && read_text(dir + "/" + name) != "stale\n";
              for (const auto &name : unlisted_names())
                clean = clean && read_text(dir + "/" + name) == "mine\n";
            }
          // Not written, and said so in summary.txt's warnings (it was
          // dropped without a word).
          if (c.name == std::string("a snapshot time after the automatic end"))
            clean = clean && summary.find("after the automatic end at") !=
                               std::string::npos;
          if (c.name ==
              std::string("V0 = 300 m/s: beyond the small-strain model"))
            clean = clean && summary.find("outside the small-strain elastic "
                                          "model") != std::string::npos;
          if (c.name == std::string("modal on a 2 x 2 x 1 mesh"))
            {
              // Every mode found: no 0 Hz (LAPACK's failure used to leave
              // zeros), six rows.
              const std::string csv = read_text(dir + "/frequencies.csv");
              clean = clean && csv.find(",0.0000,") == std::string::npos &&
                      std::count(csv.begin(), csv.end(), '\n') == 7;
            }
          if (c.name == std::string("ball still in contact at the end time"))
            clean =
              clean &&
              summary.find("contact_duration_us = none") != std::string::npos &&
              summary.find("departure_velocity_m_s = none") !=
                std::string::npos;
        }
      // The log warned that the step cannot resolve the contact.
      if (c.name == std::string("time step longer than the contact") ||
          c.name == std::string("time step of 1/8 of the contact"))
        clean = clean && read_text("case.stdout")
                             .find("WARNING: Time integration/Time step") !=
                           std::string::npos;
      // A failed run (numerical or I/O, also in set-up) always leaves a
      // summary.txt marked failed, unless summary.txt itself is what
      // cannot be written.
      if (c.exit_code == 2 && c.full_file != std::string("summary.txt.tmp"))
        clean = clean && fs::is_regular_file(dir + "/summary.txt") &&
                read_text(dir + "/summary.txt").find("status = failed") !=
                  std::string::npos;
      (c.exit_code == 0 ? ran : refused) += right_code ? 1 : 0;

      const bool pass = right_code && one_line && named && clean && !crashed;
      std::printf("%2u %s: exit code %d %s, %s %s, names '%s' %s, output %s\n",
                  i + 1,
                  c.name,
                  c.exit_code,
                  right_code ? "yes" : "NO",
                  quiet ? "stderr empty" : "one line",
                  one_line ? "yes" : "NO",
                  c.must_name,
                  named ? "yes" : "NO",
                  clean ? "clean" : "NOT CLEAN");
      if (!pass)
        std::printf("  exit code was %d, stderr was: %s\n",
                    exit_code,
                    text.c_str());
      return pass;
    }
  } // namespace



  int
  test_main(int, char **)
  {
    std::vector<Case> cases = entry_cases();
    for (const auto &c : file_and_run_cases())
      cases.push_back(c);
    bool         ok      = true;
    unsigned int refused = 0, ran = 0, crashes = 0;
    for (unsigned int i = 0; i < cases.size(); ++i)
      ok = check(cases[i], i, refused, ran, crashes) && ok;
    std::printf(
      "inputs tried: %u, refused with the right exit code: %u, ran: %u, crashes: %u\n",
      static_cast<unsigned int>(cases.size()),
      refused,
      ran,
      crashes);
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::bad_input
