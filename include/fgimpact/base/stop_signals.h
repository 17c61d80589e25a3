#ifndef fgimpact_base_stop_signals_h
#define fgimpact_base_stop_signals_h

#include <deal.II/base/mpi.h>

#include <atomic>
#include <csignal>
#include <functional>
#include <string>
#include <thread>

namespace fgimpact
{
  using namespace dealii;



  /**
   * @name Signals
   *
   * While a SignalGuard lives, SIGINT, SIGTERM, SIGHUP (the terminal
   * closed), SIGXFSZ (ulimit -f) and SIGUSR1 (a batch system's warning
   * before the time limit; mpirun forwards it to every rank and waits, as
   * it does not for SIGTERM) only set a flag (the
   * handler does nothing else, so it is async-signal-safe); the time loop
   * asks agreed_signal() once per step and stops cleanly.  The previous
   * handlers come back when the guard is destroyed.
   */
  /** @{ */
  /**
   * The stop signals blocked in the calling thread while this lives (a
   * signal then waits), and our handler put back before they are unblocked:
   * around library code that installs handlers of its own (METIS traps
   * SIGTERM and swallows it, and restores a one-shot handler).  Together
   * with block_stop_signals_in_new_threads(), no other thread receives
   * them meanwhile.
   */
  class DeferStopSignals
  {
  public:
    DeferStopSignals();
    ~DeferStopSignals();
    DeferStopSignals(const DeferStopSignals &) = delete;
    DeferStopSignals &
    operator=(const DeferStopSignals &) = delete;

  private:
    sigset_t previous_mask;
  };

  /**
   * While this lives, a stop signal that the code does not act on within
   * `grace` seconds is handed to `action` on a watchdog thread; action
   * must end the process (std::_Exit).  For the set-up of a run on one
   * rank, which looks at the signal only at its end and where nothing is
   * computed yet that a later step could save: its assembly and its
   * solver's set-up (ML's aggregation, CHOLMOD's analysis, with the
   * signals deferred: DeferStopSignals) held a SIGTERM for 4 minutes on a
   * 2.5 M DoF plate.  The signal stays recorded (agreed_stop()), so that a
   * set-up ending in time is followed by the usual clean stop.  An empty
   * action installs nothing.
   */
  class DeferredStopAction
  {
  public:
    DeferredStopAction(std::function<void(int)> action,
                       const double             grace_seconds = 2.);
    ~DeferredStopAction();

    DeferredStopAction(const DeferredStopAction &) = delete;
    DeferredStopAction &
    operator=(const DeferredStopAction &) = delete;

  private:
    std::function<void(int)> action;
    std::atomic<bool>        done{false};
    std::thread              watchdog;
  };

  /// At the start of main(), before MPI and the thread pools start: the
  /// stop signals blocked in every thread created from then on, so that
  /// only the main thread (whose SignalGuard unblocks them) receives them.
  void
  block_stop_signals_in_new_threads();

  /// "SIGTERM", ... for the stop signals, else "a signal".
  const char *
  signal_name(const int signal);

  /// SIGPIPE ignored for the whole process (stdout piped into a program
  /// that exits: the run goes on writing its files).
  void
  ignore_broken_pipe();

  class SignalGuard
  {
  public:
    SignalGuard();
    ~SignalGuard();
    SignalGuard(const SignalGuard &) = delete;
    SignalGuard &
    operator=(const SignalGuard &) = delete;
  };

  /**
   * Whether the time loop must stop, agreed over the ranks of comm (one
   * all-reduce of an int, none on one rank), so that all ranks stop at the
   * same step: -1 if local_failure is true on any rank (a failed output
   * write), else the signal received on any rank since the SignalGuard was
   * made, 0 if none.
   */
  int
  agreed_stop(const MPI_Comm comm, const bool local_failure);

  /// A stop signal received on any rank of comm (agreed_stop()): throws
  /// RunInterrupted with "interrupted by SIGNAL " + what, on every rank.
  void
  throw_if_stop_signal(const MPI_Comm comm, const std::string &what);
  /** @} */
} // namespace fgimpact

#endif
