// Geometry/Contact refinement levels = auto and what a run says about its
// own resolution:
//  1. the automatic levels of five scenes against the closed form: the
//     half-space Hertz radius a_H = sqrt(R alpha_max), alpha_max =
//     (5 m V0^2 / (4 K))^(2/5), K = 4/3 E*_top sqrt(R) (static sphere:
//     a_H = sqrt(R delta)), and the fewest levels L with
//     min(a/n_x, b/n_y) / 2^L <= a_H / 4, computed here; hertz node: 0;
//  2. runs of the default scene (quarter, resolved sphere, 60 us) read
//     back from summary.txt: auto gives level 5, an element size under
//     the ball of 5 mm / 2^5 and no warning; level 3 (1.4 element sizes
//     across the contact radius) warns and names the parameter; the
//     hertz node run says what it modelled.

#include <deal.II/base/mpi.h>

#include <fgimpact/contact/contact_law.h>
#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <test_tools.h>

namespace fgimpact_unit_tests::contact_resolution
{

  using namespace fgimpact;

  namespace
  {
    const std::string prm_file = FGIMPACT_SOURCE_DIR "/prm/default.prm";

    Parameters
    parse(const std::string &settings)
    {
      dealii::ParameterHandler prm;
      Parameters::declare_parameters(prm);
      prm.parse_input(prm_file);
      prm.parse_input_from_string(settings);
      Parameters p;
      p.parse_parameters(prm);
      return p;
    }

    /// The closed-form a_H (m) and levels of the rule, independent of the
    /// library: E*_top of the metal face (n > 0: z = h is pure metal).
    std::pair<double, unsigned int>
    expected(const Parameters &p)
    {
      const double E  = p.material.metal_youngs_modulus,
                   nu = p.material.poissons_ratio, R = p.impactor.radius;
      double a_H = 0;
      if (p.problem_type == ProblemType::static_load)
        a_H = std::sqrt(R * p.static_analysis.indentation);
      else
        {
          const double m     = 4. / 3. * M_PI * R * R * R * p.impactor.density;
          const double V0    = p.impactor.initial_velocity;
          const double K     = 4. / 3. * E / (1. - nu * nu) * std::sqrt(R);
          const double alpha = std::pow(5. * m * V0 * V0 / (4. * K), 0.4);
          a_H                = std::sqrt(R * alpha);
        }
      const auto  &g = p.geometry;
      const double h0 =
        std::min(g.length / g.subdivisions_x, g.width / g.subdivisions_y);
      unsigned int L = 0;
      while (h0 / std::pow(2., L) > a_H / 4. * (1. + 1e-12))
        ++L;
      return {a_H, p.uses_resolved_contact() ? L : 0};
    }

    std::string
    summary_text(const std::string &key)
    {
      std::ifstream in("out/summary.txt");
      std::string   line;
      while (std::getline(in, line))
        if (line.rfind(key + " = ", 0) == 0)
          return line.substr(key.size() + 3);
      return "(missing)";
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                                     ok = true;

    // 1. The rule against the closed form.
    const std::string resolved =
      "subsection Contact\n set Model = resolved sphere\nend\n";
    const std::pair<const char *, std::string> scenes[] = {
      {"default (V0 = 1 m/s)", resolved},
      {"V0 = 4 m/s",
       resolved + "subsection Impactor\n set Initial velocity = 4\nend\n"},
      {"thin, h = 10 mm",
       resolved + "subsection Geometry\n set Thickness h = 0.01\n"
                  " set Subdivisions z = 2\nend\n"},
      {"static sphere, delta = 20 um",
       "set Problem type = static\nsubsection Static\n set Load = sphere\n"
       " set Indentation = 20e-6\nend\n"},
      {"hertz node", ""}};
    std::printf("1. automatic contact refinement levels:\n");
    for (const auto &[name, settings] : scenes)
      {
        const Parameters                 p = parse(settings);
        const FunctionallyGradedMaterial material(p.material,
                                                  p.geometry.thickness);
        const double                     a =
          expected_contact_radius(p, material, p.geometry.thickness);
        const unsigned int L = automatic_contact_refinement_levels(p, a);
        const auto [a_H, L_expected] = expected(p);
        const bool same = std::abs(a - a_H) <= 1e-12 * a_H && L == L_expected;
        std::printf("   %-30s a_H %.4f mm (closed form %.4f), levels %u "
                    "(closed form %u): %s\n",
                    name,
                    a * 1e3,
                    a_H * 1e3,
                    L,
                    L_expected,
                    same ? "yes" : "NO");
        ok = ok && same;
      }

    // 2. What the runs say.
    const std::string run =
      "subsection Time integration\n set End time = 60e-6\nend\n"
      "subsection Output\n set Directory = out\n set Log interval = 0\n"
      " set Print timing = false\n set VTU interval = 0\nend\n";
    fgimpact_tests::run_quietly(prm_file, resolved + run);
    const std::string levels = summary_text("contact_refinement_levels"),
                      size   = summary_text("element_size_under_ball_mm"),
                      none   = summary_text("warnings");
    // The closed form's levels for this scene, and its element size (mm).
    const unsigned int L = expected(parse(resolved)).second;
    const bool         auto_ok =
      levels == std::to_string(L) &&
      std::abs(std::stod(size) - 5. / std::pow(2., L)) < 1e-6 && none == "none";
    std::printf(
      "2. auto: contact_model = %s, contact_refinement_levels = %s, "
      "element_size_under_ball_mm = %s (closed form: level %u, 5 mm / "
      "2^%u), "
      "warnings = %s: %s\n",
      summary_text("contact_model").c_str(),
      levels.c_str(),
      size.c_str(),
      L,
      L,
      none.c_str(),
      auto_ok ? "yes" : "NO");
    fgimpact_tests::run_quietly(
      prm_file,
      resolved + run +
        "subsection Geometry\n set Contact refinement levels = 3\nend\n");
    const std::string warning = summary_text("warnings");
    const bool        warned =
      warning.find("fewer than 4") != std::string::npos &&
      warning.find("Geometry/Contact refinement levels") != std::string::npos;
    std::printf("   level 3: warnings = %s: %s\n",
                warning.c_str(),
                warned ? "yes" : "NO");
    fgimpact_tests::run_quietly(prm_file, run);
    const bool node_ok =
      summary_text("contact_model") == "hertz node" &&
      summary_text("contact_refinement_levels") == "0" &&
      summary_text("element_size_under_ball_mm") == "5.000000" &&
      summary_text("symmetry") == "quarter" &&
      summary_text("scheme") == "implicit" &&
      summary_text("time_step_us") == "1.000000";
    std::printf("   hertz node: contact_model = %s, levels %s, element size "
                "%s mm, symmetry %s, scheme %s, dt %s us: %s\n",
                summary_text("contact_model").c_str(),
                summary_text("contact_refinement_levels").c_str(),
                summary_text("element_size_under_ball_mm").c_str(),
                summary_text("symmetry").c_str(),
                summary_text("scheme").c_str(),
                summary_text("time_step_us").c_str(),
                node_ok ? "yes" : "NO");
    ok = ok && auto_ok && warned && node_ok;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::contact_resolution
