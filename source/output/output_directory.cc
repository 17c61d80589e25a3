// The output directory: checked before the set-up and cleaned of exactly
// the files an earlier run wrote (its lock: directory_lock.cc).  Declared
// in output_directory.h.

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_directory.h>

#include <algorithm>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <map>
#include <memory>
#include <set>
#include <sys/file.h>
#include <sys/stat.h>
#include <sys/statfs.h>
#include <unistd.h>

namespace fgimpact
{
  namespace
  {
    /// Whether text[from, from + n) holds n decimal digits.
    bool
    digits(const std::string &text, const std::size_t from, const std::size_t n)
    {
      if (from + n > text.size())
        return false;
      for (std::size_t k = from; k < from + n; ++k)
        if (text[k] < '0' || text[k] > '9')
          return false;
      return true;
    }

    /// Whether name is `prefix` + n_digits digits (the step) + `suffix`, where
    /// a suffix ".R.vtu" takes any number R >= 0 of digits (the piece).
    bool
    is_series_file(const std::string &name,
                   const std::string &prefix,
                   const std::string &suffix,
                   const unsigned int n_digits = 5)
    {
      if (name.rfind(prefix, 0) != 0 || !digits(name, prefix.size(), n_digits))
        return false;
      const std::string rest = name.substr(prefix.size() + n_digits);
      if (suffix != ".R.vtu")
        return rest == suffix;
      // ".<rank>.vtu"
      const std::size_t end = rest.size() - 4;
      return rest.size() > 5 && rest[0] == '.' &&
             rest.compare(end, 4, ".vtu") == 0 && digits(rest, 1, end - 1);
    }

    /**
     * The files this program writes into the output directory, by their
     * exact names (a user's solution_report.vtu or sphere_mine.vtu is
     * not one): the fixed names, and the series with a 5-digit step and,
     * for pieces, the rank.
     */
    bool
    is_own_output(const std::string &file_name)
    {
      std::string name      = file_name;
      const auto  ends_with = [](const std::string &s, const std::string &end) {
        return s.size() >= end.size() &&
               s.compare(s.size() - end.size(), end.size(), end) == 0;
      };
      if (ends_with(name, ".tmp"))
        name.resize(name.size() - 4);
      // log.txt too: the cleaning happens before this run opens its own.
      if (name == "history.csv" || name == "probes.csv" ||
          name == "summary.txt" || name == "parameters.prm" ||
          name == "frequencies.csv" || name == "solution.pvd" ||
          name == "log.txt" || name == "input.prm" || name == "sphere.pvd" ||
          name == "contact.pvd" || name == "contact_pressure.csv" ||
          name == "peak_fields.pvtu" || name == "study.csv" ||
          name == "convergence.csv" || name == "adaptation.csv" ||
          name == "adaptive_estimate.csv" || name == "summary.json" ||
          name == "report.html")
        return true;
      // peak_fields.R.vtu
      if (name.rfind("peak_fields.", 0) == 0 && ends_with(name, ".vtu") &&
          name.size() > 16 && digits(name, 12, name.size() - 16))
        return true;
      // The series: a 5-digit step, "t" and a 9-digit time in ns (Output/
      // Snapshot times) or "peak" (the peak force's snapshot).
      for (const std::string series : {"solution_", "sphere_", "contact_"})
        for (const auto &[tag, n] :
             {std::pair<std::string, unsigned int>{"", 5},
              {"t", 9},
              {"peak", 0}})
          {
            const std::string prefix = series + tag;
            if (series == "solution_" ?
                  (is_series_file(name, prefix, ".pvtu", n) ||
                   is_series_file(name, prefix, ".R.vtu", n)) :
                  is_series_file(name, prefix, ".vtu", n))
              return true;
          }
      return false;
    }

    /// A checkpoint's own file: rank_DDDD.bin (or its temporary).
    bool
    is_checkpoint_file(const std::string &name)
    {
      return name.rfind("rank_", 0) == 0 && digits(name, 5, 4) &&
             (name.substr(9) == ".bin" || name.substr(9) == ".bin.tmp");
    }

    /// Which of the files of `directory` an earlier run of this program
    /// wrote: the names of its manifest (record_output_file()) that have
    /// our exact names (is_own_output(); a temporary by its final name);
    /// without a manifest (a run of a version before it), every file with
    /// our exact names.
    std::function<bool(const std::string &)>
    own_output_of(const std::filesystem::path &directory)
    {
      std::error_code error;
      const bool      has_manifest =
        std::filesystem::exists(directory / manifest_file_name, error);
      const auto listed = std::make_shared<const std::set<std::string>>(
        read_manifest(directory.string()));
      return [has_manifest, listed](const std::string &name) {
        if (!is_own_output(name))
          return false;
        const bool temporary =
          name.size() > 4 && name.compare(name.size() - 4, 4, ".tmp") == 0;
        return !has_manifest ||
               listed->count(temporary ? name.substr(0, name.size() - 4) :
                                         name) > 0;
      };
    }

    /**
     * Remove an earlier run's files from a subdirectory (checkpoint/: the
     * rank files; vtu/: the VTU pieces its manifest lists), those `own`
     * accepts only, and its manifest, then the subdirectory if that left it
     * empty (a user's file in it stays, and so does the subdirectory).
     */
    void
    remove_own_files(const std::filesystem::path                    &directory,
                     const std::function<bool(const std::string &)> &own)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      for (const auto &entry : fs::directory_iterator(directory, error))
        if (entry.is_regular_file() && own(entry.path().filename().string()))
          {
            fs::remove(entry.path(), error);
            AssertThrow(!error,
                        ExcMessage("Output/Directory: cannot remove the "
                                   "earlier run's " +
                                   entry.path().string() + ": " +
                                   error.message()));
          }
      fs::remove(directory / manifest_file_name, error);
      if (fs::is_empty(directory, error))
        fs::remove(directory, error);
    }

    /// Whether name is one of Accuracy = converged's run directories:
    /// level_N (the input's mesh) or base_NXxNYxNZ_level_N; or an adaptive
    /// mesh's pilot run, adaptive_cycle_N, or its estimate's check,
    /// adaptive_check_NAME.
    bool
    is_convergence_run(const std::string &name)
    {
      const auto number = [&name](std::size_t &at) {
        const std::size_t from = at;
        while (at < name.size() && name[at] >= '0' && name[at] <= '9')
          ++at;
        return at > from;
      };
      std::size_t at = 0;
      if (name == "adaptive_check_contact_zone" ||
          name == "adaptive_check_rest_of_plate" ||
          name == "adaptive_check_time_step")
        return true;
      if (name.rfind("adaptive_cycle_", 0) == 0)
        {
          at = 15;
          return number(at) && at == name.size();
        }
      if (name.rfind("base_", 0) == 0)
        {
          at = 5;
          for (const char separator : {'x', 'x', '_'})
            if (!number(at) || at >= name.size() || name[at++] != separator)
              return false;
        }
      if (name.compare(at, 6, "level_") != 0)
        return false;
      at += 6;
      return number(at) && at == name.size();
    }

    /// Accuracy = converged's convergence/level_N/ and
    /// base_NXxNYxNZ_level_N/: each run's own files (and its vtu/ and
    /// checkpoint*/), then the emptied run and convergence directories (a
    /// user's file keeps its directory).
    void
    remove_convergence_directory(const std::filesystem::path &convergence)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      for (const auto &level : fs::directory_iterator(convergence, error))
        {
          const std::string name = level.path().filename().string();
          if (!level.is_directory() || !is_convergence_run(name))
            continue;
          const auto own = own_output_of(level.path());
          for (const auto &entry : fs::directory_iterator(level.path(), error))
            {
              const std::string file = entry.path().filename().string();
              if (entry.is_directory() &&
                  (file == "vtu" || is_checkpoint_directory(file)))
                remove_own_files(entry.path(),
                                 file == "vtu" ? own_output_of(entry.path()) :
                                                 is_checkpoint_file);
              else if (entry.is_regular_file() && own(file))
                fs::remove(entry.path(), error);
            }
          fs::remove(level.path() / manifest_file_name, error);
          if (fs::is_empty(level.path(), error))
            fs::remove(level.path(), error);
        }
      if (fs::is_empty(convergence, error))
        fs::remove(convergence, error);
    }
  } // namespace



  bool
  is_run_subdirectory(const std::string &name)
  {
    return (name.rfind("case_", 0) == 0 && name.size() > 5 &&
            digits(name, 5, name.size() - 5)) ||
           name == "convergence" || is_convergence_run(name);
  }



  namespace
  {
    /// Create the output directory and check that a byte can be written
    /// there: one byte, written, closed and read back (an empty test file
    /// passes on a full disk).
    void
    create_writable_directory(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      fs::create_directories(directory, error);
      AssertThrow(!error && fs::is_directory(directory),
                  ExcMessage("Output/Directory '" + directory +
                             "' cannot be created: " + error.message()));
      const std::string probe = directory + "/.fgimpact_write_test";
      bool              writable;
      {
        std::ofstream test(probe, std::ios::binary);
        test.put('x');
        test.close();
        writable = !test.fail() && fs::file_size(probe, error) == 1 && !error;
      }
      fs::remove(probe, error);
      AssertThrow(writable,
                  ExcMessage("Output/Directory '" + directory +
                             "' is not writable (a one-byte test file could "
                             "not be written: no permission or disk full)."));
    }

    /// The entries of `directory` this program wrote (files its manifest
    /// lists or named as ours; the vtu, convergence and checkpoint
    /// directories) and the others, the lock and the manifest aside.
    std::pair<std::vector<std::filesystem::path>,
              std::vector<std::filesystem::path>>
    own_and_foreign_entries(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code       error;
      std::vector<fs::path> own, foreign;
      const auto            own_output = own_output_of(directory);
      for (const auto &entry : fs::directory_iterator(directory, error))
        if (entry.path().filename() != lock_file_name &&
            entry.path().filename() != manifest_file_name)
          ((entry.is_regular_file() &&
            own_output(entry.path().filename().string())) ||
               (entry.is_directory() &&
                (is_checkpoint_directory(entry.path().filename().string()) ||
                 entry.path().filename() == "vtu" ||
                 entry.path().filename() == "convergence")) ?
             own :
             foreign)
            .push_back(entry.path());
      return {own, foreign};
    }

    /// A checkpoint directory is replaced as a whole when a checkpoint is
    /// written: one that holds a file of the user's is refused, before
    /// anything is removed.
    void
    refuse_foreign_checkpoint_files(
      const std::string                        &directory,
      const std::vector<std::filesystem::path> &own)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      for (const auto &path : own)
        if (fs::is_directory(path) && path.filename() != "vtu" &&
            path.filename() != "convergence")
          for (const auto &entry : fs::directory_iterator(path, error))
            AssertThrow(
              entry.is_regular_file() &&
                (is_checkpoint_file(entry.path().filename().string()) ||
                 entry.path().filename() == manifest_file_name),
              ExcMessage("Output/Directory '" + directory + "' holds " +
                         entry.path().string() +
                         ", which this program did not write, in the "
                         "directory it replaces with its checkpoints; "
                         "move it or choose another directory."));
    }

    /// Remove exactly this program's files: no stale snapshot or summary
    /// of an earlier run survives next to the new ones.
    void
    remove_earlier_run(const std::vector<std::filesystem::path> &own)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      for (const auto &file : own)
        {
          if (file.filename() == "convergence")
            {
              remove_convergence_directory(file);
              continue;
            }
          if (fs::is_directory(file))
            {
              remove_own_files(file,
                               file.filename() == "vtu" ? own_output_of(file) :
                                                          is_checkpoint_file);
              continue;
            }
          fs::remove(file, error);
          AssertThrow(!error,
                      ExcMessage("Output/Directory: cannot remove the "
                                 "earlier run's " +
                                 file.string() + ": " + error.message()));
        }
    }
  } // namespace



  void
  prepare_output_directory(const OutputParameters &output)
  {
    const std::string directory = output.directory;
    create_writable_directory(directory);
    const auto [own, foreign] = own_and_foreign_entries(directory);
    refuse_foreign_checkpoint_files(directory, own);
    if (!output.overwrite)
      AssertThrow(own.empty() && foreign.empty(),
                  ExcMessage("Output/Directory '" + directory +
                             "' is not empty and Output/Overwrite = false; "
                             "choose an empty directory or set Overwrite = "
                             "true."));
    remove_earlier_run(own);
    // This run's manifest starts empty: the files just removed were the
    // earlier run's; a user's file with our name stays unlisted.
    reset_manifest(directory);
  }


  const char *
  signal_name(const int signal)
  {
    switch (signal)
      {
        case SIGINT:
          return "SIGINT";
        case SIGTERM:
          return "SIGTERM";
        case SIGHUP:
          return "SIGHUP";
        case SIGXFSZ:
          return "SIGXFSZ";
        case SIGUSR1:
          return "SIGUSR1";
        default:
          return "a signal";
      }
  }



  void
  check_output_directory_usable(const std::string &directory)
  {
    namespace fs = std::filesystem;
    const std::string where =
      "Output/Directory '" +
      (directory.size() > 80 ? directory.substr(0, 80) + "..." : directory) +
      "'";
    AssertThrow(directory.size() <= 1024,
                ExcMessage(where + " is longer than 1024 characters (" +
                           std::to_string(directory.size()) + ")."));
    // A newline, tab or NUL in a file name breaks every script and log
    // that lists it.
    AssertThrow(std::none_of(directory.begin(),
                             directory.end(),
                             [](const char c) {
                               const auto byte = static_cast<unsigned char>(c);
                               return byte < 0x20 || byte == 0x7f;
                             }),
                ExcMessage("Output/Directory contains a control character "
                           "(a newline, tab or NUL byte); choose a name "
                           "without one."));
    // The directory, or the nearest ancestor that exists: a directory the
    // program may write into, on a real file system.
    std::error_code error;
    fs::path        path = fs::absolute(directory, error);
    for (;;)
      {
        const auto status = fs::status(path, error);
        if (!error && fs::exists(status))
          {
            AssertThrow(fs::is_directory(status),
                        ExcMessage(where + ": " + path.string() +
                                   " is not a directory."));
            break;
          }
        AssertThrow(!error || error == std::errc::no_such_file_or_directory,
                    ExcMessage(where + " cannot be used: " + error.message() +
                               "."));
        AssertThrow(path.has_parent_path() && path != path.parent_path(),
                    ExcMessage(where + " cannot be created."));
        path = path.parent_path();
      }
    struct statfs file_system;
    const bool    virtual_fs = ::statfs(path.c_str(), &file_system) == 0 &&
                            (file_system.f_type == 0x9fa0 /* proc */ ||
                             file_system.f_type == 0x62656572 /* sysfs */);
    AssertThrow(!virtual_fs && ::access(path.c_str(), W_OK | X_OK) == 0,
                ExcMessage(where + " is not writable (" + path.string() +
                           (virtual_fs ? " is a virtual file system)." :
                                         ": no permission).")));
  }



} // namespace fgimpact
