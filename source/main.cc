// fgimpact: low-velocity impact of a sphere on a functionally graded plate,
// 3D elasticity with graded finite elements (Asemi & Salami 2015).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fgimpact/run_control.h>
#include <fgimpact/simulator.h>

#include <iostream>
#include <sstream>
#include <string>

namespace
{
  const char *usage =
    "Usage: fgimpact [options] [parameter_file.prm]\n"
    "\n"
    "Simulates a sphere striking a functionally graded plate (3D elasticity,\n"
    "graded 8-node bricks, modified Hertz contact, Newmark + Newton) and\n"
    "writes history.csv, summary.txt, parameters.prm and optional VTU/PVD\n"
    "files into the output directory named in the parameter file.\n"
    "Without a parameter file the documented defaults are used.\n"
    "\n"
    "Options:\n"
    "  -h, --help              print this text and exit\n"
    "  -p, --print-parameters  print the full documented default .prm and "
    "exit\n";

  /**
   * The options and the parameter file's name.  Returns the exit code if
   * the program is done (help, parameters printed, a bad option), -1 to
   * run.
   */
  int
  parse_command_line(const int    argc,
                     char        *argv[],
                     const bool   root,
                     std::string &prm_file)
  {
    using namespace dealii;
    for (int i = 1; i < argc; ++i)
      {
        const std::string arg = argv[i];
        if (arg == "-h" || arg == "--help")
          {
            if (root)
              std::cout << usage;
            return 0;
          }
        else if (arg == "-p" || arg == "--print-parameters")
          {
            ParameterHandler prm;
            fgimpact::Parameters::declare_parameters(prm);
            if (root)
              prm.print_parameters(std::cout, ParameterHandler::PRM);
            return 0;
          }
        else if (!arg.empty() && arg[0] == '-')
          {
            if (root)
              std::cerr << "fgimpact: error: unknown option '" << arg
                        << "' (see fgimpact --help)\n";
            return 1;
          }
        else if (prm_file.empty())
          prm_file = arg;
        else
          {
            if (root)
              std::cerr
                << "fgimpact: error: more than one parameter file given\n";
            return 1;
          }
      }
    return -1;
  }
} // namespace



int
main(int argc, char *argv[])
{
  using namespace dealii;
  using namespace fgimpact;

  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;

  std::string prm_file;
  const int   exit_code = parse_command_line(argc, argv, root, prm_file);
  if (exit_code >= 0)
    return exit_code;

  ParameterHandler     prm;
  fgimpact::Parameters parameters;
  // Input errors: everything is checked before any file is written.
  // Failures are reported in one line with their exit code by
  // report_failure() (source/run_control.cc).
  try
    {
      Parameters::declare_parameters(prm);
      if (!prm_file.empty())
        read_parameter_file(prm, prm_file);
      parameters.parse_parameters(prm);
      parameters.validate();
      for (const auto &warning : parameters.warnings())
        if (root)
          std::cerr << "fgimpact: warning: " << warning << std::endl;
    }
  catch (...)
    {
      return report_failure(std::current_exception(),
                            root,
                            1,
                            "error in " +
                              (prm_file.empty() ? "defaults" : prm_file));
    }

  try
    {
      Simulator simulator(parameters, MPI_COMM_WORLD);
      // Everything that can fail on bad input is checked before any file
      // is written: setup() writes nothing.  Rank 0 makes, checks and
      // cleans the directory and writes parameters.prm; every rank learns
      // the outcome, so that all stop together.
      try
        {
          simulator.setup();
          run_on_root(MPI_COMM_WORLD, [&]() {
            prepare_output_directory(parameters.output);
            std::ostringstream text;
            prm.print_parameters(text, ParameterHandler::PRM);
            write_file_atomically(parameters.output.directory +
                                    "/parameters.prm",
                                  text.str());
          });
        }
      catch (...)
        {
          return report_failure(std::current_exception(), root, 1);
        }
      simulator.run();
    }
  catch (...)
    {
      return report_failure(std::current_exception(), root, 2);
    }
  return 0;
}
