#ifndef fgimpact_study_h
#define fgimpact_study_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/app/input_file.h>
#include <fgimpact/base/logger.h>
#include <fgimpact/problem/study_parameters.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Run a study: every case's input is the base input with `overrides`,
   * then the case's assignments, Output/Directory = base/case_NNN and,
   * unless Study/Write VTU, Output/VTU interval = 0.  All cases are parsed
   * and checked before anything is written.  Cases that differ only in
   * the impactor, the contact law's constants or Newton's control share a
   * plate set-up; where ImpactStudyEngine applies they run by convolution,
   * elsewhere (logged, with the reason) through the normal time loop.
   * Writes base/case_NNN/{history.csv, summary.txt, parameters.prm,
   * input.prm}, base/study.csv (one row per case: the varied entries and
   * every numeric summary.txt key) and base/log.txt.  With only_case >= 0
   * runs that case alone, fully (VTU as in the input), into its directory.
   * Returns the exit code.
   */
  int
  run_study(const StudyParameters          &study,
            const InputFile                &input,
            const std::vector<std::string> &overrides,
            const int                       only_case,
            const std::string              &provenance,
            Logger                         &logger);
} // namespace fgimpact

#endif
