#ifndef fgimpact_validity_report_h
#define fgimpact_validity_report_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/point.h>

#include <fgimpact/material/strength.h>
#include <fgimpact/output/postprocessor.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/strength_check.h>

#include <memory>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The stresses of Hertz's half-space contact at peak pressure p0, per
   * p0 (Johnson, Contact Mechanics, Eqs. 3.45 and 3.44): the largest von
   * Mises stress, on the axis at depth `depth` (per contact radius a),
   * and the radial tension at the contact's edge on the surface,
   * (1 - 2 nu)/3.
   */
  struct HertzStressPeaks
  {
    double von_mises;
    double depth;
    double edge_tension;
  };

  HertzStressPeaks
  hertz_stress_peaks(const double nu);

  /**
   * Hertz's first yield of a sphere (radius R, m) pressed on a half-space
   * of the top face (its yield stress Y in Pa, Poisson's ratio nu; E_star
   * Hertz's modulus of plate and ball, Pa): p0 = Y / (the largest von
   * Mises stress per p0, hertz_stress_peaks), the force pi^3 p0^3 R^2 /
   * (6 E*^2) (N) and the contact radius pi p0 R / (2 E*) (m).  The contact
   * radius at first yield is far below a plate's thickness (0.14 mm in the
   * default scene), so the half-space stands for the plate.
   */
  struct HertzFirstYield
  {
    double force;
    double contact_radius;
  };

  HertzFirstYield
  hertz_first_yield(const double E_star,
                    const double Y,
                    const double nu,
                    const double R);

  /// Element sizes across Hertz's first-yield contact radius below which a
  /// computed first yield depends on the mesh and is given as none (as
  /// for the contact force: 4 element sizes across the contact).
  constexpr double first_yield_min_resolution = 4.;

  /// The warning for a plastic run on the fully integrated 8-node brick
  /// (Finite element/Volumetric strain = pointwise): plastic flow keeps
  /// the volume, the brick locks, and its pressure near the plastic zone
  /// does not converge (doc/plasticity.md; test residual_traction).
  std::string
  locking_warning();

  /// The warning for a first yield that `resolution` node spacings across
  /// Hertz's contact radius do not resolve: the computed force (N; with
  /// its time if with_time) is given as none, Hertz's (N) stands.
  std::string
  first_yield_warning(const double resolution,
                      const double computed_force,
                      const double hertz_force,
                      const bool   with_time);

  /// What the validity report needs of the scene (validity_setup() in
  /// problem/scene.h builds it from the parameters).
  struct ValiditySetup
  {
    GradedStrength::Parameters strength;
    /// The impact point on the top face (m) and the ball's radius (m).
    Point<3> impact_point;
    double   sphere_radius = 0;
    /// A Hertz model's point force: the FE stress within excluded_radius
    /// (m) of the load is skipped and Hertz's closed form at the peak
    /// force stands for it.
    bool   point_force     = false;
    double excluded_radius = 0;
    /// A rigid ball, and the elastic ball's E_i/(1 - nu_i^2) that
    /// Impactor/Young's modulus and Poisson's ratio give (Pa).
    bool   rigid_ball   = true;
    double ball_modulus = 0;
  };

  /**
   * The validity report of an impact run: the elastic stresses against
   * the graded strengths at every step (StrengthCheck), Hertz's closed
   * form under a point force, and the rigid ball's stiffening.  At the end
   * it fills ImpactResults::yield_peak, tension_peak and
   * rigid_ball_modulus_excess, adds a warning per broken assumption, and
   * prints one line saying which assumptions hold and which break.  Its
   * peaks are part of a checkpoint.
   */
  class ValidityMonitor : public Postprocessor
  {
  public:
    /// With `plasticity` (Material/Plasticity = J2) the stresses checked
    /// are those the material carries, C (eps - eps_p), and a second
    /// check keeps the elastic stress C eps over the initial yield
    /// strength (ImpactResults::elastic_yield_peak).
    ValidityMonitor(const PlateModel         &plate,
                    const ValiditySetup      &setup,
                    ImpactResults            &results,
                    const ConditionalOStream &pcout,
                    const PlasticPlate       *plasticity = nullptr);

    /// A thermal pre-stress: the stresses scanned, the carried and a
    /// plastic run's elastic trial, are the total
    /// (StrengthCheck::set_prestress()).
    void
    set_prestress(const InitialStress &initial)
    {
      check->set_prestress(initial.displacement(), initial.temperature());
      // A plastic run's elastic trial too: the elastic stress of the
      // total strain.
      if (elastic_check)
        elastic_check->set_prestress(initial.displacement(),
                                     initial.temperature());
    }

    std::string
    name() const override
    {
      return "validity";
    }

    /// 2: a plastic run's section also holds the elastic check's peak.
    std::uint32_t
    checkpoint_version() const override
    {
      return 2;
    }

    void
    execute(const StepRecord &record) override;

    /// The peaks over all ranks (collective).
    void
    save(CheckpointWriter &out, const unsigned int step) override;
    void
    load(CheckpointReader &in) override;

    /// Collect the peaks over the ranks (collective).
    void
    close_output() override;

    void
    finish(const ImpactorState &ball) override;

  private:
    /// Hertz's closed form at the peak force, in place of the FE stress
    /// near a point force.
    void
    add_hertz_contact_stress();

    /// The one-line report and the warnings.
    void
    report();

    const PlateModel              &plate;
    const ValiditySetup            setup;
    const GradedStrength           strength;
    std::unique_ptr<StrengthCheck> check;
    /// A plastic run: the elastic stress's check (no plastic strain).
    std::unique_ptr<StrengthCheck> elastic_check;
    ImpactResults                 &results;
    const ConditionalOStream      &pcout;
    StrengthPeak                   yield_peak, tension_peak, elastic_yield_peak;
    /// Whether any step brought the fields (not in the study's
    /// convolution engine).
    bool fields_seen = false;
  };
} // namespace fgimpact

#endif
