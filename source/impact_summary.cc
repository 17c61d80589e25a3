#include <fgimpact/impact_summary.h>
#include <fgimpact/postprocessing.h>

#include <algorithm>

namespace fgimpact
{
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
