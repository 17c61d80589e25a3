// report.html at the end of a run: scripts/report.py in a child process
// (declared in run_report.h).

#include <fgimpact/base/files.h>
#include <fgimpact/output/run_report.h>
#include <fgimpact/version.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

extern char **environ;

namespace fgimpact
{
  std::string
  write_run_report(const std::string &directory)
  {
    const std::string script = std::string(FGIMPACT_SCRIPTS_DIR) + "/report.py";
    if (!std::filesystem::is_regular_file(script))
      return "report.html not written: " + script + " is missing.";
    // Listed before it exists, as every file of the run: Output/Overwrite
    // cleans it; a study's cases get theirs too.
    record_output_file(directory + "/report.html");
    namespace fs = std::filesystem;
    std::error_code listing;
    if (fs::exists(directory + "/study.csv", listing))
      for (const auto &entry : fs::directory_iterator(directory, listing))
        if (entry.path().filename().string().rfind("case_", 0) == 0 &&
            fs::exists(entry.path() / "summary.txt", listing))
          record_output_file((entry.path() / "report.html").string());
    // The child: python3 from PATH, quiet, with the default signal
    // dispositions and no blocked signal (this process ignores SIGPIPE and
    // blocks the stop signals in its threads).
    posix_spawn_file_actions_t files;
    posix_spawn_file_actions_init(&files);
    posix_spawn_file_actions_addopen(&files, 1, "/dev/null", O_WRONLY, 0);
    posix_spawn_file_actions_addopen(&files, 2, "/dev/null", O_WRONLY, 0);
    posix_spawnattr_t attributes;
    posix_spawnattr_init(&attributes);
    sigset_t none, defaults;
    sigemptyset(&none);
    sigemptyset(&defaults);
    for (const int s : {SIGPIPE, SIGINT, SIGTERM, SIGHUP, SIGXFSZ, SIGUSR1})
      sigaddset(&defaults, s);
    posix_spawnattr_setsigmask(&attributes, &none);
    posix_spawnattr_setsigdefault(&attributes, &defaults);
    posix_spawnattr_setflags(&attributes,
                             POSIX_SPAWN_SETSIGMASK | POSIX_SPAWN_SETSIGDEF);
    std::string arguments[] = {"python3", script, directory};
    char       *argv[]      = {arguments[0].data(),
                               arguments[1].data(),
                               arguments[2].data(),
                               nullptr};
    pid_t       child       = 0;
    const int   error =
      posix_spawnp(&child, "python3", &files, &attributes, argv, environ);
    posix_spawn_file_actions_destroy(&files);
    posix_spawnattr_destroy(&attributes);
    if (error != 0)
      return "report.html not written: cannot start python3 (" +
             std::string(std::strerror(error)) + ").";
    int status = 0;
    while (::waitpid(child, &status, 0) < 0 && errno == EINTR)
      {}
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
      return "report.html not written: python3 " + script + " " + directory +
             " failed; run it to see why.";
    return "";
  }
} // namespace fgimpact
