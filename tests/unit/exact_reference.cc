// Independent checks of the exact 3D-elasticity reference solution in
// tests/exact/plate_exact.h (simply supported plate, E(z), rho(z)) and the
// reference numbers a finite element validation can compare against.
//
// The checks use closed forms solved here, not in the header:
//  - Rayleigh-Lamb roots (antisymmetric and symmetric) of a homogeneous
//    plate at the mode's wave number k = pi sqrt((m/a)^2 + (n/b)^2);
//  - the in-plane shear mode omega = c_T k;
//  - Kirchhoff/classical plate theory in the thin limit, for the
//    homogeneous plate and for the graded one (bending-stretching coupling,
//    D* = D - B^2 / A), statics and the fundamental frequency;
//  - convergence of the thickness integration (N and 2N sub-layers) and of
//    the frequency scan (grid refined twice).

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <exact/plate_exact.h>
#include <functional>
#include <tuple>
#include <vector>

namespace fgimpact_unit_tests::exact_reference
{

  using namespace fgimpact_exact;

  namespace
  {
    bool all_ok = true;

    void
    report(const char *what, const bool pass)
    {
      all_ok = all_ok && pass;
      std::printf("%-62s %s\n", what, pass ? "PASS" : "FAIL");
    }

    double
    rel(const double a, const double b)
    {
      return std::abs(a - b) / std::abs(b);
    }

    // cos(x d) and sin(x d) / x as functions of x^2 (real for x^2 < 0).
    double
    C(const double x2, const double d)
    {
      return x2 >= 0 ? std::cos(std::sqrt(x2) * d) :
                       std::cosh(std::sqrt(-x2) * d);
    }
    double
    S(const double x2, const double d)
    {
      if (x2 > 0)
        return std::sin(std::sqrt(x2) * d) / std::sqrt(x2);
      if (x2 < 0)
        return std::sinh(std::sqrt(-x2) * d) / std::sqrt(-x2);
      return d;
    }

    // Pole-free Rayleigh-Lamb functions for a plate of thickness 2d, divided
    // by alpha (antisymmetric) or beta (symmetric) to remove the spurious
    // roots alpha = 0 and beta = 0.
    struct RayleighLamb
    {
      double c_L, c_T, d;
      double
      antisymmetric(const double omega, const double k) const
      {
        const double a2 = omega * omega / (c_L * c_L) - k * k;
        const double b2 = omega * omega / (c_T * c_T) - k * k;
        return (b2 - k * k) * (b2 - k * k) * S(a2, d) * C(b2, d) +
               4 * k * k * b2 * C(a2, d) * S(b2, d);
      }
      double
      symmetric(const double omega, const double k) const
      {
        const double a2 = omega * omega / (c_L * c_L) - k * k;
        const double b2 = omega * omega / (c_T * c_T) - k * k;
        return (b2 - k * k) * (b2 - k * k) * C(a2, d) * S(b2, d) +
               4 * k * k * a2 * S(a2, d) * C(b2, d);
      }
      // Lowest root above omega = 0 (where both functions vanish trivially)
      // by a fine scan from 0.01 c_T k and bisection to machine precision.
      double
      lowest_root(const bool sym, const double k) const
      {
        auto f = [&](const double w) {
          return sym ? symmetric(w, k) : antisymmetric(w, k);
        };
        const double step = 1e-3 * c_T * k;
        double       w0 = 0.01 * c_T * k, f0 = f(w0);
        for (;;)
          {
            const double w1 = w0 + step, f1 = f(w1);
            if ((f0 > 0) != (f1 > 0))
              {
                double lo = w0, hi = w1, flo = f0;
                for (int i = 0; i < 200 && hi - lo > 1e-15 * hi; ++i)
                  {
                    const double mid = 0.5 * (lo + hi), fm = f(mid);
                    if ((fm > 0) == (flo > 0))
                      lo = mid, flo = fm;
                    else
                      hi = mid;
                  }
                return 0.5 * (lo + hi);
              }
            w0 = w1;
            f0 = f1;
          }
      }
    };

    // First root of a given type in a list of modes (or -1).
    double
    first_of(const std::vector<Mode> &modes, const ModeType t)
    {
      for (const auto &md : modes)
        if (md.type == t)
          return md.omega;
      return -1;
    }

    // Centre deflection, positive downward.
    double
    centre_deflection(const ThicknessSolution &s,
                      const double             z,
                      const double             a,
                      const double             b)
    {
      return -s.W(z) * s.in_plane_factor(a / 2, b / 2);
    }
  } // namespace

  int
  test_main(int, char **)
  {
    const double       Em = 70e9, rho_m = 2707., Ec = 380e9, rho_c = 3800.;
    const double       nu = 0.3, a = 0.2, b = 0.1, h = 0.02, q0 = 1e6;
    const Plate        metal  = homogeneous_plate(Em, rho_m, nu, a, b, h);
    const Plate        fgm1   = power_law_plate(1., a, b, h);
    const Plate        fgm5   = power_law_plate(5., a, b, h);
    const double       lambda = Em * nu / ((1 + nu) * (1 - 2 * nu));
    const double       mu     = Em / (2 * (1 + nu));
    const double       c_L    = std::sqrt((lambda + 2 * mu) / rho_m);
    const double       c_T    = std::sqrt(mu / rho_m);
    const RayleighLamb rl{c_L, c_T, h / 2};
    auto               wave_number = [&](const unsigned m, const unsigned n) {
      return M_PI * std::sqrt((m / a) * (m / a) + (n / b) * (n / b));
    };

    // ---------------------------------------------------------------------
    std::printf("1. Homogeneous plate against Rayleigh-Lamb (tol 1e-8)\n");
    const std::vector<std::pair<unsigned, unsigned>> mn_list = {{1, 1},
                                                                {2, 1},
                                                                {1, 2},
                                                                {3, 1}};
    for (const auto &[m, n] : mn_list)
      {
        const double k     = wave_number(m, n);
        const auto   modes = natural_frequencies(metal, m, n, 3);
        const double wA    = rl.lowest_root(false, k);
        const double wS    = rl.lowest_root(true, k);
        const double wF    = first_of(modes, ModeType::flexural);
        const double wE    = first_of(modes, ModeType::extensional);
        const double wSH   = first_of(modes, ModeType::in_plane_shear);
        char         line[200];
        std::printf("  (m,n) = (%u,%u): f_A0 = %.6e Hz, f_S0 = %.6e Hz\n",
                    m,
                    n,
                    wA / (2 * M_PI),
                    wS / (2 * M_PI));
        std::snprintf(line, sizeof line, "  lowest root is flexural");
        report(line, modes[0].type == ModeType::flexural);
        std::snprintf(line,
                      sizeof line,
                      "  flexural = antisymmetric Rayleigh-Lamb");
        report(line, wF > 0 && rel(wF, wA) < 1e-8);
        std::snprintf(line,
                      sizeof line,
                      "  extensional = symmetric Rayleigh-Lamb");
        report(line, wE > 0 && rel(wE, wS) < 1e-8);
        std::snprintf(line,
                      sizeof line,
                      "  in-plane shear = c_T k (tol 1e-10)");
        report(line, wSH > 0 && rel(wSH, c_T * k) < 1e-10);
        // Flexural mode of a homogeneous plate: W symmetric about mid-plane.
        const auto &shape = modes[0].shape;
        report("  flexural W(0) = W(h)", rel(shape.W(0.), shape.W(h)) < 1e-8);
      }

    // ---------------------------------------------------------------------
    std::printf("2. Thin-plate limit (Kirchhoff / classical plate theory)\n");
    {
      // Homogeneous: w = q0 / (D pi^4 (1/a^2 + 1/b^2)^2).
      auto ratio_homogeneous = [&](const double hh) {
        const Plate  p = homogeneous_plate(Em, rho_m, nu, a, b, hh);
        const auto   s = static_sinusoidal(p, q0, 1, 1);
        const double D = Em * hh * hh * hh / (12 * (1 - nu * nu));
        const double wK =
          q0 / (D * std::pow(M_PI, 4) * std::pow(1 / (a * a) + 1 / (b * b), 2));
        return centre_deflection(s, hh / 2, a, b) / wK;
      };
      const double r1 = ratio_homogeneous(0.001 * a);
      const double r2 = ratio_homogeneous(0.002 * a);
      const double r0 = ratio_homogeneous(h);
      std::printf("  homogeneous w_3D(h/2) / w_Kirchhoff: h/a = 0.001: %.6f\n",
                  r1);
      std::printf("  homogeneous w_3D(h/2) / w_Kirchhoff: h/a = 0.1:   %.6f\n",
                  r0);
      report("  h/a = 0.001 within 2e-5 of Kirchhoff", std::abs(r1 - 1) < 2e-5);
      report("  deviation ~ (h/a)^2 (0.001 vs 0.002, within 1%)",
             rel((r2 - 1) / 4, r1 - 1) < 1e-2);
      // h = 0.02 is h/b = 0.2 for the short side (k h = 0.70): the 3D
      // deflection exceeds Kirchhoff by about 12 percent, close to Mindlin's
      // w_M / w_K = 1 + D k^2 / (kappa G h), kappa = 5/6.
      const double k11 = wave_number(1, 1);
      const double rM =
        1 + Em * h * h / (12 * (1 - nu * nu)) * k11 * k11 / (5. / 6. * mu);
      std::printf(
        "  Mindlin (kappa = 5/6) w_M / w_Kirchhoff, h/a = 0.1: %.6f\n", rM);
      report("  h/a = 0.1: 3D exceeds Kirchhoff by 5-20%, Mindlin within 2%",
             r0 > 1.05 && r0 < 1.2 && rel(r0, rM) < 0.02);

      // Graded n = 1: D* = D - B^2/A from the thickness moments of Q11(z);
      // fundamental frequency omega^2 = D* k^4 / int rho dz.
      const double hh = 0.001 * a, k = wave_number(1, 1);
      const double nind = 1.;
      const double A0   = hh * (Ec + (Em - Ec) / (nind + 1)) / (1 - nu * nu);
      const double B0 =
        hh * hh * (Ec / 2 + (Em - Ec) / (nind + 2)) / (1 - nu * nu);
      const double D0 =
        hh * hh * hh * (Ec / 3 + (Em - Ec) / (nind + 3)) / (1 - nu * nu);
      const double Dstar = D0 - B0 * B0 / A0;
      const double I0    = hh * (rho_c + (rho_m - rho_c) / (nind + 1));
      const Plate  thin  = power_law_plate(nind, a, b, hh);
      const auto   s     = static_sinusoidal(thin, q0, 1, 1);
      const double rs =
        centre_deflection(s, hh / 2, a, b) / (q0 / (Dstar * std::pow(k, 4)));
      const double wCPT  = k * k * std::sqrt(Dstar / I0);
      const auto   modes = natural_frequencies(thin, 1, 1, 1);
      const double rf    = modes[0].omega / wCPT;
      std::printf("  graded n = 1, h/a = 0.001: w_3D / w_CPT = %.6f, "
                  "omega_3D / omega_CPT = %.6f\n",
                  rs,
                  rf);
      report("  graded thin plate: static within 2e-5 of CPT (D - B^2/A)",
             std::abs(rs - 1) < 2e-5);
      report("  graded thin plate: fundamental frequency within 2e-5 of CPT",
             modes[0].type == ModeType::flexural && std::abs(rf - 1) < 2e-5);
    }

    // ---------------------------------------------------------------------
    std::printf("3. Integration accuracy: N = 256 vs 2N = 512 sub-layers\n");
    for (const double nind : {1., 5.})
      {
        const Plate p = power_law_plate(nind, a, b, h);
        Options     o1, o2;
        o1.layers = 256;
        o2.layers = 512;
        const double w1 =
          centre_deflection(static_sinusoidal(p, q0, 1, 1, o1), h / 2, a, b);
        const double w2 =
          centre_deflection(static_sinusoidal(p, q0, 1, 1, o2), h / 2, a, b);
        const double s1 = static_sinusoidal(p, q0, 1, 1, o1).sigma_xx(h);
        const double s2 = static_sinusoidal(p, q0, 1, 1, o2).sigma_xx(h);
        const double f1 = natural_frequencies(p, 1, 1, 1, 0., o1)[0].omega;
        const double f2 = natural_frequencies(p, 1, 1, 1, 0., o2)[0].omega;
        char         line[200];
        std::snprintf(line,
                      sizeof line,
                      "  n = %g: centre deflection, rel. diff < 1e-9",
                      nind);
        report(line, rel(w1, w2) < 1e-9);
        std::snprintf(line,
                      sizeof line,
                      "  n = %g: sigma_xx(h), rel. diff < 1e-9",
                      nind);
        report(line, rel(s1, s2) < 1e-9);
        std::snprintf(line,
                      sizeof line,
                      "  n = %g: first flexural frequency, rel. diff < 1e-9",
                      nind);
        report(line, rel(f1, f2) < 1e-9);
      }
    {
      // Scan robustness: the six lowest roots of the n = 1 plate, (1,1) and
      // (3,3), do not change when the scan grid is refined twice.
      for (const auto &[m, n] :
           std::vector<std::pair<unsigned, unsigned>>{{1, 1}, {3, 3}})
        {
          Options fine;
          fine.scan_points = 400;
          const auto r1    = natural_frequencies(fgm1, m, n, 6);
          const auto r2    = natural_frequencies(fgm1, m, n, 6, 0., fine);
          bool       same  = r1.size() == r2.size();
          for (std::size_t i = 0; same && i < r1.size(); ++i)
            same =
              rel(r1[i].omega, r2[i].omega) < 1e-12 && r1[i].type == r2[i].type;
          char line[200];
          std::snprintf(
            line,
            sizeof line,
            "  n = 1, (m,n) = (%u,%u): 6 roots unchanged on 4x finer scan",
            m,
            n);
          report(line, same);
          std::printf("    types:");
          for (const auto &md : r1)
            std::printf(" %s", to_string(md.type));
          std::printf("\n");
        }
      // The in-plane shear mode of the graded plate: W = L = 0 exactly.
      const auto modes = natural_frequencies(fgm1, 1, 1, 3);
      report("  n = 1: an in-plane shear mode with W = L = 0 exists",
             first_of(modes, ModeType::in_plane_shear) > 0);
    }

    // ---------------------------------------------------------------------
    std::printf("4. Reference numbers, q0 = %g Pa, (m,n) = (1,1), "
                "a = %g, b = %g, h = %g m\n",
                q0,
                a,
                b,
                h);
    for (const auto &[name, plate] :
         std::vector<std::pair<const char *, Plate>>{
           {"homogeneous (metal)", metal}, {"graded n = 1", fgm1}})
      {
        std::printf("  %s\n", name);
        const auto s = static_sinusoidal(plate, q0, 1, 1);
        std::printf("    centre deflection (downward) [um]:\n");
        for (const auto &[label, z] :
             std::vector<std::pair<const char *, double>>{{"0", 0.},
                                                          {"h/2", h / 2},
                                                          {"h", h}})
          std::printf("      z = %-4s  %.6e\n",
                      label,
                      1e6 * centre_deflection(s, z, a, b));
        std::printf("    centre sigma_xx [MPa]:\n");
        for (const auto &[label, z] :
             std::vector<std::pair<const char *, double>>{{"0", 0.},
                                                          {"h/4", h / 4},
                                                          {"h/2", h / 2},
                                                          {"3h/4", 3 * h / 4},
                                                          {"h", h}})
          std::printf("      z = %-4s  %.6e\n",
                      label,
                      1e-6 * s.sigma_xx(z) * s.in_plane_factor(a / 2, b / 2));
        // Flexural roots of all (m,n) <= 3 below the third lowest
        // fundamental flexural frequency.
        std::vector<double> fundamentals;
        for (unsigned m = 1; m <= 3; ++m)
          for (unsigned n = 1; n <= 3; ++n)
            fundamentals.push_back(
              natural_frequencies(plate, m, n, 1)[0].omega);
        std::sort(fundamentals.begin(), fundamentals.end());
        std::vector<std::tuple<double, unsigned, unsigned>> flexural;
        for (unsigned m = 1; m <= 3; ++m)
          for (unsigned n = 1; n <= 3; ++n)
            for (const auto &md : natural_frequencies(
                   plate, m, n, 0, 1.000001 * fundamentals[2]))
              if (md.type == ModeType::flexural)
                flexural.emplace_back(md.omega, m, n);
        std::sort(flexural.begin(), flexural.end());
        std::printf("    lowest flexural natural frequencies [Hz]:\n");
        for (std::size_t i = 0; i < 3 && i < flexural.size(); ++i)
          std::printf("      (m,n) = (%u,%u)  %.6e\n",
                      std::get<1>(flexural[i]),
                      std::get<2>(flexural[i]),
                      std::get<0>(flexural[i]) / (2 * M_PI));
        report("    three flexural frequencies found", flexural.size() >= 3);
      }

    std::printf("%s\n", all_ok ? "all checks passed" : "SOME CHECKS FAILED");
    return all_ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::exact_reference
