#ifndef fgimpact_impactor_h
#define fgimpact_impactor_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <string>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The spherical impactor: a point mass with radius R that moves along -z
   * (the impact direction) and carries the Hertz contact.  Its motion is one
   * scalar unknown, the displacement w_p (positive in the impact direction).
   */
  class Impactor
  {
  public:
    struct Parameters
    {
      double radius           = 0.015;
      double density          = 7800.;
      double given_mass       = 0.; // 0: mass from radius and density
      double initial_velocity = 1.;
      double impact_x         = -1.; // < 0: centre of the plate
      double impact_y         = -1.;
      bool   elastic          = false;
      double youngs_modulus   = 207e9;
      double poissons_ratio   = 0.3;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    explicit Impactor(const Parameters &parameters);

    /// Mass m_i in kg: 4/3 pi R^3 rho_i unless given directly.
    double
    mass() const;

    double
    radius() const
    {
      return parameters.radius;
    }
    double
    initial_velocity() const
    {
      return parameters.initial_velocity;
    }

    /// Indentation modulus of the impactor, Q_zi = E_i/(1 - nu_i^2) (Pa),
    /// infinite for a rigid impactor (Eq. 2.7).
    double
    indentation_modulus() const;

    /// E_i/(1 - nu_i^2) of Impactor/Young's modulus and Poisson's ratio
    /// (Pa), also for a rigid ball: the elastic ball it stands for.
    double
    elastic_indentation_modulus() const;

    /// The period of an elastic ball's lowest vibration excited by a
    /// normal impact (s): Lamb's spheroidal mode 0S2, omega R / c_s = 2.64
    /// (nu = 0.25; it moves by about 1 % over nu = 0.2-0.35), c_s the shear
    /// wave speed with the density m / (4/3 pi R^3).  Hertz's quasi-static
    /// ball needs it well below the contact duration.  0 for a rigid ball.
    double
    lowest_vibration_period() const;

    /// For an elastic ball, one log line: its lowest vibration period
    /// against the contact duration T_contact (s), a warning above 20 %
    /// (a quasi-static ball then overestimates its stiffness); empty for a
    /// rigid ball.
    std::string
    vibration_report(const double T_contact) const;

    /// Impact point on the top face (x, y) in m, given the plate size.
    Point<2>
    impact_point(const double a, const double b) const;

    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

  private:
    const Parameters parameters;
  };
} // namespace fgimpact

#endif
