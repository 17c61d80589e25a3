// The ball and the contact nodes in ParaView warp with the plate: read
// back from the files a user opens (vtu/sphere_NNNNN.vtu,
// vtu/contact_NNNNN.vtu, vtu/solution_NNNNN.0.vtu, history.csv) after a
// resolved-sphere impact,
//  (1) the sphere is written at its reference position, its lowest point
//      on the undeformed top face (the plate VTU's largest z, float32:
//      to 1e-8 m), and its
//      point field displacement_m is (0, 0, -w) at every point, w the
//      impactor displacement of history.csv at that time: WarpByVector with
//      factor 1 puts it where it is;
//  (2) the contact nodes' displacement_m z equals the plate's displacement
//      at the same point of solution_NNNNN.0.vtu (float32);
//  (3) warped by factor 1, every node with a positive contact pressure
//      lies on the warped sphere: u_z + w - (R - sqrt(R^2 - r^2)) = 0 (the
//      LCP's complementarity, R and the impact point taken from the
//      sphere's file);
//  (4) the ball as drawn at the contact's scale: its points on the sphere,
//      at least 8 rings within the contact radius, and its facets there
//      within 1 % of the impactor displacement w of the sphere (chord sag
//      R (1 - cos(dtheta/2))); with 24 even rings the first lay beyond the
//      contact and the sag was R dtheta^2/8 = 8 um against w = 38 um.
// Before, the sphere was written at its true position without a point
// field (a warped plate left it floating), and the nodes had none.

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::vtu_ball_warp
{

  using namespace dealii;

  namespace
  {

    std::string
    file(const std::string &series, const unsigned int n)
    {
      return "out/vtu/" + series + "_" + Utilities::int_to_string(n, 5) +
             (series == "solution" ? ".0.vtu" : ".vtu");
    }

    /// history.csv's impactor displacement (m) by step (dt = 1 us: one row
    /// per step).
    std::vector<double>
    impactor_displacements()
    {
      std::ifstream in("out/history.csv");
      std::string   line;
      std::getline(in, line);
      const auto header = Utilities::split_string_list(line, ',');
      const auto column =
        std::find(header.begin(), header.end(), "impactor_displacement_um") -
        header.begin();
      std::vector<double> w;
      while (std::getline(in, line))
        w.push_back(1e-6 *
                    std::stod(Utilities::split_string_list(line, ',')[column]));
      return w;
    }
  } // namespace



  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    fgimpact_tests::remove_output("out");
    fgimpact_tests::run_quietly(
      "",
      "subsection Contact\n set Model = resolved sphere\nend\n"
      "subsection Time integration\n set End time = 60e-6\nend\n"
      "subsection Output\n set Directory = out\n set Log interval = 0\n"
      " set Print timing = false\n set VTU interval = 10\n"
      " set VTU compression = none\n set Fields = displacement\nend\n");
    const std::vector<double> w = impactor_displacements();

    // (1) The sphere at its reference position, displaced by -w.
    double     top     = -1e9;
    const auto points0 = fgimpact_tests::read_points(file("solution", 0));
    for (std::size_t k = 2; k < points0.size(); k += 3)
      top = std::max<double>(top, points0[k]);
    double worst_bottom = 0, worst_w = 0, largest_w = 0;
    double R = 0, x0 = 0, y0 = 0;
    for (unsigned int n = 0; n <= 60; n += 10)
      {
        const std::string text = fgimpact_tests::file_text(file("sphere", n));
        const auto        p    = fgimpact_tests::ascii_array(text, "");
        const auto d    = fgimpact_tests::ascii_array(text, "displacement_m");
        double     zmin = 1e9, zmax = -1e9;
        for (std::size_t k = 0; k < p.size(); k += 3)
          {
            if (p[k + 2] < zmin)
              {
                zmin = p[k + 2];
                x0   = p[k];
                y0   = p[k + 1];
              }
            zmax = std::max(zmax, p[k + 2]);
          }
        R            = 0.5 * (zmax - zmin);
        worst_bottom = std::max(worst_bottom, std::abs(zmin - top));
        for (std::size_t k = 0; k < d.size(); k += 3)
          worst_w = std::max({worst_w,
                              std::abs(d[k]),
                              std::abs(d[k + 1]),
                              std::abs(d[k + 2] + w[n])});
        largest_w = std::max(largest_w, w[n]);
      }
    const bool sphere_ok =
      worst_bottom < 1e-8 && worst_w < 1e-10 && largest_w > 0;
    // Verdicts on the differences, not their digits: they are rounding (of
    // float32 and of the files' decimals) and round-off.
    std::printf("sphere at its reference (lowest point - top face below 1e-8 "
                "m: %s) with displacement_m = (0, 0, -w of history.csv) at "
                "every point of 7 snapshots (largest error below 1e-10 m: %s, "
                "w up to %.2f um): %s\n",
                worst_bottom < 1e-8 ? "yes" : "NO",
                worst_w < 1e-10 ? "yes" : "NO",
                largest_w * 1e6,
                sphere_ok ? "yes" : "NO");

    // (2) and (3) at 50 us, near the peak force.
    const unsigned int n     = 50;
    const std::string  text  = fgimpact_tests::file_text(file("contact", n));
    const auto         nodes = fgimpact_tests::ascii_array(text, "");
    const auto         d = fgimpact_tests::ascii_array(text, "displacement_m");
    const auto         pressure =
      fgimpact_tests::ascii_array(text, "contact_pressure_MPa");
    const auto plate_points = fgimpact_tests::read_points(file("solution", n));
    const auto plate_u =
      fgimpact_tests::read_array(file("solution", n), "displacement_m");
    double       largest_uz = 0, worst_plate = 0, worst_gap = 0, a = 0;
    unsigned int matched = 0, active = 0;
    for (std::size_t j = 0; j < pressure.size(); ++j)
      largest_uz = std::max(largest_uz, std::abs(d[3 * j + 2]));
    for (std::size_t j = 0; j < pressure.size(); ++j)
      {
        for (std::size_t k = 0; 3 * k + 2 < plate_points.size(); ++k)
          if (std::abs(plate_points[3 * k] - nodes[3 * j]) < 1e-7 &&
              std::abs(plate_points[3 * k + 1] - nodes[3 * j + 1]) < 1e-7 &&
              std::abs(plate_points[3 * k + 2] - nodes[3 * j + 2]) < 1e-7)
            {
              worst_plate =
                std::max(worst_plate,
                         std::abs(plate_u[3 * k + 2] - d[3 * j + 2]) /
                           largest_uz);
              ++matched;
              break;
            }
        if (pressure[j] > 0)
          {
            const double r2 = std::pow(nodes[3 * j] - x0, 2) +
                              std::pow(nodes[3 * j + 1] - y0, 2);
            const double gap = R - std::sqrt(R * R - r2);
            worst_gap =
              std::max(worst_gap, std::abs(d[3 * j + 2] + w[n] - gap) / w[n]);
            a = std::max(a, std::sqrt(r2));
            ++active;
          }
      }
    const bool plate_ok = matched == pressure.size() && worst_plate < 1e-5;
    const bool gap_ok   = active > 0 && worst_gap < 1e-6;
    std::printf("contact nodes' displacement_m z = the plate's at the same "
                "point, %u of %zu nodes found (largest difference / largest "
                "|u_z| below 1e-5: %s): %s\n",
                matched,
                static_cast<std::size_t>(pressure.size()),
                worst_plate < 1e-5 ? "yes" : "NO",
                plate_ok ? "yes" : "NO");
    std::printf("warped by 1, the %u nodes in contact lie on the warped "
                "sphere (largest |u_z + w - gap(r)| / w below 1e-6: %s): %s\n",
                active,
                worst_gap < 1e-6 ? "yes" : "NO",
                gap_ok ? "yes" : "NO");

    // (4) The drawn ball at the contact's scale: every point on the sphere
    // |p - c| = R, and the facets within the contact radius a (the nodes in
    // contact above) depart from the sphere by less than 1 % of w: a chord
    // between two rings dtheta apart sags R (1 - cos(dtheta/2)) below it.
    const auto sphere =
      fgimpact_tests::ascii_array(fgimpact_tests::file_text(file("sphere", n)),
                                  "");
    double zlow = 1e9;
    for (std::size_t k = 2; k < sphere.size(); k += 3)
      zlow = std::min(zlow, sphere[k]);
    const double        zc           = zlow + R; // the centre
    double              worst_radius = 0;
    std::vector<double> thetas;
    for (std::size_t k = 0; k < sphere.size(); k += 3)
      {
        const double dx = sphere[k] - x0, dy = sphere[k + 1] - y0,
                     dz  = sphere[k + 2] - zc;
        const double rho = std::sqrt(dx * dx + dy * dy + dz * dz);
        worst_radius     = std::max(worst_radius, std::abs(rho - R) / R);
        thetas.push_back(std::acos(std::clamp(-dz / rho, -1., 1.)));
      }
    std::sort(thetas.begin(), thetas.end());
    thetas.erase(std::unique(thetas.begin(),
                             thetas.end(),
                             [](double s, double t) {
                               return std::abs(s - t) < 1e-9;
                             }),
                 thetas.end());
    unsigned int rings_inside = 0;
    double       worst_sag    = 0;
    for (std::size_t i = 1; i < thetas.size(); ++i)
      if (thetas[i - 1] < 0.5 * M_PI && R * std::sin(thetas[i - 1]) < a)
        {
          // The lower hemisphere only (sin is small at the top pole too).
          rings_inside += (R * std::sin(thetas[i]) < a);
          worst_sag =
            std::max(worst_sag,
                     R * (1. - std::cos(0.5 * (thetas[i] - thetas[i - 1]))));
        }
    const bool ball_ok =
      worst_radius < 1e-8 && rings_inside >= 8 && worst_sag < 1e-2 * w[n];
    std::printf("the ball's points on the sphere (|p - c| - R below 1e-8 R: "
                "%s); within the contact radius at least 8 rings (%s) and "
                "facets within 1 %% of w of the sphere (%s): %s\n",
                worst_radius < 1e-8 ? "yes" : "NO",
                rings_inside >= 8 ? "yes" : "NO",
                worst_sag < 1e-2 * w[n] ? "yes" : "NO",
                ball_ok ? "yes" : "NO");
    return sphere_ok && plate_ok && gap_ok && ball_ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::vtu_ball_warp
