#include <fgimpact/app/simulator.h>
#include <fgimpact/contact/impactor.h>
#include <fgimpact/output/impact_summary.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>

#include <algorithm>
#include <cstdio>

namespace fgimpact
{
  ImpactResults
  setup_results(const PlateModel   &plate,
                const Scene        &scene,
                const ContactModel &contact,
                const double        setup_time)
  {
    ImpactResults results;
    results.n_dofs = plate.n_dofs();
    results.n_mpi_ranks =
      Utilities::MPI::n_mpi_processes(plate.get_mpi_communicator());
    results.impactor_mass = scene.impactor().mass();
    results.plate_mass    = plate.total_mass() / scene.share();
    contact.fill_results(results);
    results.setup_time = setup_time;
    return results;
  }



  ModelDescription
  describe_model(const Parameters &parameters,
                 const Scene      &scene,
                 const PlateModel &plate,
                 const double      time_step)
  {
    using Model        = ContactModelParameters::Model;
    const auto      &g = plate.get_geometry();
    const auto      &m = parameters.material;
    ModelDescription d;
    const Model      model = parameters.contact_model.model;
    d.contact_model        = ContactModelParameters::model_names().name(model);
    d.contact_refinement_levels = plate.contact_refinement().levels;
    d.element_size_under_ball   = plate.cell_size_at(scene.impact_point());
    d.time_step                 = time_step;
    d.scheme =
      TimeStepper::scheme_names().name(parameters.time_integration.scheme);
    d.element_degree   = plate.get_fe().degree;
    const double share = g.share();
    d.symmetry      = share > 0.75 ? "none" : share > 0.3 ? "half" : "quarter";
    d.property_mode = property_mode_names().name(m.property_mode);
    d.gradation     = gradation_names().name(m.gradation);
    d.power_law_index = m.power_law_index;
    d.impactor_radius = parameters.impactor.radius;
    d.thickness       = g.thickness();
    d.homogenization  = homogenization_names().name(m.homogenization);
    return d;
  }



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



  void
  write_impact_summary(const std::string   &filename,
                       const ImpactResults &r,
                       const bool           contact_area,
                       const bool           instrumentation,
                       const std::string   &status,
                       const double         t_end)
  {
    SummaryWriter out;
    // completed, interrupted (SIGINT/SIGTERM) or failed, and the time
    // the results cover.  contact_duration_us and departure_velocity_m_s
    // are `none` while the ball has not left the plate.
    out.add_text("status", status);
    out.add("time_reached_us", t_end * 1e6, 4);
    // What was modelled.
    const ModelDescription &d = r.model;
    out.add_text("contact_model", d.contact_model);
    out.add("contact_refinement_levels", d.contact_refinement_levels, 0);
    out.add("element_size_under_ball_mm", d.element_size_under_ball * 1e3, 6);
    out.add("time_step_us", d.time_step * 1e6, 6);
    out.add_text("scheme", d.scheme);
    out.add("element_degree", d.element_degree, 0);
    out.add_text("symmetry", d.symmetry);
    out.add_text("property_mode", d.property_mode);
    out.add_text("gradation", d.gradation);
    out.add("power_law_index", d.power_law_index, 6);
    out.add_text("homogenization", d.homogenization);
    std::string warnings;
    for (const auto &w : r.warnings)
      warnings += (warnings.empty() ? "" : "; ") + w;
    out.add_text("warnings", warnings.empty() ? "none" : warnings);
    out.add("peak_contact_force_N", r.peak_contact_force, 4);
    out.add("max_sampled_contact_force_N", r.max_sampled_force, 4);
    out.add("time_of_peak_force_us", r.time_of_peak_force * 1e6, 4);
    out.add("contact_duration_us", r.contact_duration * 1e6, 4);
    out.add("departure_velocity_m_s", r.departure_velocity, 7);
    out.add("max_indentation_um", r.max_indentation * 1e6, 5);
    out.add("max_midplane_deflection_um", r.max_midplane_deflection * 1e6, 5);
    out.add("max_top_deflection_um", r.max_top_deflection * 1e6, 5);
    out.add_scientific("contact_stiffness_Kh_N_m1.5", r.contact_stiffness);
    out.add_scientific("contact_modulus_Q_Pa", r.contact_modulus);
    out.add("impactor_mass_kg", r.impactor_mass, 8);
    out.add("plate_mass_kg", r.plate_mass, 8);
    out.add("impulse_N_s", r.impulse, 9);
    out.add("contact_node_offset_mm", r.contact_node_offset * 1e3, 6);
    if (contact_area)
      {
        out.add("max_contact_radius_mm", r.max_contact_radius * 1e3, 5);
        out.add("max_contact_pressure_MPa", r.max_contact_pressure * 1e-6, 4);
        out.add("max_contact_nodes", r.max_contact_nodes, 0);
        out.add("n_contact_candidates", r.n_contact_candidates, 0);
      }
    out.add("n_impacts", r.n_impacts, 0);
    out.add("n_dofs", r.n_dofs, 0);
    out.add("n_mpi_ranks", r.n_mpi_ranks, 0);
    out.add("n_time_steps", r.n_time_steps, 0);
    out.add("max_newton_iterations", r.max_newton_iterations, 0);
    out.add("linear_solver_iterations", r.linear_iterations, 0);
    out.add("max_linear_solver_iterations", r.max_linear_iterations, 0);
    out.add_scientific("max_relative_energy_drift", r.max_energy_drift);
    out.add_scientific("impulse_identity_error", r.impulse_identity_error);
    out.add("setup_s", r.setup_time, 3);
    out.add("factorization_s", r.factorization_time, 3);
    out.add("time_loop_s", r.time_loop_time, 3);
    out.add("time_per_step_ms",
            1e3 * r.time_loop_time / std::max(r.n_time_steps, 1u),
            4);
    out.add("output_s", r.output_time, 3);
    if (instrumentation)
      {
        out.add("spmv_ms", 1e3 * r.spmv_time, 4);
        out.add("solve_ms", 1e3 * r.solve_time, 4);
      }
    out.add("wall_time_s", r.wall_time, 3);
    out.write(filename);
  }
} // namespace fgimpact
