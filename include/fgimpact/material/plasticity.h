#ifndef fgimpact_plasticity_h
#define fgimpact_plasticity_h

#include <deal.II/base/symmetric_tensor.h>

namespace fgimpact
{
  using namespace dealii;

  /// The plastic state of one material point: the plastic strain and the
  /// equivalent plastic strain (accumulated, sqrt(2/3) |d eps_p|).
  struct PlasticState
  {
    SymmetricTensor<2, 3> plastic_strain;
    double                equivalent_plastic_strain = 0;
  };

  /// What J2Plasticity::update() returns for one point and one strain.
  struct PlasticUpdate
  {
    SymmetricTensor<2, 3> stress;  // Pa
    SymmetricTensor<4, 3> tangent; // Pa, consistent with the return map
    PlasticState          state;   // at the end of the increment
    /// The plastic work of the increment per volume, sigma : d eps_p
    /// (J/m^3; the hardening energy H eps_bar^2 / 2 included), with the
    /// yield stress's mean over the increment (exact for linear
    /// hardening on a radial path).
    double plastic_work = 0;
    bool   yielding     = false;
  };

  /**
   * Small-strain J2 (von Mises) plasticity with linear isotropic hardening,
   * the yield stress sigma_y = Y + H eps_bar: the radial return of Simo &
   * Hughes (Computational Inelasticity, Box 3.1) and its consistent
   * tangent (Box 3.2), exact for this model in one step.  Units: Pa.
   *
   * For a graded plate, Y and H come from the TTO rule of mixtures
   * (GradedStrength); the ceramic-rich part is elastic (Y infinite).
   */
  class J2Plasticity
  {
  public:
    /// lambda, mu: Lame's constants (Pa); Y: initial yield stress (Pa,
    /// infinite: elastic); H: hardening modulus (Pa, 0: perfectly
    /// plastic).  Without with_tangent, `tangent` is left zero (the
    /// initial-stiffness iteration needs the stress only).
    static PlasticUpdate
    update(const double                 lambda,
           const double                 mu,
           const double                 Y,
           const double                 H,
           const SymmetricTensor<2, 3> &strain,
           const PlasticState          &old_state,
           const bool                   with_tangent = true);

    /// sigma with its deviator scaled onto the yield surface where its von
    /// Mises stress exceeds yield_stress (Pa; infinite: unchanged).  The
    /// recovered (extrapolated) stress of a plastic run: a nodal value
    /// extrapolated from admissible Gauss-point stresses can overshoot the
    /// yield surface, which no material point can.
    static SymmetricTensor<2, 3>
    admissible_stress(const SymmetricTensor<2, 3> &sigma,
                      const double                 yield_stress);
  };
} // namespace fgimpact

#endif
