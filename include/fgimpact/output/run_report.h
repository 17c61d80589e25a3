#ifndef fgimpact_run_report_h
#define fgimpact_run_report_h

#include <string>

namespace fgimpact
{
  /**
   * Output/Report: the run's one-page report, DIRECTORY/report.html,
   * written by scripts/report.py (the scene, the headline numbers with
   * their error estimates, the validity verdicts, the time histories, the
   * pictures, the convergence table, a study's cases) with the python3 on
   * PATH (standard library only).  Call on one rank after the run's files
   * are complete.  Returns an empty string, or a one-line note on why no
   * report was written (no python3, the script missing or failing): the
   * run's results stand without it.
   */
  std::string
  write_run_report(const std::string &directory);
} // namespace fgimpact

#endif
