// The graded strengths of the validity report (strength.h).

#include <fgimpact/material/strength.h>

namespace fgimpact
{
  void
  GradedStrength::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    prm.declare_entry(
      "Metal yield strength",
      "275e6",
      Patterns::Double(0., 1e11),
      "Yield strength Y_m of the metal phase: the validity report compares "
      "the von Mises stress of the metal-rich part (V_m >= 1/2) with the "
      "graded yield strength of the TTO rule (TTO q). Default: an "
      "aluminium alloy 6061-T6 (the paper's metal, E_m = 70 GPa, rho = "
      "2707 kg/m^3, is an aluminium it does not name). 0 switches the check "
      "off. Unit: Pa.");
    prm.declare_entry(
      "Ceramic tensile strength",
      "260e6",
      Patterns::Double(0., 1e11),
      "Tensile strength S_c of the ceramic phase: the validity report "
      "compares the largest principal stress of the ceramic-rich part "
      "(V_m < 1/2) with (1 - V_m) S_c + V_m Y_m. Default: a dense alumina "
      "(the paper's ceramic, E_c = 380 GPa, rho = 3800 kg/m^3; tensile "
      "strengths of 200-300 MPa, flexural about 380 MPa). 0 switches the "
      "check off. Unit: Pa.");
    prm.declare_entry(
      "TTO q",
      "4.5e9",
      Patterns::Double(0., 1e13),
      "The Tamura-Tomota-Ozawa stress transfer q = (sigma_c - sigma_m) / "
      "(eps_c - eps_m) of the metal-ceramic mixture: the graded yield "
      "strength is Y_m [V_m + (q + E_m)/(q + E_c) E_c/E_m (1 - V_m)]. "
      "Large q: the phases strain alike; 0: they carry the same stress. "
      "Default 4.5 GPa, the value used for Ti/TiB (Jin, Paulino & Dodds "
      "2003); Ni/Al2O3 measured about 90 GPa. Unit: Pa.");
    prm.declare_entry(
      "Plasticity",
      "none",
      Patterns::Selection("none|J2"),
      "none: the plate is elastic (the paper). J2: the metal-rich part "
      "(V_m >= 1/2) is elastic-plastic, small-strain von Mises plasticity "
      "with linear isotropic hardening, its yield strength graded by the "
      "TTO rule (Metal yield strength, TTO q), the ceramic phase elastic; "
      "needs Contact/Model = resolved sphere for an impact (a point force "
      "has no converged stress under it).");
    prm.declare_entry(
      "Metal hardening modulus",
      "3e8",
      Patterns::Double(0., 1e12),
      "Plasticity = J2: the metal's hardening modulus H_m = d sigma_y / d "
      "eps_p (linear isotropic hardening), graded as the yield strength, "
      "H_m Y(z)/Y_m. 0 = perfectly plastic. Default: 6061-T6, whose "
      "true stress rises from 275 to about 310 MPa over 12 % plastic "
      "strain. Unit: Pa.");
    prm.leave_subsection();
  }



  void
  GradedStrength::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    metal_yield_strength     = prm.get_double("Metal yield strength");
    ceramic_tensile_strength = prm.get_double("Ceramic tensile strength");
    tto_q                    = prm.get_double("TTO q");
    plasticity =
      (prm.get("Plasticity") == "J2" ? Plasticity::j2 : Plasticity::none);
    metal_hardening_modulus = prm.get_double("Metal hardening modulus");
    prm.leave_subsection();
  }



  GradedStrength::GradedStrength(const Parameters                 &parameters,
                                 const FunctionallyGradedMaterial &material)
    : parameters(parameters)
    , material(material)
  {}



  bool
  GradedStrength::metal_rich(const double z) const
  {
    return material.metal_volume_fraction(z) >= 0.5;
  }



  double
  GradedStrength::yield_strength(const double z) const
  {
    const double Ym = parameters.metal_yield_strength;
    const double Vm = material.metal_volume_fraction(z);
    const double q  = parameters.tto_q;
    const auto  &p  = material.get_parameters();
    const double Em = p.metal_youngs_modulus, Ec = p.ceramic_youngs_modulus;
    return Ym * (Vm + (q + Em) / (q + Ec) * Ec / Em * (1. - Vm));
  }



  double
  GradedStrength::hardening_modulus(const double z) const
  {
    const double Ym = parameters.metal_yield_strength;
    return Ym > 0. ?
             parameters.metal_hardening_modulus * yield_strength(z) / Ym :
             0.;
  }



  double
  GradedStrength::tensile_strength(const double z) const
  {
    if (parameters.ceramic_tensile_strength == 0.)
      return 0.;
    const double Vm = material.metal_volume_fraction(z);
    return (1. - Vm) * parameters.ceramic_tensile_strength +
           Vm * parameters.metal_yield_strength;
  }
} // namespace fgimpact
