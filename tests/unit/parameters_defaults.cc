// The defaults are written twice: as the ParameterHandler's default
// strings (declare_parameters) and as the member initializers of the
// Parameters structs.  Parsing an empty input must give exactly the
// default-constructed Parameters, member by member.

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/app/parameters.h>

#include <cstdio>
#include <sstream>
#include <string>

using namespace fgimpact;

namespace
{
  unsigned int n_checked = 0, n_different = 0;

  template <typename T>
  void
  same(const char *name, const T &parsed, const T &initialized)
  {
    ++n_checked;
    if (!(parsed == initialized))
      {
        ++n_different;
        std::ostringstream s;
        s << "DIFFERENT: " << name;
        std::printf("%s\n", s.str().c_str());
      }
  }
} // namespace

#define SAME(member) same(#member, parsed.member, initialized.member)

int
main()
{
  dealii::ParameterHandler prm;
  Parameters::declare_parameters(prm);
  prm.parse_input_from_string("");
  Parameters parsed;
  parsed.parse_parameters(prm);
  const Parameters initialized;

  SAME(problem_type);
  SAME(accuracy.preset);
  SAME(accuracy.log_message);
  SAME(geometry.length);
  SAME(geometry.width);
  SAME(geometry.thickness);
  SAME(geometry.subdivisions_x);
  SAME(geometry.subdivisions_y);
  SAME(geometry.subdivisions_z);
  SAME(geometry.supports);
  SAME(geometry.bottom_support);
  SAME(geometry.contact_refinement_auto);
  SAME(geometry.contact_refinement_levels);
  SAME(geometry.symmetry);
  SAME(geometry.contact_refinement_radius);
  SAME(material.metal_youngs_modulus);
  SAME(material.metal_density);
  SAME(material.ceramic_youngs_modulus);
  SAME(material.ceramic_density);
  SAME(material.poissons_ratio);
  SAME(material.power_law_index);
  SAME(material.property_mode);
  SAME(finite_element.degree);
  SAME(contact.plate_modulus);
  SAME(contact.swanson_beta);
  SAME(contact.given_stiffness);
  SAME(contact_model.model);
  SAME(contact_model.paraboloid_gap);
  SAME(contact_model.modified_mass);
  SAME(contact_model.candidate_radius);
  SAME(impactor.radius);
  SAME(impactor.density);
  SAME(impactor.given_mass);
  SAME(impactor.initial_velocity);
  SAME(impactor.impact_x);
  SAME(impactor.impact_y);
  SAME(impactor.elastic);
  SAME(impactor.youngs_modulus);
  SAME(impactor.poissons_ratio);
  SAME(time_integration.scheme);
  SAME(time_integration.time_step);
  SAME(time_integration.end_time);
  SAME(time_integration.safety_factor);
  SAME(time_integration.newmark.beta);
  SAME(time_integration.newmark.gamma);
  SAME(time_integration.newton.tolerance);
  SAME(time_integration.newton.max_iterations);
  SAME(linear_solver.type);
  SAME(linear_solver.preconditioner);
  SAME(linear_solver.auto_limit);
  SAME(linear_solver.cholmod_ordering);
  SAME(linear_solver.tolerance);
  SAME(linear_solver.max_iterations);
  SAME(static_analysis.load);
  SAME(static_analysis.pressure);
  SAME(static_analysis.point_force);
  SAME(static_analysis.indentation);
  SAME(modal.n_modes);
  SAME(modal.shift);
  SAME(modal.tolerance);
  SAME(modal.max_iterations);
  SAME(output.directory);
  SAME(output.vtu_interval);
  SAME(output.log_interval);
  SAME(output.print_timing);
  SAME(output.instrumentation);
  SAME(output.vtu_compression);
  SAME(output.overwrite);

  std::printf("%u members compared, %u different\n", n_checked, n_different);
  return n_different == 0 ? 0 : 1;
}
