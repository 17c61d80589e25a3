// The impact scene (scene.h): built once from the parameters and the
// material, read by everything that needs the impactor or where it strikes.

#include <fgimpact/contact/contact_law.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/problem/scene.h>
#include <fgimpact/problem/symmetry.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  double
  expected_contact_radius(const Parameters                 &parameters,
                          const FunctionallyGradedMaterial &material,
                          const double                      thickness)
  {
    const Impactor impactor(parameters.impactor);
    const double   R = impactor.radius();
    if (parameters.problem_type == ProblemType::static_load &&
        parameters.static_analysis.load ==
          StaticAnalysisParameters::Load::sphere)
      return std::sqrt(R * parameters.static_analysis.indentation);
    // Hertz's E* of plate and ball (a softer ball: a larger contact).
    const double Q =
      combined_indentation_modulus(top_face_modulus(material, thickness),
                                   impactor.indentation_modulus());
    return hertz_impact_contact_radius(Q,
                                       R,
                                       impactor.mass(),
                                       impactor.initial_velocity());
  }



  Scene::Scene(const Parameters                 &parameters,
               const FunctionallyGradedMaterial &material,
               const double                      share)
    : ball(parameters.impactor)
  {
    const auto  &g = parameters.geometry;
    const double h = g.thickness;
    const auto   p = ball.impact_point(g.length, g.width);
    point          = Point<3>(p[0], p[1], h);
    contact_radius = fgimpact::expected_contact_radius(parameters, material, h);
    modulus        = fgimpact::top_face_modulus(material, h);
    part_share     = share;
  }



  ValiditySetup
  validity_setup(const Parameters    &parameters,
                 const Scene         &scene,
                 const ContactModel  &contact,
                 const ImpactResults &results)
  {
    const Impactor::Parameters &ball = scene.impactor().get_parameters();
    ValiditySetup               setup;
    setup.strength        = parameters.strength;
    setup.impact_point    = scene.impact_point();
    setup.sphere_radius   = ball.radius;
    setup.point_force     = !contact.reports_contact_area();
    setup.excluded_radius = std::max(2. * results.model.element_size_under_ball,
                                     3. * scene.expected_contact_radius());
    setup.rigid_ball      = !ball.elastic;
    setup.ball_modulus    = scene.impactor().elastic_indentation_modulus();
    return setup;
  }



  LocalRefinement
  contact_refinement_of(const Parameters &parameters, const Scene &scene)
  {
    LocalRefinement refinement;
    refinement.centre         = scene.impact_point();
    const double a_max        = scene.expected_contact_radius();
    refinement.contact_radius = a_max;
    refinement.levels =
      parameters.geometry.contact_refinement_auto ?
        automatic_contact_refinement_levels(parameters, a_max) :
        parameters.geometry.contact_refinement_levels;
    refinement.radius = (parameters.geometry.contact_refinement_radius > 0. ?
                           parameters.geometry.contact_refinement_radius :
                           1.5 * a_max);
    return refinement;
  }



  unsigned int
  automatic_contact_refinement_levels(const Parameters &parameters,
                                      const double      contact_radius)
  {
    if (!parameters.uses_resolved_contact())
      return 0;
    // The fewest levels whose in-plane element size h0 / 2^L puts
    // contact_elements_per_radius element sizes across the estimated
    // largest contact radius (doc/contact.md derives the number).
    const auto  &g = parameters.geometry;
    const double h0 =
      std::min(g.length / g.subdivisions_x, g.width / g.subdivisions_y);
    unsigned int levels = 0;
    while (levels < 12 &&
           h0 / std::pow(2., levels) >
             contact_radius / contact_elements_per_radius * (1. + 1e-12))
      ++levels;
    return levels;
  }



  Scene
  scene_without_mesh(const Parameters &parameters)
  {
    const SymmetricPart              part = resolve_symmetry(parameters);
    const PlateGeometry              geometry(parameters.geometry, part.cut);
    const FunctionallyGradedMaterial material(parameters.material,
                                              geometry.thickness());
    return Scene(parameters, material, geometry.share());
  }
} // namespace fgimpact
