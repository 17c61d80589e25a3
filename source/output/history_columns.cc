// The history.csv columns: name, decimals and value in one list each
// (declared in postprocessor.h), apart from the postprocessor that writes
// them (HistoryWriter); and
// the probes whose values they show.

#include <fgimpact/output/monitor.h>

namespace fgimpact
{
  const std::vector<HistoryColumn> &
  history_columns()
  {
    // Deflections and the impactor's motion positive in the impact
    // direction (-z); stresses at the mid-plane centre.
    static const std::vector<HistoryColumn> columns = {
      {"t_us", 4, [](const HistorySample &s) { return s.t * 1e6; }},
      {"contact_force_N",
       4,
       [](const HistorySample &s) { return s.contact->force; }},
      {"indentation_um",
       5,
       [](const HistorySample &s) { return s.contact->alpha * 1e6; }},
      {"approach_um",
       5,
       [](const HistorySample &s) { return (s.ball->w - s.W_mid) * 1e6; }},
      {"impactor_displacement_um",
       5,
       [](const HistorySample &s) { return s.ball->w * 1e6; }},
      {"impactor_velocity_m_s",
       7,
       [](const HistorySample &s) { return s.ball->v; }},
      {"midplane_deflection_um",
       5,
       [](const HistorySample &s) { return s.W_mid * 1e6; }},
      {"top_deflection_um",
       5,
       [](const HistorySample &s) { return s.W_top * 1e6; }},
      {"sigma_xx_mid_MPa",
       5,
       [](const HistorySample &s) { return s.sigma_mid[0][0] * 1e-6; }},
      {"sigma_yy_mid_MPa",
       5,
       [](const HistorySample &s) { return s.sigma_mid[1][1] * 1e-6; }},
      {"sigma_zz_mid_MPa",
       5,
       [](const HistorySample &s) { return s.sigma_mid[2][2] * 1e-6; }},
      {"energy_impactor_J",
       9,
       [](const HistorySample &s) { return s.E_impactor; }},
      {"energy_plate_kinetic_J",
       9,
       [](const HistorySample &s) { return s.E_kinetic; }},
      {"energy_strain_J", 9, [](const HistorySample &s) { return s.E_strain; }},
      {"energy_contact_J",
       9,
       [](const HistorySample &s) { return s.E_contact; }},
      {"energy_total_J", 9, [](const HistorySample &s) { return s.E_total; }},
      {"contact_node_deflection_um",
       5,
       [](const HistorySample &s) {
         return -s.contact->node_displacement * 1e6;
       }},
      {"newton_iterations", 0, [](const HistorySample &s) {
         return static_cast<double>(s.contact->newton_iterations);
       }}};
    return columns;
  }



  const std::vector<HistoryColumn> &
  contact_area_columns()
  {
    static const std::vector<HistoryColumn> columns = {
      {"contact_radius_mm",
       5,
       [](const HistorySample &s) { return s.contact->contact_radius * 1e3; }},
      {"max_contact_pressure_MPa",
       4,
       [](const HistorySample &s) { return s.contact->max_pressure * 1e-6; }},
      {"n_contact_nodes", 0, [](const HistorySample &s) {
         return static_cast<double>(s.contact->n_active);
       }}};
    return columns;
  }



  std::array<Point<3>, 2>
  history_probe_points(const PlateGeometry &geometry)
  {
    return {{geometry.centre(geometry.thickness() / 2),
             geometry.centre(geometry.thickness())}};
  }



  PlateSample
  probe_plate(const PointProbe                    &mid_probe,
              const PointProbe                    &top_probe,
              const TrilinosWrappers::MPI::Vector &u)
  {
    PlateSample plate;
    plate.W_mid     = -mid_probe.displacement(u)[2];
    plate.W_top     = -top_probe.displacement(u)[2];
    plate.sigma_mid = mid_probe.stress(u);
    return plate;
  }


  const std::vector<HistoryColumn> &
  plasticity_columns()
  {
    static const std::vector<HistoryColumn> columns = {
      {"energy_plastic_J",
       9,
       [](const HistorySample &s) { return s.E_plastic; }},
      {"max_plastic_strain", 6, [](const HistorySample &s) {
         return s.max_plastic_strain;
       }}};
    return columns;
  }
} // namespace fgimpact
