// Static Hertz indentation: a rigid sphere (R = 15 mm) pressed 1 um into a
// homogeneous block (E = 70 GPa, nu = 0.3) bonded to a rigid base, with
// the contact refinement under the ball (Static/Load = sphere, the resolved
// contact's LCP with the compliance of K).  Against Hertz's half-space
// solution F = 4/3 E* sqrt(R) delta^{3/2}, a = sqrt(R delta),
// p = p0 sqrt(1 - r^2/a^2):
//  - the finite block (depth H, bonded base) is stiffer than the half-space
//    by a far-field term proportional to F/(E H); it is measured by the
//    same block at twice the size (F_inf = 2 F(2H) - F(H) at level 7) and
//    divided out;
//  - the force converges with the refinement level (observed order).

#include <deal.II/base/mpi.h>

#include <fgimpact/analysis/static_analysis.h>
#include <fgimpact/material/material.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/plate/plate_model.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::static_hertz
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    const double E = 70e9, nu = 0.3, R = 0.015, delta = 1e-6;

    StaticAnalysis::Results
    indent(const double scale, const unsigned int levels)
    {
      PlateGeometry::Parameters gp;
      gp.length         = 0.04 * scale;
      gp.width          = 0.04 * scale;
      gp.thickness      = 0.02 * scale;
      gp.subdivisions_x = static_cast<unsigned int>(8 * scale);
      gp.subdivisions_y = static_cast<unsigned int>(8 * scale);
      gp.subdivisions_z = static_cast<unsigned int>(4 * scale);
      gp.supports       = {{SideSupport::free,
                            SideSupport::free,
                            SideSupport::free,
                            SideSupport::free}};
      gp.bottom_support = SideSupport::clamped;
      FunctionallyGradedMaterial::Parameters mp;
      mp.metal_youngs_modulus = E;
      mp.poissons_ratio       = nu;
      mp.power_law_index      = 0; // pure metal: homogeneous
      const PlateGeometry              geometry(gp);
      const FunctionallyGradedMaterial material(mp, gp.thickness);
      PlateModel                       plate(PlateModel::Parameters(),
                       geometry,
                       material,
                       MPI_COMM_WORLD);
      LocalRefinement                  refinement;
      refinement.centre = Point<3>(gp.length / 2, gp.width / 2, gp.thickness);
      refinement.radius = 1.5 * std::sqrt(R * delta);
      refinement.levels = levels;
      plate.setup(refinement);

      StaticAnalysis::Parameters sp;
      sp.load        = StaticAnalysis::Load::sphere;
      sp.indentation = delta;
      SphereIndenter indenter;
      indenter.radius = R;
      StaticAnalysis analysis(sp,
                              EffectiveMatrixSolver::Parameters(),
                              plate,
                              Point<2>(gp.length / 2, gp.width / 2),
                              indenter);
      analysis.solve();
      return analysis.get_results();
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

    const double E_star = E / (1 - nu * nu);
    const double a      = std::sqrt(R * delta);
    const double F  = 4. / 3. * E_star * std::sqrt(R) * std::pow(delta, 1.5);
    const double p0 = 3. * F / (2. * numbers::PI * a * a);
    std::printf("Hertz: F = %.4f N, a = %.5f mm, p0 = %.3f MPa\n",
                F,
                a * 1e3,
                p0 * 1e-6);

    StaticAnalysis::Results r[3];
    for (unsigned int k = 0; k < 3; ++k)
      {
        r[k] = indent(1., 6 + k);
        std::printf("level %u: F = %.4f N (%+.3f %% from Hertz), contact "
                    "radius %.5f mm, %u nodes\n",
                    6 + k,
                    r[k].contact_force,
                    100. * (r[k].contact_force / F - 1.),
                    r[k].contact_radius * 1e3,
                    r[k].n_contact_nodes);
      }
    const double d1    = r[1].contact_force - r[0].contact_force;
    const double d2    = r[2].contact_force - r[1].contact_force;
    const double order = std::log2(d1 / d2);
    std::printf("observed order in the element size: %.2f\n", order);

    const StaticAnalysis::Results big = indent(2., 7);
    const double F_infinite_block = 2. * big.contact_force - r[1].contact_force;
    const double block_factor     = r[1].contact_force / F_infinite_block;
    std::printf("block correction: F(2H) = %.4f N at level 7, F(H)/F(inf) - 1 "
                "= %.3f %% (Boussinesq estimate %.3f %%)\n",
                big.contact_force,
                100. * (block_factor - 1.),
                100. * 1.5 * 2. * a * (3. - 2. * nu) /
                  (3. * numbers::PI * (1. - nu) * 0.02));

    const double force_error = r[2].contact_force / block_factor / F - 1.;
    // The contact radius: the semi-axis of Hertz's elliptic profile fitted
    // to the nodal pressures inside 0.8 a (p^2 linear in r^2), and, for
    // information, the discrete edge: between the farthest node in contact
    // and the nearest free node.
    double sx = 0, sy = 0, sxx = 0, sxy = 0, n_fit = 0, nearest_free = 1e9;
    for (unsigned int j = 0; j < r[2].node_radius.size(); ++j)
      {
        const double x = r[2].node_radius[j] * r[2].node_radius[j];
        const double y = r[2].node_pressure[j] * r[2].node_pressure[j];
        if (r[2].node_pressure[j] == 0.)
          nearest_free = std::min(nearest_free, r[2].node_radius[j]);
        else if (r[2].node_radius[j] < 0.8 * a)
          {
            sx += x, sy += y, sxx += x * x, sxy += x * y, n_fit += 1;
          }
      }
    const double slope     = (n_fit * sxy - sx * sy) / (n_fit * sxx - sx * sx);
    const double intercept = (sy - slope * sx) / n_fit;
    const double a_fit     = std::sqrt(-intercept / slope);
    const double radius_error = a_fit / a - 1.;
    std::printf("level 8, discrete contact edge between %+.2f %% and %+.2f %% "
                "of a\n",
                100. * (r[2].contact_radius / a - 1.),
                100. * (nearest_free / a - 1.));
    double       pressure_error = 0;
    unsigned int n_inside       = 0;
    for (unsigned int j = 0; j < r[2].node_radius.size(); ++j)
      if (r[2].node_radius[j] < 0.8 * a)
        {
          const double rr = r[2].node_radius[j] / a;
          pressure_error  = std::max(pressure_error,
                                    std::abs(r[2].node_pressure[j] -
                                             p0 * std::sqrt(1. - rr * rr)) /
                                      p0);
          ++n_inside;
        }
    std::printf("level 8, block-corrected force error %+.3f %% (limit 1 %%)\n",
                100. * force_error);
    std::printf("level 8, contact radius (elliptic fit) error %+.3f %% (limit "
                "2 %%)\n",
                100. * radius_error);
    std::printf("level 8, max |p - p_Hertz| / p0 inside 0.8 a (%u nodes): "
                "%.3f %% (limit 3 %%)\n",
                n_inside,
                100. * pressure_error);

    const bool ok = std::abs(force_error) < 0.01 &&
                    std::abs(radius_error) < 0.02 && pressure_error < 0.03 &&
                    order > 1.;
    std::printf("%s\n", ok ? "OK" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::static_hertz
