#ifndef fgimpact_temperature_dependence_h
#define fgimpact_temperature_dependence_h

#include <fgimpact/base/selection.h>

#include <string>

namespace fgimpact
{
  /**
   * Touloukian's form of a temperature-dependent property, as Reddy & Chin
   * (1998) and Shen (2009) tabulate it:
   *
   *   P(T) = P0 (P_-1 / T + 1 + P1 T + P2 T^2 + P3 T^3),  T in K.
   *
   * P0 carries the unit; a constant property has P_-1 = P1 = P2 = P3 = 0.
   */
  struct TouloukianLaw
  {
    double P0  = 0.;
    double Pm1 = 0.;
    double P1  = 0.;
    double P2  = 0.;
    double P3  = 0.;

    double
    operator()(const double T) const
    {
      return P0 * (Pm1 / T + 1. + T * (P1 + T * (P2 + T * P3)));
    }
  };

  /// The five properties of one constituent against temperature: E (Pa),
  /// nu, rho (kg/m^3), alpha (1/K) and k (W/(m K)).
  struct ConstituentLaws
  {
    TouloukianLaw E, nu, rho, alpha, k;
  };

  /// Material/Metal material and Material/Ceramic material.
  enum class NamedMaterial
  {
    /// The constant values of the Material entries.
    constant,
    Si3N4,
    SUS304,
    ZrO2,
    Ti6Al4V,
    Al2O3,
    Ni
  };

  /// The names of Material/Metal material (constant, SUS304, Ti-6Al-4V,
  /// Ni) and Material/Ceramic material (constant, Si3N4, ZrO2, Al2O3).
  const SelectionTable<NamedMaterial> &
  metal_material_names();
  const SelectionTable<NamedMaterial> &
  ceramic_material_names();

  /// The source of the named sets, for the entries' help.
  std::string
  named_material_help();

  /// The laws of a named constituent (not NamedMaterial::constant);
  /// doc/thermal_data.md gives each row's source.  Ni's k is its branch
  /// at and below 635 K; constituent_state() switches branches.
  const ConstituentLaws &
  constituent_laws(const NamedMaterial material);

  /// A constituent's properties at one temperature.
  struct ConstituentState
  {
    double E, nu, rho, alpha, k;
  };

  /// The named constituent's properties at T (K).
  ConstituentState
  constituent_state(const NamedMaterial material, const double T);
} // namespace fgimpact

#endif
