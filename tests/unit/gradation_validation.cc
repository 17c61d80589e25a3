// Every gradation and homogenization (Material/Gradation, Homogenization)
// against the exact 3D elasticity solution of tests/exact/plate_exact.h with
// nu(z): the simply supported plate's mid-plane centre deflection under the
// pressure q0 sin(pi x/a) sin(pi y/b) and its two lowest flexural natural
// frequencies, Q2 graded elements on 20 x 10 x 4, each within 0.1 %.
// The constituents differ in Poisson's ratio (metal 0.3, ceramic 0.25), so
// nu varies through the thickness in every case.  The exact plate's
// profiles are written here again from the formulas of README/doc/theory.md
// (not taken from the library), and the library's profiles are checked
// against them at 101 heights.
// Set FGIMPACT_VERBOSE=1 to print the numbers.

#include <deal.II/base/mpi.h>

#include <fgimpact/analysis/modal_analysis.h>
#include <fgimpact/analysis/static_analysis.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exact/plate_exact.h>
#include <filesystem>
#include <fstream>
#include <functional>
#include <test_tools.h>

namespace fgimpact_unit_tests::gradation_validation
{

  using namespace fgimpact;

  namespace
  {
    const double E_m = 70e9, nu_m = 0.3, rho_m = 2707.;
    const double E_c = 380e9, nu_c = 0.25, rho_c = 3800.;
    const double h = 0.02;

    struct Case
    {
      const char                                  *name;
      Gradation                                    gradation;
      Homogenization                               homogenization;
      double                                       n;
      std::function<std::array<double, 3>(double)> exact; // E, nu, rho at zeta
    };

    /// Mori-Tanaka in the Hashin-Shtrikman lower-bound form (the same
    /// numbers, written differently from the library's).
    std::array<double, 3>
    mori_tanaka(const double Vm)
    {
      const double Vc = 1. - Vm;
      const double Km = E_m / (3 * (1 - 2 * nu_m)), Gm = E_m / (2 * (1 + nu_m));
      const double Kc = E_c / (3 * (1 - 2 * nu_c)), Gc = E_c / (2 * (1 + nu_c));
      const double K = Km + Vc / (1 / (Kc - Km) + 3 * Vm / (3 * Km + 4 * Gm));
      const double z = Gm / 6 * (9 * Km + 8 * Gm) / (Km + 2 * Gm);
      const double G = Gm + Vc / (1 / (Gc - Gm) + Vm / (Gm + z));
      return {9 * K * G / (3 * K + G),
              (3 * K - 2 * G) / (6 * K + 2 * G),
              rho_c * Vc + rho_m * Vm};
    }

    std::array<double, 3>
    mixture(const double Vm)
    {
      return {E_c * (1 - Vm) + E_m * Vm,
              nu_c * (1 - Vm) + nu_m * Vm,
              rho_c * (1 - Vm) + rho_m * Vm};
    }

    double
    sigmoid(const double zeta, const double n)
    {
      return zeta <= 0.5 ? 0.5 * std::pow(2 * zeta, n) :
                           1 - 0.5 * std::pow(2 - 2 * zeta, n);
    }

    // The tabulated profile: rows at the element boundaries of nz = 4 (a
    // piecewise linear profile with kinks inside an element is not a Q2
    // polynomial there).
    const std::vector<std::array<double, 4>> table = {{0.00, 380e9, 0.25, 3800},
                                                      {0.25, 300e9, 0.22, 3500},
                                                      {0.50, 200e9, 0.28, 3300},
                                                      {0.75, 120e9, 0.26, 3000},
                                                      {1.00, 70e9, 0.30, 2707}};

    std::array<double, 3>
    tabulated(const double zeta)
    {
      unsigned int i = 0;
      while (i + 2 < table.size() && zeta > table[i + 1][0])
        ++i;
      const double t = (zeta - table[i][0]) / (table[i + 1][0] - table[i][0]);
      std::array<double, 3> v;
      for (unsigned int k = 0; k < 3; ++k)
        v[k] = table[i][k + 1] + t * (table[i + 1][k + 1] - table[i][k + 1]);
      return v;
    }

    FunctionallyGradedMaterial::Parameters
    material_parameters(const Case &c)
    {
      FunctionallyGradedMaterial::Parameters p;
      p.metal_youngs_modulus   = E_m;
      p.poissons_ratio         = nu_m;
      p.metal_density          = rho_m;
      p.ceramic_youngs_modulus = E_c;
      p.ceramic_poissons_ratio = nu_c;
      p.ceramic_density        = rho_c;
      p.power_law_index        = c.n;
      p.gradation              = c.gradation;
      p.homogenization         = c.homogenization;
      p.profile_file           = "gradation_validation_profile.csv";
      return p;
    }

    fgimpact_exact::Plate
    exact_plate(const Case &c)
    {
      fgimpact_exact::Plate plate = fgimpact_exact::homogeneous_plate();
      const auto            f     = c.exact;
      plate.E                     = [f](const double z) { return f(z / h)[0]; };
      plate.nu_z                  = [f](const double z) { return f(z / h)[1]; };
      plate.rho                   = [f](const double z) { return f(z / h)[2]; };
      return plate;
    }

    /// The largest relative difference between the library's profile and
    /// the formula's, over 101 heights.
    double
    profile_difference(const FunctionallyGradedMaterial &material,
                       const Case                       &c)
    {
      double d = 0;
      for (unsigned int i = 0; i <= 100; ++i)
        {
          const IsotropicProperties p = material.properties(h * i / 100.);
          const auto                e = c.exact(i / 100.);
          d                           = std::max({d,
                                                  std::abs(p.E / e[0] - 1),
                                                  std::abs(p.nu / e[1] - 1),
                                                  std::abs(p.rho / e[2] - 1)});
        }
      return d;
    }

    /// The lowest two exact flexural frequencies over (m, n) <= 3 (Hz).
    std::vector<double>
    exact_flexural(const fgimpact_exact::Plate &plate)
    {
      std::vector<double> f;
      for (unsigned int m = 1; m <= 3; ++m)
        for (unsigned int n = 1; n <= 2; ++n)
          for (const auto &mode :
               fgimpact_exact::natural_frequencies(plate, m, n, 2))
            if (mode.type == fgimpact_exact::ModeType::flexural)
              f.push_back(mode.frequency_hz());
      std::sort(f.begin(), f.end());
      f.resize(2);
      return f;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;
    {
      std::ofstream csv("gradation_validation_profile.csv");
      csv << "# a measured-like profile\nz/h, E, nu, rho\n";
      for (const auto &row : table)
        csv << row[0] << ", " << row[1] << ", " << row[2] << ", " << row[3]
            << '\n';
    }

    const std::vector<Case> cases = {
      {"power law n = 2, rule of mixtures",
       Gradation::power_law,
       Homogenization::rule_of_mixtures,
       2.,
       [](double z) { return mixture(z * z); }},
      {"power law n = 2, Mori-Tanaka",
       Gradation::power_law,
       Homogenization::mori_tanaka,
       2.,
       [](double z) { return mori_tanaka(z * z); }},
      {"exponential",
       Gradation::exponential,
       Homogenization::rule_of_mixtures,
       1.,
       [](double z) {
         return std::array<double, 3>{E_c * std::pow(E_m / E_c, z),
                                      nu_c + (nu_m - nu_c) * z,
                                      rho_c * std::pow(rho_m / rho_c, z)};
       }},
      {"sigmoid n = 2, rule of mixtures",
       Gradation::sigmoid,
       Homogenization::rule_of_mixtures,
       2.,
       [](double z) { return mixture(sigmoid(z, 2.)); }},
      {"sigmoid n = 2, Mori-Tanaka",
       Gradation::sigmoid,
       Homogenization::mori_tanaka,
       2.,
       [](double z) { return mori_tanaka(sigmoid(z, 2.)); }},
      {"tabulated (5 rows)",
       Gradation::tabulated,
       Homogenization::rule_of_mixtures,
       1.,
       tabulated}};

    bool ok = true;
    std::printf("Q2 20 x 10 x 4 graded elements vs the exact 3D solution\n"
                "%-36s %9s %9s %9s %9s\n",
                "case",
                "profile",
                "w_mid %",
                "f1 %",
                "f2 %");
    for (const Case &c : cases)
      {
        PlateGeometry::Parameters gp;
        gp.thickness      = h;
        gp.subdivisions_x = 20;
        gp.subdivisions_y = 10;
        gp.subdivisions_z = 4;
        PlateModel::Parameters fp;
        fp.degree = 2;
        const PlateGeometry              geometry(gp);
        const FunctionallyGradedMaterial material(material_parameters(c), h);
        PlateModel plate(fp, geometry, material, MPI_COMM_WORLD);
        plate.setup();

        EffectiveMatrixSolver::Parameters lp;
        lp.type = EffectiveMatrixSolver::Type::cholmod;
        const StaticAnalysis::Parameters sp;
        StaticAnalysis statics(sp, lp, plate, Point<2>(0.1, 0.05));
        statics.solve();
        const double w_fe = statics.get_results().deflection[1];

        ModalAnalysis::Parameters mp;
        mp.n_modes = 4;
        ModalAnalysis modal(mp, lp, plate);
        modal.solve();
        std::vector<double> f_fe;
        for (const auto &mode : modal.get_modes())
          if (mode.w_fraction > 0.5 && f_fe.size() < 2)
            f_fe.push_back(mode.frequency);

        const fgimpact_exact::Plate exact = exact_plate(c);
        const double                w_exact =
          -fgimpact_exact::static_sinusoidal(exact, 1e6, 1, 1).W(h / 2);
        const std::vector<double> f_exact = exact_flexural(exact);

        const double d_profile = profile_difference(material, c);
        const double e_w       = 100 * (w_fe / w_exact - 1);
        double       e_f[2]    = {1e9, 1e9};
        for (unsigned int i = 0; i < f_fe.size(); ++i)
          e_f[i] = 100 * (f_fe[i] / f_exact[i] - 1);
        const bool pass = d_profile < 1e-12 && std::abs(e_w) < 0.1 &&
                          std::abs(e_f[0]) < 0.1 && std::abs(e_f[1]) < 0.1;
        ok = ok && pass;
        std::printf("%-36s %9s %+9.4f %+9.4f %+9.4f %s\n",
                    c.name,
                    d_profile < 1e-12 ? "same" : "DIFFERS",
                    e_w,
                    e_f[0],
                    e_f[1],
                    pass ? "ok" : "FAILED");
        if (verbose)
          std::fprintf(stderr,
                       "  w %.5f um (exact %.5f), f %.2f %.2f Hz (exact %.2f "
                       "%.2f)\n",
                       w_fe * 1e6,
                       w_exact * 1e6,
                       f_fe.size() > 0 ? f_fe[0] : 0.,
                       f_fe.size() > 1 ? f_fe[1] : 0.,
                       f_exact[0],
                       f_exact[1]);
      }
    std::filesystem::remove("gradation_validation_profile.csv");
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::gradation_validation
