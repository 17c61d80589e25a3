#include <deal.II/base/exceptions.h>

#include <fgimpact/material/temperature_dependence.h>

namespace fgimpact
{
  const SelectionTable<NamedMaterial> &
  metal_material_names()
  {
    static const SelectionTable<NamedMaterial> names = {
      {"constant", NamedMaterial::constant},
      {"SUS304", NamedMaterial::SUS304},
      {"Ti-6Al-4V", NamedMaterial::Ti6Al4V},
      {"Ni", NamedMaterial::Ni}};
    return names;
  }



  const SelectionTable<NamedMaterial> &
  ceramic_material_names()
  {
    static const SelectionTable<NamedMaterial> names = {
      {"constant", NamedMaterial::constant},
      {"Si3N4", NamedMaterial::Si3N4},
      {"ZrO2", NamedMaterial::ZrO2},
      {"Al2O3", NamedMaterial::Al2O3}};
    return names;
  }



  std::string
  named_material_help()
  {
    return "The named sets follow Touloukian's P(T) = P0 (P_-1/T + 1 + P1 T "
           "+ P2 T^2 + P3 T^3) for E, nu, alpha and k (rho constant), with "
           "the coefficients of Reddy & Chin (1998) and Shen (2009) as "
           "public codes reproduce them (doc/thermal_data.md gives each "
           "row's source; E(Si3N4, 300 K) = 322.27 GPa, E(SUS304, 300 K) = "
           "207.79 GPa). Warnings there: ZrO2's alpha grows to 47e-6/K at "
           "600 K, Ti-6Al-4V's alpha falls to 0 at 679 K, Al2O3's k rises "
           "with T; Ni's k has two branches (T <= 635 K and above).";
  }



  const ConstituentLaws &
  constituent_laws(const NamedMaterial material)
  {
    // Rows of doc/thermal_data.md (sources S1-S3): E, nu, rho, alpha, k.
    static const ConstituentLaws si3n4{
      {348.43e9, 0., -3.070e-4, 2.160e-7, -8.946e-11},
      {0.24},
      {2370.},
      {5.8723e-6, 0., 9.095e-4},
      {13.723, 0., -1.032e-3, 5.466e-7, -7.876e-11}};
    static const ConstituentLaws sus304{
      {201.04e9, 0., 3.079e-4, -6.534e-7},
      {0.3262, 0., -2.002e-4, 3.797e-7},
      {8166.},
      {12.330e-6, 0., 8.086e-4},
      {15.379, 0., -1.264e-3, 2.092e-6, -7.223e-10}};
    static const ConstituentLaws zro2{
      {244.27e9, 0., -1.371e-3, 1.214e-6, -3.681e-10},
      {0.2882, 0., 1.133e-4},
      {3000.},
      {12.766e-6, 0., -1.491e-3, 1.006e-5, -6.778e-11},
      {1.700, 0., 1.276e-4, 6.648e-8}};
    static const ConstituentLaws ti6al4v{{122.56e9, 0., -4.586e-4},
                                         {0.2884, 0., 1.121e-4},
                                         {4429.},
                                         {7.5788e-6, 0., 6.638e-4, -3.147e-6},
                                         {1.000, 0., 1.704e-2}};
    static const ConstituentLaws al2o3{
      {349.55e9, 0., -3.853e-4, 4.027e-7, -1.673e-10},
      {0.26},
      {3750.},
      {6.8269e-6, 0., 1.838e-4},
      {-14.087, -1123.6, -6.227e-3}};
    static const ConstituentLaws ni{
      {223.95e9, 0., -2.794e-4, 3.998e-9},
      {0.31},
      {8900.},
      {9.9209e-6, 0., 8.705e-4},
      {187.66, 0., -2.869e-3, 4.005e-6, -1.983e-9}};
    switch (material)
      {
        case NamedMaterial::Si3N4:
          return si3n4;
        case NamedMaterial::SUS304:
          return sus304;
        case NamedMaterial::ZrO2:
          return zro2;
        case NamedMaterial::Ti6Al4V:
          return ti6al4v;
        case NamedMaterial::Al2O3:
          return al2o3;
        case NamedMaterial::Ni:
          return ni;
        case NamedMaterial::constant:
          break;
      }
    AssertThrow(false, dealii::ExcInternalError());
    return si3n4;
  }



  ConstituentState
  constituent_state(const NamedMaterial material, const double T)
  {
    const ConstituentLaws &laws = constituent_laws(material);
    // Ni's conductivity: a second branch above 635 K (a 2.7 % step there).
    static const TouloukianLaw ni_k_high{
      58.754, 0., -4.614e-4, 6.657e-7, -1.523e-10};
    const double k =
      (material == NamedMaterial::Ni && T > 635.) ? ni_k_high(T) : laws.k(T);
    return {laws.E(T), laws.nu(T), laws.rho(T), laws.alpha(T), k};
  }
} // namespace fgimpact
