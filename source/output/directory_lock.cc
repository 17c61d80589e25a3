// One writer per output directory: the lock file (flock), and the runs in
// directories above or inside another's (a study's case).  Declared in
// output_directory.h.

#include <deal.II/base/exceptions.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/output/output_directory.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <sys/file.h>
#include <sys/stat.h>
#include <unistd.h>

namespace fgimpact
{
  namespace
  {
    /// Close fd (a lock file another process holds) and throw the one
    /// line naming the directory and the holder's process id (in the file).
    /// holder: the directory whose lock is held, if not `directory` itself
    /// (one above it or inside it).
    [[noreturn]] void
    refuse_busy(const std::string &directory,
                const int          fd,
                const std::string &holder = "")
    {
      char          pid[32] = {};
      const ssize_t n       = ::read(fd, pid, sizeof(pid) - 1);
      ::close(fd);
      const std::string id =
        "process id " +
        (n > 0 ? one_line(std::string(pid, n)) : std::string("unknown"));
      AssertThrow(holder.empty(),
                  ExcMessage("Output/Directory '" + directory + "' overlaps '" +
                             holder +
                             "', the output directory of another fgimpact "
                             "run (" +
                             id +
                             "), which may clean or write it; wait for it to "
                             "end or choose a directory outside it."));
      AssertThrow(false,
                  ExcMessage("Output/Directory '" + directory +
                             "' is in use by another fgimpact run (" + id +
                             "); wait for it to end or choose another "
                             "directory."));
      std::abort(); // not reached
    }

    /// The refusal of a lock file that is a symbolic link (it would be
    /// written through, into whatever file it points to).
    std::string
    symbolic_link_lock(const std::string &directory)
    {
      return "Output/Directory '" + directory + "': its lock file " +
             lock_file_name +
             " is a symbolic link; remove it (the lock is never written "
             "through a link).";
    }



    /// The lock files this process holds (directory -> descriptor): one
    /// writer per output directory.
    std::map<std::string, int> &
    held_locks()
    {
      static std::map<std::string, int> locks;
      return locks;
    }

    /// Refuse when another process holds the lock of `holder`, a directory
    /// above or inside `directory` through which the two runs overlap:
    /// probed with a descriptor of our own, a lock this process holds (a
    /// study's, for its cases) skipped first.
    void
    refuse_if_held_elsewhere(const std::string           &directory,
                             const std::filesystem::path &holder)
    {
      std::error_code   error;
      const std::string key =
        std::filesystem::weakly_canonical(holder, error).string();
      if (held_locks().count(key) > 0)
        return;
      const std::string name = (holder / lock_file_name).string();
      const int         fd =
        ::open(name.c_str(), O_RDONLY | O_CLOEXEC | O_NOFOLLOW | O_NONBLOCK);
      if (fd < 0)
        return;
      struct stat status;
      if (::fstat(fd, &status) == 0 && S_ISREG(status.st_mode) &&
          ::flock(fd, LOCK_EX | LOCK_NB) != 0)
        refuse_busy(directory, fd, holder.string());
      ::close(fd);
    }

    /// Runs that write into each other's directory: one above `directory`
    /// whose path to it passes a run subdirectory (a study in out, this run
    /// in out/case_001), or one in a run subdirectory of `directory` (a
    /// case or a level, down to out/case_N/convergence/level_N).  Unrelated
    /// runs in nested directories (a run in ~ and one in ~/plate) go on.
    void
    refuse_nested_runs(const std::string &directory)
    {
      namespace fs = std::filesystem;
      std::error_code error;
      const fs::path  path = fs::weakly_canonical(directory, error);
      if (error)
        return;
      for (fs::path up = path.parent_path(); !up.empty(); up = up.parent_path())
        {
          const fs::path relative = path.lexically_relative(up);
          if (!relative.empty() &&
              is_run_subdirectory(relative.begin()->string()))
            refuse_if_held_elsewhere(directory, up);
          if (up == up.root_path())
            break;
        }
      const std::function<void(const fs::path &, unsigned int)> inside =
        [&](const fs::path &parent, const unsigned int depth) {
          std::error_code list_error;
          for (const auto &entry : fs::directory_iterator(parent, list_error))
            if (entry.is_directory(list_error) &&
                !entry.is_symlink(list_error) &&
                is_run_subdirectory(entry.path().filename().string()))
              {
                refuse_if_held_elsewhere(directory, entry.path());
                if (depth < 3)
                  inside(entry.path(), depth + 1);
              }
        };
      inside(path, 1);
    }
  } // namespace



  void
  check_output_directory_free(const std::string &directory)
  {
    const std::string name = directory + "/" + lock_file_name;
    const int fd = ::open(name.c_str(), O_RDWR | O_CLOEXEC | O_NOFOLLOW);
    AssertThrow(fd >= 0 || errno != ELOOP,
                ExcMessage(symbolic_link_lock(directory)));
    if (fd >= 0)
      {
        // A lock file: a run was there; refused if it is still running.
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
          refuse_busy(directory, fd);
        ::close(fd); // releases the probe's lock
      }
    refuse_nested_runs(directory);
  }



  namespace
  {
    /// The lock file `name` of `directory`, opened (created if missing) and
    /// checked to be a regular file, not a link: its descriptor.
    int
    open_lock_file(const std::string &directory, const std::string &name)
    {
      // O_NOFOLLOW: a lock file that is a symbolic link (to a user's file,
      // say) is refused, never written through; so is one that is not a
      // regular file.
      const int fd =
        ::open(name.c_str(), O_RDWR | O_CREAT | O_CLOEXEC | O_NOFOLLOW, 0644);
      AssertThrow(fd >= 0 || errno != ELOOP,
                  ExcMessage(symbolic_link_lock(directory)));
      AssertThrow(fd >= 0,
                  ExcMessage("Output/Directory '" + directory +
                             "': cannot create the lock file " + name + ": " +
                             std::strerror(errno)));
      struct stat lock_status;
      if (::fstat(fd, &lock_status) != 0 || !S_ISREG(lock_status.st_mode))
        {
          ::close(fd);
          AssertThrow(false,
                      ExcMessage("Output/Directory '" + directory +
                                 "': the lock file " + name +
                                 " is not a regular file; remove it."));
        }
      return fd;
    }

    /// Whether the locked descriptor fd is still the file `name`: a run
    /// that ends removes its lock file, so a lock taken on a file opened
    /// just before that removal locks nothing anyone else sees.
    bool
    is_linked_as(const int fd, const std::string &name)
    {
      struct stat held, linked;
      return ::fstat(fd, &held) == 0 && ::stat(name.c_str(), &linked) == 0 &&
             held.st_dev == linked.st_dev && held.st_ino == linked.st_ino;
    }
  } // namespace



  void
  lock_output_directory(const std::string &directory)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::create_directories(directory, error);
    const std::string key = fs::weakly_canonical(directory, error).string();
    if (held_locks().count(key) > 0)
      return; // this process holds it already (a study's directory)
    const std::string name = directory + "/" + lock_file_name;
    int               fd   = -1;
    // Retried while the file locked was removed in between by the run that
    // held it (it ends): the lock must be on the file the next run opens.
    for (unsigned int attempt = 0; fd < 0; ++attempt)
      {
        fd = open_lock_file(directory, name);
        if (::flock(fd, LOCK_EX | LOCK_NB) != 0)
          refuse_busy(directory, fd);
        if (!is_linked_as(fd, name) && attempt < 100)
          {
            ::close(fd);
            fd = -1;
          }
      }
    // Locked first, then the directories above and inside looked at: of two
    // nested runs starting at once, at least one sees the other's lock.
    try
      {
        refuse_nested_runs(directory);
      }
    catch (...)
      {
        ::close(fd);
        throw;
      }
    // The holder's process id, for the message above; the kernel releases
    // the lock when this process ends, however it ends, and
    // release_output_directory_locks() removes the file at the end.
    const std::string pid = std::to_string(::getpid()) + "\n";
    if (::ftruncate(fd, 0) != 0 || ::write(fd, pid.data(), pid.size()) < 0)
      {
        // The lock holds without the id.
      }
    held_locks()[key] = fd;
  }



  void
  release_output_directory_locks()
  {
    for (const auto &[directory, fd] : held_locks())
      {
        // Removed while still locked, and only if it is still our file: a
        // run waiting on it retries on a new one (lock_output_directory()).
        const std::string name = directory + "/" + lock_file_name;
        if (is_linked_as(fd, name))
          ::unlink(name.c_str());
        ::close(fd);
      }
    held_locks().clear();
  }
} // namespace fgimpact
