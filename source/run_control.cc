#include <deal.II/base/utilities.h>

#include <deal.II/lac/solver_control.h>

#include <fgimpact/checkpoint.h>
#include <fgimpact/monitor.h>
#include <fgimpact/run_control.h>

#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <new>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    volatile std::sig_atomic_t stop_signal = 0;
    struct sigaction           previous_int, previous_term;

    extern "C" void
    on_stop_signal(const int signal)
    {
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



    /// The files this program writes into the output directory.
    bool
    is_own_output(std::string name)
    {
      const auto ends_with = [](const std::string &s, const std::string &end) {
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
          name == "peak_fields.pvtu")
        return true;
      for (const std::string series :
           {"solution_", "sphere_", "contact_", "peak_fields."})
        if (name.rfind(series, 0) == 0 &&
            (ends_with(name, ".vtu") || ends_with(name, ".pvtu")))
          return true;
      return false;
    }
  } // namespace



  std::string
  one_line(const std::string &text)
  {
    std::string out;
    bool        space = false;
    for (const char ch : text)
      {
        if (ch == '\n' || ch == '\r' || ch == '\t' || ch == ' ')
          space = !out.empty();
        else
          {
            if (space)
              out += ' ';
            out += ch;
            space = false;
          }
      }
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



  SignalGuard::SignalGuard()
  {
    stop_signal             = 0;
    struct sigaction action = {};
    action.sa_handler       = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    sigaction(SIGINT, &action, &previous_int);
    sigaction(SIGTERM, &action, &previous_term);
  }



  SignalGuard::~SignalGuard()
  {
    sigaction(SIGINT, &previous_int, nullptr);
    sigaction(SIGTERM, &previous_term, nullptr);
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
  raise_stop_flag(const int signal)
  {
    stop_signal = signal;
  }



  void
  write_file_atomically(const std::string &filename, const std::string &text)
  {
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



  void
  prepare_output_directory(const OutputParameters &output)
  {
    namespace fs                = std::filesystem;
    const std::string directory = output.directory;
    std::error_code   error;
    fs::create_directories(directory, error);
    AssertThrow(!error && fs::is_directory(directory),
                ExcMessage("Output/Directory '" + directory +
                           "' cannot be created: " + error.message()));

    // One byte, written, closed and read back: an empty test file passes
    // on a full disk.
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

    std::vector<fs::path> own, foreign;
    for (const auto &entry : fs::directory_iterator(directory, error))
      ((entry.is_regular_file() &&
        is_own_output(entry.path().filename().string())) ||
           (entry.is_directory() &&
            is_checkpoint_directory(entry.path().filename().string())) ?
         own :
         foreign)
        .push_back(entry.path());
    if (!output.overwrite)
      AssertThrow(own.empty() && foreign.empty(),
                  ExcMessage("Output/Directory '" + directory +
                             "' is not empty and Output/Overwrite = false; "
                             "choose an empty directory or set Overwrite = "
                             "true."));
    // Exactly this program's files: no stale snapshot or summary of an
    // earlier run survives next to the new ones.
    for (const auto &file : own)
      {
        fs::remove_all(file, error); // checkpoint/ is a directory
        AssertThrow(!error,
                    ExcMessage("Output/Directory: cannot remove the earlier "
                               "run's " +
                               file.string() + ": " + error.message()));
      }
  }
} // namespace fgimpact
