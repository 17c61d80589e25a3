// A plastic run writes the stress the metal carries, sigma = C (eps -
// eps_p), read back from the files users read (issue 37, item 2).  The
// default scene with the resolved sphere on a J2 face, quarter plate,
// contact refinement level 3, End time = auto, a VTU snapshot every 10
// steps and at the peak force:
//  1. In every snapshot, wherever the recovered equivalent plastic strain
//     is positive, the recovered von Mises stress is at most the written
//     current yield stress Y(z) + H(z) eps_bar (1e-5 relative: the VTU's
//     float32); before the fix it was 10 x the yield strength.
//  2. The return map's own verdict, the cell field von_mises_over_yield
//     (the Gauss points' von Mises over their yield stress), is at most 1
//     (1e-5).
//  3. summary.txt: max_von_mises_over_yield (the stress carried) is at
//     most 1 (to its 4 printed digits), elastic_von_mises_over_yield (the
//     elastic trial's) above 1, and probe_top_peak_von_mises_MPa (the
//     probe at the impact point) at most yield_strength_at_peak_MPa's
//     hardened range (the top face is pure metal: Y_m plus
//     H eps_bar_max with the defaults Y_m = 275 MPa, H_m = 0.3 GPa).
//  4. A yield strength no stress reaches (1e11 Pa): the snapshots' stress
//     fields equal the elastic run's (1e-6 of the largest value).
//  5. The crater's diameter in summary.txt equals the one of the last
//     snapshot's top face (where the thinning W_top(r) - W_mid changes
//     sign along y = y_c), and the plastic zone's depth and radius lie
//     within the snapshot's plastic cells, less than an element inside.

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <map>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::plastic_stress_vtu
{

  using namespace dealii;

  namespace
  {
    /// The scene with `extra` settings into out_NAME; its summary.txt.
    std::map<std::string, std::string>
    impact(const std::string &name, const std::string &extra)
    {
      const std::string directory = "out_" + name;
      fgimpact_tests::remove_output(directory);
      fgimpact_tests::run_quietly(
        FGIMPACT_SOURCE_DIR "/prm/default.prm",
        "subsection Geometry\n set Symmetry = quarter\n"
        " set Contact refinement levels = 3\nend\n"
        "subsection Contact\n set Model = resolved sphere\nend\n"
        "subsection Time integration\n set End time = auto\nend\n"
        "subsection Output\n set Directory = " +
          directory +
          "\n set VTU interval = 10\n set VTU compression = none\n"
          " set Fields = stress, von_mises\n set Log interval = 0\n"
          " set Print timing = false\nend\n" +
          extra);
      return fgimpact_tests::read_summary(directory + "/summary.txt");
    }


    const std::string j2 = "subsection Material\n set Plasticity = J2\nend\n";
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    // 1.-2. The snapshots of the J2 run.
    const auto   plastic = impact("j2", j2);
    const auto   files = fgimpact_tests::snapshot_files("out_j2", "solution_");
    unsigned int n_plastic_points = 0;
    bool         below_yield = true, cells_below = true;
    for (const auto &file : files)
      {
        const auto vm    = fgimpact_tests::read_array(file, "von_mises_MPa");
        const auto yield = fgimpact_tests::read_array(file, "yield_stress_MPa");
        const auto eps_bar =
          fgimpact_tests::read_array(file, "equivalent_plastic_strain_nodal");
        for (std::size_t i = 0; i < vm.size(); ++i)
          if (eps_bar[i] > 0.f)
            {
              ++n_plastic_points;
              below_yield = below_yield && vm[i] <= yield[i] * (1. + 1e-5);
            }
        for (const float r :
             fgimpact_tests::read_array(file, "von_mises_over_yield"))
          cells_below = cells_below && r <= 1. + 1e-5;
      }
    std::printf("J2 run, %s snapshots: von Mises <= the written yield stress "
                "at every point with plastic strain (%s such points): %s\n",
                files.size() >= 10 ? "at least 10" : "FEWER THAN 10",
                n_plastic_points > 100 ? "more than 100" : "FEWER THAN 100",
                below_yield ? "yes" : "NO");
    std::printf("the cells' von_mises_over_yield (Gauss points) <= 1: %s\n",
                cells_below ? "yes" : "NO");
    ok = ok && files.size() >= 10 && n_plastic_points > 100 && below_yield &&
         cells_below;

    // 3. summary.txt.
    const double carried = std::stod(plastic.at("max_von_mises_over_yield"));
    const double elastic =
      std::stod(plastic.at("elastic_von_mises_over_yield"));
    const double probe = std::stod(plastic.at("probe_top_peak_von_mises_MPa"));
    const double hardened =
      275e6 + 0.3e9 * std::stod(plastic.at("max_equivalent_plastic_strain"));
    const bool summary_ok =
      carried <= 1. && elastic > 1. && probe * 1e6 <= hardened * (1. + 1e-4);
    std::printf(
      "summary.txt: max_von_mises_over_yield <= 1: %s; "
      "elastic_von_mises_over_yield > 1: %s; the top probe's peak von "
      "Mises within the top face's hardened yield stress: %s\n",
      carried <= 1. ? "yes" : "NO",
      elastic > 1. ? "yes" : "NO",
      probe * 1e6 <= hardened * (1. + 1e-4) ? "yes" : "NO");
    ok = ok && summary_ok;

    // 3b. First yield (issue 37, item 3): Hertz's on a half-space of the top
    // face, from Johnson's largest von Mises stress 0.62 p0 (nu = 0.3), p0 =
    // Y / 0.62, F = pi^3 p0^3 R^2 / (6 E*^2) with the summary's E*, and its
    // contact radius pi p0 R / (2 E*) over the node spacing under the ball
    // (Q1: the element size, 0.3125 mm at level 3: 0.43); below 4 the
    // computed first yield is none.  Johnson's 0.62 has 2 digits: 2.5 % in
    // F.
    {
      const double E = std::stod(plastic.at("contact_modulus_Q_Pa"));
      const double R = 0.015, p0 = 275e6 / 0.62;
      const double F = std::pow(numbers::PI * p0, 3) * R * R / (6. * E * E);
      const double a = numbers::PI * p0 * R / (2. * E);
      const double h =
        std::stod(plastic.at("element_size_under_ball_mm")) * 1e-3;
      const double Fs = std::stod(plastic.at("first_yield_hertz_force_N"));
      const double rs =
        std::stod(plastic.at("first_yield_contact_radius_node_spacings"));
      const bool first_yield_ok =
        std::abs(Fs / F - 1.) < 0.025 && std::abs(rs / (a / h) - 1.) < 0.01 &&
        rs < 4. && plastic.at("first_yield_contact_force_N") == "none" &&
        plastic.at("first_yield_time_us") == "none";
      std::printf("first yield: Hertz's force within 2.5 %% of Johnson's, its "
                  "contact radius in node spacings (Q1: element sizes) "
                  "within 1 %%, below 4 and "
                  "the computed time and force none: %s\n",
                  first_yield_ok ? "yes" : "NO");
      ok = ok && first_yield_ok;
    }

    // 5. The crater and the plastic zone, against the last snapshot (End
    // time 200 us, a multiple of the VTU interval).
    {
      const auto s = impact("crater",
                            j2 + "subsection Time integration\n set End time = "
                                 "2e-4\nend\nsubsection Output\n set Fields = "
                                 "displacement\n set VTU interval = 50\nend\n");
      // Step 200's pieces (a mirrored part writes two).
      const double h = 0.02, xc = 0.1, yc = 0.05, tol = 1e-7; // m (float32)
      double       W_mid = 0;
      std::vector<std::pair<double, double>> line;
      double                                 depth = 0, radius = 0;
      for (const auto &file :
           fgimpact_tests::snapshot_files("out_crater", "solution_"))
        {
          if (file.find("solution_00200") == std::string::npos)
            continue;
          const auto x = fgimpact_tests::read_points(file);
          const auto u = fgimpact_tests::read_array(file, "displacement_m");
          const auto eps =
            fgimpact_tests::read_array(file, "equivalent_plastic_strain");
          // W_mid under the impact point, the top face's deflection along
          // y = y_c, x <= x_c, and the vertices of the plastic cells.
          for (std::size_t i = 0; i < x.size() / 3; ++i)
            {
              const double px = x[3 * i], py = x[3 * i + 1], pz = x[3 * i + 2];
              if (std::abs(px - xc) < tol && std::abs(py - yc) < tol &&
                  std::abs(pz - h / 2) < tol)
                W_mid = -u[3 * i + 2];
              if (std::abs(pz - h) < tol && std::abs(py - yc) < tol &&
                  px <= xc + tol)
                line.emplace_back(std::max(xc - px, 0.), -u[3 * i + 2]);
              if (eps[i] > 0.f)
                {
                  depth  = std::max(depth, h - pz);
                  radius = std::max(radius, std::hypot(px - xc, py - yc));
                }
            }
        }
      std::sort(line.begin(), line.end());
      double diameter = std::nan("");
      for (std::size_t i = 1; i < line.size(); ++i)
        {
          const double d0 = line[i - 1].second - W_mid,
                       d1 = line[i].second - W_mid;
          if (d0 > 0. && d1 <= 0.)
            {
              diameter =
                2. * (line[i - 1].first +
                      d0 / (d0 - d1) * (line[i].first - line[i - 1].first));
              break;
            }
        }
      const double written = std::stod(s.at("crater_diameter_mm")) * 1e-3;
      const double zone_d  = std::stod(s.at("plastic_zone_depth_mm")) * 1e-3;
      const double zone_r  = std::stod(s.at("plastic_zone_radius_mm")) * 1e-3;
      const double element =
        std::stod(s.at("element_size_under_ball_mm")) * 1e-3;
      const bool crater_ok = std::abs(diameter - written) < 1e-6;
      // A Gauss point lies inside its cell: the zone reaches into the
      // deepest (farthest) plastic cell, by less than one element size.
      const bool zone_ok = zone_d <= depth + tol && zone_d > depth - element &&
                           zone_r <= radius + tol && zone_r > radius - element;
      std::printf(
        "crater: summary.txt's crater_diameter_mm equals the last "
        "snapshot's top-face profile's to 1e-3 mm: %s; the plastic "
        "zone's depth and radius within the snapshot's plastic cells, "
        "less than an element inside: %s\n",
        crater_ok ? "yes" : "NO",
        zone_ok ? "yes" : "NO");
      ok = ok && crater_ok && zone_ok;
    }

    // 4. The elastic limit.
    impact("elastic", "");
    impact("stiff",
           "subsection Material\n set Plasticity = J2\n"
           " set Metal yield strength = 1e11\nend\n");
    const auto a = fgimpact_tests::snapshot_files("out_elastic", "solution_"),
               b = fgimpact_tests::snapshot_files("out_stiff", "solution_");
    bool same    = a.size() == b.size() && !a.empty();
    for (std::size_t f = 0; same && f < a.size(); ++f)
      for (const std::string field :
           {"sigma_xx_MPa", "sigma_zz_MPa", "sigma_xz_MPa", "von_mises_MPa"})
        {
          const auto  x       = fgimpact_tests::read_array(a[f], field);
          const auto  y       = fgimpact_tests::read_array(b[f], field);
          float       largest = 0, difference = 0;
          std::size_t n = std::min(x.size(), y.size());
          for (std::size_t i = 0; i < n; ++i)
            {
              largest    = std::max(largest, std::abs(x[i]));
              difference = std::max(difference, std::abs(x[i] - y[i]));
            }
          same = same && x.size() == y.size() && difference <= 1e-6 * largest;
        }
    std::printf("yield strength 1e11 Pa: every snapshot's stress fields equal "
                "the elastic run's to 1e-6: %s\n",
                same ? "yes" : "NO");
    ok = ok && same;

    std::printf("%s\n", ok ? "all checks passed" : "CHECK FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::plastic_stress_vtu
