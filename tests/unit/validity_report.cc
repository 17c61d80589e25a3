// The validity report (summary.txt's max_von_mises_over_yield,
// max_principal_over_tensile_strength, where and when, and `validity`),
// against closed forms:
//  1. Hertz's stresses on the axis: sigma_z from Boussinesq's point force
//     integrated over Hertz's pressure p0 sqrt(1 - r^2/a^2) by quadrature
//     (independent of the closed form in hertz_stress_peaks()), and the
//     largest von Mises stress 0.620 p0 at 0.48 a for nu = 0.3 (Johnson,
//     Contact Mechanics, Fig. 3.9: tau_1 = 0.31 p0), so first yield at
//     p0 = 1.61 Y (Johnson: 1.60 Y).
//  2. The TTO yield strength in its limits: q -> infinity (equal strains)
//     Y_m (V_m + E_c/E_m V_c), q = 0 (equal stresses) Y_m.
//  3. A rigid ball on a homogeneous thick block, resolved contact: the FE
//     von Mises peak against Hertz's 0.620 p0 at the run's peak force,
//     under the ball at depth 0.48 a; no ceramic-rich part, so its check
//     reads none.
//  4. The paper's hertz node on a small plate: its point force's FE stress
//     is skipped near the load and Hertz's closed form stands for it; the
//     summary's ratio is recomputed here from its peak force and modulus.

#include <deal.II/base/mpi.h>

#include <fgimpact/material/strength.h>
#include <fgimpact/output/validity_report.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <test_tools.h>

namespace fgimpact_unit_tests::validity_report
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    /// summary.txt as key -> value text.
    std::map<std::string, std::string>
    read_summary(const std::string &file)
    {
      std::map<std::string, std::string> keys;
      std::ifstream                      in(file);
      std::string                        line;
      while (std::getline(in, line))
        {
          const auto eq = line.find(" = ");
          if (line.empty() || line[0] == '#' || eq == std::string::npos)
            continue;
          keys[line.substr(0, eq)] = line.substr(eq + 3);
        }
      return keys;
    }

    /// sigma_z / p0 on the axis at depth zeta a: Boussinesq's point force,
    /// -3 z^3 / (2 pi rho^5), over the Hertz pressure (midpoint rule in
    /// r = a sin(theta), which removes the root at the edge).
    double
    sigma_z_by_quadrature(const double zeta)
    {
      const unsigned int n   = 20000;
      double             sum = 0;
      for (unsigned int k = 0; k < n; ++k)
        {
          const double theta = (k + 0.5) * M_PI / 2 / n;
          const double r = std::sin(theta), dr = std::cos(theta) * M_PI / 2 / n;
          const double p = std::cos(theta); // sqrt(1 - r^2)
          sum += p * 3 * std::pow(zeta, 3) /
                 (2 * M_PI * std::pow(r * r + zeta * zeta, 2.5)) * 2 * M_PI *
                 r * dr;
        }
      return -sum;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    // 1. Hertz on the axis.
    double worst = 0;
    for (const double zeta : {0.25, 0.5, 1., 2.})
      worst = std::max(worst,
                       std::abs(sigma_z_by_quadrature(zeta) +
                                1. / (1. + zeta * zeta)));
    const HertzStressPeaks h = hertz_stress_peaks(0.3);
    std::printf("Hertz axis: sigma_z by quadrature of Boussinesq against "
                "-p0/(1 + zeta^2): largest difference %.1e p0 (limit 1e-6)\n",
                worst);
    std::printf("Hertz, nu = 0.3: von Mises %.4f p0 at %.3f a (Johnson 0.62 "
                "p0 at 0.48 a), edge tension %.4f p0; first yield at p0 = "
                "%.3f Y\n",
                h.von_mises,
                h.depth,
                h.edge_tension,
                1. / h.von_mises);
    ok = ok && worst < 1e-6 && std::abs(h.von_mises - 0.62) < 0.005 &&
         std::abs(h.depth - 0.48) < 0.01 &&
         std::abs(h.edge_tension - 0.4 / 3.) < 1e-12;

    // 2. TTO limits, on the paper's materials (n = 1: V_m = z/h).
    FunctionallyGradedMaterial::Parameters mp;
    const FunctionallyGradedMaterial       material(mp, 0.02);
    GradedStrength::Parameters             sp;
    double                                 tto_error = 0;
    for (const double q : {1e22, 0.})
      {
        sp.tto_q = q;
        const GradedStrength strength(sp, material);
        for (const double Vm : {0.5, 0.75, 1.})
          {
            const double exact =
              q > 0 ? sp.metal_yield_strength * (Vm + 380. / 70. * (1 - Vm)) :
                      sp.metal_yield_strength;
            tto_error =
              std::max(tto_error,
                       std::abs(strength.yield_strength(Vm * 0.02) / exact -
                                1));
          }
      }
    // A verdict, not the error: it is to be near zero (1e-11, from q = 1e22
    // standing for infinity).
    std::printf("TTO yield strength in its limits q -> infinity and q = 0: "
                "largest relative error below 1e-9: %s\n",
                tto_error < 1e-9 ? "yes" : "NO");
    ok = ok && tto_error < 1e-9;

    // 3. A rigid ball on a thick block, resolved.
    {
      const auto run = fgimpact_tests::run_quietly(
        "",
        "subsection Geometry\n set Length a = 0.04\n set Width b = 0.04\n"
        " set Thickness h = 0.02\n set Subdivisions x = 8\n"
        " set Subdivisions y = 8\n set Subdivisions z = 4\n"
        " set Symmetry = quarter\n set Contact refinement levels = 5\nend\n"
        "subsection Boundary conditions\n set Face x min = free\n"
        " set Face x max = free\n set Face y min = free\n"
        " set Face y max = free\n set Face z min = clamped\nend\n"
        "subsection Material\n set Power-law index = 0\nend\n"
        "subsection Contact\n set Model = resolved sphere\nend\n"
        "subsection Time integration\n set Time step = 0.5e-6\n"
        " set End time = auto\nend\n"
        "subsection Output\n set Directory = out_block\n"
        " set VTU interval = 0\n set Log interval = 0\n"
        " set Print timing = false\nend\n");
      const ImpactResults &r = run.results;
      const double         Q = 70e9 / 0.91, R = 0.015;
      const double         F       = r.peak_contact_force;
      const double         a       = std::cbrt(3 * F * R / (4 * Q));
      const double         p0      = 3 * F / (2 * M_PI * a * a);
      const double         vm      = h.von_mises * p0;
      const auto           summary = read_summary("out_block/summary.txt");
      const double         error   = r.yield_peak.stress / vm - 1;
      const double depth_error = (0.02 - r.yield_peak.point[2]) / a - h.depth;
      std::printf("block, resolved: von Mises peak %.1f MPa against Hertz's "
                  "%.1f MPa at F = %.1f N (%+.2f %%, limit 5 %%), at depth "
                  "%.3f a (Hertz %.3f a; the element is %.3f a), %.2f us "
                  "after the peak force\n",
                  r.yield_peak.stress * 1e-6,
                  vm * 1e-6,
                  F,
                  100 * error,
                  h.depth + depth_error,
                  h.depth,
                  r.model.element_size_under_ball / a,
                  (r.yield_peak.time - r.time_of_peak_force) * 1e6);
      std::printf("block, summary: max_von_mises_over_yield = %s, "
                  "max_principal_over_tensile_strength = %s\n",
                  summary.at("max_von_mises_over_yield").c_str(),
                  summary.at("max_principal_over_tensile_strength").c_str());
      ok = ok && std::abs(error) < 0.05 &&
           std::abs(depth_error) < r.model.element_size_under_ball / a &&
           std::abs(r.yield_peak.time - r.time_of_peak_force) < 1.5e-6 &&
           summary.at("max_principal_over_tensile_strength") == "none" &&
           std::abs(std::stod(summary.at("max_von_mises_over_yield")) -
                    r.yield_peak.ratio) < 1e-4;
    }

    // 4. The paper's hertz node: Hertz's closed form at the peak force.
    {
      fgimpact_tests::run_quietly(
        "",
        "subsection Geometry\n set Subdivisions x = 10\n"
        " set Subdivisions y = 6\n set Subdivisions z = 2\nend\n"
        "subsection Time integration\n set End time = 150e-6\nend\n"
        "subsection Output\n set Directory = out_node\n set VTU interval = 0\n"
        " set Log interval = 0\n set Print timing = false\nend\n");
      const auto   s  = read_summary("out_node/summary.txt");
      const double F  = std::stod(s.at("peak_contact_force_N"));
      const double Q  = std::stod(s.at("contact_modulus_Q_Pa"));
      const double a  = std::cbrt(3 * F * 0.015 / (4 * Q));
      const double p0 = 3 * F / (2 * M_PI * a * a);
      // The top face is pure metal; at 0.48 a below it V_m = 1 - 0.48 a/h.
      const double Vm = 1 - h.depth * a / 0.02;
      const double Y =
        275e6 * (Vm + (4.5e9 + 70e9) / (4.5e9 + 380e9) * 380. / 70. * (1 - Vm));
      const double ratio = h.von_mises * p0 / Y;
      const double shown = std::stod(s.at("max_von_mises_over_yield"));
      std::printf("hertz node: max_von_mises_over_yield = %.4f, Hertz at the "
                  "summary's peak force %.4f; validity = %s\n",
                  shown,
                  ratio,
                  s.at("validity").c_str());
      ok = ok && std::abs(shown - ratio) < 2e-4 &&
           s.at("validity").find("breaks: elastic metal") == 0;
    }
    std::printf("%s\n", ok ? "OK" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::validity_report
