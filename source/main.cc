// fgimpact: low-velocity impact of a sphere on a functionally graded plate,
// 3D elasticity with graded finite elements (Asemi & Salami 2015).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fgimpact/simulator.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
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

  /// Collapse a deal.II exception text or any message into one line.
  std::string
  one_line(const std::string &text)
  {
    std::string out;
    bool        space = false;
    for (const char ch : text)
      {
        if (ch == '\n' || ch == '\t' || ch == ' ')
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
  message_of(const dealii::ExceptionBase &e)
  {
    std::ostringstream s;
    e.print_info(s);
    return one_line(s.str());
  }

  /// Make the output directory and check that files can be written there.
  void
  prepare_output_directory(const std::string &directory)
  {
    namespace fs = std::filesystem;
    std::error_code error;
    fs::create_directories(directory, error);
    AssertThrow(!error && fs::is_directory(directory),
                dealii::ExcMessage("Output/Directory '" + directory +
                                   "' cannot be created: " + error.message()));
    const std::string probe = directory + "/.fgimpact_write_test";
    {
      std::ofstream test(probe);
      AssertThrow(test.good(),
                  dealii::ExcMessage("Output/Directory '" + directory +
                                     "' is not writable."));
    }
    fs::remove(probe, error);
  }
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
  try
    {
      Parameters::declare_parameters(prm);
      if (!prm_file.empty())
        prm.parse_input(prm_file);
      parameters.parse_parameters(prm);
      parameters.validate();
    }
  catch (const ExceptionBase &e)
    {
      if (root)
        std::cerr << "fgimpact: error in "
                  << (prm_file.empty() ? "defaults" : prm_file) << ": "
                  << message_of(e) << '\n';
      return 1;
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "fgimpact: error in " << prm_file << ": "
                  << one_line(e.what()) << '\n';
      return 1;
    }

  try
    {
      Simulator simulator(parameters, MPI_COMM_WORLD);
      // Everything that can fail on bad input is checked before any file
      // is written: setup() writes nothing.
      try
        {
          simulator.setup();
          // Rank 0 makes and checks the directory; every rank learns the
          // outcome, so that all stop together.
          std::string error;
          if (root)
            try
              {
                prepare_output_directory(parameters.output.directory);
              }
            catch (const ExceptionBase &e)
              {
                error = message_of(e);
              }
          error = Utilities::MPI::broadcast(MPI_COMM_WORLD, error, 0);
          AssertThrow(error.empty(), ExcMessage(error));
        }
      catch (const ExceptionBase &e)
        {
          if (root)
            std::cerr << "fgimpact: error: " << message_of(e) << '\n';
          return 1;
        }
      if (root)
        {
          std::ofstream out(parameters.output.directory + "/parameters.prm");
          prm.print_parameters(out, ParameterHandler::PRM);
        }
      simulator.run();
    }
  catch (const ExceptionBase &e)
    {
      if (root)
        std::cerr << "fgimpact: error: " << message_of(e) << '\n';
      return 2;
    }
  catch (const std::exception &e)
    {
      if (root)
        std::cerr << "fgimpact: error: " << one_line(e.what()) << '\n';
      return 2;
    }
  return 0;
}
