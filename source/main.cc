// fgimpact: low-velocity impact of a sphere on a functionally graded plate,
// 3D elasticity with graded finite elements (Asemi & Salami 2015).

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fgimpact/command_line.h>
#include <fgimpact/input_file.h>
#include <fgimpact/logger.h>
#include <fgimpact/simulator.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>

namespace
{
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
            prm.print_parameters(std::cout, dealii::ParameterHandler::PRM);
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

  /// Rank 0 reads the input (a file or standard input, includes
  /// expanded), every rank gets its text; throws ExcMessage.
  std::unique_ptr<fgimpact::InputFile>
  read_input(const std::string &prm_file, const MPI_Comm comm)
  {
    using namespace dealii;
    std::unique_ptr<fgimpact::InputFile> input;
    std::string                          error;
    const bool root = Utilities::MPI::this_mpi_process(comm) == 0;
    if (root)
      try
        {
          input = std::make_unique<fgimpact::InputFile>(prm_file);
        }
      catch (const ExceptionBase &e)
        {
          error = message_of(e);
        }
    error = Utilities::MPI::broadcast(comm, error, 0);
    AssertThrow(error.empty(), ExcMessage(error));
    const std::string text =
      Utilities::MPI::broadcast(comm, root ? input->expanded() : "", 0);
    if (!root)
      input = std::make_unique<fgimpact::InputFile>(prm_file, text);
    return input;
  }
  /// Rank 0, before the run: log.txt (provenance first), the provenance
  /// for summary.txt, parameters.prm (expanded) and input.prm (as given).
  void
  start_run_files(const std::string              &directory,
                  const int                       argc,
                  const char *const              *argv,
                  fgimpact::Logger               &logger,
                  const dealii::ParameterHandler &prm,
                  const fgimpact::InputFile      &input)
  {
    const std::string provenance = fgimpact::CommandLine::provenance(
      argc, argv, dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    logger.open(directory + "/log.txt", provenance);
    fgimpact::SummaryWriter::set_preamble(provenance);
    std::ofstream out(directory + "/parameters.prm");
    prm.print_parameters(out, dealii::ParameterHandler::PRM);
    std::ofstream(directory + "/input.prm") << input.original();
  }
} // namespace



int
main(int argc, char *argv[])
{
  using namespace dealii;
  using namespace fgimpact;

  CommandLine::prepare_mpi_environment();
  Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
  Logger     logger(root);

  const CommandLine::Options options   = CommandLine::parse(argc, argv);
  const int                  exit_code = handle_informational(options, root);
  if (exit_code >= 0)
    return exit_code;
  const std::string &prm_file = options.prm_file;

  ParameterHandler           prm;
  fgimpact::Parameters       parameters;
  std::unique_ptr<InputFile> input;
  // Input errors: everything is checked before any file is written.
  try
    {
      Parameters::declare_parameters(prm);
      input = read_input(prm_file, MPI_COMM_WORLD);
      input->parse_into(prm, options.overrides);
      parameters.parse_parameters(prm);
      parameters.validate();
    }
  catch (const ExceptionBase &e)
    {
      if (root)
        std::cerr << "fgimpact: error in "
                  << (prm_file == "-" ? "standard input" : prm_file) << ": "
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
          if (options.action == CommandLine::Action::validate)
            {
              if (root)
                std::cout << "fgimpact: " << prm_file
                          << " is valid (checked and set up; nothing run, "
                             "nothing written)\n";
              return 0;
            }
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
      const std::string &directory = parameters.output.directory;
      if (root)
        start_run_files(directory, argc, argv, logger, prm, *input);
      simulator.run();
      if (root)
        std::cout << "fgimpact: results in " << directory << '\n';
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
