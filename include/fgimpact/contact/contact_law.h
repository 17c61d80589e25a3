#ifndef fgimpact_contact_law_h
#define fgimpact_contact_law_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/contact/impactor.h>
#include <fgimpact/material/material.h>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Elastic constants of a transversely isotropic material whose axis of
   * symmetry is z (plane of isotropy xy).  nu_xz is the ratio with
   * eps_z = -nu_xz sigma_x / E_x, i.e. compliance S_13 = -nu_xz / E_x.
   * Units: Pa, dimensionless.
   */
  struct TransverselyIsotropicConstants
  {
    double E_x;   ///< in-plane Young's modulus
    double E_z;   ///< transverse Young's modulus
    double G_xz;  ///< transverse shear modulus
    double G_xy;  ///< in-plane shear modulus, E_x / (2 (1 + nu_xy))
    double nu_xy; ///< in-plane Poisson's ratio
    double nu_xz; ///< see above
  };

  /**
   * Turner's apparent (indentation) modulus Q of a transversely isotropic
   * half-space, Eqs. 2.9-2.10 of the paper in dimensionally consistent form:
   *
   *   Q = 2 / (alpha_1 alpha_3),
   *   alpha_3 = sqrt((alpha_1 + alpha_2)/2) (1 - nu_xy)/G_xy,
   *
   * (the paper prints the square root over (1 - nu_xy)/G_xy as well, which
   * leaves Q in sqrt(Pa)).  See doc/theory.md for the derivation.
   */
  double
  turner_apparent_modulus(const TransverselyIsotropicConstants &c);

  /**
   * The exact indentation modulus of a transversely isotropic half-space
   * indented along its axis of symmetry, in stiffness form (Delafargue & Ulm
   * 2004, Eq. 21, equivalent to Turner 1980):
   *
   *   M = 2 sqrt( (C11 C33 - C13^2)/C11 / (1/C44 + 2/(sqrt(C11 C33) + C13)) ).
   *
   * Computed independently of turner_apparent_modulus() (through the
   * stiffness matrix) so that each checks the other.
   */
  double
  delafargue_ulm_indentation_modulus(const TransverselyIsotropicConstants &c);

  /// The top face's indentation modulus E(h)/(1 - nu^2) (Pa): the
  /// material that a small contact sees.
  double
  top_face_modulus(const FunctionallyGradedMaterial &material,
                   const double                      thickness);

  /// Hertz's contact duration (s) of a ball (mass m in kg, speed V0 in
  /// m/s) on a rigid half-space with the law F = K alpha^{3/2}:
  /// T = 2.943 alpha_max / V0, alpha_max = (5 m V0^2 / (4 K))^{2/5}.  A
  /// lower bound of a plate's (99 us against 126 us in the default scene).
  double
  hertz_impact_duration(const double K, const double m, const double V0);

  /// Hertz's effective modulus of plate and ball, 1/Q = 1/Q_plate +
  /// 1/Q_ball (Pa); Q_plate itself for a rigid ball (Q_ball infinite).
  double
  combined_indentation_modulus(const double Q_plate, const double Q_ball);

  /**
   * The largest contact radius (m) of a rigid sphere (radius R in m, mass
   * m in kg, speed V0 in m/s) striking a half-space of indentation modulus
   * Q (Pa): a = sqrt(R alpha_max), 1/2 m V0^2 = 2/5 K alpha_max^{5/2},
   * K = 4/3 Q sqrt(R).  A plate yields, so its contact is smaller: an
   * upper estimate for the candidate set and the local refinement.
   */
  double
  hertz_impact_contact_radius(const double Q,
                              const double R,
                              const double m,
                              const double V0);

  /**
   * The modified Hertz contact law, Eqs. 2.2-2.10 and 2.8:
   *
   *   F(alpha) = beta K_h alpha^{3/2} for alpha > 0, 0 otherwise,
   *   K_h = 4/3 Q_alpha sqrt(R).
   *
   * alpha in m, F in N, K_h in N/m^{3/2}.
   */
  class HertzContactLaw
  {
  public:
    enum class PlateModulus
    {
      /// Turner's modulus of the Voigt/Reuss contact region (Eqs. 2.2-2.3,
      /// 2.9): the paper's modified Hertz law.
      turner_graded,
      /// Plain isotropic Hertz law with the top (metal) face's
      /// Q = E_m / (1 - nu^2).
      isotropic_top
    };

    struct Parameters
    {
      PlateModulus plate_modulus   = PlateModulus::turner_graded;
      double       swanson_beta    = 1.;
      double       given_stiffness = 0.; // N/m^1.5, 0: from the law

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    HertzContactLaw(const Parameters                 &parameters,
                    const FunctionallyGradedMaterial &material,
                    const Impactor                   &impactor);

    /// Apparent material of the contact region, Eqs. 2.2-2.3.
    static TransverselyIsotropicConstants
    contact_region_constants(const FunctionallyGradedMaterial &material);

    /// Q_alpha (Pa), Eq. 2.6 or 2.7.
    double
    contact_modulus() const
    {
      return Q_alpha;
    }

    /// Contact force F(alpha) = beta K_h alpha_+^{3/2} (N).
    double
    force(const double alpha) const;

    /// dF/dalpha (N/m).
    double
    force_derivative(const double alpha) const;

    /// Stored Hertz energy 2/5 beta K_h alpha_+^{5/2} (J).
    double
    potential(const double alpha) const;

  private:
    const Parameters parameters;
    double           Q_plate;
    double           Q_alpha;
    double           K_h;
  };
} // namespace fgimpact

#endif
