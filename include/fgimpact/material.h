#ifndef fgimpact_material_h
#define fgimpact_material_h

#include <deal.II/base/parameter_handler.h>

namespace fgimpact
{
  using namespace dealii;

  /**
   * How element properties are represented inside an element.
   */
  enum class PropertyMode
  {
    /// Nodal values interpolated with the element shape functions at every
    /// quadrature point (the paper's Eq. 3.3, graded finite elements).
    graded,
    /// One value per element, taken at the element centre (conventional
    /// piecewise homogeneous elements).
    homogeneous,
    /// E(z), rho(z) of Eq. 2.1 evaluated at every quadrature point: no
    /// interpolation, so a steep gradient (large n) is not smeared over an
    /// element.
    pointwise
  };

  /**
   * Power-law functionally graded material, Eq. 2.1 of Asemi & Salami (2015):
   *
   *   P(z) = P_c + (P_m - P_c) (z/h)^n,
   *
   * z measured from the bottom face, so the bottom (z = 0) is pure ceramic and
   * the top (z = h) pure metal; n = 0 gives pure metal throughout.  Poisson's
   * ratio is constant.  All quantities in SI units (Pa, kg/m^3, m).
   */
  class FunctionallyGradedMaterial
  {
  public:
    struct Parameters
    {
      double       metal_youngs_modulus   = 70e9;
      double       metal_density          = 2707.;
      double       ceramic_youngs_modulus = 380e9;
      double       ceramic_density        = 3800.;
      double       poissons_ratio         = 0.3;
      double       power_law_index        = 1.;
      PropertyMode property_mode          = PropertyMode::graded;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    FunctionallyGradedMaterial(const Parameters &parameters,
                               const double      thickness);

    /// Metal volume fraction (z/h)^n at height z (m), clipped to [0, h].
    double
    metal_volume_fraction(const double z) const;

    /// Young's modulus E(z) in Pa.
    double
    youngs_modulus(const double z) const;

    /// Mass density rho(z) in kg/m^3.
    double
    density(const double z) const;

    double
    poissons_ratio() const
    {
      return parameters.poissons_ratio;
    }

    /// Lame's first parameter per unit Young's modulus, lambda/E.
    double
    lambda_per_E() const;

    /// Shear modulus per unit Young's modulus, mu/E = 1/(2(1+nu)).
    double
    mu_per_E() const;

    /// Total metal volume fraction of the whole thickness, Eq. 2.2:
    /// V_m = 1/(1+n).
    double
    total_metal_volume_fraction() const;

    /// Exact through-thickness integral of rho(z) dz (kg/m^2), used to check
    /// the assembled mass.
    double
    mass_per_unit_area() const;

    const Parameters &
    get_parameters() const
    {
      return parameters;
    }
    double
    thickness() const
    {
      return h;
    }

  private:
    const Parameters parameters;
    const double     h;
  };
} // namespace fgimpact

#endif
