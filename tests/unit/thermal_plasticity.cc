// J2 plasticity starts from the thermal pre-stress (issue 42).  A pure
// aluminium square plate (Power-law index 0) 0.2 x 0.2 x 0.005 m
// (a/h = 40), simply supported with immovable sides, under a uniform
// Delta T = 200 K: plate theory's elastic thermal stress
// -E alpha Delta T / (1 - nu) = -460 MPa is beyond the yield strength
// Y = 275 MPa.  With the in-plane strain held (eps_xx = eps_yy = 0 from
// the stress-free plate), sigma_zz = 0 and linear hardening H = 0.3 GPa,
// the equibiaxial state has the in-plane plastic strain p (eps_p = p (1, 1,
// -2), eps_bar = 2 |p|) with
//
//   |p| = (E' alpha Delta T - Y) / (E' + 2 H),  E' = E / (1 - nu),
//   sigma_xx = sigma_yy = -(Y + 2 H |p|) = -276.10 MPa,
//   eps_bar = 2 |p| = 3.678e-3.
//
// The thermal step is elastic; a static run relaxes this state in its
// first load step (an impact from it is refused: bad_input).
// A static sphere indentation of 0.1 um (J2 needs Load = sphere) on the
// quarter model, elements h/2 wide: at the interior point (a/4, b/4,
// h/2), far from the ball and the sides, the VTU's recovered sigma_xx_MPa
// and sigma_yy_MPa within 0.2 % of the closed form at a/h = 40.  The
// recovered equivalent_plastic_strain_nodal carries the sides' edge layer
// (the whole-face w = 0 of the simply supported sides, as the elastic
// interior stress's +0.70 % at a/h = 40 in thermal_closed_forms), at
// first order in h/a: at a/h = 20 and 40 its order lies in [0.8, 1.2]
// and its extrapolation to h/a = 0 is within 0.5 %.  The elastic run's
// written stress there (Plasticity = none) is the elastic -460 MPa
// (within 1 %): the return map that ignored the pre-stress would leave
// it there.
//
// The impact from a pre-stress below the yield strength: the default
// scene's plate in pure aluminium, immovable sides, Delta T = 80 K
// (-187 MPa, 0.68 Y), the resolved sphere at contact level 3, End time =
// auto, quarter model:
//  - the energy balance closes with the pre-stress's work on the plastic
//    strain (PlasticPlate::set_prestress()): max_relative_energy_drift
//    below 1e-3, as without a temperature field (1.7e-4; 1.2e-2 with that
//    work left out);
//  - two implementations of the total stress of a plastic run agree: in
//    every VTU snapshot the recovered sigma_xx_MPa at the plate's centre
//    on the mid-plane (StressRecovery, C (eps + eps0 - eps_p) returned to
//    the yield surface) equals history.csv's sigma_xx_mid_MPa at that
//    step (PointProbe: the pre-stress at the point plus the linear
//    functional and the plastic correction) within 1e-4 of the thermal
//    stress (float32, 5 printed decimals).

#include <deal.II/base/mpi.h>

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <test_tools.h>
#include <vtu_reader.h>

namespace fgimpact_unit_tests::thermal_plasticity
{
  using namespace dealii;

  namespace
  {
    struct Interior
    {
      double sigma_xx = std::nan(""), sigma_yy = std::nan(""),
             eps_bar = std::nan("");
    };

    /// The static run with `extra` into out_NAME; the VTU's values at
    /// (0.05, 0.05, h/2).
    Interior
    run(const std::string &name, const std::string &extra, const int ratio)
    {
      // a/h = ratio, elements h/2 wide in plane (2 through the thickness).
      const double      h         = 0.2 / ratio;
      const std::string directory = "out_" + name;
      fgimpact_tests::remove_output(directory);
      fgimpact_tests::run_quietly(
        "",
        "set Problem type = static\n"
        "subsection Geometry\n set Symmetry = quarter\n set Length a = 0.2\n"
        " set Width b = 0.2\n set Thickness h = " +
          std::to_string(h) +
          "\n set Subdivisions x = " + std::to_string(2 * ratio) +
          "\n set Subdivisions y = " + std::to_string(2 * ratio) +
          "\n"
          " set Subdivisions z = 2\nend\n"
          "subsection Material\n set Power-law index = 0\nend\n"
          "subsection Boundary conditions\n set In-plane edges = immovable\n"
          "end\n"
          "subsection Thermal\n set Temperature field = uniform\n"
          " set Temperature change = 200\nend\n"
          "subsection Static\n set Load = sphere\n set Indentation = 1e-7\n"
          " set Load steps = 2\nend\n"
          "subsection Output\n set Directory = " +
          directory +
          "\n set VTU compression = none\n set Fields = stress\n"
          " set Mirror symmetric part = false\n set Print timing = false\n"
          "end\n" +
          extra);
      const std::string file = directory + "/vtu/solution_00000.0.vtu";
      const auto        x    = fgimpact_tests::read_points(file);
      const auto        s_xx = fgimpact_tests::read_array(file, "sigma_xx_MPa");
      const auto        s_yy = fgimpact_tests::read_array(file, "sigma_yy_MPa");
      const bool        j2   = !extra.empty();
      Interior          value;
      for (std::size_t i = 0; i < x.size() / 3; ++i)
        if (std::abs(x[3 * i] - 0.05) < 1e-7 &&
            std::abs(x[3 * i + 1] - 0.05) < 1e-7 &&
            std::abs(x[3 * i + 2] - h / 2) < 1e-7)
          {
            value.sigma_xx = s_xx[i];
            value.sigma_yy = s_yy[i];
            if (j2)
              value.eps_bar = fgimpact_tests::read_array(
                file, "equivalent_plastic_strain_nodal")[i];
          }
      return value;
    }

    bool
    report(const char  *what,
           const double value,
           const double exact,
           const double tolerance)
    {
      const double error = value / exact - 1.;
      const bool   pass  = std::abs(error) < tolerance;
      std::printf("  %-40s %+.4f (%s %.1f %%)\n",
                  what,
                  error,
                  pass ? "within" : "NOT within",
                  100. * tolerance);
      return pass;
    }

    /// The impact from a pre-stress below the yield strength.
    bool
    check_impact()
    {
      fgimpact_tests::remove_output("out_impact");
      fgimpact_tests::run_quietly(
        "",
        "subsection Geometry\n set Symmetry = quarter\n"
        " set Contact refinement levels = 3\nend\n"
        "subsection Contact\n set Model = resolved sphere\nend\n"
        "subsection Material\n set Plasticity = J2\n"
        " set Power-law index = 0\nend\n"
        "subsection Boundary conditions\n set In-plane edges = immovable\n"
        "end\n"
        "subsection Thermal\n set Temperature field = uniform\n"
        " set Temperature change = 80\nend\n"
        "subsection Time integration\n set End time = auto\nend\n"
        "subsection Output\n set Directory = out_impact\n"
        " set VTU interval = 20\n set VTU compression = none\n"
        " set Fields = stress\n set Mirror symmetric part = false\n"
        " set Log interval = 0\n set Print timing = false\nend\n");
      const auto summary =
        fgimpact_tests::read_summary("out_impact/summary.txt");
      const double drift = std::stod(summary.at("max_relative_energy_drift"));
      const double work  = std::stod(summary.at("plastic_dissipation_J"));
      const auto history = fgimpact_tests::csv_column("out_impact/history.csv",
                                                      "sigma_xx_mid_MPa");
      // The quarter's corner (a/2, b/2) at mid-height.
      const double xc = 0.1, yc = 0.05, zc = 0.01, tol = 1e-7;
      unsigned int n_files = 0;
      double       worst = 0, scale = 0;
      for (const auto &file :
           fgimpact_tests::snapshot_files("out_impact", "solution_0"))
        {
          const auto         name = file.substr(file.rfind("solution_") + 9);
          const unsigned int step = std::stoi(name.substr(0, 5));
          const auto         x    = fgimpact_tests::read_points(file);
          const auto sxx = fgimpact_tests::read_array(file, "sigma_xx_MPa");
          for (std::size_t i = 0; i < sxx.size(); ++i)
            if (std::abs(x[3 * i] - xc) < tol &&
                std::abs(x[3 * i + 1] - yc) < tol &&
                std::abs(x[3 * i + 2] - zc) < tol && step < history.size())
              {
                ++n_files;
                scale = std::max(scale, std::abs(history[step]));
                worst = std::max(worst, std::abs(sxx[i] - history[step]));
              }
        }
      const bool agree = n_files >= 5 && worst <= 1e-4 * scale;
      const bool pass  = drift < 1e-3 && work > 0. && agree;
      std::printf("impact from -187 MPa (0.68 Y): plastic work > 0: %s; "
                  "max_relative_energy_drift < 1e-3: %s; in %s snapshots the "
                  "VTU's recovered sigma_xx at the centre's mid-plane equals "
                  "history.csv's within 1e-4: %s\n",
                  work > 0. ? "yes" : "NO",
                  drift < 1e-3 ? "yes" : "NO",
                  n_files >= 5 ? "at least 5" : "FEWER THAN 5",
                  worst <= 1e-4 * scale ? "yes" : "NO");
      return pass;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const double E = 100e9, alpha = 23e-6, dT = 200., Y = 275e6, H = 0.3e9;
    const double p       = (E * alpha * dT - Y) / (E + 2. * H);
    const double sigma   = -(Y + 2. * H * p) * 1e-6; // MPa
    const double eps_bar = 2. * p;
    std::printf("closed form: sigma_xx = sigma_yy = %.2f MPa, eps_bar = "
                "%.4e; elastic %.1f MPa\n",
                sigma,
                eps_bar,
                -E * alpha * dT * 1e-6);

    const std::string j2 = "subsection Material\n set Plasticity = J2\nend\n";
    const Interior    elastic   = run("elastic", "", 40);
    const Interior    plastic20 = run("j2_20", j2, 20);
    const Interior    plastic   = run("j2_40", j2, 40);
    bool              ok        = true;
    std::printf("elastic run, a/h = 40, at (a/4, b/4, h/2), relative "
                "error:\n");
    ok = report("sigma_xx against -E' alpha Delta T",
                elastic.sigma_xx,
                -E * alpha * dT * 1e-6,
                0.01) &&
         ok;
    std::printf("J2 runs from the pre-stress, relative error:\n");
    ok = report("sigma_xx, a/h = 40", plastic.sigma_xx, sigma, 0.002) && ok;
    ok = report("sigma_yy, a/h = 40", plastic.sigma_yy, sigma, 0.002) && ok;
    // eps_bar carries the sides' edge layer at first order in h/a (a/h =
    // 20, 40, 80: +7.1 %, +3.4 %, +1.7 %): its order, and its
    // extrapolation to a thin plate, 2 e(40) - e(20).
    const double e20      = plastic20.eps_bar / eps_bar - 1.,
                 e40      = plastic.eps_bar / eps_bar - 1.;
    const double order    = std::log2(e20 / e40);
    const bool   order_ok = order > 0.8 && order < 1.2;
    std::printf("  equivalent_plastic_strain_nodal at a/h = 20, 40: %+.4f, "
                "%+.4f; order in h/a %.2f (%s [0.8, 1.2])\n",
                e20,
                e40,
                order,
                order_ok ? "in" : "NOT in");
    ok = report("its extrapolation to h/a = 0",
                eps_bar * (1. + 2. * e40 - e20),
                eps_bar,
                0.005) &&
         ok && order_ok;
    ok = check_impact() && ok;
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::thermal_plasticity
