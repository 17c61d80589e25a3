#ifndef fgimpact_material_h
#define fgimpact_material_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/material/gradation.h>
#include <fgimpact/material/temperature_dependence.h>

#include <cmath>
#include <functional>
#include <memory>
#include <string>

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

  /// The names of Material/Property mode.
  const SelectionTable<PropertyMode> &
  property_mode_names();

  /**
   * The nodal values that graded elements interpolate
   * (Material/Graded nodal values).
   */
  enum class GradedNodalValues
  {
    /// The profile sampled at the nodes (Eq. 3.3 as in the paper).
    sampled,
    /// The element-wise L2 projection of the profile onto the polynomials of
    /// the element's degree in z, evaluated at the nodes: each element keeps
    /// the exact layer average (and, for degree >= 1, the first moment) of
    /// E, nu and rho, and a boundary layer thinner than an element is not
    /// misread (doc/theory.md, "Layer-averaged nodal values").
    layer_average
  };

  /// The names of Material/Graded nodal values.
  const SelectionTable<GradedNodalValues> &
  graded_nodal_values_names();

  /**
   * Functionally graded material.  The default is the power law of Eq. 2.1
   * of Asemi & Salami (2015) with the rule of mixtures:
   *
   *   P(z) = P_c + (P_m - P_c) (z/h)^n,
   *
   * z measured from the bottom face, so the bottom (z = 0) is pure ceramic and
   * the top (z = h) pure metal; n = 0 gives pure metal throughout.  The other
   * gradations (exponential, sigmoid, tabulated) and the Mori-Tanaka
   * homogenization are those of gradation.h; Poisson's ratio then may vary
   * through the thickness.  All quantities in SI units (Pa, kg/m^3, m).
   */
  class FunctionallyGradedMaterial
  {
  public:
    struct Parameters
    {
      double metal_youngs_modulus   = 70e9;
      double metal_density          = 2707.;
      double ceramic_youngs_modulus = 380e9;
      double ceramic_density        = 3800.;
      double poissons_ratio         = 0.3;
      /// Negative: the same as poissons_ratio (Material/Ceramic Poisson's
      /// ratio = same).
      double ceramic_poissons_ratio = -2.;
      double power_law_index        = 1.;
      /// Linear thermal expansion coefficients (1/K) and thermal
      /// conductivities (W/(m K)) of the constituents (Thermal/*: only a
      /// temperature field reads them); the defaults are aluminium and
      /// alumina, the default scene's pair.
      double metal_thermal_expansion   = 23e-6;
      double ceramic_thermal_expansion = 7.4e-6;
      double metal_conductivity        = 204.;
      double ceramic_conductivity      = 10.4;
      /// Material/Metal material, Ceramic material: a named constituent
      /// whose properties follow temperature (temperature_dependence.h);
      /// constant: the entries above.
      NamedMaterial     metal_material      = NamedMaterial::constant;
      NamedMaterial     ceramic_material    = NamedMaterial::constant;
      PropertyMode      property_mode       = PropertyMode::graded;
      Gradation         gradation           = Gradation::power_law;
      Homogenization    homogenization      = Homogenization::rule_of_mixtures;
      GradedNodalValues graded_nodal_values = GradedNodalValues::sampled;
      /// Gradation = tabulated: the CSV file (after
      /// resolve_relative_paths(), relative to the .prm's directory).
      std::string profile_file;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Before parse_parameters(): a relative Profile file in prm is made
      /// absolute, relative to the directory of prm_file (the top-level
      /// input; "", "-" or "standard input": the working directory).
      static void
      resolve_relative_paths(ParameterHandler  &prm,
                             const std::string &prm_file);

      /// The metal and ceramic constituents.
      Constituents
      constituents() const;

      /// Whether a constituent is named (its properties follow T).
      bool
      temperature_dependent() const
      {
        return metal_material != NamedMaterial::constant ||
               ceramic_material != NamedMaterial::constant;
      }

      /// A named constituent's E, nu, rho, alpha and k written into the
      /// constant entries, the metal's at T_metal (K, the top face), the
      /// ceramic's at T_ceramic (the bottom face): what reads the
      /// constituents' constants (the contact modulus, the graded
      /// strengths) sees the faces' values.
      void
      use_named_at(const double T_metal, const double T_ceramic);
    };

    /// temperature: T(z) in K at which named constituents are evaluated
    /// (empty: their values in the constant entries, use_named_at()).
    FunctionallyGradedMaterial(
      const Parameters                    &parameters,
      const double                         thickness,
      const std::function<double(double)> &temperature = {});

    /// E (Pa), nu and rho (kg/m^3) at height z (m), z clipped to [0, h].
    IsotropicProperties
    properties(const double z) const;

    /// Young's modulus E(z) in Pa.
    double
    youngs_modulus(const double z) const;

    /// Mass density rho(z) in kg/m^3.
    double
    density(const double z) const;

    /// Poisson's ratio nu(z).
    double
    poissons_ratio(const double z) const;

    /// The linear thermal expansion coefficient alpha(z) (1/K): the rule
    /// of mixtures of the constituents' at the metal volume fraction
    /// metal_volume_fraction(z), for every gradation law.
    double
    thermal_expansion(const double z) const;

    /// The thermal conductivity k(z) (W/(m K)), by the same rule.
    double
    conductivity(const double z) const;

    /// alpha and k at height z (m) with the constituents at temperature
    /// T (K) (source/material/material_temperature.cc).
    double
    thermal_expansion(const double z, const double T) const;
    double
    conductivity(const double z, const double T) const;

    /// Whether the constituents' properties depend on temperature here
    /// (named constituents and a temperature field bound).
    bool
    follows_temperature() const
    {
      return parameters.temperature_dependent() && temperature;
    }

    /// Whether nu is the same at every z: the constitutive law then uses
    /// it exactly (no interpolation, so the default scene's numbers are
    /// those of the constant-nu program).
    bool
    constant_poissons_ratio() const;

    /// Power law: total metal volume fraction of the whole thickness,
    /// Eq. 2.2: V_m = 1/(1+n); sigmoid: 1/2.  NaN for the exponential and
    /// tabulated profiles, which have no phases (the gradation law says).
    double
    total_metal_volume_fraction() const;

    /// The metal volume fraction V_m at height z (m): the gradation's for
    /// the power law and the sigmoid; for the laws without phases
    /// (exponential, tabulated) the fraction whose rule of mixtures gives
    /// E(z), (E - E_c) / (E_m - E_c) clipped to [0, 1] (1 if E_m = E_c).
    double
    metal_volume_fraction(const double z) const;

    /// Whether the gradation grades a metal volume fraction (power law,
    /// sigmoid), so that the two phases' properties apply.
    bool
    grades_volume_fraction() const
    {
      return std::isfinite(total_metal_volume_fraction());
    }

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
    /// E, nu, rho of the constituents at T (K): the named ones' laws,
    /// the constants otherwise.
    Constituents
    constituents_at(const double T) const;

    const Parameters                    parameters;
    const double                        h;
    const std::unique_ptr<GradationLaw> law;
    const std::function<double(double)> temperature;
  };
} // namespace fgimpact

#endif
