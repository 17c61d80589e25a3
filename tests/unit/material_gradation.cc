// Eq. 2.1 and 2.2: the gradation law's end points, the paper's n = 0 = pure
// metal convention against closed forms, and the total metal fraction V_m
// against the quadrature of the graded density.

#include <fgimpact/material/material.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::material_gradation
{

  using namespace fgimpact;

  int
  test_main(int, char **)
  {
    FunctionallyGradedMaterial::Parameters p; // paper's constituents
    const double                           h  = 0.02;
    bool                                   ok = true;
    auto check = [&](const char *what, const double value, const double exact) {
      const double err  = std::abs(value - exact) / std::abs(exact);
      const bool   pass = err <= 1e-15;
      ok                = ok && pass;
      std::printf("%-44s %s\n", what, pass ? "exact" : "WRONG");
      if (!pass)
        std::printf("   got %.17g, expected %.17g\n", value, exact);
    };

    for (const double n : {0., 0.5, 1., 3., 5., 1e4})
      {
        p.power_law_index = n;
        const FunctionallyGradedMaterial m(p, h);
        std::printf("n = %g\n", n);
        // Top (z = h) is pure metal for every n.
        check("  E(h) = E_m", m.youngs_modulus(h), 70e9);
        check("  rho(h) = rho_m", m.density(h), 2707.);
        // Bottom (z = 0) is pure ceramic except for n = 0 (pure metal).
        check("  E(0) = (n = 0 ? E_m : E_c)",
              m.youngs_modulus(0.),
              n == 0 ? 70e9 : 380e9);
        check("  rho(0) = (n = 0 ? rho_m : rho_c)",
              m.density(0.),
              n == 0 ? 2707. : 3800.);
        // Mid-plane: V = (1/2)^n.
        check("  E(h/2) = E_c + (E_m - E_c) 2^-n",
              m.youngs_modulus(h / 2),
              380e9 + (70e9 - 380e9) * std::pow(0.5, n));
        // V_m of the library (Eq. 2.2, used by the contact law) against the
        // through-thickness integral of the density it grades:
        // int rho dz = h (rho_c (1 - V_m) + rho_m V_m).  Quadrature in
        // z = h s^2 (smooth for n = 0.5), 5-point Gauss on 20,000 intervals
        // (n = 1e4 varies on 1/20,000 of s).
        const double       gauss_x[5] = {-0.9061798459386640,
                                         -0.5384693101056831,
                                         0.,
                                         0.5384693101056831,
                                         0.9061798459386640};
        const double       gauss_w[5] = {0.2369268850561891,
                                         0.4786286704993665,
                                         0.5688888888888889,
                                         0.4786286704993665,
                                         0.2369268850561891};
        const unsigned int intervals  = 20000;
        double             mass       = 0;
        for (unsigned int i = 0; i < intervals; ++i)
          for (unsigned int q = 0; q < 5; ++q)
            {
              const double s = (i + 0.5 + 0.5 * gauss_x[q]) / intervals;
              mass += 0.5 * gauss_w[q] / intervals * m.density(h * s * s) * 2. *
                      h * s;
            }
        const double Vm = m.total_metal_volume_fraction();
        const double error =
          std::abs(mass - h * (3800. * (1. - Vm) + 2707. * Vm)) / (h * 2707.);
        const bool pass = error <= 1e-12;
        ok              = ok && pass;
        std::printf("  V_m against int rho dz: relative error %s\n",
                    pass ? "below 1e-12" : "ABOVE 1e-12");
        if (!pass)
          std::printf("   error %.3e\n", error);
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::material_gradation
