#ifndef fgimpact_run_files_h
#define fgimpact_run_files_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/app/input_file.h>
#include <fgimpact/base/logger.h>

#include <string>

namespace fgimpact
{
  struct OutputParameters;

  /// parameters.prm (expanded), written atomically by rank 0.
  void
  write_parameters_file(const OutputParameters         &output,
                        const dealii::ParameterHandler &prm);

  /**
   * Rank 0, before the run: lock and clean the output directory
   * (Output/Overwrite; before log.txt is opened, so that the earlier run's
   * log goes and this run's stays), then log.txt (provenance first), the
   * provenance for summary.txt, parameters.prm (expanded) and input.prm (as
   * given), both written atomically.  A resume removes nothing, continues
   * log.txt and keeps input.prm.
   */
  void
  start_run_files(const OutputParameters         &output,
                  const int                       argc,
                  const char *const              *argv,
                  Logger                         &logger,
                  const dealii::ParameterHandler &prm,
                  const InputFile                &input,
                  const bool                      resume);

  /// A run's last words (rank 0): its report (Output/Report) and where its
  /// results are.
  void
  finish_run(const OutputParameters &output);
} // namespace fgimpact

#endif
