// Numerical extremes (issue 13.8), each against a closed form or a scaling
// law (impact_extremes.cc and rigid_plate_limit.cc cover the moderate
// range; this extends them to the extremes of the issue):
//  - n = 0 and 10^6 (P(z) = P_c + (P_m - P_c)(z/h)^n, n = 0 pure metal,
//    n -> inf ceramic below a vanishing top layer): the plate mass against
//    a b h (rho_c + (rho_m - rho_c)/(n + 1)), and the stiffness matrix of
//    n = 10^6 against E_c/E_m times that of n = 0 (one Poisson's ratio: K
//    scales with E), homogeneous elements;
//  - in the rigid-plate limit (plate 1000x stiffer, contact stiffness K of
//    the 70 GPa half-space), Hertz's impact on a rigid half-space
//    (Goldsmith): alpha_max = (5 m V0^2 / (4 K))^(2/5),
//    F_max = K alpha_max^(3/2), T = 2.94328 alpha_max / V0, at
//    V0 = 10^-4 and 100 m/s, impactor mass x10^3 and x10^-3, h = 200 mm
//    and h = 1 mm (on a rigid base: bottom face w = 0), dt = 1 ns (light ball)
//    and dt = 100 us (heavy ball, 19 steps in contact: second-order error (pi
//    dt / T)^2 = 2.7 %).
// dt = 100 us on the default ball (longer than the contact) is refused by
// the energy watchdog: tests/unit/bad_input.cc.

#include <deal.II/base/mpi.h>

#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <test_tools.h>

namespace fgimpact_unit_tests::numerical_extremes
{

  using namespace fgimpact;

  namespace
  {
    bool ok = true;

    void
    check(const char *what, const double error, const double tolerance)
    {
      const bool pass = std::abs(error) < tolerance;
      ok              = ok && pass;
      std::printf("%-58s error %9.2e < %.0e: %s\n",
                  what,
                  std::abs(error) < 1e-12 ? 0. : std::abs(error),
                  tolerance,
                  pass ? "yes" : "NO");
    }

    void
    power_law_extremes()
    {
      const double a = 0.2, b = 0.1, h = 0.02;
      const double rho_m = 2707, rho_c = 3800, E_m = 70e9, E_c = 380e9;
      const auto   metal =
        fgimpact_tests::make_plate(4, 2, 2, 1, 0., PropertyMode::homogeneous);
      const auto ceramic =
        fgimpact_tests::make_plate(4, 2, 2, 1, 1e6, PropertyMode::homogeneous);
      check("n = 0: plate mass vs rho_m a b h",
            metal.plate->total_mass() / (rho_m * a * b * h) - 1,
            1e-12);
      check("n = 1e6: plate mass vs a b h (rho_c + (rho_m - rho_c)/(n+1))",
            ceramic.plate->total_mass() /
                (a * b * h * (rho_c + (rho_m - rho_c) / (1e6 + 1))) -
              1,
            1e-5);
      // K(n = 1e6) - (E_c/E_m) K(n = 0), relative, over the unconstrained
      // entries (constrained rows hold a diagonal scale of their own).
      double      difference = 0, norm = 0;
      const auto &K0 = metal.plate->stiffness_matrix();
      const auto &K1 = ceramic.plate->stiffness_matrix();
      for (auto e = K1.begin(); e != K1.end(); ++e)
        if (!metal.plate->get_constraints().is_constrained(e->row()) &&
            !metal.plate->get_constraints().is_constrained(e->column()))
          {
            const double scaled = E_c / E_m * K0.el(e->row(), e->column());
            difference += std::pow(e->value() - scaled, 2);
            norm += std::pow(e->value(), 2);
          }
      check("n = 1e6 vs n = 0: stiffness matrix K1 = (E_c/E_m) K0",
            std::sqrt(difference / norm),
            1e-5);
    }

    /// The rigid-plate limit with mass factor, V0, h and dt; checks F_max
    /// and T against Hertz on a rigid half-space.
    void
    rigid_limit(const char  *what,
                const double mass_factor,
                const double V0,
                const double h,
                const double dt,
                const double tolerance)
    {
      const double R = 0.015, rho_i = 7800 * mass_factor;
      const double m         = 4. / 3. * M_PI * R * R * R * rho_i;
      const double K         = 4. / 3. * 70e9 / (1 - 0.09) * std::sqrt(R);
      const double alpha_max = std::pow(5 * m * V0 * V0 / (4 * K), 0.4);
      const double F_max     = K * std::pow(alpha_max, 1.5);
      const double T_c       = 2.94328 * alpha_max / V0;
      // A plate 1000x stiffer than aluminium; a 1 mm one on a rigid base
      // (bottom face w = 0), which its bending stiffness alone is not.
      const double E = 70e12;
      char         settings[1000];
      std::snprintf(
        settings,
        sizeof(settings),
        "subsection Geometry\n set Thickness h = %.17g\nend\n"
        "subsection Boundary conditions\n set Face z min = %s\nend\n"
        "subsection Material\n set Metal Young's modulus = %.17g\n"
        " set Ceramic Young's modulus = %.17g\n set Ceramic density = 2707\n"
        "end\nsubsection Contact\n set Contact stiffness = %.17g\nend\n"
        "subsection Impactor\n set Mass = %.17g\n"
        " set Initial velocity = %.17g\nend\n"
        "subsection Time integration\n set Time step = %.17g\n"
        " set End time = %.17g\nend\n"
        "subsection Newton\n set Tolerance = 1e-12\nend\n",
        h,
        h < 0.005 ? "simply supported" : "free",
        E,
        E,
        K,
        m,
        V0,
        dt,
        std::max(1.25 * T_c, 3 * dt));
      const ImpactResults r = fgimpact_tests::run_impact(settings);
      std::string         label(what);
      check((label + ": peak force vs Hertz").c_str(),
            r.peak_contact_force / F_max - 1,
            tolerance);
      check((label + ": contact duration vs Hertz").c_str(),
            r.contact_duration / T_c - 1,
            tolerance);
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    std::setvbuf(stdout, nullptr, _IOLBF, BUFSIZ);
    power_law_extremes();
    // Contact durations: 122 us x (m/m0)^(2/5) V0^(-1/5); dt ~ T/200.
    rigid_limit("V0 = 1e-4 m/s", 1, 1e-4, 0.02, 4e-6, 0.01);
    rigid_limit("V0 = 100 m/s", 1, 100, 0.02, 0.25e-6, 0.01);
    rigid_limit("impactor mass x1e3", 1e3, 1, 0.02, 10e-6, 0.01);
    rigid_limit("impactor mass x1e-3", 1e-3, 1, 0.02, 0.04e-6, 0.01);
    rigid_limit("h = 200 mm", 1, 1, 0.2, 0.5e-6, 0.01);
    rigid_limit("h = 1 mm", 1, 1, 0.001, 0.5e-6, 0.01);
    rigid_limit("dt = 1 ns (mass x1e-3)", 1e-3, 1, 0.02, 1e-9, 0.01);
    rigid_limit("dt = 100 us (mass x1e3)", 1e3, 1, 0.02, 100e-6, 0.05);
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::numerical_extremes
