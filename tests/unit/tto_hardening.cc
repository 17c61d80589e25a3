// The graded hardening of Material/Plasticity = J2 (issue 37): the
// Tamura-Tomota-Ozawa mixture's own hardening, against an independent
// implementation of the rule, a uniaxial bar of the two phases.
//
// The bar: the metal bilinear (E_m, yield Y_m, tangent E_m H_m/(E_m + H_m)),
// the ceramic elastic (E_c); the phases' stresses and strains satisfy
// sigma = V_m sigma_m + V_c sigma_c, eps = V_m eps_m + V_c eps_c and
// sigma_c - sigma_m = q (eps_m - eps_c) (the softer metal strains more,
// the stiffer ceramic carries more: q > 0).  For a given eps the metal strain
// is found by bisection (no formula of the program is used).  From it:
//  - the mixture's yield point (where the metal yields) against
//    GradedStrength::yield_strength(z);
//  - its modulus E before and tangent E_t after, by differences (exact for
//    a bilinear metal), and H = E E_t / (E - E_t), the slope of stress
//    over plastic strain, against GradedStrength::hardening_modulus(z)
//    with Graded hardening = TTO tangent;
//  - the old rule, scaled as yield (H_m Y(z) / Y_m), still offered.
// At V_m = 0.9 (q = 4.5 GPa, the paper's phases, H_m = 0.3 GPa) the
// issue's numbers: TTO 0.83 GPa against 0.30 GPa scaled as yield.

#include <deal.II/base/mpi.h>

#include <fgimpact/material/strength.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::tto_hardening
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    struct Bar
    {
      double Vm, q, Em, Ec, Ym, Hm;

      double
      metal_stress(const double eps_m) const
      {
        const double eps_y = Ym / Em;
        const double Et    = Em * Hm / (Em + Hm);
        return eps_m <= eps_y ? Em * eps_m : Ym + Et * (eps_m - eps_y);
      }

      /// The residual of the transfer law at metal strain eps_m for the
      /// bar's strain eps: increasing in eps_m.
      double
      residual(const double eps, const double eps_m) const
      {
        const double Vc    = 1. - Vm;
        const double eps_c = (eps - Vm * eps_m) / Vc;
        return metal_stress(eps_m) + q * eps_m - (Ec + q) * eps_c;
      }

      /// The metal strain and the bar's stress at strain eps.
      std::pair<double, double>
      at(const double eps) const
      {
        if (Vm == 1.)
          return {eps, metal_stress(eps)};
        double lo = -1., hi = 1.;
        for (unsigned int i = 0; i < 200; ++i)
          {
            const double mid                    = 0.5 * (lo + hi);
            (residual(eps, mid) > 0. ? hi : lo) = mid;
          }
        const double eps_m = 0.5 * (lo + hi);
        const double eps_c = (eps - Vm * eps_m) / (1. - Vm);
        return {eps_m, Vm * metal_stress(eps_m) + (1. - Vm) * Ec * eps_c};
      }

      /// The bar's strain at which the metal yields (bisection on eps).
      double
      yield_strain() const
      {
        double lo = 0., hi = 1.;
        for (unsigned int i = 0; i < 200; ++i)
          {
            const double mid                    = 0.5 * (lo + hi);
            (at(mid).first > Ym / Em ? hi : lo) = mid;
          }
        return 0.5 * (lo + hi);
      }
    };
  } // namespace



  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    // The paper's phases graded with n = 1: V_m = z/h.
    FunctionallyGradedMaterial::Parameters mp;
    const double                           h = 0.02;
    const FunctionallyGradedMaterial       material(mp, h);
    GradedStrength::Parameters             sp;
    double worst_yield = 0, worst_hardening = 0, worst_scaled = 0;
    double tto_at_09 = 0, scaled_at_09 = 0;
    for (const double q : {4.5e9, 90e9, 0.})
      for (const double Hm : {3e8, 0., 5e9})
        for (const double Vm : {0.5, 0.7, 0.9, 1.})
          {
            sp.tto_q                   = q;
            sp.metal_hardening_modulus = Hm;
            sp.graded_hardening =
              GradedStrength::Parameters::GradedHardening::tto_tangent;
            const GradedStrength tto(sp, material);
            sp.graded_hardening =
              GradedStrength::Parameters::GradedHardening::scaled_as_yield;
            const GradedStrength scaled(sp, material);
            const Bar            bar{Vm,
                          q,
                          mp.metal_youngs_modulus,
                          mp.ceramic_youngs_modulus,
                          sp.metal_yield_strength,
                          Hm};
            const double         z     = Vm * h;
            const double         eps_y = bar.yield_strain();
            const double         Y     = bar.at(eps_y).second;
            const double         E = bar.at(0.5 * eps_y).second / (0.5 * eps_y);
            const double         Et =
              (bar.at(3. * eps_y).second - bar.at(2. * eps_y).second) / eps_y;
            const double H = E * Et / (E - Et);
            worst_yield =
              std::max(worst_yield, std::abs(tto.yield_strength(z) / Y - 1.));
            worst_hardening = std::max(worst_hardening,
                                       std::abs(tto.hardening_modulus(z) - H) /
                                         std::max(H, 1e6));
            worst_scaled    = std::max(worst_scaled,
                                    std::abs(scaled.hardening_modulus(z) -
                                             Hm * tto.yield_strength(z) /
                                               sp.metal_yield_strength) /
                                      std::max(Hm, 1e6));
            if (q == 4.5e9 && Hm == 3e8 && Vm == 0.9)
              {
                tto_at_09    = tto.hardening_modulus(z);
                scaled_at_09 = scaled.hardening_modulus(z);
              }
          }
    // Verdicts only: the differences are bisection round-off (1e-10).
    const bool yield_ok     = worst_yield < 1e-7,
               hardening_ok = worst_hardening < 1e-6,
               scaled_ok    = worst_scaled < 1e-12;
    std::printf("the bar's yield stress against yield_strength(z) (q = 4.5, "
                "90, 0 GPa; H_m = 0.3, 0, 5 GPa; V_m = 0.5 ... 1): within "
                "1e-7 relative: %s\n",
                yield_ok ? "yes" : "NO");
    std::printf("the bar's hardening E E_t / (E - E_t) against "
                "hardening_modulus(z), Graded hardening = TTO tangent: within "
                "1e-6 relative: %s\n",
                hardening_ok ? "yes" : "NO");
    std::printf("scaled as yield: H_m Y(z) / Y_m: %s\n",
                scaled_ok ? "yes" : "NO");
    std::printf("V_m = 0.9, q = 4.5 GPa, H_m = 0.3 GPa: TTO %.3f GPa, scaled "
                "as yield %.3f GPa\n",
                tto_at_09 * 1e-9,
                scaled_at_09 * 1e-9);
    const bool ok = yield_ok && hardening_ok && scaled_ok &&
                    std::abs(tto_at_09 - 0.83e9) < 0.01e9 &&
                    std::abs(scaled_at_09 - 0.30e9) < 0.01e9;
    std::printf("%s\n", ok ? "all checks passed" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::tto_hardening
