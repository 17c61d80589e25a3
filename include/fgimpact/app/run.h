#ifndef fgimpact_run_h
#define fgimpact_run_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/app/command_line.h>
#include <fgimpact/app/input_file.h>
#include <fgimpact/base/logger.h>
#include <fgimpact/problem/parameters.h>

#include <functional>
#include <string>
#include <vector>

namespace fgimpact
{
  /**
   * Every parameter of a run from its input, as the executable reads it:
   * declared in prm, the input parsed, the overrides ("Section/Entry=
   * value") on top, a relative Material/Profile file made relative to the
   * input's directory, parsed into `parameters` and checked.  adjust, if
   * given, changes prm after the overrides (a study case's entries and
   * directory).  Throws ExcMessage (one line) on bad input.  The
   * executable, a study's base input and its cases, and the tests' run
   * helper read parameters through it.
   */
  void
  read_run_parameters(
    const InputFile                                  &input,
    const std::vector<std::string>                   &overrides,
    ParameterHandler                                 &prm,
    Parameters                                       &parameters,
    const std::function<void(ParameterHandler &prm)> &adjust = {});

  /**
   * The run of the executable after its command line (action run or
   * validate): read the input (a file or standard input, includes expanded,
   * on every rank; the -s overrides; relative paths), parse and check every
   * parameter, then a study (Study/Entries or --study) or one simulation:
   * the output directory checked and locked, the set-up, the start files
   * (parameters.prm, input.prm, log.txt), the run.  Returns the exit code:
   * 0, 1 for bad input (one line, nothing written), 2 for a failed run
   * (one line, summary.txt with status = failed), 128 + the signal for an
   * interrupted one (summary.txt with status = interrupted).
   */
  int
  run_from_command_line(const CommandLine::Options &options,
                        const int                   argc,
                        char                      **argv,
                        Logger                     &logger);
} // namespace fgimpact

#endif
