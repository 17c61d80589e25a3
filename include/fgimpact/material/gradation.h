#ifndef fgimpact_gradation_h
#define fgimpact_gradation_h

#include <fgimpact/base/selection.h>

#include <limits>
#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  /// Young's modulus E (Pa), Poisson's ratio nu and density rho (kg/m^3)
  /// at one point.
  struct IsotropicProperties
  {
    double E;
    double nu;
    double rho;
  };

  /// How the properties vary through the thickness (Material/Gradation).
  enum class Gradation
  {
    /// Metal volume fraction V_m = zeta^n (Eq. 2.1).
    power_law,
    /// P(zeta) = P_c exp(ln(P_m / P_c) zeta) for E and rho, nu linear.
    exponential,
    /// Chung & Chi's two power laws, V_m = (2 zeta)^n / 2 below the
    /// mid-plane, 1 - (2 - 2 zeta)^n / 2 above.
    sigmoid,
    /// E, nu, rho interpolated linearly in a table of zeta (a CSV file).
    tabulated
  };

  /// How the two constituents' properties are combined at a volume
  /// fraction (Material/Homogenization).
  enum class Homogenization
  {
    /// P = P_c + (P_m - P_c) V_m for E, nu and rho (Voigt on E).
    rule_of_mixtures,
    /// Mori-Tanaka bulk and shear moduli, metal matrix and ceramic
    /// inclusions; rho by the rule of mixtures.
    mori_tanaka
  };

  /// The names of Material/Gradation and Material/Homogenization.
  const SelectionTable<Gradation> &
  gradation_names();
  /// "name: help ..." of every gradation law (Material/Gradation's help).
  std::string
  gradation_help();
  const SelectionTable<Homogenization> &
  homogenization_names();

  /// The two constituents: metal (top face, z = h) and ceramic (bottom).
  struct Constituents
  {
    IsotropicProperties metal;
    IsotropicProperties ceramic;
  };

  /// The properties of the mixture at metal volume fraction V_m in [0, 1].
  IsotropicProperties
  homogenize(const Constituents  &constituents,
             const double         metal_fraction,
             const Homogenization homogenization);

  /**
   * A measured through-thickness profile: rows (zeta = z/h from the bottom
   * face, E in Pa, nu, rho in kg/m^3), zeta strictly increasing from 0 to 1,
   * interpolated piecewise linearly.
   */
  class TabulatedProfile
  {
  public:
    /// Read a CSV file (comma or whitespace separated; '#' starts a
    /// comment; one optional header line).  Throws ExcMessage with one line
    /// naming the file and line on a malformed or non-monotone table.
    explicit TabulatedProfile(const std::string &filename);

    /// From rows directly (tests); the same checks, `name` in messages.
    TabulatedProfile(const std::vector<std::vector<double>> &rows,
                     const std::string                      &name);

    IsotropicProperties
    operator()(const double zeta) const;

    /// Whether nu is the same in every row.
    bool
    constant_poissons_ratio() const;

  private:
    void
    check(const std::vector<unsigned int> &line_numbers,
          const std::string               &name) const;

    std::vector<double>              zeta;
    std::vector<IsotropicProperties> values;
  };

  /**
   * The gradation law: properties at zeta = z/h (0 = bottom face, ceramic;
   * 1 = top face, metal, for the power law, exponential and sigmoid laws).
   */
  class GradationLaw
  {
  public:
    virtual ~GradationLaw() = default;

    virtual IsotropicProperties
    properties(const double zeta) const = 0;

    /// Whether nu is the same at every zeta (the graded elements then use
    /// it exactly, without interpolation).
    virtual bool
    constant_poissons_ratio() const = 0;

    /// The metal's volume fraction over the whole thickness for a law
    /// that grades a volume fraction (power law, sigmoid); NaN for a law
    /// that gives the properties themselves (exponential, tabulated).
    virtual double
    total_metal_volume_fraction() const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }

    /// The metal volume fraction V_m at zeta for a law that grades one;
    /// NaN for the others.
    virtual double
    metal_fraction(const double /*zeta*/) const
    {
      return std::numeric_limits<double>::quiet_NaN();
    }
  };

  /// The factory (the registry in gradation.cc): `profile` is read only
  /// for Gradation::tabulated.  Throws if Mori-Tanaka is asked of a law
  /// without a volume fraction.
  std::unique_ptr<GradationLaw>
  create_gradation_law(const Gradation      gradation,
                       const Homogenization homogenization,
                       const Constituents  &constituents,
                       const double         index,
                       const std::string   &profile_file);
} // namespace fgimpact

#endif
