#ifndef fgimpact_base_exceptions_h
#define fgimpact_base_exceptions_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/mpi.h>

#include <exception>
#include <functional>
#include <string>

namespace fgimpact
{
  using namespace dealii;

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

  /// The one line report_failure() prints for the exception (without its
  /// context): a study case's failure reason is the same text.
  std::string
  failure_message(const std::exception_ptr &failure);

  /// The one-line failure of an iterative linear solver that stopped after
  /// `iterations` without converging `where` ("at time step 12 (t = 24
  /// us)", "during set-up (...)"; empty: nowhere said): the two entries
  /// to change.
  ExcNumericalFailure
  linear_solver_failure(const std::string &where,
                        const unsigned int iterations);

  /// Whether the failure is one of a valid run (numerical, I/O, out of
  /// memory: exit code 2, with summary.txt marked failed) rather than bad
  /// input (exit code 1, nothing written).
  bool
  is_run_failure(const std::exception_ptr &failure);

  /// Whether the failure is numerical (ExcNumericalFailure: a run that blew
  /// up, a Newton iteration that diverged, a factorization that failed).
  bool
  is_numerical_failure(const std::exception_ptr &failure);

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
} // namespace fgimpact

#endif
