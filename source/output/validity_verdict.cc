// An impact run's verdict on its own validity: the end-of-run warnings
// (resolution, small strains) and the validity report's line (the summary
// keys are in impact_summary.cc).

#include <fgimpact/contact/impactor.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>

#include <algorithm>
#include <cstdio>

namespace fgimpact
{
  std::vector<std::string>
  resolution_warnings(const ImpactResults &r, const bool contact_area)
  {
    std::vector<std::string> warnings;
    const double             size = r.model.element_size_under_ball;
    if (contact_area && size > 0. &&
        r.max_contact_radius < contact_elements_per_radius * size)
      {
        char text[400];
        std::snprintf(
          text,
          sizeof(text),
          "the largest contact radius (%.4g mm) spans only %.2f element "
          "sizes (%.4g mm; fewer than %.0f): the contact force is not "
          "resolved; raise Geometry/Contact refinement levels (now %u) or "
          "set it to auto",
          r.max_contact_radius * 1e3,
          r.max_contact_radius / size,
          size * 1e3,
          contact_elements_per_radius,
          r.model.contact_refinement_levels);
        warnings.emplace_back(text);
      }
    // Small strains and Hertz's a << R: beyond these the model is
    // outside its assumptions (a finite-strain, large-deflection problem).
    const double R = r.model.impactor_radius, h = r.model.thickness;
    const auto   beyond = [&](const char  *what,
                            const double value,
                            const double limit,
                            const char  *of) {
      char text[300];
      std::snprintf(text,
                    sizeof(text),
                    "the %s (%.4g mm) exceeds %.0f %% of %s (%.4g mm): "
                      "outside the small-strain elastic model; lower "
                      "Impactor/Initial velocity or check the scene",
                    what,
                    value * 1e3,
                    100. * limit,
                    of,
                    (of[0] == 'R' ? R : h) * 1e3);
      warnings.emplace_back(text);
    };
    if (R > 0 && r.max_indentation > indentation_limit * R)
      beyond("largest indentation", r.max_indentation, indentation_limit, "R");
    if (h > 0 && r.max_indentation > deflection_limit * h)
      beyond("largest indentation", r.max_indentation, deflection_limit, "h");
    if (h > 0 && r.max_midplane_deflection > deflection_limit * h)
      beyond("largest mid-plane deflection",
             r.max_midplane_deflection,
             deflection_limit,
             "h");
    return warnings;
  }



  namespace
  {
    /// The metal check's item of the verdict, and whether it breaks.
    std::pair<std::string, bool>
    metal_validity(const ImpactResults &r)
    {
      char text[300];
      if (r.plastic.modelled)
        {
          // What an elastic metal would carry: Hooke's stress of the
          // total strain (the plastic strain not taken off).
          std::snprintf(text,
                        sizeof(text),
                        "plastic metal modelled (J2; the elastic stress "
                        "would be %.2f x the yield strength)",
                        r.elastic_yield_peak.ratio);
          return {text, false};
        }
      const bool broken = r.yield_peak.ratio > 1.;
      std::snprintf(text,
                    sizeof(text),
                    "elastic metal (von Mises %.2f x the yield strength%s)",
                    r.yield_peak.ratio,
                    broken ? ": set Material/Plasticity to J2 with "
                             "Contact/Model to resolved sphere" :
                             "");
      return {text, broken};
    }



    /// The ceramic check's item, and whether it breaks.
    std::pair<std::string, bool>
    ceramic_validity(const ImpactResults &r)
    {
      const bool broken = r.tension_peak.ratio > 1.;
      char       text[300];
      std::snprintf(text,
                    sizeof(text),
                    "intact ceramic (largest principal stress %.2f x the "
                    "tensile strength%s)",
                    r.tension_peak.ratio,
                    broken ? ": cracking is not modelled" : "");
      return {text, broken};
    }



    /// The rigid ball's item (its stiffening of Hertz's E* above the
    /// elastic ball's), and whether it breaks.
    std::pair<std::string, bool>
    rigid_ball_validity(const ImpactResults &r)
    {
      // The stiffening that matters: 5 % in E* is 2 % in the peak force
      // (F_max ~ E*^(2/5)).
      constexpr double rigid_ball_limit = 0.05;
      const bool       broken = r.rigid_ball_modulus_excess > rigid_ball_limit;
      char             text[300];
      std::snprintf(text,
                    sizeof(text),
                    "rigid ball (E* %.1f %% above the elastic ball's%s)",
                    100. * r.rigid_ball_modulus_excess,
                    broken ? ": set Impactor/Material to elastic" : "");
      return {text, broken};
    }



    /// The small-strain item (with a plastic run's largest equivalent
    /// plastic strain), and whether it breaks.
    std::pair<std::string, bool>
    strain_validity(const ImpactResults &r)
    {
      bool small_strains = true;
      for (const auto &w : r.warnings)
        small_strains =
          small_strains && w.find("small-strain") == std::string::npos;
      // Small-strain plasticity: J2 on infinitesimal strains holds to a
      // few per cent of plastic strain.
      constexpr double plastic_strain_limit = 0.05;
      small_strains =
        small_strains && !(r.plastic.modelled &&
                           r.plastic.max_plastic_strain > plastic_strain_limit);
      if (!r.plastic.modelled)
        return {"small strains", !small_strains};
      // The number behind the verdict.
      char text[300];
      std::snprintf(text,
                    sizeof(text),
                    "small strains (largest equivalent plastic strain %.2f "
                    "%% against %.0f %%)",
                    100. * r.plastic.max_plastic_strain,
                    100. * plastic_strain_limit);
      return {text, !small_strains};
    }
  } // namespace



  std::string
  validity_text(const ImpactResults &r)
  {
    if (!std::isfinite(r.yield_peak.ratio) &&
        !std::isfinite(r.tension_peak.ratio) &&
        !std::isfinite(r.rigid_ball_modulus_excess))
      return "not checked";
    std::string breaks, holds;
    const auto  add = [&](const std::pair<std::string, bool> &item) {
      std::string &list = item.second ? breaks : holds;
      list += (list.empty() ? "" : "; ") + item.first;
    };
    if (std::isfinite(r.yield_peak.ratio))
      add(metal_validity(r));
    if (std::isfinite(r.tension_peak.ratio))
      add(ceramic_validity(r));
    if (std::isfinite(r.rigid_ball_modulus_excess) &&
        r.rigid_ball_modulus_excess > 0.)
      add(rigid_ball_validity(r));
    add(strain_validity(r));
    // No commas: study.csv holds this text as it is.
    return "breaks: " + (breaks.empty() ? std::string("none") : breaks) +
           " | holds: " + (holds.empty() ? std::string("none") : holds) +
           (r.stress_fields_checked ?
              "" :
              " | stress fields not scanned (a study case by convolution: "
              "--study-case K or Study/Method = time loop scans them)");
  }
} // namespace fgimpact
