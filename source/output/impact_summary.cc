// summary.txt of an impact run: its keys (name, unit, digits, value) in one
// table per group, and the writer; the validity line and the end-of-run
// warnings are in validity_verdict.cc.

#include <fgimpact/contact/impactor.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>

#include <algorithm>
#include <cstdio>

namespace fgimpact
{
  namespace
  {
    using R = ImpactResults;
    using C = SummaryContext;

    /// A key with `decimals` fixed decimals of value(r) (in the key's
    /// unit), shown when `when` holds.
    SummaryKey
    number(const char *name,
           const int   decimals,
           double (*value)(const R &),
           const SummaryKey::When when = SummaryKey::When::always)
    {
      SummaryKey key;
      key.name     = name;
      key.decimals = decimals;
      key.number   = value;
      key.when     = when;
      return key;
    }

    SummaryKey
    scientific(const char *name, double (*value)(const R &))
    {
      SummaryKey key = number(name, 0, value);
      key.scientific = true;
      return key;
    }

    SummaryKey
    text(const char *name, std::string (*value)(const R &, const C &))
    {
      SummaryKey key;
      key.name = name;
      key.text = value;
      return key;
    }
  } // namespace



  namespace
  {
    /// The run's status and what it modelled.  status: completed,
    /// interrupted (SIGINT/SIGTERM) or failed.
    std::vector<SummaryKey>
    model_keys()
    {
      using W = SummaryKey::When;
      return {
        text("status", [](const R &, const C &c) { return c.status; }),
        {"time_reached_us", 4, nullptr, nullptr, false, W::always, true},
        text("contact_model",
             [](const R &r, const C &) { return r.model.contact_model; }),
        number("contact_refinement_levels",
               0,
               [](const R &r) {
                 return double(r.model.contact_refinement_levels);
               }),
        number("element_size_under_ball_mm",
               6,
               [](const R &r) {
                 return r.model.element_size_under_ball * 1e3;
               }),
        number("time_step_us",
               6,
               [](const R &r) { return r.model.time_step * 1e6; }),
        text("scheme", [](const R &r, const C &) { return r.model.scheme; }),
        number("element_degree",
               0,
               [](const R &r) { return double(r.model.element_degree); }),
        text("element_technology",
             [](const R &r, const C &) { return r.model.element_technology; }),
        text("symmetry",
             [](const R &r, const C &) { return r.model.symmetry; }),
        text("property_mode",
             [](const R &r, const C &) { return r.model.property_mode; }),
        text("gradation",
             [](const R &r, const C &) { return r.model.gradation; }),
        number("power_law_index",
               6,
               [](const R &r) { return r.model.power_law_index; }),
        text("homogenization",
             [](const R &r, const C &) { return r.model.homogenization; }),
        text("warnings", [](const R &r, const C &) {
          std::string warnings;
          for (const auto &w : r.warnings)
            warnings += (warnings.empty() ? "" : "; ") + w;
          return warnings.empty() ? std::string("none") : warnings;
        })};
    }



    /// The time history's results; contact_duration_us and
    /// departure_velocity_m_s are `none` (NaN) while the ball has not left.
    std::vector<SummaryKey>
    result_keys()
    {
      using W = SummaryKey::When;
      return {number("peak_contact_force_N",
                     4,
                     [](const R &r) { return r.peak_contact_force; }),
              number("max_sampled_contact_force_N",
                     4,
                     [](const R &r) { return r.max_sampled_force; }),
              number("time_of_peak_force_us",
                     4,
                     [](const R &r) { return r.time_of_peak_force * 1e6; }),
              number("contact_duration_us",
                     4,
                     [](const R &r) { return r.contact_duration * 1e6; }),
              number("departure_velocity_m_s",
                     7,
                     [](const R &r) { return r.departure_velocity; }),
              number("max_approach_um",
                     5,
                     [](const R &r) { return r.max_approach * 1e6; }),
              number(
                "max_indentation_um",
                5,
                [](const R &r) { return r.max_indentation * 1e6; },
                W::contact_law),
              number(
                "max_hertz_indentation_um",
                5,
                [](const R &r) { return r.max_indentation * 1e6; },
                W::contact_area),
              number("max_midplane_deflection_um",
                     5,
                     [](const R &r) {
                       return r.max_midplane_deflection * 1e6;
                     }),
              number("max_top_deflection_um", 5, [](const R &r) {
                return r.max_top_deflection * 1e6;
              })};
    }



    /// The contact's constants and the ball, then the resolved contact's
    /// extent (where it has an area).
    std::vector<SummaryKey>
    contact_keys()
    {
      using W = SummaryKey::When;
      return {scientific("contact_stiffness_Kh_N_m1.5",
                         [](const R &r) { return r.contact_stiffness; }),
              scientific("contact_modulus_Q_Pa",
                         [](const R &r) { return r.contact_modulus; }),
              number("impactor_mass_kg",
                     8,
                     [](const R &r) { return r.impactor_mass; }),
              number("plate_mass_kg",
                     8,
                     [](const R &r) { return r.plate_mass; }),
              number("impulse_N_s", 9, [](const R &r) { return r.impulse; }),
              number("contact_node_offset_mm",
                     6,
                     [](const R &r) { return r.contact_node_offset * 1e3; }),
              number(
                "max_contact_radius_mm",
                5,
                [](const R &r) { return r.max_contact_radius * 1e3; },
                W::contact_area),
              number(
                "max_contact_pressure_MPa",
                4,
                [](const R &r) { return r.max_contact_pressure * 1e-6; },
                W::contact_area),
              number(
                "max_contact_nodes",
                0,
                [](const R &r) { return double(r.max_contact_nodes); },
                W::contact_area),
              number(
                "n_contact_candidates",
                0,
                [](const R &r) { return double(r.n_contact_candidates); },
                W::contact_area)};
    }



    /// The validity report's numbers of one peak: ratio, stress and
    /// strength (MPa), where (mm) and when (us).
    template <StrengthPeak ImpactResults::*peak>
    std::vector<SummaryKey>
    strength_keys(const char *const names[7])
    {
      return {
        number(names[0], 4, [](const R &r) { return (r.*peak).ratio; }),
        number(names[1], 2, [](const R &r) { return (r.*peak).stress * 1e-6; }),
        number(names[2],
               2,
               [](const R &r) { return (r.*peak).strength * 1e-6; }),
        number(names[3],
               3,
               [](const R &r) { return (r.*peak).point[0] * 1e3; }),
        number(names[4],
               3,
               [](const R &r) { return (r.*peak).point[1] * 1e3; }),
        number(names[5],
               3,
               [](const R &r) { return (r.*peak).point[2] * 1e3; }),
        number(names[6], 3, [](const R &r) { return (r.*peak).time * 1e6; })};
    }

    /// The validity report (validity_report.h).
    std::vector<SummaryKey>
    validity_keys()
    {
      static const char *const yield[7]   = {"max_von_mises_over_yield",
                                             "von_mises_at_peak_MPa",
                                             "yield_strength_at_peak_MPa",
                                             "von_mises_peak_x_mm",
                                             "von_mises_peak_y_mm",
                                             "von_mises_peak_z_mm",
                                             "von_mises_peak_time_us"};
      static const char *const tension[7] = {
        "max_principal_over_tensile_strength",
        "principal_at_peak_MPa",
        "tensile_strength_at_peak_MPa",
        "principal_peak_x_mm",
        "principal_peak_y_mm",
        "principal_peak_z_mm",
        "principal_peak_time_us"};
      std::vector<SummaryKey> keys = strength_keys<&R::yield_peak>(yield);
      for (const auto &key : strength_keys<&R::tension_peak>(tension))
        keys.push_back(key);
      // The elastic stress (C eps) over the initial yield strength: in a
      // plastic run max_von_mises_over_yield is the stress the metal
      // carries over its current yield stress, this one what an elastic
      // metal would carry.
      keys.push_back(number("elastic_von_mises_over_yield", 4, [](const R &r) {
        return r.elastic_yield_peak.ratio;
      }));
      keys.push_back(number("rigid_ball_modulus_excess", 4, [](const R &r) {
        return r.rigid_ball_modulus_excess;
      }));
      keys.push_back(text("validity", [](const R &r, const C &) {
        return validity_text(r);
      }));
      return keys;
    }



    /// What a plastic plate leaves (PlasticityReport): dissipation,
    /// crater and plastic zone.
    std::vector<SummaryKey>
    plasticity_keys()
    {
      const auto W = SummaryKey::When::plasticity;
      return {number(
                "plastic_dissipation_J",
                9,
                [](const R &r) { return r.plastic.dissipation; },
                W),
              number(
                "permanent_indentation_um",
                5,
                [](const R &r) {
                  return r.plastic.permanent_indentation * 1e6;
                },
                W),
              number(
                "crater_diameter_mm",
                4,
                [](const R &r) { return r.plastic.crater_diameter * 1e3; },
                W),
              number(
                "plastic_zone_depth_mm",
                4,
                [](const R &r) { return r.plastic.plastic_zone_depth * 1e3; },
                W),
              number(
                "plastic_zone_radius_mm",
                4,
                [](const R &r) { return r.plastic.plastic_zone_radius * 1e3; },
                W),
              number(
                "max_equivalent_plastic_strain",
                6,
                [](const R &r) { return r.plastic.max_plastic_strain; },
                W)};
    }



    /// A plastic impact's first yield, restitution and the plate's
    /// plastic iterations.
    std::vector<SummaryKey>
    first_yield_keys()
    {
      const auto W = SummaryKey::When::plasticity;
      return {number(
                "first_yield_time_us",
                4,
                [](const R &r) { return r.plastic.first_yield_time * 1e6; },
                W),
              number(
                "first_yield_contact_force_N",
                4,
                [](const R &r) { return r.plastic.first_yield_force; },
                W),
              number(
                "first_yield_hertz_force_N",
                3,
                [](const R &r) { return r.plastic.first_yield_hertz_force; },
                W),
              number(
                "first_yield_contact_radius_node_spacings",
                3,
                [](const R &r) { return r.plastic.first_yield_resolution; },
                W),
              number(
                "coefficient_of_restitution",
                6,
                [](const R &r) { return r.plastic.restitution; },
                W),
              number(
                "mean_plate_iterations",
                3,
                [](const R &r) { return r.plastic.mean_iterations; },
                W),
              number(
                "max_plate_iterations",
                0,
                [](const R &r) { return double(r.plastic.max_iterations); },
                W)};
    }



    /// The problem's size, the solvers' effort, checks and timings.
    std::vector<SummaryKey>
    run_keys()
    {
      using W = SummaryKey::When;
      return {
        number("n_impacts", 0, [](const R &r) { return double(r.n_impacts); }),
        number("n_dofs", 0, [](const R &r) { return double(r.n_dofs); }),
        number("n_mpi_ranks",
               0,
               [](const R &r) { return double(r.n_mpi_ranks); }),
        number("n_time_steps",
               0,
               [](const R &r) { return double(r.n_time_steps); }),
        number("max_newton_iterations",
               0,
               [](const R &r) { return double(r.max_newton_iterations); }),
        number("linear_solver_iterations",
               0,
               [](const R &r) { return double(r.linear_iterations); }),
        number("max_linear_solver_iterations",
               0,
               [](const R &r) { return double(r.max_linear_iterations); }),
        scientific("max_relative_energy_drift",
                   [](const R &r) { return r.max_energy_drift; }),
        scientific("impulse_identity_error",
                   [](const R &r) { return r.impulse_identity_error; }),
        number("setup_s", 3, [](const R &r) { return r.setup_time; }),
        number("factorization_s",
               3,
               [](const R &r) { return r.factorization_time; }),
        number("time_loop_s", 3, [](const R &r) { return r.time_loop_time; }),
        number("time_per_step_ms",
               4,
               [](const R &r) {
                 return 1e3 * r.time_loop_time / std::max(r.n_time_steps, 1u);
               }),
        number("output_s", 3, [](const R &r) { return r.output_time; }),
        number(
          "spmv_ms",
          4,
          [](const R &r) { return 1e3 * r.spmv_time; },
          W::instrumentation),
        number(
          "solve_ms",
          4,
          [](const R &r) { return 1e3 * r.solve_time; },
          W::instrumentation),
        number("wall_time_s", 3, [](const R &r) { return r.wall_time; })};
    }
  } // namespace



  const std::vector<SummaryKey> &
  impact_summary_keys()
  {
    // In the file's order.
    static const std::vector<SummaryKey> keys = [] {
      std::vector<SummaryKey> all = model_keys();
      for (const auto &group : {result_keys(),
                                contact_keys(),
                                plasticity_keys(),
                                first_yield_keys(),
                                validity_keys(),
                                run_keys()})
        all.insert(all.end(), group.begin(), group.end());
      return all;
    }();
    return keys;
  }



  SummaryWriter
  impact_summary(const ImpactResults &r,
                 const bool           contact_area,
                 const bool           instrumentation,
                 const std::string   &status,
                 const double         t_end)
  {
    const SummaryContext context{status, t_end};
    SummaryWriter        out;
    for (const SummaryKey &key : impact_summary_keys())
      {
        if ((key.when == SummaryKey::When::contact_area && !contact_area) ||
            (key.when == SummaryKey::When::contact_law && contact_area) ||
            (key.when == SummaryKey::When::instrumentation &&
             !instrumentation) ||
            (key.when == SummaryKey::When::plasticity && !r.plastic.modelled))
          continue;
        if (key.text)
          out.add_text(key.name, key.text(r, context));
        else if (key.time_reached)
          out.add(key.name, t_end * 1e6, key.decimals);
        else if (key.scientific)
          out.add_scientific(key.name, key.number(r));
        else
          out.add(key.name, key.number(r), key.decimals);
      }
    // One pair per Output/Probe points entry, named after the probe.
    for (const auto &peak : r.probe_peaks)
      {
        const std::string key = "probe_" + peak.name + "_peak_von_mises";
        out.add(key + "_MPa", peak.von_mises * 1e-6, 3);
        out.add(key + "_time_us", peak.time * 1e6, 3);
      }
    return out;
  }
} // namespace fgimpact
