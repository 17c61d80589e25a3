// Static uniform pressure and point force against the exact 3D elasticity
// solution (tests/exact/plate_exact.h), summed as a double Fourier series
// over the (m, n) modes of the simply supported plate, for the homogeneous
// and the n = 1 graded plate (a = 0.2, b = 0.1, h = 0.02 m):
//  - uniform q0 = 1 MPa on the top face: q = sum over odd m, n of
//    16 q0 / (pi^2 m n) sin(m pi x/a) sin(n pi y/b);
//  - point force P = 1 kN at the top-face centre: q = sum over all m, n of
//    4 P / (a b) sin(m pi/2) sin(n pi/2) sin(m pi x/a) sin(n pi y/b).
// At the centre only odd m, n contribute. The mid-plane and bottom centre
// deflections of the point force converge exponentially (each mode decays
// like exp(-k z) away from the loaded face, k^2 = (m pi/a)^2 + (n pi/b)^2);
// the top one diverges (u ~ 1/r under a point force), and so does the FE
// deflection at the loaded node under refinement, which the test shows.
// The series is truncated at k h <= 40; the truncation error is estimated
// from the geometric decay of the last shells of k h.
// Checks: Q1 error and observed order under uniform refinement (10x5x2,
// 20x10x4, 40x20x8) and the Q2 20x10x4 error, all at the mid-plane centre
// (and the bottom centre for the point force).
// Set FGIMPACT_VERBOSE=1 to print the numbers with more digits.

#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>

#include <fgimpact/analysis/static_analysis.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exact/plate_exact.h>
#include <string>
#include <test_tools.h>

namespace fgimpact_unit_tests::static_loads
{

  using namespace fgimpact;

  namespace
  {
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;

    constexpr double a = 0.2, b = 0.1, h = 0.02; // m
    constexpr double q0 = 1e6;                   // Pa
    constexpr double P  = 1e3;                   // N

    /// Centre deflections (m, downward) from the exact series, the
    /// estimated truncation error of each (m), and the partial sums of the
    /// (divergent) series for the point force's loaded point, k h <= 10, 20,
    /// 40 (m).
    struct Series
    {
      double                uniform_mid = 0, point_mid = 0, point_bottom = 0;
      double                uniform_mid_error = 0, point_mid_error = 0;
      double                point_bottom_error = 0;
      std::array<double, 3> point_top_partial  = {{0., 0., 0.}};
      unsigned int          n_modes            = 0;
    };

    /// Sum the series over odd m, n with k h <= 40. The magnitudes of the
    /// terms are also accumulated in shells of k h of width 5, A_j; the
    /// truncation error is estimated (bounded, if the decay stays geometric)
    /// by the tail A_L r / (1 - r), r = A_L / A_{L-1}, of the last two
    /// shells.
    Series
    exact_series(const fgimpact_exact::Plate &plate)
    {
      constexpr double                   kh_max   = 40.;
      constexpr unsigned int             n_shells = 8;
      std::vector<std::array<double, 3>> shell(n_shells, {{0., 0., 0.}});
      std::array<double, 3>              sum = {{0., 0., 0.}};
      Series                             s;
      for (unsigned int m = 1; M_PI * m / a * h <= kh_max; m += 2)
        for (unsigned int n = 1;; n += 2)
          {
            const double kh =
              M_PI * std::sqrt(std::pow(m / a, 2) + std::pow(n / b, 2)) * h;
            if (kh > kh_max)
              break;
            // Unit amplitude: the centre deflection is -W(z) s, with
            // s = sin(m pi/2) sin(n pi/2) = +-1 for odd m, n. The point
            // force's coefficient carries the same factor s (s^2 = 1), the
            // uniform pressure's does not.
            const auto mode =
              fgimpact_exact::static_sinusoidal(plate, 1., m, n);
            const double s_mn      = ((m + n) / 2 % 2 == 1) ? 1. : -1.;
            const double c_uniform = 16. * q0 / (M_PI * M_PI * m * n) * s_mn;
            const double c_point   = 4. * P / (a * b);
            const double term[3]   = {c_uniform * -mode.W(h / 2),
                                      c_point * -mode.W(h / 2),
                                      c_point * -mode.W(0.)};
            auto &sh = shell[std::min<unsigned int>(kh / 5., n_shells - 1)];
            for (unsigned int i = 0; i < 3; ++i)
              {
                sum[i] += term[i];
                sh[i] += std::abs(term[i]);
              }
            const double top = c_point * -mode.W(h);
            for (unsigned int j = 0; j < 3; ++j)
              if (kh <= 10. * (1u << j))
                s.point_top_partial[j] += top;
            ++s.n_modes;
          }
      std::array<double, 3> tail = {{0., 0., 0.}};
      for (unsigned int i = 0; i < 3; ++i)
        {
          const double r = shell[n_shells - 1][i] / shell[n_shells - 2][i];
          // r >= 1 would mean no geometric decay: report an infinite error.
          tail[i] =
            (r > 0 && r < 1) ? shell[n_shells - 1][i] * r / (1. - r) : INFINITY;
        }
      s.uniform_mid        = sum[0];
      s.point_mid          = sum[1];
      s.point_bottom       = sum[2];
      s.uniform_mid_error  = tail[0];
      s.point_mid_error    = tail[1];
      s.point_bottom_error = tail[2];
      return s;
    }

    /// FE centre deflections (m, downward) at z = 0, h/2, h for the Static
    /// subsection's Load = load (uniform q0 or point P at the top centre).
    StaticAnalysis::Results
    fe_static(const double       n,
              const unsigned int degree,
              const unsigned int nx,
              const unsigned int ny,
              const unsigned int nz,
              const std::string &load)
    {
      // The load through the program's own parameter entries.
      ParameterHandler prm;
      StaticAnalysis::Parameters::declare_parameters(prm);
      prm.parse_input_from_string("subsection Static\n set Load = " + load +
                                  "\n set Pressure = " + std::to_string(q0) +
                                  "\n set Point force = " + std::to_string(P) +
                                  "\nend\n");
      StaticAnalysis::Parameters sp;
      sp.parse_parameters(prm);

      const auto c = fgimpact_tests::make_plate(nx, ny, nz, degree, n);
      EffectiveMatrixSolver::Parameters lp;
      lp.type = EffectiveMatrixSolver::Type::cholmod;
      StaticAnalysis analysis(sp, lp, *c.plate, Point<2>(a / 2, b / 2));
      analysis.solve();
      return analysis.get_results();
    }

    bool
    report(const char *what, const bool ok)
    {
      std::printf("  %s: %s\n", what, ok ? "yes" : "NO");
      return ok;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    for (const double n : {0., 1.})
      {
        // n = 0 is pure metal: the homogeneous plate.
        const Series ex =
          exact_series(fgimpact_exact::power_law_plate(n, a, b, h));
        std::printf("%s plate, exact series over %u modes (odd m, n, k h <= "
                    "40):\n"
                    "  uniform 1 MPa: mid-plane centre %.4f um\n"
                    "  point 1 kN: mid-plane centre %.4f um, bottom centre "
                    "%.4f um\n"
                    "  point 1 kN, loaded point, partial sums k h <= 10, 20, "
                    "40: %.3f, %.3f, %.3f um (diverges)\n",
                    n == 0 ? "homogeneous (n = 0)" : "graded n = 1",
                    ex.n_modes,
                    ex.uniform_mid * 1e6,
                    ex.point_mid * 1e6,
                    ex.point_bottom * 1e6,
                    ex.point_top_partial[0] * 1e6,
                    ex.point_top_partial[1] * 1e6,
                    ex.point_top_partial[2] * 1e6);
        if (verbose)
          std::fprintf(
            stderr,
            "  exact: uniform mid %.10e m (tail %.1e), point mid "
            "%.10e m (tail %.1e), point bottom %.10e m (tail %.1e)\n",
            ex.uniform_mid,
            ex.uniform_mid_error,
            ex.point_mid,
            ex.point_mid_error,
            ex.point_bottom,
            ex.point_bottom_error);
        ok &= report("series truncation error below 1e-7 relative",
                     ex.uniform_mid_error < 1e-7 * ex.uniform_mid &&
                       ex.point_mid_error < 1e-7 * ex.point_mid &&
                       ex.point_bottom_error < 1e-7 * ex.point_bottom);

        // Q1 under uniform refinement in all three directions.
        std::array<double, 3> e_uniform{}, e_point_mid{}, e_point_bottom{},
          w_top{};
        for (unsigned int l = 0; l < 3; ++l)
          {
            const unsigned int k = 1u << l;
            const auto ru  = fe_static(n, 1, 10 * k, 5 * k, 2 * k, "uniform");
            const auto rp  = fe_static(n, 1, 10 * k, 5 * k, 2 * k, "point");
            e_uniform[l]   = ru.deflection[1] / ex.uniform_mid - 1;
            e_point_mid[l] = rp.deflection[1] / ex.point_mid - 1;
            e_point_bottom[l] = rp.deflection[0] / ex.point_bottom - 1;
            w_top[l]          = rp.deflection[2];
            if (verbose)
              std::fprintf(stderr,
                           "  Q1 %ux%ux%u: uniform mid %.6f um (error %+.4e); "
                           "point mid %.6f um (%+.4e), bottom %.6f um "
                           "(%+.4e), top %.6f um\n",
                           10 * k,
                           5 * k,
                           2 * k,
                           ru.deflection[1] * 1e6,
                           e_uniform[l],
                           rp.deflection[1] * 1e6,
                           e_point_mid[l],
                           rp.deflection[0] * 1e6,
                           e_point_bottom[l],
                           rp.deflection[2] * 1e6);
          }
        // Observed order from the last two meshes (20x10x4 -> 40x20x8).
        auto order = [](const std::array<double, 3> &e) {
          return std::log2(std::abs(e[1] / e[2]));
        };
        if (verbose)
          std::fprintf(stderr,
                       "  Q1 orders (10x5x2 -> 20x10x4 -> 40x20x8): uniform "
                       "%.3f %.3f, point mid %.3f %.3f, point bottom %.3f "
                       "%.3f\n",
                       std::log2(std::abs(e_uniform[0] / e_uniform[1])),
                       order(e_uniform),
                       std::log2(std::abs(e_point_mid[0] / e_point_mid[1])),
                       order(e_point_mid),
                       std::log2(
                         std::abs(e_point_bottom[0] / e_point_bottom[1])),
                       order(e_point_bottom));

        const auto   q2u             = fe_static(n, 2, 20, 10, 4, "uniform");
        const auto   q2p             = fe_static(n, 2, 20, 10, 4, "point");
        const double e2_uniform      = q2u.deflection[1] / ex.uniform_mid - 1;
        const double e2_point_mid    = q2p.deflection[1] / ex.point_mid - 1;
        const double e2_point_bottom = q2p.deflection[0] / ex.point_bottom - 1;
        if (verbose)
          std::fprintf(
            stderr,
            "  Q2 20x10x4: uniform mid %+.4e, point mid %+.4e, point "
            "bottom %+.4e, top %.6f um\n",
            e2_uniform,
            e2_point_mid,
            e2_point_bottom,
            q2p.deflection[2] * 1e6);

        // Tolerances: measured errors (doc/validation.md) with a margin of
        // 1.3 to 4; orders: the observed 1.8 to 3.1 (pre-asymptotic), so only
        // "at least 1.5" is asserted for the point force.
        ok &= report("uniform, Q1 observed order 2 +- 0.2",
                     std::abs(order(e_uniform) - 2.) < 0.2);
        ok &= report("uniform, Q1 40x20x8 within 3 %",
                     std::abs(e_uniform[2]) < 0.03);
        ok &= report("uniform, Q2 20x10x4 within 0.05 %",
                     std::abs(e2_uniform) < 5e-4);
        ok &= report("point, mid-plane: Q1 observed order above 1.5",
                     order(e_point_mid) > 1.5);
        ok &= report("point, mid-plane: Q1 40x20x8 within 1 %",
                     std::abs(e_point_mid[2]) < 0.01);
        ok &= report("point, mid-plane: Q2 20x10x4 within 1.5 %",
                     std::abs(e2_point_mid) < 0.015);
        ok &= report("point, bottom: Q1 observed order above 1.5",
                     order(e_point_bottom) > 1.5);
        ok &= report("point, bottom: Q1 40x20x8 within 2.5 %",
                     std::abs(e_point_bottom[2]) < 0.025);
        ok &= report("point, bottom: Q2 20x10x4 within 0.5 %",
                     std::abs(e2_point_bottom) < 0.005);

        // The loaded node: no limit (u ~ 1/r), the FE value grows under
        // refinement like the partial sums of the exact series.
        std::printf(
          "  point 1 kN, FE deflection at the loaded node, Q1 10x5x2, "
          "20x10x4, 40x20x8: %.2f, %.2f, %.2f um; Q2 20x10x4: %.2f "
          "um\n",
          w_top[0] * 1e6,
          w_top[1] * 1e6,
          w_top[2] * 1e6,
          q2p.deflection[2] * 1e6);
        ok &= report("point, loaded node: grows by more than 30 % per "
                     "refinement",
                     w_top[1] > 1.3 * w_top[0] && w_top[2] > 1.3 * w_top[1]);
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::static_loads
