// The executable's run after its command line (Lethe's thin main): read
// the input, then a study or one simulation, every failure through
// report_failure() with its exit code.  main.cc only starts MPI, guards the
// signals and dispatches the command line.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/utilities.h>

#include <fgimpact/app/input_file.h>
#include <fgimpact/app/run.h>
#include <fgimpact/app/run_files.h>
#include <fgimpact/app/study.h>
#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/output/output_directory.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/study/simulator.h>

#include <cstdio>
#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>

namespace fgimpact
{
  namespace
  {
    /// Rank 0 reads the input (a file or standard input, includes
    /// expanded), every rank gets its text; throws ExcMessage on every rank.
    std::unique_ptr<fgimpact::InputFile>
    read_input(const std::string &prm_file, const MPI_Comm comm)
    {
      using namespace dealii;
      std::unique_ptr<fgimpact::InputFile> input;
      fgimpact::run_on_root(comm, [&]() {
        input = std::make_unique<fgimpact::InputFile>(prm_file);
      });
      if (Utilities::MPI::n_mpi_processes(comm) > 1)
        {
          const std::string text =
            Utilities::MPI::broadcast(comm, input ? input->expanded() : "", 0);
          if (!input)
            input = std::make_unique<fgimpact::InputFile>(prm_file, text);
        }
      return input;
    }


    /**
     * Declares, reads and checks every parameter (the -s overrides applied
     * before validate(), --study lists appended to Study/Entries) and prints
     * the warnings; throws on bad input, before any file is written.
     */
    void
    read_parameters(const fgimpact::CommandLine::Options &options,
                    dealii::ParameterHandler             &prm,
                    fgimpact::Parameters                 &parameters,
                    std::unique_ptr<fgimpact::InputFile> &input,
                    fgimpact::StudyParameters            &study,
                    const bool                            root)
    {
      input = read_input(options.prm_file, MPI_COMM_WORLD);
      read_run_parameters(*input, options.overrides, prm, parameters);
      study.parse_parameters(prm);
      study.append_command_line(options.study);
      for (const auto &warning : parameters.warnings())
        if (root)
          std::cerr << "fgimpact: warning: " << warning << std::endl;
    }

    /// The expanded parameters for the checkpoints; with --resume, rank 0
    /// checks the checkpoint against them (a failure is thrown on every
    /// rank).
    fgimpact::CheckpointSettings
    checkpoint_settings(const fgimpact::CommandLine::Options &options,
                        const dealii::ParameterHandler       &prm)
    {
      using namespace dealii;
      fgimpact::CheckpointSettings checkpoint;
      checkpoint.resume_directory = options.resume_directory;
      std::ostringstream text;
      prm.print_parameters(text,
                           ParameterHandler::OutputStyle(
                             ParameterHandler::PRM | ParameterHandler::Short));
      checkpoint.parameters_text = text.str();
      if (!options.resume_directory.empty())
        fgimpact::run_on_root(MPI_COMM_WORLD, [&]() {
          checkpoint.resume_step =
            fgimpact::check_resume(options.resume_directory,
                                   checkpoint.parameters_text,
                                   Utilities::MPI::n_mpi_processes(
                                     MPI_COMM_WORLD));
        });
      checkpoint.resume_step =
        Utilities::MPI::max(checkpoint.resume_step, MPI_COMM_WORLD);
      return checkpoint;
    }


    /**
     * A failure before the time loop: bad input (exit code 1) writes
     * nothing; a failed run of valid input (a numerical failure in set-up, a
     * start file that cannot be written: exit code 2) writes, if may_write
     * (not --validate), the start files (start_files, if not yet tried) and
     * summary.txt with status = failed, as far as it can.
     */
    int
    fail_before_run(const std::exception_ptr    &failure,
                    const fgimpact::Simulator   &simulator,
                    const bool                   may_write,
                    const std::function<void()> &start_files,
                    const bool                   root)
    {
      if (may_write && fgimpact::is_run_failure(failure))
        try
          {
            if (start_files)
              start_files();
            simulator.write_failed_summary();
          }
        catch (...)
          {}
      return fgimpact::report_failure(failure, root, 1);
    }



    /// What a stop signal in the set-up ends the run with.
    fgimpact::RunInterrupted
    setup_interruption(const int signal)
    {
      return fgimpact::RunInterrupted(
        signal,
        std::string("interrupted by ") + fgimpact::signal_name(signal) +
          " during the set-up (nothing computed); summary.txt says status = "
          "interrupted; run it again.");
    }



    /// A stop signal (SIGINT, SIGTERM, SIGHUP, SIGXFSZ, SIGUSR1) that came
    /// during the
    /// set-up or the start files (it only set a flag): nothing computed,
    /// summary.txt says interrupted; RunInterrupted on every rank.
    void
    stop_if_signalled_in_setup(const fgimpact::Simulator &simulator)
    {
      const int stop = fgimpact::agreed_stop(MPI_COMM_WORLD, false);
      if (stop <= 0)
        return;
      simulator.write_failed_summary("interrupted");
      throw setup_interruption(stop);
    }



    /// The action for a stop signal that a solver's set-up (ML's
    /// aggregation, CHOLMOD's analysis: minutes for millions of DoFs) holds
    /// back longer than 2 s (DeferredStopAction), on one rank: nothing is
    /// computed, so the start files, summary.txt (status = interrupted) and
    /// the usual line, then the exit (128 + the signal) without waiting for
    /// the solver.  On several ranks the signal waits for the set-up's end
    /// (the ranks must stop together): an empty action.
    std::function<void(int)>
    stop_during_solver_setup(const fgimpact::Simulator   &simulator,
                             const std::function<void()> &start_files)
    {
      if (dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD) > 1)
        return nullptr;
      return [&simulator, start_files](const int signal) {
        try
          {
            start_files();
          }
        catch (...)
          {}
        simulator.write_failed_summary("interrupted");
        const int code = fgimpact::report_failure(
          std::make_exception_ptr(setup_interruption(signal)), true, 2);
        fgimpact::release_output_directory_locks();
        std::fflush(nullptr);
        std::_Exit(code);
      };
    }



    /// An output directory that cannot be used, or that another run holds,
    /// is refused (bad input, exit code 1) before the set-up's work (and by
    /// --validate); 0 if it is usable and free.
    int
    refuse_unusable_directory(const fgimpact::OutputParameters &output,
                              const bool                        root)
    {
      try
        {
          fgimpact::run_on_root(MPI_COMM_WORLD, [&]() {
            fgimpact::check_output_directory_usable(output.directory);
            fgimpact::check_output_directory_free(output.directory);
          });
        }
      catch (...)
        {
          return fgimpact::report_failure(std::current_exception(), root, 1);
        }
      return 0;
    }



    /// --study-case names a case of a study: without one it would be
    /// ignored without a word.  Exit code 1.
    int
    refuse_study_case(const int study_case, const bool root)
    {
      return fgimpact::report_failure(
        std::make_exception_ptr(std::runtime_error(
          "--study-case " + std::to_string(study_case) +
          " needs a study (Study/Entries or --study); without one there is "
          "no case to run.")),
        root,
        1);
    }



    /// --validate: the input passed every check and the set-up; exit code 0.
    int
    report_valid(const fgimpact::InputFile &input_file,
                 const fgimpact::Simulator &simulator,
                 const bool                 root)
    {
      if (root)
        std::cout << "fgimpact: " << input_file.input_name()
                  << " is valid (checked and set up; nothing run, nothing "
                     "written)\n"
                  << "  " << simulator.get_resource_estimate().describe()
                  << '\n';
      return 0;
    }



    /// However the run ends here (a kill aside), its output directories
    /// are left without their lock files.
    struct ReleaseLocksAtEnd
    {
      ~ReleaseLocksAtEnd() { fgimpact::release_output_directory_locks(); }
    };



    /**
     * Everything that can fail on bad input is checked before any file is
     * written: Simulator::setup() writes nothing.  A numerical failure of
     * the valid input there (a factorization, a solver) is a failed run:
     * the start files and summary.txt (status = failed), as in the time
     * loop (--validate writes nothing).  The exit code of a failure, or -1
     * once set up.
     */
    int
    setup_or_fail(fgimpact::Simulator         &simulator,
                  const bool                   validate,
                  const std::function<void()> &start_files,
                  const bool                   root)
    {
      using namespace fgimpact;
      try
        {
          const DeferredStopAction stop_in_solver_setup(
            validate ? nullptr :
                       stop_during_solver_setup(simulator, start_files));
          simulator.setup();
        }
      catch (...)
        {
          return fail_before_run(
            std::current_exception(), simulator, !validate, start_files, root);
        }
      return -1;
    }



    /// Write the start files: -1, or the exit code of a start file that
    /// cannot be written, an I/O failure (exit code 2, summary.txt failed
    /// if it can still be written).  An unusable directory was refused
    /// before, as bad input (exit code 1, nothing written).
    int
    start_or_fail(const fgimpact::Simulator   &simulator,
                  const std::function<void()> &start_files,
                  const bool                   root)
    {
      try
        {
          start_files();
        }
      catch (...)
        {
          return fail_before_run(
            std::current_exception(), simulator, true, nullptr, root);
        }
      return -1;
    }



    /// Checkpoints store the parameters; a resume refuses changed ones
    /// (bad input throws).  On a resume accepted, parameters.prm is
    /// written (prm and parameters must outlive the run).
    fgimpact::CheckpointSettings
    resume_settings(const fgimpact::CommandLine::Options &options,
                    const dealii::ParameterHandler       &prm,
                    const fgimpact::Parameters           &parameters)
    {
      using namespace fgimpact;
      AssertThrow(options.resume_directory.empty() ||
                    parameters.accuracy.preset !=
                      AccuracyPreset::Preset::converged,
                  ExcMessage("--resume: an Accuracy = converged run is a "
                             "sequence of runs and cannot be resumed; "
                             "run it again."));
      AssertThrow(options.resume_directory.empty() ||
                    parameters.geometry.adaptive_cycles == 0,
                  ExcMessage("--resume: a run with Geometry/Adaptive "
                             "refinement cycles > 0 is a sequence of runs "
                             "and cannot be resumed; run it again."));
      CheckpointSettings checkpoint = checkpoint_settings(options, prm);
      checkpoint.on_resume_accepted = [&prm, &parameters]() {
        run_on_root(MPI_COMM_WORLD,
                    [&]() { write_parameters_file(parameters.output, prm); });
      };
      return checkpoint;
    }



    /// Set up, write the start files and run one simulation; the exit code.
    int
    simulate(const fgimpact::CommandLine::Options &options,
             const fgimpact::Parameters           &parameters,
             const dealii::ParameterHandler       &prm,
             const fgimpact::InputFile            &input_file,
             const fgimpact::CheckpointSettings   &checkpoint,
             fgimpact::Logger                     &logger,
             int                                   argc,
             char                                **argv)
    {
      using namespace dealii;
      using namespace fgimpact;
      const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
      if (const int code = refuse_unusable_directory(parameters.output, root))
        return code;
      try
        {
          Simulator simulator(parameters, MPI_COMM_WORLD);
          simulator.set_checkpointing(checkpoint);
          const bool validate = options.action == CommandLine::Action::validate;
          // Rank 0 prepares the directory and writes the start files; every
          // rank learns the outcome, so that all stop together.
          const auto start_files = [&]() {
            run_on_root(MPI_COMM_WORLD, [&]() {
              start_run_files(parameters.output,
                              argc,
                              argv,
                              logger,
                              prm,
                              input_file,
                              !options.resume_directory.empty());
            });
          };
          if (const int code =
                setup_or_fail(simulator, validate, start_files, root);
              code >= 0)
            return code;
          if (validate)
            return report_valid(input_file, simulator, root);
          if (const int code = start_or_fail(simulator, start_files, root);
              code >= 0)
            return code;
          stop_if_signalled_in_setup(simulator);
          simulator.run();
          if (root)
            finish_run(parameters.output);
        }
      catch (...)
        {
          return report_failure(std::current_exception(), root, 2);
        }
      return 0;
    }
  } // namespace



  void
  read_run_parameters(const InputFile                &input,
                      const std::vector<std::string> &overrides,
                      ParameterHandler               &prm,
                      Parameters                     &parameters,
                      const std::function<void(ParameterHandler &prm)> &adjust)
  {
    Parameters::declare_parameters(prm);
    input.parse_into(prm, overrides);
    if (adjust)
      adjust(prm);
    FunctionallyGradedMaterial::Parameters::resolve_relative_paths(
      prm, input.input_name());
    parameters.parse_parameters(prm);
    parameters.validate();
  }



  int
  run_from_command_line(const CommandLine::Options &options,
                        const int                   argc,
                        char                      **argv,
                        Logger                     &logger)
  {
    using namespace dealii;
    const ReleaseLocksAtEnd release_locks;
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    ParameterHandler           prm;
    Parameters                 parameters;
    std::unique_ptr<InputFile> input;
    StudyParameters            study;
    // Input errors: checked before any file is written, reported in one line
    // with their exit code by report_failure() (base/exceptions.cc).
    try
      {
        read_parameters(options, prm, parameters, input, study, root);
      }
    catch (...)
      {
        const std::string &file = options.prm_file;
        return report_failure(std::current_exception(),
                              root,
                              1,
                              "error in " +
                                (file == "-" ? "standard input" : file));
      }

    if (options.study_case >= 0 && study.entries.empty())
      return refuse_study_case(options.study_case, root);

    // A study (Study/Entries or --study): its own cases and outputs.
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD);
    if (!study.entries.empty() && options.action == CommandLine::Action::run)
      return run_study(study,
                       *input,
                       options.overrides,
                       options.study_case,
                       CommandLine::provenance(argc, argv, n_ranks),
                       logger);

    CheckpointSettings checkpoint;
    try
      {
        checkpoint = resume_settings(options, prm, parameters);
      }
    catch (...)
      {
        return report_failure(std::current_exception(), root, 1);
      }

    return simulate(
      options, parameters, prm, *input, checkpoint, logger, argc, argv);
  }
} // namespace fgimpact
