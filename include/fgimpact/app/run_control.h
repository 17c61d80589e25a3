#ifndef fgimpact_run_control_h
#define fgimpact_run_control_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <csignal>
#include <exception>
#include <functional>
#include <set>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  struct OutputParameters;

  /**
   * @name What a run does when it cannot go on
   *
   * Exit codes of the executable: 0 completed, 1 bad input (nothing
   * written), 2 numerical or I/O failure during set-up or the run (with
   * summary.txt marked failed where it can be written), 128 + signal
   * number when SIGINT or SIGTERM stopped the time loop.
   */
  /** @{ */

  /// A numerical failure (solver not converging, blow-up): exit code 2 even
  /// when it happens during set-up.  The text is one line naming the phase
  /// or the time step and the parameter to change.
  DeclException1(ExcNumericalFailure, std::string, << arg1);

  /// A file that could not be written completely (disk full, I/O error):
  /// one line naming the file.
  DeclException1(ExcOutputFailure, std::string, << arg1);

  /// A --resume whose output files cannot be continued (one shorter than
  /// at the checkpoint, say): exit code 1, like bad input, and every file
  /// left as it was.
  DeclException1(ExcResumeRefused, std::string, << arg1);

  /// Thrown by the time loop after SIGINT or SIGTERM, once history.csv,
  /// summary.txt (status = interrupted) and the PVD are complete.
  struct RunInterrupted : public std::exception
  {
    RunInterrupted(const int signal, const std::string &message)
      : signal(signal)
      , message(message)
    {}

    const char *
    what() const noexcept override
    {
      return message.c_str();
    }

    int         signal;
    std::string message;
  };

  /**
   * The one-line report of the exception on its way out of main() (on
   * rank 0 only if root is false nothing is printed) and the exit code:
   * RunInterrupted -> 128 + signal, ExcNumericalFailure, ExcOutputFailure
   * and SolverControl::NoConvergence -> 2, anything else -> default_code.
   * context goes before the message ("error", "error in file.prm").
   */
  int
  report_failure(const std::exception_ptr &failure,
                 const bool                root,
                 const int                 default_code,
                 const std::string        &context = "error");

  /// Whether the failure is one of a valid run (numerical, I/O, out of
  /// memory: exit code 2, with summary.txt marked failed) rather than bad
  /// input (exit code 1, nothing written).
  bool
  is_run_failure(const std::exception_ptr &failure);

  /// Collapse a multi-line text (deal.II's exception texts) into one line.
  std::string
  one_line(const std::string &text);

  /// The text of a deal.II exception (without the source location and
  /// stack trace of print_info's caller), in one line.
  std::string
  message_of(const ExceptionBase &e);

  /// Run f on rank 0 of comm only and rethrow its failure on every rank (an
  /// ExcOutputFailure as such, anything else as ExcMessage), so that all
  /// ranks stop together.
  void
  run_on_root(const MPI_Comm comm, const std::function<void()> &f);
  /** @} */



  /**
   * @name Signals
   *
   * While a SignalGuard lives, SIGINT, SIGTERM, SIGHUP (the terminal
   * closed) and SIGXFSZ (ulimit -f) only set a flag (the
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



  /**
   * @name Files never half-written
   */
  /** @{ */

  /// Write text to filename through filename.tmp and a rename, checking
  /// every step; throws ExcOutputFailure naming the file.
  void
  write_file_atomically(const std::string &filename, const std::string &text);

  /// The lock file of an output directory (lock_output_directory()).
  inline constexpr const char *lock_file_name = ".fgimpact.lock";

  /// The manifest of a directory this program writes into: the names of
  /// the files its runs wrote there, one per line (record_output_file()).
  inline constexpr const char *manifest_file_name = ".fgimpact.files";

  /**
   * Note, before it is created, that this run writes `path`: its name is
   * appended (once per process) to the manifest of the directory that
   * holds it.  The cleaning of a later run with Output/Overwrite removes
   * the files a manifest lists and no other (a user's file named like
   * ours stays).  Thread-safe; a manifest that cannot be written throws
   * ExcOutputFailure naming it.
   */
  void
  record_output_file(const std::string &path);

  /// The names the manifest of `directory` lists; empty if it has none.
  std::set<std::string>
  read_manifest(const std::string &directory);

  /// Start the manifest of `directory` afresh (a new run, after cleaning).
  void
  reset_manifest(const std::string &directory);

  /**
   * One writer per output directory: create it if needed and take an
   * exclusive advisory lock (flock) on its lock file, held until this
   * process ends (the kernel releases it on any death), with the process
   * id in the file.  A directory another process holds: ExcMessage naming
   * Output/Directory and the holder's process id.  Call on one rank before
   * anything is written there (a fresh run or a resume).
   */
  void
  lock_output_directory(const std::string &directory);

  /// Whether name is a directory this program writes runs into, inside an
  /// output directory: a study's case_N, Accuracy = converged's
  /// convergence and its level_N or base_NXxNYxNZ_level_N.
  bool
  is_run_subdirectory(const std::string &name);

  /// Before the set-up: refuse at once (ExcMessage, as
  /// lock_output_directory()) a directory another process holds; writes
  /// nothing.  lock_output_directory() takes the lock later.
  void
  check_output_directory_free(const std::string &directory);

  /**
   * Before the set-up (and with --validate): refuse an output directory
   * that cannot be used, writing nothing: a name longer than 1024
   * characters, a path through a file or a symbolic-link loop, a
   * directory (or the nearest existing ancestor) that is not writable or
   * on a virtual file system (/proc, /sys).  ExcMessage naming
   * Output/Directory.
   */
  void
  check_output_directory_usable(const std::string &directory);

  /**
   * Create the output directory, check that a byte can be written there,
   * and clean it: with Output/Overwrite remove exactly the files this
   * program writes, by their exact names (history.csv, summary.txt,
   * parameters.prm, input.prm, log.txt, frequencies.csv, study.csv, the
   * PVD files, solution_DDDDD.pvtu, solution_DDDDD.R.vtu,
   * sphere_DDDDD.vtu, contact_DDDDD.vtu, peak_fields.pvtu and .R.vtu,
   * leftover *.tmp, and the rank_DDDD.bin files of the checkpoint
   * directories, which go only if nothing else is in them), otherwise
   * refuse a non-empty directory (the lock file aside).  Call on one rank,
   * before the run opens its log.txt there; throws ExcMessage naming
   * Output/Directory or Output/Overwrite.
   */
  void
  prepare_output_directory(const OutputParameters &output);
  /** @} */
} // namespace fgimpact

#endif
