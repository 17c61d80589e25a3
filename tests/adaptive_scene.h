// The scene of the adaptive-mesh tests (adaptive_mesh, adaptive_estimate):
// the quarter of the default plate with the resolved sphere, and the five
// headline numbers they compare, by column and summary key.

#ifndef fgimpact_tests_adaptive_scene_h
#define fgimpact_tests_adaptive_scene_h

#include <string>
#include <utility>
#include <vector>

namespace fgimpact_tests::adaptive
{
  /// The five headline numbers: CSV column (and summary.txt key with the
  /// unit), and the key stem of their estimates and changes.
  inline const std::vector<std::pair<std::string, std::string>> &
  headline()
  {
    static const std::vector<std::pair<std::string, std::string>> h = {
      {"peak_contact_force_N", "peak_contact_force"},
      {"contact_duration_us", "contact_duration"},
      {"departure_velocity_m_s", "departure_velocity"},
      {"max_midplane_deflection_um", "max_midplane_deflection"},
      {"max_approach_um", "max_approach"}};
    return h;
  }

  /// The quarter of the default plate, resolved sphere, End time = auto,
  /// no VTU and no probes: base NX x NX/2 x NX/10 (whole plate), `levels`
  /// contact refinement levels under the ball.
  inline std::string
  scene(const unsigned int nx, const unsigned int levels)
  {
    return "subsection Geometry\n set Symmetry = quarter\n"
           " set Subdivisions x = " +
           std::to_string(nx) +
           "\n set Subdivisions y = " + std::to_string(nx / 2) +
           "\n set Subdivisions z = " + std::to_string(nx / 10) +
           "\n set Contact refinement levels = " + std::to_string(levels) +
           "\nend\nsubsection Contact\n set Model = resolved sphere\nend\n"
           "subsection Time integration\n set End time = auto\nend\n"
           "subsection Output\n set VTU interval = 0\n set Log interval = 0\n"
           " set Print timing = false\n set Probe points =\nend\n";
  }
} // namespace fgimpact_tests::adaptive

#endif
