// Turner's apparent modulus (Eq. 2.9 in consistent form) against
// (1) the isotropic limit Q = E/(1 - nu^2) and
// (2) the exact indentation modulus of a transversely isotropic half-space
//     (Delafargue & Ulm 2004), computed from the stiffness matrix.
// (3) the n = 1 contact region of the paper against a value computed by hand
//     from Eqs. 2.2-2.3 (E_z = 118.2 GPa, E_x = 225 GPa, G_xz = 45.47 GPa).

#include <fgimpact/contact/contact_law.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::turner_modulus
{

  using namespace fgimpact;

  int
  test_main(int, char **)
  {
    bool ok = true;
    std::printf("isotropic limit, |Q/(E/(1-nu^2)) - 1| <= 1e-14:\n");
    for (const double E : {1e6, 70e9, 380e9})
      for (const double nu : {0., 0.25, 0.3, 0.45})
        {
          TransverselyIsotropicConstants c{
            E, E, E / (2 * (1 + nu)), E / (2 * (1 + nu)), nu, nu};
          const double exact = E / (1 - nu * nu);
          const double e1    = std::abs(turner_apparent_modulus(c) / exact - 1);
          const double e2 =
            std::abs(delafargue_ulm_indentation_modulus(c) / exact - 1);
          const bool pass = e1 <= 1e-14 && e2 <= 1e-14;
          ok              = ok && pass;
          std::printf(
            "  E = %8.2e Pa, nu = %.2f: Turner %s, Delafargue-Ulm %s\n",
            E,
            nu,
            e1 <= 1e-14 ? "exact" : "WRONG",
            e2 <= 1e-14 ? "exact" : "WRONG");
        }

    std::printf("transversely isotropic, |Turner/M_exact - 1| <= 1e-13:\n");
    const TransverselyIsotropicConstants materials[] = {
      {225e9, 118.2203e9, 45.47e9, 225e9 / 2.6, 0.3, 0.3},
      {200e9, 100e9, 40e9, 200e9 / 2.6, 0.3, 0.3},
      {100e9, 200e9, 40e9, 100e9 / 2.6, 0.3, 0.3},
      {140e9, 10e9, 5e9, 140e9 / 2.5, 0.25, 0.2},
      {10e9, 140e9, 5e9, 10e9 / 2.8, 0.4, 0.02}};
    for (const auto &c : materials)
      {
        const double Q    = turner_apparent_modulus(c);
        const double M    = delafargue_ulm_indentation_modulus(c);
        const bool   pass = std::abs(Q / M - 1) <= 1e-13;
        ok                = ok && pass;
        std::printf("  Ex = %5.1f GPa, Ez = %5.1f GPa: M = %.4f GPa, %s\n",
                    c.E_x / 1e9,
                    c.E_z / 1e9,
                    M / 1e9,
                    pass ? "equal" : "DIFFERENT");
      }

    // The paper's n = 1 contact region.
    FunctionallyGradedMaterial::Parameters p;
    p.power_law_index = 1;
    const FunctionallyGradedMaterial m(p, 0.02);
    const auto c = HertzContactLaw::contact_region_constants(m);
    // Hand values: E_z = 1/(0.5/380 + 0.5/70) GPa, E_x = 225 GPa.
    const double Ez        = 1. / (0.5 / 380e9 + 0.5 / 70e9);
    const bool   region_ok = std::abs(c.E_z / Ez - 1) < 1e-15 &&
                           std::abs(c.E_x / 225e9 - 1) < 1e-15 &&
                           std::abs(c.G_xz / (Ez / 2.6) - 1) < 1e-14;
    ok = ok && region_ok;
    std::printf(
      "n = 1 contact region E_z = %.4f GPa, E_x = %.1f GPa, G_xz = %.4f GPa: %s\n",
      c.E_z / 1e9,
      c.E_x / 1e9,
      c.G_xz / 1e9,
      region_ok ? "as Eq. 2.3" : "WRONG");
    std::printf("n = 1 Q_alpha = %.3f GPa\n", turner_apparent_modulus(c) / 1e9);

    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::turner_modulus
