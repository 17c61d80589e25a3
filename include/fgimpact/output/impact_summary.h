#ifndef fgimpact_impact_summary_h
#define fgimpact_impact_summary_h

#include <fgimpact/contact/resolved_contact.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/results.h>

#include <string>
#include <vector>

namespace fgimpact
{
  /// The validity limits of the small-strain model: the largest
  /// indentation against the ball's radius R (Hertz: a/R = sqrt(alpha/R),
  /// 0.05 R is a/R = 0.22) and the indentation and mid-plane deflection
  /// against the thickness h (a deflection of 0.2 h brings membrane
  /// stretching of a few per cent).
  constexpr double indentation_limit = 0.05, deflection_limit = 0.2;

  /**
   * The end-of-run warnings: a resolved contact whose largest contact
   * radius spans fewer than contact_elements_per_radius element sizes; an
   * indentation or deflection beyond the small-strain limits above.  One
   * line each, naming what to change.
   */
  std::vector<std::string>
  resolution_warnings(const ImpactResults &r, const bool contact_area);

  /**
   * The validity report in one line (no commas: study.csv holds it),
   * "breaks: a; b | holds: c; d", over the
   * elastic metal (von Mises against the graded yield strength), the
   * intact ceramic (principal stress against the tensile strength), the
   * rigid ball (E* more than 5 % above the elastic ball's) and the small
   * strains (resolution_warnings()), then " | stress fields not scanned
   * (...)" for a study case by convolution; "not checked" if none was.
   */
  std::string
  validity_text(const ImpactResults &r);

  /// What a summary key may need besides the results.
  struct SummaryContext
  {
    std::string status; // completed | interrupted | failed
    double      t_end;  // s, the time the results cover
  };

  /**
   * One key of an impact run's summary.txt: its name (with the unit), and
   * either a number in the key's unit with `decimals` fixed decimals (or
   * in scientific notation) or a word; shown always, for a resolved
   * contact, or with Output/Instrumentation.
   */
  struct SummaryKey
  {
    enum class When
    {
      always,
      contact_area, // a resolved contact (a contact area)
      contact_law,  // a Hertz law (no contact area)
      instrumentation,
      plasticity // Material/Plasticity = J2
    };
    const char *name                            = "";
    int         decimals                        = 0;
    double (*number)(const ImpactResults &)     = nullptr;
    std::string (*text)(const ImpactResults &,
                        const SummaryContext &) = nullptr;
    bool scientific                             = false;
    When when                                   = When::always;
    /// time_reached_us: the context's t_end.
    bool time_reached = false;
  };

  /// The keys of an impact run's summary.txt in the file's order,
  /// declared once: impact_summary() writes them, and doc/outputs.md's
  /// table is checked against them (test readme_columns).
  const std::vector<SummaryKey> &
  impact_summary_keys();

  /**
   * The contents of an impact run's summary.txt: every key of the
   * doc/outputs.md's table from r (scaled to the units in the names), with
   * `status` (completed, interrupted or failed) and time_reached_us =
   * t_end.  The monitor writes it at the end of the time loop; the driver
   * writes it with status = failed when set-up fails before the monitor
   * exists, so that a failed run always has the same keys (both through
   * the run's SummaryFile).  contact_area: the resolved sphere's keys;
   * instrumentation: spmv_ms and solve_ms.
   */
  SummaryWriter
  impact_summary(const ImpactResults &r,
                 const bool           contact_area,
                 const bool           instrumentation,
                 const std::string   &status,
                 const double         t_end);
} // namespace fgimpact

#endif
