// The graded strengths of the validity report (strength.h).

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/material/strength.h>

namespace fgimpact
{
  namespace
  {
    /// The names of Material/Plasticity.
    const SelectionTable<GradedStrength::Plasticity> &
    plasticity_names()
    {
      using P                              = GradedStrength::Plasticity;
      static const SelectionTable<P> names = {{"none", P::none}, {"J2", P::j2}};
      return names;
    }

    /// The names of Material/Graded hardening.
    const SelectionTable<GradedStrength::Parameters::GradedHardening> &
    hardening_names()
    {
      using H = GradedStrength::Parameters::GradedHardening;
      static const SelectionTable<H> names = {{"TTO tangent", H::tto_tangent},
                                              {"scaled as yield",
                                               H::scaled_as_yield}};
      return names;
    }
  } // namespace


  namespace
  {
    /// The metal's yield and the ceramic's tensile strength.
    void
    add_strength_rows(ParameterTable<GradedStrength::Parameters> &t)
    {
      using P = GradedStrength::Parameters;

      t.add(
        "Metal yield strength",
        &P::metal_yield_strength,
        Patterns::Double(0., 1e11),
        "Yield strength Y_m of the metal phase: the validity report compares "
        "the von Mises stress of the metal-rich part (V_m >= 1/2) with the "
        "graded yield strength of the TTO rule (TTO q). Default: an "
        "aluminium alloy 6061-T6 (the paper's metal, E_m = 70 GPa, rho = "
        "2707 kg/m^3, is an aluminium it does not name). 0 switches the check "
        "off. Unit: Pa.");
      t.add(
        "Ceramic tensile strength",
        &P::ceramic_tensile_strength,
        Patterns::Double(0., 1e11),
        "Tensile strength S_c of the ceramic phase: the validity report "
        "compares the largest principal stress of the ceramic-rich part "
        "(V_m < 1/2) with (1 - V_m) S_c + V_m Y_m. Default: a dense alumina "
        "(the paper's ceramic, E_c = 380 GPa, rho = 3800 kg/m^3; tensile "
        "strengths of 200-300 MPa, flexural about 380 MPa). 0 switches the "
        "check off. Unit: Pa.");
    }

    /// Plasticity and its hardening.
    void
    add_plasticity_rows(ParameterTable<GradedStrength::Parameters> &t)
    {
      using P = GradedStrength::Parameters;
      t.add("TTO q",
            &P::tto_q,
            Patterns::Double(0., 1e13),
            "The Tamura-Tomota-Ozawa stress transfer q = (sigma_c - sigma_m) / "
            "(eps_m - eps_c) of the metal-ceramic mixture (the softer metal "
            "strains more, the ceramic carries more): the graded yield "
            "strength is Y_m [V_m + (q + E_m)/(q + E_c) E_c/E_m (1 - V_m)]. "
            "Large q: the phases strain alike; 0: they carry the same stress. "
            "Default 4.5 GPa, the value used for Ti/TiB (Jin, Paulino & Dodds "
            "2003); Ni/Al2O3 measured about 90 GPa. Unit: Pa.");
      t.add(
        "Plasticity",
        &P::plasticity,
        plasticity_names(),
        "none: the plate is elastic (the paper). J2: the metal-rich part "
        "(V_m >= 1/2) is elastic-plastic, small-strain von Mises plasticity "
        "with linear isotropic hardening, its yield strength graded by the "
        "TTO rule (Metal yield strength, TTO q), the ceramic phase elastic; "
        "needs Contact/Model = resolved sphere for an impact (a point force "
        "has no converged stress under it).");
      t.add(
        "Metal hardening modulus",
        &P::metal_hardening_modulus,
        Patterns::Double(0., 1e12),
        "Plasticity = J2: the metal's hardening modulus H_m = d sigma_y / d "
        "eps_p (linear isotropic hardening), graded by Graded hardening. 0 = "
        "a perfectly plastic metal (the mixture still hardens with TTO "
        "tangent: its ceramic stays elastic). Default: 6061-T6, whose "
        "true stress rises from 275 to about 310 MPa over 12 % plastic "
        "strain. Unit: Pa.");
      t.add("Graded hardening",
            &P::graded_hardening,
            hardening_names(),
            "Plasticity = J2: the hardening modulus H(z) of the metal-rich "
            "mixture. TTO tangent: the mixture's own, from the TTO rule with "
            "the same q applied to the metal's tangent E_m H_m/(E_m + H_m) and "
            "the elastic ceramic, H = E E_t/(E - E_t) (E, E_t: the mixture's "
            "TTO modulus and tangent; at V_m = 0.9, q = 4.5 GPa: 0.83 GPa). "
            "scaled as yield: H_m Y(z)/Y_m (0.30 GPa there), the earlier rule, "
            "an assumption without a derivation, kept to compare.");
    }

    /// The entries of GradedStrength::Parameters that set a member as they
    /// stand.
    const ParameterTable<GradedStrength::Parameters> &
    strength_table()
    {
      using P                              = GradedStrength::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        add_strength_rows(t);
        add_plasticity_rows(t);
        return t;
      }();
      return table;
    }
  } // namespace



  void
  GradedStrength::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    strength_table().declare(prm);
    prm.leave_subsection();
  }



  void
  GradedStrength::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Material");
    strength_table().parse(prm, *this);
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
  GradedStrength::tto_modulus(const double z, const double E_metal) const
  {
    const double Vm = material.metal_volume_fraction(z), Vc = 1. - Vm;
    const double q  = parameters.tto_q;
    const double Ec = material.get_parameters().ceramic_youngs_modulus;
    return ((q + Ec) * Vm * E_metal + (q + E_metal) * Vc * Ec) /
           ((q + Ec) * Vm + (q + E_metal) * Vc);
  }



  double
  GradedStrength::hardening_modulus(const double z) const
  {
    const double Ym = parameters.metal_yield_strength;
    const double Hm = parameters.metal_hardening_modulus;
    if (Ym <= 0.)
      return 0.;
    if (parameters.graded_hardening ==
        Parameters::GradedHardening::scaled_as_yield)
      return Hm * yield_strength(z) / Ym;
    // The mixture's tangent after the metal yields follows from the same
    // transfer law applied to increments (the metal at its tangent, the
    // ceramic elastic); its slope over the plastic strain is E E_t/(E -
    // E_t).  V_m = 1: H_m; H_m = 0: still > 0 for V_m < 1.
    const double Em = material.get_parameters().metal_youngs_modulus;
    const double E  = tto_modulus(z, Em);
    const double Et = tto_modulus(z, Em * Hm / (Em + Hm));
    return E * Et / (E - Et);
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
