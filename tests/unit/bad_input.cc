// Bad input gets a one-line error naming the parameter, a non-zero exit
// and no output written: runs the fgimpact executable on broken .prm files.

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <sys/wait.h>

namespace fs = std::filesystem;

int
main()
{
  struct Case
  {
    const char *name;
    std::string prm;
    const char *must_name; // text the one-line message must contain
  };
  const Case cases[] = {
    {"malformed number",
     "subsection Geometry\n set Length a = 0.2m\nend\n",
     "Length a"},
    {"out of range",
     "subsection Material\n set Poisson's ratio = 0.7\nend\n",
     "Poisson's ratio"},
    {"unknown entry",
     "subsection Impactor\n set Radious = 0.01\nend\n",
     "Radious"},
    {"impossible geometry: impact point outside the plate",
     "subsection Impactor\n set Impact point x = 0.5\nend\n",
     "Impact point x"},
    {"end time shorter than a step",
     "subsection Time integration\n set End time = 1e-7\nend\n",
     "End time"},
    {"bad selection",
     "subsection Boundary conditions\n set Face x min = pinned\nend\n",
     "Face x min"},
    {"explicit time step above the stability limit",
     "subsection Geometry\n set Subdivisions x = 4\n set Subdivisions y = 2\n"
     " set Subdivisions z = 1\nend\nsubsection Time integration\n"
     " set Scheme = explicit\n set Time step = 1e-5\nend\n",
     "Time step"},
    {"unwritable output directory", "", "Output/Directory"}};

  bool ok = true;
  for (const auto &c : cases)
    {
      const std::string dir =
        std::string("bad_out_") + std::to_string(&c - cases);
      fs::remove_all(dir);
      const std::string out_dir =
        std::string(c.name) == "unwritable output directory" ?
          "/proc/fgimpact_cannot_write" :
          dir;
      {
        std::ofstream prm("bad.prm");
        prm << c.prm << "subsection Output\n set Directory = " << out_dir
            << "\nend\n";
      }
      const std::string command = std::string(FGIMPACT_EXECUTABLE) +
                                  " bad.prm > bad.stdout 2> bad.stderr";
      const int status    = std::system(command.c_str());
      const int exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;

      std::ifstream     err("bad.stderr");
      std::stringstream buffer;
      buffer << err.rdbuf();
      const std::string text     = buffer.str();
      const auto        lines    = std::count(text.begin(), text.end(), '\n');
      const bool        nonzero  = exit_code != 0;
      const bool        one_line = (lines == 1);
      const bool        named    = text.find(c.must_name) != std::string::npos;
      const bool        nothing_written = !fs::exists(out_dir);
      ok = ok && nonzero && one_line && named && nothing_written;
      std::printf(
        "%s: non-zero exit %s, one line %s, names '%s' %s, no output %s\n",
        c.name,
        nonzero ? "yes" : "NO",
        one_line ? "yes" : "NO",
        c.must_name,
        named ? "yes" : "NO",
        nothing_written ? "yes" : "NO");
      if (!(one_line && named))
        std::printf("  stderr was: %s\n", text.c_str());
    }
  // A numerical failure: Newton capped at one iteration cannot meet a
  // 1e-15 tolerance in the first contact step.  Exit code 2, one line that
  // names the time step.
  {
    fs::remove_all("newton_out");
    {
      std::ofstream prm("newton.prm");
      prm
        << "subsection Geometry\n set Subdivisions x = 4\n set Subdivisions y "
           "= 2\n set Subdivisions z = 1\nend\n"
           "subsection Newton\n set Tolerance = 1e-15\n set Max iterations = "
           "1\nend\nsubsection Output\n set Directory = newton_out\nend\n";
    }
    const int status =
      std::system((std::string(FGIMPACT_EXECUTABLE) +
                   " newton.prm > newton.stdout 2> newton.stderr")
                    .c_str());
    std::ifstream     err("newton.stderr");
    std::stringstream buffer;
    buffer << err.rdbuf();
    const std::string text     = buffer.str();
    const bool        exit_two = WIFEXITED(status) && WEXITSTATUS(status) == 2;
    const bool one_line   = std::count(text.begin(), text.end(), '\n') == 1;
    const bool names_step = text.find("time step 1 ") != std::string::npos;
    ok                    = ok && exit_two && one_line && names_step;
    std::printf(
      "Newton failure: exit code 2 %s, one line %s, names the time step %s\n",
      exit_two ? "yes" : "NO",
      one_line ? "yes" : "NO",
      names_step ? "yes" : "NO");
    if (!(one_line && names_step))
      std::printf("  stderr was: %s\n", text.c_str());
  }
  std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
  return ok ? 0 : 1;
}
