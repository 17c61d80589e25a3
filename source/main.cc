// fgimpact: low-velocity impact of a sphere on a functionally graded plate,
// 3D elasticity with graded finite elements (Asemi & Salami 2015).  This
// file starts MPI, guards the signals and dispatches the command line; the
// run itself is fgimpact::run_from_command_line() (app/run.h).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/app/command_line.h>
#include <fgimpact/app/run.h>
#include <fgimpact/base/logger.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/problem/parameters.h>

#include <iostream>

namespace
{
  /**
   * Options that finish the program (help, version, printing the defaults,
   * a bad command line): the exit code; -1 to go on.
   */
  int
  handle_informational(const fgimpact::CommandLine::Options &options,
                       const bool                            root)
  {
    using namespace fgimpact::CommandLine;
    if (options.action == Action::run || options.action == Action::validate)
      return -1;
    if (!root)
      return options.action == Action::error ? 1 : 0;
    switch (options.action)
      {
        case Action::help:
          std::cout << usage();
          return 0;
        case Action::version:
          std::cout << version_text();
          return 0;
        case Action::print_parameters:
          {
            dealii::ParameterHandler prm;
            fgimpact::Parameters::declare_parameters(prm);
            fgimpact::CommandLine::print_parameters(prm, std::cout);
            return 0;
          }
        case Action::error:
          std::cerr << "fgimpact: error: " << options.error
                    << " (see fgimpact --help)\n"
                    << (options.show_usage ? usage() : "");
          return 1;
        default:
          return -1;
      }
  }
} // namespace



int
main(int argc, char *argv[])
{
  using namespace dealii;
  using namespace fgimpact;

  // Before any thread exists (MPI's, the thread pools'): the stop signals
  // go to the main thread only (its SignalGuard below unblocks them).
  block_stop_signals_in_new_threads();
  CommandLine::prepare_mpi_environment();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  // After MPI's start-up, which may install handlers of its own.
  ignore_broken_pipe();
  // From here on SIGINT, SIGTERM, SIGHUP, SIGXFSZ and SIGUSR1 only set a flag,
  // which the set-up, the time loop and the static and modal solves look at: no
  // signal is lost, and every run that ends has a summary.txt.
  const SignalGuard signals;
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  Logger     logger(root);

  const CommandLine::Options options   = CommandLine::parse(argc, argv);
  const int                  exit_code = handle_informational(options, root);
  if (exit_code >= 0)
    return exit_code;

  return run_from_command_line(options, argc, argv, logger);
}
