#ifndef fgimpact_scene_h
#define fgimpact_scene_h

#include <deal.II/base/point.h>

#include <fgimpact/contact/impactor.h>
#include <fgimpact/contact/resolved_contact.h>
#include <fgimpact/material/material.h>
#include <fgimpact/output/validity_report.h>
#include <fgimpact/problem/parameters.h>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The largest contact radius to expect (m): for an impact the rigid ball
   * on a half-space of the top face's modulus
   * (hertz_impact_contact_radius()), for a static sphere indentation delta
   * sqrt(R delta).  Sizes the contact refinement and the resolved
   * contact's candidate set.
   */
  double
  expected_contact_radius(const Parameters                 &parameters,
                          const FunctionallyGradedMaterial &material,
                          const double                      thickness);

  /**
   * The impact scene, built once from the parameters and the material
   * (before the mesh) and handed to the plate's refinement, the contact
   * model, the drivers, the study engine and the summary: the impactor,
   * where it strikes, the contact radius to expect, the top face's
   * modulus and the modelled part's share of the plate.  Quantities of
   * the part are converted to the whole plate with share() only.
   */
  class Scene
  {
  public:
    Scene(const Parameters                 &parameters,
          const FunctionallyGradedMaterial &material,
          const double                      share);

    const Impactor &
    impactor() const
    {
      return ball;
    }

    /// The impact point on the top face z = h (m).
    const Point<3> &
    impact_point() const
    {
      return point;
    }

    /// (x, y) of the impact point (m).
    Point<2>
    impact_point_in_plane() const
    {
      return Point<2>(point[0], point[1]);
    }

    /// expected_contact_radius() of this scene (m).
    double
    expected_contact_radius() const
    {
      return contact_radius;
    }

    /// top_face_modulus() of the plate (Pa).
    double
    top_face_modulus() const
    {
      return modulus;
    }

    /// The modelled part's share of the plate: 1 (whole), 1/2 or 1/4
    /// (Geometry/Symmetry); forces, masses and energies of the part times
    /// 1/share() are the whole plate's.
    double
    share() const
    {
      return part_share;
    }

  private:
    const Impactor ball;
    Point<3>       point;
    double         contact_radius;
    double         modulus;
    double         part_share;
  };
  /**
   * The validity report's set-up for a run of this scene (ImpactDriver and
   * the study's engine alike): the strengths, the impact point, the ball,
   * and for a Hertz model's point force (no contact area) the FE stress
   * skipped within two elements (results.model.element_size_under_ball)
   * and three expected contact radii of the load.
   */
  ValiditySetup
  validity_setup(const Parameters    &parameters,
                 const Scene         &scene,
                 const ContactModel  &contact,
                 const ImpactResults &results);


  /// Geometry/Contact refinement levels = auto: 0 unless the contact is
  /// resolved (Parameters::uses_resolved_contact()); then the fewest levels
  /// with contact_elements_per_radius in-plane element sizes across
  /// contact_radius (m, the half-space Hertz estimate).
  unsigned int
  automatic_contact_refinement_levels(const Parameters &parameters,
                                      const double      contact_radius);

  /// Geometry/Contact refinement *: centre, radius (automatic: 1.5 times
  /// the scene's expected contact radius) and levels (auto resolved).
  LocalRefinement
  contact_refinement_of(const Parameters &parameters, const Scene &scene);

  /// The scene of `parameters` without the mesh (cheap: the geometry of
  /// the modelled part and the material, for the expected contact radius
  /// and the impact point).
  Scene
  scene_without_mesh(const Parameters &parameters);
} // namespace fgimpact

#endif
