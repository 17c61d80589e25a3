// The gradation laws and homogenizations of Material/Gradation and
// Material/Homogenization against closed forms: end values (bottom = ceramic,
// top = metal), the sigmoid's mid-plane and symmetry, Mori-Tanaka's limits
// and its equality with the Hashin-Shtrikman lower bound (a different
// formula), the tabulated profile's interpolation, and the one-line errors
// for malformed tables (file and line named).

#include <deal.II/base/exceptions.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/material/material.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace fgimpact_unit_tests::gradation_laws
{

  using namespace fgimpact;

  namespace
  {
    bool ok = true;

    void
    check(const char *what, const double value, const double exact)
    {
      const double err  = std::abs(value - exact) / std::abs(exact);
      const bool   pass = err <= 1e-14;
      ok                = ok && pass;
      std::printf("%-58s %s\n", what, pass ? "exact" : "WRONG");
      if (!pass)
        std::printf("   got %.17g, expected %.17g\n", value, exact);
    }

    FunctionallyGradedMaterial
    make(const Gradation      g,
         const Homogenization hm,
         const double         n,
         const std::string   &file = "")
    {
      FunctionallyGradedMaterial::Parameters p;
      p.ceramic_poissons_ratio = 0.25;
      p.gradation              = g;
      p.homogenization         = hm;
      p.power_law_index        = n;
      p.profile_file           = file;
      return FunctionallyGradedMaterial(p, 0.02);
    }

    /// The first line of the error for a table with `text`.
    std::string
    table_error(const std::string &text)
    {
      std::ofstream("bad_profile.csv") << text;
      try
        {
          make(Gradation::tabulated,
               Homogenization::rule_of_mixtures,
               1.,
               "bad_profile.csv");
        }
      catch (const dealii::ExceptionBase &e)
        {
          return message_of(e);
        }
      return "accepted";
    }
  } // namespace

  int
  test_main(int, char **)
  {
    const double h = 0.02;
    for (const auto hm :
         {Homogenization::rule_of_mixtures, Homogenization::mori_tanaka})
      for (const auto g : {Gradation::power_law, Gradation::sigmoid})
        {
          const auto m = make(g, hm, 2.);
          std::printf("%s, %s\n",
                      g == Gradation::power_law ? "power law n = 2" :
                                                  "sigmoid n = 2",
                      hm == Homogenization::mori_tanaka ? "Mori-Tanaka" :
                                                          "rule of mixtures");
          check("  E(0) = E_c", m.properties(0).E, 380e9);
          check("  nu(0) = nu_c", m.properties(0).nu, 0.25);
          check("  rho(0) = rho_c", m.properties(0).rho, 3800.);
          check("  E(h) = E_m", m.properties(h).E, 70e9);
          check("  nu(h) = nu_m", m.properties(h).nu, 0.3);
          check("  rho(h) = rho_m", m.properties(h).rho, 2707.);
          // V_m(h/2) = 1/4 (power law), 1/2 (sigmoid); rho is linear in V_m.
          const double Vm = (g == Gradation::power_law ? 0.25 : 0.5);
          check("  rho(h/2) = rho_c + (rho_m - rho_c) V_m(1/2)",
                m.properties(h / 2).rho,
                3800. + (2707. - 3800.) * Vm);
          if (hm == Homogenization::mori_tanaka)
            {
              // Hashin-Shtrikman lower bound (metal matrix, softer phase):
              // K = K_m + V_c / (1/(K_c - K_m) + 3 V_m / (3 K_m + 4 G_m)).
              const double Km = 70e9 / (3 * (1 - 0.6)), Gm = 70e9 / 2.6;
              const double Kc = 380e9 / (3 * (1 - 0.5)), Gc = 380e9 / 2.5;
              const double Vc = 1 - Vm;
              const double K =
                Km + Vc / (1 / (Kc - Km) + 3 * Vm / (3 * Km + 4 * Gm));
              const double z = Gm / 6 * (9 * Km + 8 * Gm) / (Km + 2 * Gm);
              const double G = Gm + Vc / (1 / (Gc - Gm) + Vm / (Gm + z));
              const IsotropicProperties p = m.properties(h / 2);
              check("  Mori-Tanaka K(h/2) = Hashin-Shtrikman lower bound",
                    p.E / (3 * (1 - 2 * p.nu)),
                    K);
              check("  Mori-Tanaka G(h/2) = Hashin-Shtrikman lower bound",
                    p.E / (2 * (1 + p.nu)),
                    G);
            }
          if (g == Gradation::sigmoid)
            {
              // V_m(zeta) + V_m(1 - zeta) = 1 (point symmetry about the
              // mid-plane), seen in rho.
              check("  rho(h/5) + rho(4h/5) = rho_c + rho_m",
                    m.properties(h / 5).rho + m.properties(4 * h / 5).rho,
                    3800. + 2707.);
            }
        }

    {
      const auto m =
        make(Gradation::exponential, Homogenization::rule_of_mixtures, 1.);
      std::printf("exponential\n");
      check("  E(0) = E_c", m.properties(0).E, 380e9);
      check("  E(h) = E_m", m.properties(h).E, 70e9);
      check("  E(h/2) = sqrt(E_c E_m)",
            m.properties(h / 2).E,
            std::sqrt(380e9 * 70e9));
      check("  rho(h/2) = sqrt(rho_c rho_m)",
            m.properties(h / 2).rho,
            std::sqrt(3800. * 2707.));
      check("  nu(h/2) = (nu_c + nu_m)/2", m.properties(h / 2).nu, 0.275);
    }

    {
      std::ofstream("profile.csv")
        << "# measured\nz/h, E, nu, rho\n0, 100e9, 0.2, 3000\n"
           "0.5, 200e9, 0.3, 2000\n\n1.0 50e9 0.25 2500 # blanks work too\n";
      const auto m = make(Gradation::tabulated,
                          Homogenization::rule_of_mixtures,
                          1.,
                          "profile.csv");
      std::printf("tabulated\n");
      check("  E(h/4) = 150e9", m.properties(h / 4).E, 150e9);
      check("  nu(3h/4) = 0.275", m.properties(3 * h / 4).nu, 0.275);
      check("  rho(h) = 2500", m.properties(h).rho, 2500.);
    }

    std::printf("malformed tables:\n");
    for (const std::string &text :
         {std::string("0, 1e9, 0.3, 1000\n0.6, 1e9, 0.3, 1000\n"
                      "0.5, 1e9, 0.3, 1000\n1, 1e9, 0.3, 1000\n"),
          std::string("z/h, E, nu, rho\n0, 1e9, 0.3\n1, 1e9, 0.3, 1000\n"),
          std::string("0, 1e9, 0.3, 1000\n0.5, -1e9, 0.3, 1000\n"
                      "1, 1e9, 0.3, 1000\n"),
          std::string("0, 1e9, 0.3, 1000\n0.5, 1e9, 0.5, 1000\n"
                      "1, 1e9, 0.3, 1000\n"),
          std::string("0.1, 1e9, 0.3, 1000\n1, 1e9, 0.3, 1000\n"),
          std::string("0, 1e9, 0.3, 1000\n0.9, 1e9, 0.3, 1000\n"),
          std::string("0, 1e9, 0.3, 1000\n0.5, 1e9, abc, 1000\n")})
      {
        const std::string e = table_error(text);
        std::printf("  %s\n", e.c_str());
        ok = ok && e.find("bad_profile.csv', line ") != std::string::npos;
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::gradation_laws
