#include <deal.II/base/utilities.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/stop_signals.h>

#include <chrono>
#include <csignal>
#include <cstring>
#include <iterator>
#include <pthread.h>

namespace fgimpact
{
  namespace
  {
    volatile std::sig_atomic_t stop_signal = 0;
    /// The signals that stop a run cleanly (summary.txt status =
    /// interrupted, a checkpoint): the user's (SIGINT, SIGTERM), a closed
    /// terminal (SIGHUP), a file-size limit (SIGXFSZ, ulimit -f; the
    /// failed write is then reported as such) and SIGUSR1: the signal a
    /// batch system sends before the time limit (Slurm's --signal), and
    /// the one Open MPI's mpirun forwards to every rank and waits for
    /// (SIGTERM to mpirun kills the ranks 1 s later, odls_base_sigkill_-
    /// timeout, before a long set-up or factorization has looked at it).
    const int stop_signals[5] = {SIGINT, SIGTERM, SIGHUP, SIGXFSZ, SIGUSR1};
    struct sigaction previous[5];

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

    /// The watchdog of DeferredStopAction.  Its thread blocks the stop
    /// signals: one sent to the process goes to the main thread's handler
    /// (stop_signal), or, while the main thread defers them
    /// (DeferStopSignals), waits for sigtimedwait() here and is recorded
    /// as the handler would.  Once a signal is recorded, `grace` s later
    /// `action` ends the process unless `done` (the set-up ended: the usual
    /// stop follows).
    void
    watch_setup(const std::function<void(int)> &action,
                const double                    grace,
                const std::atomic<bool>        &done)
    {
      const sigset_t set = stop_signal_set();
      // A short tick: the set-up's end waits for it (join).
      const timespec tick   = {0, 20000000}; // 0.02 s
      double         waited = -1;            // s since the signal
      while (!done)
        {
          const int signal = sigtimedwait(&set, nullptr, &tick);
          if (signal > 0 && stop_signal == 0)
            stop_signal = signal;
          // SIGXFSZ is a failed write, reported as such.
          if (stop_signal == 0 || stop_signal == SIGXFSZ)
            continue;
          if (waited < 0)
            waited = 0;
          else if (signal <= 0)
            waited += 0.02;
          if (waited >= grace)
            {
              action(stop_signal);
              return;
            }
        }
    }

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



  DeferredStopAction::DeferredStopAction(std::function<void(int)> action,
                                         const double             grace)
    : action(std::move(action))
  {
    if (!this->action)
      return;
    // The thread starts with the stop signals blocked (it inherits the
    // mask), so that only sigtimedwait() takes them there.
    const sigset_t set = stop_signal_set();
    sigset_t       old;
    pthread_sigmask(SIG_BLOCK, &set, &old);
    watchdog =
      std::thread(watch_setup, std::cref(this->action), grace, std::cref(done));
    pthread_sigmask(SIG_SETMASK, &old, nullptr);
  }



  DeferredStopAction::~DeferredStopAction()
  {
    done = true;
    if (watchdog.joinable())
      watchdog.join();
  }



  SignalGuard::SignalGuard()
  {
    // No reset of stop_signal: a nested guard (the time loop's) must not
    // lose a signal that came during the set-up.
    struct sigaction action = {};
    action.sa_handler       = on_stop_signal;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESTART;
    for (unsigned int i = 0; i < std::size(stop_signals); ++i)
      sigaction(stop_signals[i], &action, &previous[i]);
    ++guard_depth;
    // The main thread receives them (block_stop_signals_in_new_threads()
    // blocked them for every thread).
    const sigset_t set = stop_signal_set();
    pthread_sigmask(SIG_UNBLOCK, &set, nullptr);
  }



  SignalGuard::~SignalGuard()
  {
    for (unsigned int i = 0; i < std::size(stop_signals); ++i)
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
  ignore_broken_pipe()
  {
    // Output piped into `head`: a write to the closed pipe fails (EPIPE)
    // instead of killing the run; the log's screen copy is then lost, and
    // the files (log.txt, history.csv, summary.txt) go on.
    std::signal(SIGPIPE, SIG_IGN);
  }

} // namespace fgimpact
