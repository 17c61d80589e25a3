#ifndef fgimpact_strength_h
#define fgimpact_strength_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>

#include <fgimpact/material/material.h>

#include <limits>

namespace fgimpact
{
  using namespace dealii;

  /// The largest ratio of a stress to its strength found so far, with
  /// where (m) and when (s) it occurred.
  struct StrengthPeak
  {
    double   ratio    = 0; // stress / strength
    double   stress   = 0; // Pa
    double   strength = 0; // Pa
    Point<3> point;        // m
    double   time = 0;     // s

    /// Not checked: every number NaN (summary.txt writes none).
    static StrengthPeak
    unchecked()
    {
      const double nan = std::numeric_limits<double>::quiet_NaN();
      return {nan, nan, nan, Point<3>(nan, nan, nan), nan};
    }
  };

  /**
   * The strengths of the two phases (Material/Metal yield strength,
   * Ceramic tensile strength, TTO q), and the graded strengths that the
   * validity report compares the elastic stresses with:
   *
   *  - the metal-rich part (V_m >= 1/2) yields at the Tamura-Tomota-Ozawa
   *    (TTO) rule of mixtures, the ceramic phase elastic,
   *      Y(V_m) = Y_m [V_m + (q + E_m)/(q + E_c) E_c/E_m (1 - V_m)],
   *    q = (sigma_c - sigma_m)/(eps_c - eps_m) the stress transfer between
   *    the phases (q -> infinity: equal strains; q = 0: equal stresses;
   *    Jin, Paulino & Dodds, Eng. Fract. Mech. 70 (2003) 1885);
   *  - the ceramic-rich part (V_m < 1/2) breaks in tension at the linear
   *    rule of mixtures of the ceramic's tensile strength and the metal's
   *    yield strength, S_t = (1 - V_m) S_c + V_m Y_m (an estimate: brittle
   *    failure of a mixture has no established rule).
   *
   * A strength of 0 switches its check off.  Units: Pa.
   */
  class GradedStrength
  {
  public:
    /// Material/Plasticity.
    enum class Plasticity
    {
      none, // the paper: elastic
      j2    // the metal-rich part: J2 with the TTO strengths
    };

    struct Parameters
    {
      /// Material/Graded hardening.
      enum class GradedHardening
      {
        tto_tangent,    // the TTO mixture's own tangent (default)
        scaled_as_yield // H_m Y(z) / Y_m (before issue 37)
      };

      Plasticity      plasticity               = Plasticity::none;
      GradedHardening graded_hardening         = GradedHardening::tto_tangent;
      double          metal_hardening_modulus  = 3e8; // Pa
      double          metal_yield_strength     = 275e6;
      double          ceramic_tensile_strength = 260e6;
      double          tto_q                    = 4.5e9;

      /// The entries, in the Material subsection.
      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    GradedStrength(const Parameters                 &parameters,
                   const FunctionallyGradedMaterial &material);

    /// Whether the point at height z (m) is metal-rich, V_m >= 1/2.
    bool
    metal_rich(const double z) const;

    /// Y(V_m(z)) of the TTO rule (Pa); 0 if the check is off.
    double
    yield_strength(const double z) const;

    /// The hardening modulus H(z) of Plasticity = J2 (Pa).  TTO tangent:
    /// the mixture's uniaxial slope of stress over plastic strain,
    /// H = E E_t / (E - E_t), E and E_t the TTO rule's moduli of the
    /// mixture with the metal's elastic modulus E_m and its tangent
    /// E_m H_m / (E_m + H_m) (doc/plasticity.md); scaled as yield:
    /// H_m Y(z) / Y_m.
    double
    hardening_modulus(const double z) const;

    /// The TTO rule's modulus of the mixture at height z (m) whose metal
    /// phase has the modulus (or tangent) E_metal (Pa), the ceramic its
    /// elastic one: [(q + E_c) V_m E_metal + (q + E_metal) V_c E_c] /
    /// [(q + E_c) V_m + (q + E_metal) V_c].
    double
    tto_modulus(const double z, const double E_metal) const;

    /// S_t(V_m(z)) (Pa); 0 if the check is off.
    double
    tensile_strength(const double z) const;

    const Parameters &
    get_parameters() const
    {
      return parameters;
    }

  private:
    const Parameters                  parameters;
    const FunctionallyGradedMaterial &material;
  };
} // namespace fgimpact

#endif
