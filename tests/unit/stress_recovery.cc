// The recovered (nodal-averaged, continuous) stress of the VTU output,
// StressRecovery:
//  1. at mesh vertices (inside the plate: 8 cells; on the top face: 4; at
//     a corner: 1) it equals the history probe (PointProbe, which averages
//     the adjacent cells' stress) to 1e-12 relative, for a smooth
//     non-linear displacement on a graded plate, graded and homogeneous
//     elements; the principal stresses are the eigenvalues of the
//     recovered tensor, sorted, and von Mises is its invariant;
//  2. for the static sinusoidal load on the simply supported n = 1 plate,
//     the recovered sigma_xx at the centre of the bottom and top faces
//     converges to the exact 3D solution (tests/exact/plate_exact.h) under
//     uniform refinement (Q2: 8x4x2, 16x8x4, 32x16x8; observed order at
//     least 0.9), and Q1 at the mid-plane (order 1.8 at least).
// Set FGIMPACT_VERBOSE=1 to print the time of one recovery on the default
// mesh (40 x 20 x 4).

#include <deal.II/base/function.h>
#include <deal.II/base/timer.h>

#include <deal.II/numerics/vector_tools.h>

#include <fgimpact/analysis/static_analysis.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/plate/stress_recovery.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <exact/plate_exact.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::stress_recovery
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    const bool verbose = std::getenv("FGIMPACT_VERBOSE") != nullptr;

    /// u = 1e-6 m * (x y/a b, y z^2/b h^2, sin(x/a) z/h) in m.
    class Field : public Function<3>
    {
    public:
      Field()
        : Function<3>(3)
      {}
      double
      value(const Point<3> &p, const unsigned int c) const override
      {
        const double x = p[0] / 0.2, y = p[1] / 0.1, z = p[2] / 0.02;
        const double v[3] = {x * y, y * z * z, std::sin(x) * z};
        return 1e-6 * v[c];
      }
    };

    /// The scalar DoF of the recovery at the mesh vertex p.
    types::global_dof_index
    vertex_dof(const StressRecovery &recovery, const Point<3> &p)
    {
      for (const auto &cell :
           recovery.get_dof_handler().active_cell_iterators())
        for (const unsigned int v : cell->vertex_indices())
          if (cell->vertex(v).distance(p) < 1e-12)
            return cell->vertex_dof_index(v, 0);
      AssertThrow(false,
                  ExcMessage("not a mesh vertex: " + std::to_string(p[0]) +
                             " " + std::to_string(p[1]) + " " +
                             std::to_string(p[2])));
      return 0;
    }

    TrilinosWrappers::MPI::Vector
    ghosted(const PlateModel &plate, const TrilinosWrappers::MPI::Vector &u)
    {
      TrilinosWrappers::MPI::Vector g(plate.locally_owned_dofs(),
                                      plate.locally_relevant_dofs(),
                                      plate.get_mpi_communicator());
      g = u;
      return g;
    }

    bool
    compare_with_probe(const char *label, const PropertyMode mode)
    {
      auto        c     = fgimpact_tests::make_plate(10, 6, 4, 1, 1., mode);
      const auto &plate = *c.plate;
      TrilinosWrappers::MPI::Vector u;
      plate.initialize_vector(u);
      VectorTools::interpolate(plate.get_mapping(),
                               plate.get_dof_handler(),
                               Field(),
                               u);
      StressRecovery recovery(plate);
      recovery.recover(ghosted(plate, u));

      bool ok = true;
      std::printf("%s elements:\n", label);
      for (const Point<3> &p : {Point<3>(0.1, 0.05, 0.01),
                                Point<3>(0.1, 0.05, 0.02),
                                Point<3>(0.2, 0.1, 0.)})
        {
          const auto                  dof       = vertex_dof(recovery, p);
          const SymmetricTensor<2, 3> recovered = recovery.stress(dof);
          const SymmetricTensor<2, 3> probe = PointProbe(plate, p).stress(u);
          const double error = (recovered - probe).norm() / probe.norm();

          // Derived fields from the recovered tensor.
          const auto   lambda = eigenvalues(probe);
          const auto   s      = deviator(probe);
          const double vm     = std::sqrt(1.5 * (s * s)) * 1e-6;
          double       derived_error =
            std::abs(recovery.field(StressRecovery::von_mises)(dof) - vm) / vm;
          for (unsigned int k = 0; k < 3; ++k)
            derived_error =
              std::max(derived_error,
                       std::abs(recovery.field(StressRecovery::Field(
                                  StressRecovery::principal_1 + k))(dof) -
                                lambda[k] * 1e-6) /
                         (std::abs(lambda[0]) * 1e-6));
          const bool pass = error < 1e-12 && derived_error < 1e-12;
          std::printf("  vertex (%.2f, %.2f, %.2f) m: sigma_xx %.6f, sigma_zz "
                      "%.6f, sigma_xz %.6f MPa; recovered = probe, and von "
                      "Mises, sigma_1..3 from it, to 1e-12: %s\n",
                      p[0],
                      p[1],
                      p[2],
                      recovered[0][0] * 1e-6,
                      recovered[2][2] * 1e-6,
                      recovered[0][2] * 1e-6,
                      pass ? "yes" : "NO");
          ok = ok && pass;
        }
      return ok;
    }

    /// Relative errors of the recovered sigma_xx at the centre of the
    /// plate at the heights z (m; at most 2, named by `names`); returns
    /// whether they decrease with at least min_order.
    bool
    converge_to_exact(const unsigned int         degree,
                      const unsigned int         nx,
                      const double               min_order,
                      const std::vector<double> &heights,
                      const char                *names)
    {
      const auto exact = fgimpact_exact::static_sinusoidal(
        fgimpact_exact::power_law_plate(1.), 1e6, 1, 1);
      std::printf("Q%u, %s:\n", degree, names);
      const unsigned int n_sides     = heights.size();
      double             previous[2] = {0, 0}, order[2] = {0, 0};
      bool               decreasing = true;
      for (const unsigned int k : {1u, 2u, 4u})
        {
          const auto c = fgimpact_tests::make_plate(
            nx * k, nx * k / 2, nx * k / 4, degree, 1.);
          const auto                       &plate = *c.plate;
          EffectiveMatrixSolver::Parameters lp;
          lp.type = EffectiveMatrixSolver::Type::cholmod;
          StaticAnalysis analysis(StaticAnalysis::Parameters(),
                                  lp,
                                  plate,
                                  Point<2>(0.1, 0.05));
          analysis.solve();
          StressRecovery recovery(plate);
          recovery.recover(ghosted(plate, analysis.displacement()));

          double error[2] = {0, 0};
          for (unsigned int side = 0; side < n_sides; ++side)
            {
              const double z   = heights[side];
              const auto   dof = vertex_dof(recovery, Point<3>(0.1, 0.05, z));
              const double fe  = recovery.stress(dof)[0][0];
              error[side]      = std::abs(fe / exact.sigma_xx(z) - 1.);
              if (k > 1)
                {
                  order[side] = std::log2(previous[side] / error[side]);
                  decreasing  = decreasing && error[side] < previous[side];
                }
              previous[side] = error[side];
            }
          std::printf("  %2ux%2ux%2u: relative error",
                      nx * k,
                      nx * k / 2,
                      nx * k / 4);
          for (unsigned int side = 0; side < n_sides; ++side)
            std::printf(" %.2e", error[side]);
          std::printf("\n");
        }
      bool pass = decreasing;
      std::printf("  observed order on the finest pair:");
      for (unsigned int side = 0; side < n_sides; ++side)
        {
          pass = pass && order[side] >= min_order;
          std::printf(" %.1f", order[side]);
        }
      std::printf("; errors decrease with order %.1f at least: %s\n",
                  min_order,
                  pass ? "yes" : "NO");
      return pass;
    }

    void
    time_recovery()
    {
      const auto c = fgimpact_tests::make_plate(40, 20, 4, 1, 1.);
      TrilinosWrappers::MPI::Vector u;
      c.plate->initialize_vector(u);
      VectorTools::interpolate(c.plate->get_mapping(),
                               c.plate->get_dof_handler(),
                               Field(),
                               u);
      const auto     u_ghosted = ghosted(*c.plate, u);
      StressRecovery recovery(*c.plate);
      Timer          timer;
      for (unsigned int i = 0; i < 10; ++i)
        recovery.recover(u_ghosted);
      std::fprintf(stderr,
                   "one recovery on 40x20x4: %.2f ms\n",
                   timer.wall_time() * 100.);
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;
    ok &= compare_with_probe("graded", PropertyMode::graded);
    ok &= compare_with_probe("homogeneous", PropertyMode::homogeneous);
    // Static sinusoidal load, n = 1 plate: the recovered sigma_xx at the
    // centre of the bottom and top faces against the exact 3D solution.
    // Q2: first order at least (0.9; a one-sided derivative at the face).
    // Q1 at the faces is not checked: the one-sided cells of a face vertex
    // give a slow, non-monotonic convergence (relative errors 0.25, 0.008,
    // 0.040 on the three meshes at the bottom, about 2.5 % on 64 x 32 x 16);
    // at the mid-plane, where the averaged cells lie on both sides, the
    // recovered Q1 stress converges with order 2 (1.4, then 1.83 observed
    // on the two pairs; 1.8 required on the finest).
    {
      const auto exact = fgimpact_exact::static_sinusoidal(
        fgimpact_exact::power_law_plate(1.), 1e6, 1, 1);
      std::printf("static sinusoidal load, n = 1: recovered sigma_xx at the "
                  "centre against the exact 3D solution (bottom %.3f MPa, top "
                  "%.3f MPa)\n",
                  exact.sigma_xx(0.) * 1e-6,
                  exact.sigma_xx(0.02) * 1e-6);
    }
    ok &= converge_to_exact(2, 8, 0.9, {0., 0.02}, "bottom and top faces");
    ok &= converge_to_exact(1, 8, 1.8, {0.01}, "mid-plane");
    if (verbose)
      time_recovery();
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::stress_recovery
