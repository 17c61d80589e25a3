// Eq. 2.1 and 2.2: the gradation law's end points, the paper's n = 0 = pure
// metal convention, and V_m = 1/(1+n) against closed forms.

#include <fgimpact/material.h>

#include <cmath>
#include <cstdio>

using namespace fgimpact;

int
main()
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
      check("  V_m = 1/(1+n)", m.total_metal_volume_fraction(), 1. / (1. + n));
      check("  int rho dz = h (rho_c V_c + rho_m V_m)",
            m.mass_per_unit_area(),
            h * (3800. * n / (1. + n) + 2707. / (1. + n)));
    }
  std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
  return ok ? 0 : 1;
}
