#include <fgimpact/material/material.h>

#include <algorithm>

namespace fgimpact
{
  void
  FunctionallyGradedMaterial::Parameters::use_named_at(const double T_metal,
                                                       const double T_ceramic)
  {
    if (metal_material != NamedMaterial::constant)
      {
        const ConstituentState m = constituent_state(metal_material, T_metal);
        metal_youngs_modulus     = m.E;
        poissons_ratio           = m.nu;
        metal_density            = m.rho;
        metal_thermal_expansion  = m.alpha;
        metal_conductivity       = m.k;
      }
    if (ceramic_material != NamedMaterial::constant)
      {
        const ConstituentState c =
          constituent_state(ceramic_material, T_ceramic);
        ceramic_youngs_modulus    = c.E;
        ceramic_poissons_ratio    = c.nu;
        ceramic_density           = c.rho;
        ceramic_thermal_expansion = c.alpha;
        ceramic_conductivity      = c.k;
      }
  }



  Constituents
  FunctionallyGradedMaterial::constituents_at(const double T) const
  {
    Constituents phases = parameters.constituents();
    if (parameters.metal_material != NamedMaterial::constant)
      {
        const ConstituentState m =
          constituent_state(parameters.metal_material, T);
        phases.metal = {m.E, m.nu, m.rho};
      }
    if (parameters.ceramic_material != NamedMaterial::constant)
      {
        const ConstituentState c =
          constituent_state(parameters.ceramic_material, T);
        phases.ceramic = {c.E, c.nu, c.rho};
      }
    return phases;
  }



  double
  FunctionallyGradedMaterial::thermal_expansion(const double z,
                                                const double T) const
  {
    const double alpha_m =
      parameters.metal_material != NamedMaterial::constant ?
        constituent_state(parameters.metal_material, T).alpha :
        parameters.metal_thermal_expansion;
    const double alpha_c =
      parameters.ceramic_material != NamedMaterial::constant ?
        constituent_state(parameters.ceramic_material, T).alpha :
        parameters.ceramic_thermal_expansion;
    return alpha_c + (alpha_m - alpha_c) * metal_volume_fraction(z);
  }



  double
  FunctionallyGradedMaterial::conductivity(const double z, const double T) const
  {
    const double k_m = parameters.metal_material != NamedMaterial::constant ?
                         constituent_state(parameters.metal_material, T).k :
                         parameters.metal_conductivity;
    const double k_c = parameters.ceramic_material != NamedMaterial::constant ?
                         constituent_state(parameters.ceramic_material, T).k :
                         parameters.ceramic_conductivity;
    return k_c + (k_m - k_c) * metal_volume_fraction(z);
  }
} // namespace fgimpact
