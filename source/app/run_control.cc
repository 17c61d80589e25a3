#include <deal.II/base/utilities.h>

#include <deal.II/lac/solver_control.h>

#include <fgimpact/app/run_control.h>
#include <fgimpact/output/checkpoint.h>
#include <fgimpact/output/monitor.h>

#include <csignal>
#include <cstdio>
#include <cstring>
#include <fcntl.h>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <iterator>
#include <mutex>
#include <new>
#include <set>
#include <sstream>
#include <unistd.h>

namespace fgimpact
{
  namespace
  {
    volatile std::sig_atomic_t stop_signal = 0;
    /// The signals that stop a run cleanly (summary.txt status =
    /// interrupted, a checkpoint): the user's (SIGINT, SIGTERM), a closed
    /// terminal (SIGHUP) and a file-size limit (SIGXFSZ, ulimit -f; the
    /// failed write is then reported as such).
    const int        stop_signals[4] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ};
    struct sigaction previous[4];

    extern "C" void
    on_stop_signal(const int signal)
    {
      // SIGXFSZ comes with every write past the file-size limit (the
      // first VTU snapshot writes many): each write fails (EFBIG), which
      // the run reports; it never means "stop now".
      if (signal == SIGXFSZ)
        {
          if (stop_signal == 0)
            stop_signal = signal;
          return;
        }
      // A second signal while the first is being honoured: the default
      // action (the user insists).  signal() and raise() are
      // async-signal-safe.
      if (stop_signal != 0)
        {
          std::signal(signal, SIG_DFL);
          std::raise(signal);
          return;
        }
      stop_signal = signal;
    }



  } // namespace



  namespace
  {
    /// A word (no spaces) of a message longer than this is shortened: a
    /// user's 5 MB value must not become a 5 MB error line.
    constexpr std::size_t max_word_length = 200;

    /// Position near `at` that does not split a UTF-8 character.
    std::size_t
    character_boundary(const std::string &text, std::size_t at)
    {
      while (at > 0 && at < text.size() &&
             (static_cast<unsigned char>(text[at]) & 0xC0) == 0x80)
        --at;
      return at;
    }

    /// The word as printed: its head and tail around the count of the
    /// characters left out.
    std::string
    shortened(const std::string &word)
    {
      if (word.size() <= max_word_length)
        return word;
      const std::size_t head = character_boundary(word, 120);
      const std::size_t tail = character_boundary(word, word.size() - 40);
      return word.substr(0, head) + "[... " + std::to_string(tail - head) +
             " characters left out ...]" + word.substr(tail);
    }
  } // namespace



  std::string
  one_line(const std::string &text)
  {
    std::string out, word;
    const auto  end_word = [&]() {
      if (!word.empty() && !out.empty())
        out += ' ';
      out += shortened(word);
      word.clear();
    };
    for (const char ch : text)
      {
        const auto byte = static_cast<unsigned char>(ch);
        if (ch == '\n' || ch == '\r' || ch == '\t' || ch == ' ')
          end_word();
        else if (byte < 0x20 || byte == 0x7f)
          {
            // A control character (a NUL byte of a file) as \xNN.
            char escaped[8];
            std::snprintf(escaped, sizeof(escaped), "\\x%02X", byte);
            word += escaped;
          }
        else
          word += ch;
      }
    end_word();
    return out;
  }



  std::string
  message_of(const ExceptionBase &e)
  {
    std::ostringstream s;
    e.print_info(s);
    return one_line(s.str());
  }



  int
  report_failure(const std::exception_ptr &failure,
                 const bool                root,
                 const int                 default_code,
                 const std::string        &context)
  {
    std::string text;
    std::string prefix = context + ": ";
    int         code   = default_code;
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const RunInterrupted &e)
      {
        text   = e.message;
        prefix = "";
        code   = 128 + e.signal;
      }
    catch (const SolverControl::NoConvergence &e)
      {
        // deal.II's text is several sentences; the caller did not say
        // where, so name the parameters.
        text = "the linear solver did not converge after " +
               std::to_string(e.last_step) +
               " iterations; raise Linear solver/Max iterations or use a "
               "direct Linear solver/Type.";
        code = 2;
      }
    catch (const ExcNumericalFailure &e)
      {
        text = message_of(e);
        code = 2;
      }
    catch (const ExcOutputFailure &e)
      {
        text = message_of(e);
        code = 2;
      }
    catch (const ExcResumeRefused &e)
      {
        text = message_of(e);
        code = 1;
      }
    catch (const ExceptionBase &e)
      {
        text = message_of(e);
      }
    catch (const std::bad_alloc &)
      {
        text = "out of memory (std::bad_alloc); use coarser Geometry/"
               "Subdivisions or more MPI ranks.";
        code = 2;
      }
    catch (const std::exception &e)
      {
        text = one_line(e.what());
      }
    catch (...)
      {
        text = "unknown exception.";
      }
    if (root)
      std::cerr << "fgimpact: " << prefix << text << std::endl;
    return code;
  }



  bool
  is_run_failure(const std::exception_ptr &failure)
  {
    try
      {
        std::rethrow_exception(failure);
      }
    catch (const SolverControl::NoConvergence &)
      {
        return true;
      }
    catch (const ExcNumericalFailure &)
      {
        return true;
      }
    catch (const ExcOutputFailure &)
      {
        return true;
      }
    catch (const std::bad_alloc &)
      {
        return true;
      }
    catch (...)
      {
        return false;
      }
  }



  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &f)
  {
    // The outcome as a string: its first character is the kind.
    std::string failure = "0";
    if (Utilities::MPI::this_mpi_process(comm) == 0)
      try
        {
          f();
        }
      catch (const ExcOutputFailure &e)
        {
          failure = "2" + message_of(e);
        }
      catch (const ExceptionBase &e)
        {
          failure = "1" + message_of(e);
        }
      catch (const std::exception &e)
        {
          failure = "1" + one_line(e.what());
        }
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      failure = Utilities::MPI::broadcast(comm, failure, 0);
    AssertThrow(failure[0] != '2', ExcOutputFailure(failure.substr(1)));
    AssertThrow(failure[0] != '1', ExcMessage(failure.substr(1)));
  }



  namespace
  {
    /// The stop signals as a set.
    sigset_t
    stop_signal_set()
    {
      sigset_t set;
      sigemptyset(&set);
      for (const int s : stop_signals)
        sigaddset(&set, s);
      return set;
    }

    /// Whether a SignalGuard is active (its handler is to be put back).
    int guard_depth = 0;

    void
    install_stop_handler()
    {
      struct sigaction action = {};
      action.sa_handler       = on_stop_signal;
      sigemptyset(&action.sa_mask);
      action.sa_flags = SA_RESTART;
      for (const int s : stop_signals)
        sigaction(s, &action, nullptr);
    }
  } // namespace



  void
  block_stop_signals_in_new_threads()
  {
    const sigset_t set = stop_signal_set();
    pthread_sigmask(SIG_BLOCK, &set, nullptr);
  }



  DeferStopSignals::DeferStopSignals()
  {
    const sigset_t set = stop_signal_set();
    pthread_sigmask(SIG_BLOCK, &set, &previous_mask);
  }



  DeferStopSignals::~DeferStopSignals()
  {
    if (guard_depth > 0)
      install_stop_handler();
    pthread_sigmask(SIG_SETMASK, &previous_mask, nullptr);
  }



  SignalGuard::SignalGuard()
  {
    // No reset of stop_signal: a nested guard (the time loop's) must not
    // lose a signal that came during the set-up.
    struct sigaction action = {};
    action.sa_handler       = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (unsigned int i = 0; i < 4; ++i)
      sigaction(stop_signals[i], &action, &previous[i]);
    ++guard_depth;
    // The main thread receives them (block_stop_signals_in_new_threads()
    // blocked them for every thread).
    const sigset_t set = stop_signal_set();
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  }



  SignalGuard::~SignalGuard()
  {
    for (unsigned int i = 0; i < 4; ++i)
      sigaction(stop_signals[i], &previous[i], nullptr);
    --guard_depth;
  }



  int
  agreed_stop(const MPI_Comm comm, const bool local_failure)
  {
    // Signal numbers are below 1000.
    int code = local_failure ? 1000 : static_cast<int>(stop_signal);
    if (Utilities::MPI::n_mpi_processes(comm) > 1)
      code = Utilities::MPI::max(code, comm);
    return code >= 1000 ? -1 : code;
  }


  void
  throw_if_stop_signal(const MPI_Comm comm, const std::string &what)
  {
    const int stop = agreed_stop(comm, false);
    if (stop > 0)
      throw RunInterrupted(stop,
                           std::string("interrupted by ") + signal_name(stop) +
                             " " + what);
  }



  void
  write_file_atomically(const std::string &filename, const std::string &text)
  {
    record_output_file(filename);
    const std::string temporary = filename + ".tmp";
    bool              ok        = false;
    {
      std::ofstream out(temporary, std::ios::binary);
      out.write(text.data(), text.size());
      out.flush();
      out.close();
      ok = !out.fail();
    }
    ok = ok && std::rename(temporary.c_str(), filename.c_str()) == 0;
    if (!ok)
      {
        std::remove(temporary.c_str());
        AssertThrow(false,
                    ExcOutputFailure("cannot write " + filename +
                                     " (disk full or I/O error)."));
      }
  }



  namespace
  {
    /// The files this process has recorded (record_output_file()).
    std::mutex &
    manifest_mutex()
    {
      static std::mutex mutex;
      return mutex;
    }

    std::set<std::string> &
    recorded_files()
    {
      static std::set<std::string> files;
      return files;
    }

    /// The directories whose manifest recorded_files() holds: a resumed
    /// run appends only what its killed predecessor did not list.
    std::set<std::string> &
    loaded_manifests()
    {
      static std::set<std::string> directories;
      return directories;
    }
  } // namespace



  void
  record_output_file(const std::string &path)
  {
    namespace fs        = std::filesystem;
    const fs::path file = fs::absolute(path).lexically_normal();
    const std::lock_guard<std::mutex> guard(manifest_mutex());
    if (loaded_manifests().insert(file.parent_path().string()).second)
      for (const auto &name : read_manifest(file.parent_path().string()))
        recorded_files().insert((file.parent_path() / name).string());
    if (!recorded_files().insert(file.string()).second)
      return;
    const std::string manifest =
      (file.parent_path() / manifest_file_name).string();
    const std::string line = file.filename().string() + "\n";
    const int         fd =
      ::open(manifest.c_str(),
             O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC | O_NOFOLLOW,
             0644);
    const bool written = fd >= 0 && ::write(fd, line.data(), line.size()) ==
                                      static_cast<ssize_t>(line.size());
    if (fd >= 0)
      ::close(fd);
    if (!written)
      {
        recorded_files().erase(file.string());
        AssertThrow(false,
                    ExcOutputFailure("cannot write " + manifest +
                                     " (disk full or I/O error)."));
      }
  }



  std::set<std::string>
  read_manifest(const std::string &directory)
  {
    std::set<std::string> names;
    std::ifstream         in(directory + "/" + manifest_file_name);
    for (std::string line; std::getline(in, line);)
      if (!line.empty())
        names.insert(line);
    return names;
  }



  void
  reset_manifest(const std::string &directory)
  {
    namespace fs        = std::filesystem;
    const fs::path path = fs::absolute(directory).lexically_normal();
    const std::lock_guard<std::mutex> guard(manifest_mutex());
    auto                             &files = recorded_files();
    for (auto it = files.begin(); it != files.end();)
      it =
        fs::path(*it).parent_path() == path ? files.erase(it) : std::next(it);
    loaded_manifests().insert(path.string()); // empty from now on
    std::error_code error;
    fs::remove(path / manifest_file_name, error);
  }



  void
  ignore_broken_pipe()
  {
    // Output piped into `head`: a write to the closed pipe fails (EPIPE)
    // instead of killing the run; the log's screen copy is then lost, and
    // the files (log.txt, history.csv, summary.txt) go on.
    std::signal(SIGPIPE, SIG_IGN);
  }


} // namespace fgimpact
