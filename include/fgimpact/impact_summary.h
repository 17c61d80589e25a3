#ifndef fgimpact_impact_summary_h
#define fgimpact_impact_summary_h

#include <fgimpact/results.h>

#include <string>

namespace fgimpact
{
  /**
   * summary.txt of an impact run: every key of the README's table from r
   * (scaled to the units in the names), with `status` (completed,
   * interrupted or failed) and time_reached_us = t_end.  The monitor
   * writes it at the end of the time loop; the driver writes it with
   * status = failed when set-up fails before the monitor exists, so that
   * a failed run always has the same keys.  contact_area: the resolved
   * sphere's keys; instrumentation: spmv_ms and solve_ms.  Throws
   * ExcOutputFailure if filename cannot be written.
   */
  void
  write_impact_summary(const std::string   &filename,
                       const ImpactResults &r,
                       const bool           contact_area,
                       const bool           instrumentation,
                       const std::string   &status,
                       const double         t_end);
} // namespace fgimpact

#endif
