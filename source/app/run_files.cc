// The files a single run writes at its start and end (run.cc's lifecycle):
// the directory locked and cleaned, log.txt, parameters.prm, input.prm,
// and at the end report.html and the last line.
#include <deal.II/base/mpi.h>

#include <fgimpact/app/command_line.h>
#include <fgimpact/app/run_files.h>
#include <fgimpact/base/files.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_directory.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/run_report.h>

#include <iostream>
#include <sstream>

namespace fgimpact
{
  void
  write_parameters_file(const OutputParameters         &output,
                        const dealii::ParameterHandler &prm)
  {
    std::ostringstream parameters;
    prm.print_parameters(parameters, dealii::ParameterHandler::PRM);
    write_file_atomically(output.directory + "/parameters.prm",
                          parameters.str());
  }


  void
  start_run_files(const OutputParameters         &output,
                  const int                       argc,
                  const char *const              *argv,
                  Logger                         &logger,
                  const dealii::ParameterHandler &prm,
                  const InputFile                &input,
                  const bool                      resume)
  {
    // One writer per directory, before anything is written there.
    lock_output_directory(output.directory);
    // Resuming: nothing removed, log.txt continued, input.prm kept.
    if (!resume)
      prepare_output_directory(output);
    const std::string provenance = CommandLine::provenance(
      argc, argv, dealii::Utilities::MPI::n_mpi_processes(MPI_COMM_WORLD));
    logger.open(output.directory + "/log.txt", provenance, resume);
    SummaryWriter::set_preamble(provenance);
    // Resuming: parameters.prm once the resume is accepted
    // (CheckpointSettings::on_resume_accepted).
    if (!resume)
      {
        write_parameters_file(output, prm);
        write_file_atomically(output.directory + "/input.prm",
                              input.original());
      }
  }


  void
  finish_run(const OutputParameters &output)
  {
    if (output.report)
      if (const std::string note = write_run_report(output.directory);
          !note.empty())
        std::cout << "  note: " << note << '\n';
    std::cout << "fgimpact: results in " << output.directory << '\n';
  }


} // namespace fgimpact
