// The elastic ball of the resolved contact (its Boussinesq surface
// compliance H in the contact's LCP), against closed forms:
//  1. H alone: a uniform pressure p on a disc of radius c, as nodal forces
//     p A_j, moves the ball's surface at the centre by 2 p c / Q_i
//     (Boussinesq; Johnson, Contact Mechanics, Eq. 3.27); a quarter plate
//     (the mirror images of its candidates) gives the whole plate's H.
//  2. The impact of an elastic ball on a thick block against the impact
//     of two elastic bodies in Hertz's theory (quasi-static, the block a
//     half-space): with 1/E* = (1 - nu^2)/E + (1 - nu_i^2)/E_i,
//     K = 4/3 E* sqrt(R), alpha_max = (5 m V0^2 / (4 K))^{2/5},
//       F_max = K alpha_max^{3/2},  T = 2.94328 alpha_max / V0
//     (energy 1/2 m V0^2 = 2/5 K alpha_max^{5/2}; T from the integral of
//     the rebound).  The finite block (bonded base at depth H, its mass and
//     waves) departs from the half-space; the rigid ball on the same mesh
//     measures that correction (its closed form has Q in place of E*), and
//     it is divided out, as the static test (static_hertz) does with the
//     block of twice the size.  Two refinement levels.

#include <deal.II/base/mpi.h>

#include <fgimpact/contact/impactor_profile.h>
#include <fgimpact/contact/resolved_contact.h>
#include <fgimpact/material/material.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/plate/plate_model.h>

#include <cmath>
#include <cstdio>
#include <test_tools.h>

namespace fgimpact_unit_tests::elastic_ball
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    const double E = 70e9, nu = 0.3, E_ball = 207e9, nu_ball = 0.3;
    const double Q_ball = E_ball / (1 - nu_ball * nu_ball);

    /// The ball's surface displacement at the impact point (m) under a
    /// uniform pressure p (Pa) on the candidates within c (m), whole plate
    /// or quarter.
    double
    disc_displacement(const bool         quarter,
                      const unsigned int levels,
                      const double       p,
                      const double       c)
    {
      PlateGeometry::Parameters gp;
      gp.subdivisions_x = 8;
      gp.subdivisions_y = 4;
      gp.subdivisions_z = 2;
      FunctionallyGradedMaterial::Parameters mp;
      mp.power_law_index = 0;
      const PlateGeometry              geometry(gp, {{quarter, quarter}});
      const FunctionallyGradedMaterial material(mp, gp.thickness);
      PlateModel                       plate(PlateModel::Parameters(),
                       geometry,
                       material,
                       MPI_COMM_WORLD);
      LocalRefinement                  refinement;
      refinement.centre = Point<3>(gp.length / 2, gp.width / 2, gp.thickness);
      refinement.radius = 1.5 * c;
      refinement.levels = levels;
      plate.setup(refinement);
      const ResolvedSphereContact contact(plate,
                                          0.015,
                                          Point<2>(gp.length / 2, gp.width / 2),
                                          2. * c,
                                          create_sphere_profile(0.015, false),
                                          E / (1 - nu * nu),
                                          false,
                                          Q_ball);
      const auto                 &H = contact.ball_compliance();
      double                      u = 0;
      for (unsigned int j = 0; j < H.n(); ++j)
        if (contact.candidate_radii()[j] <= c * (1 + 1e-9))
          u += H(0, j) * p * contact.candidate_areas()[j];
      return u;
    }

    ImpactResults
    block_impact(const std::string &ball, const unsigned int levels)
    {
      return fgimpact_tests::run_quietly(
               "",
               "subsection Geometry\n set Length a = 0.04\n set Width b = 0.04\n"
               " set Thickness h = 0.02\n set Subdivisions x = 8\n"
               " set Subdivisions y = 8\n set Subdivisions z = 4\n"
               " set Symmetry = quarter\n"
               " set Contact refinement levels = " +
                 std::to_string(levels) +
                 "\nend\n"
                 "subsection Boundary conditions\n set Face x min = free\n"
                 " set Face x max = free\n set Face y min = free\n"
                 " set Face y max = free\n set Face z min = clamped\nend\n"
                 "subsection Material\n set Power-law index = 0\n"
                 " set Metal Young's modulus = 70e9\n set Poisson's ratio = "
                 "0.3\nend\n"
                 "subsection Impactor\n set Radius = 0.015\n set Material = " +
                 ball +
                 "\n set Young's modulus = 207e9\n set Poisson's ratio = 0.3\n"
                 "end\n"
                 "subsection Contact\n set Model = resolved sphere\nend\n"
                 "subsection Time integration\n set Time step = 0.5e-6\n"
                 " set End time = auto\nend\n"
                 "subsection Output\n set Directory = out\n"
                 " set VTU interval = 0\n set Log interval = 0\n"
                 " set Print timing = false\nend\n")
        .results;
    }

    struct Hertz
    {
      double force, duration;
    };

    Hertz
    hertz_impact(const double Q, const double m, const double V0)
    {
      const double R     = 0.015;
      const double K     = 4. / 3. * Q * std::sqrt(R);
      const double alpha = std::pow(1.25 * m * V0 * V0 / K, 0.4);
      return {K * std::pow(alpha, 1.5), 2.94328 * alpha / V0};
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;

    // 1. A disc of radius 1 mm under 1 GPa.
    const double p = 1e9, c = 1e-3, exact = 2 * p * c / Q_ball;
    double       error[2];
    for (unsigned int k = 0; k < 2; ++k)
      {
        const unsigned int levels  = 5 + k;
        const double       whole   = disc_displacement(false, levels, p, c);
        const double       quarter = disc_displacement(true, levels, p, c);
        error[k]                   = whole / exact - 1;
        const double symmetry      = std::abs(quarter / whole - 1);
        // The quarter's difference is round-off: its verdict, not its digits.
        std::printf("disc under uniform pressure, level %u: centre %.5f um "
                    "(Boussinesq %.5f um, error %+.3f %%), quarter against "
                    "whole below 1e-12: %s\n",
                    levels,
                    whole * 1e6,
                    exact * 1e6,
                    100 * error[k],
                    symmetry < 1e-12 ? "yes" : "NO");
        ok = ok && symmetry < 1e-12;
      }
    std::printf("disc: error ratio level 5 / level 6 %.2f (limit > 1.5), "
                "level 6 error %.3f %% (limit 2 %%)\n",
                std::abs(error[0] / error[1]),
                100 * std::abs(error[1]));
    ok = ok && std::abs(error[0] / error[1]) > 1.5 && std::abs(error[1]) < 0.02;

    // 2. The impact on the block, rigid and elastic ball, levels 4 and 5.
    const double Q = E / (1 - nu * nu), Q_star = 1 / (1 / Q + 1 / Q_ball);
    double       force_error[2], duration_error[2];
    for (unsigned int k = 0; k < 2; ++k)
      {
        const unsigned int  levels  = 4 + k;
        const ImpactResults rigid   = block_impact("rigid", levels);
        const ImpactResults elastic = block_impact("elastic", levels);
        const double        m = rigid.impactor_mass, V0 = 1;
        const Hertz         hr = hertz_impact(Q, m, V0);
        const Hertz         he = hertz_impact(Q_star, m, V0);
        // The block's correction: the rigid ball's ratio to its closed form.
        const double block_force = rigid.peak_contact_force / hr.force;
        const double block_time  = rigid.contact_duration / hr.duration;
        force_error[k] =
          elastic.peak_contact_force / he.force / block_force - 1;
        duration_error[k] =
          elastic.contact_duration / he.duration / block_time - 1;
        std::printf(
          "level %u: rigid ball %.2f N, %.3f us (Hertz %.2f N, %.3f us: "
          "block correction %+.3f %%, %+.3f %%)\n",
          levels,
          rigid.peak_contact_force,
          rigid.contact_duration * 1e6,
          hr.force,
          hr.duration * 1e6,
          100 * (block_force - 1),
          100 * (block_time - 1));
        std::printf("level %u: elastic ball %.2f N, %.3f us (Hertz %.2f N, "
                    "%.3f us); corrected errors %+.3f %%, %+.3f %%; energy "
                    "drift %.1e\n",
                    levels,
                    elastic.peak_contact_force,
                    elastic.contact_duration * 1e6,
                    he.force,
                    he.duration * 1e6,
                    100 * force_error[k],
                    100 * duration_error[k],
                    elastic.max_energy_drift);
        ok = ok && std::abs(force_error[k]) < 0.01 &&
             std::abs(duration_error[k]) < 0.01 &&
             elastic.max_energy_drift < 1e-3;
      }
    std::printf("%s\n", ok ? "OK" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::elastic_ball
