// The probes of Output/Probe points (ProbeSet, probes.csv):
//  1. at a mesh node the probe's displacement, velocity and acceleration
//     are the nodal values of u, v and a exactly;
//  2. its recovered stress is StressRecovery's nodal field interpolated at
//     the point (an independent evaluation: recover, then interpolate; to
//     1e-12), and at a vertex it equals the history probe (PointProbe);
//  3. static sinusoidal load on the simply supported n = 1 plate: at the
//     centre line, z = 0.8 h (inside the elements of every mesh), the
//     probe's recovered sigma_xx and the history probe's cell-averaged
//     sigma_xx both converge to the exact 3D solution
//     (tests/exact/plate_exact.h; Q1 on 8x4x2, 16x8x4, 32x16x8);
//  4. momentum balance of an implicit impact (hertz node, 8x4x2, 60 us):
//     the support reaction (K u + M a - f summed over the supported z
//     DoFs) equals the contact force plus the plate's inertia
//     int rho a_z dV, computed here by quadrature: max error over the steps
//     relative to the peak force; the reaction itself is of the order of
//     the force (printed); again with the B-bar brick, whose reaction
//     weights carry the cell's mean dilatation.
// Runs unchanged on several MPI ranks (same output).

#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/numerics/vector_tools.h>

#include <fgimpact/analysis/static_analysis.h>
#include <fgimpact/plate/probe_set.h>
#include <fgimpact/plate/probes.h>
#include <fgimpact/plate/stress_recovery.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>
#include <cstdio>
#include <exact/plate_exact.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::probe_points
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    /// A smooth non-linear field (m): u = 1e-6 (x y/ab, y z^2/bh^2,
    /// sin(x/a) z/h) times scale.
    class Field : public Function<3>
    {
    public:
      explicit Field(const double scale)
        : Function<3>(3)
        , scale(scale)
      {}
      double
      value(const Point<3> &p, const unsigned int c) const override
      {
        const double x = p[0] / 0.2, y = p[1] / 0.1, z = p[2] / 0.02;
        const double v[3] = {x * y, y * z * z, std::sin(x) * z};
        return scale * 1e-6 * v[c];
      }

    private:
      const double scale;
    };

    TrilinosWrappers::MPI::Vector
    ghosted(const PlateModel &plate, const TrilinosWrappers::MPI::Vector &u)
    {
      TrilinosWrappers::MPI::Vector g(plate.locally_owned_dofs(),
                                      plate.locally_relevant_dofs(),
                                      plate.get_mpi_communicator());
      g = u;
      return g;
    }

    TrilinosWrappers::MPI::Vector
    interpolate(const PlateModel &plate, const double scale)
    {
      TrilinosWrappers::MPI::Vector u;
      plate.initialize_vector(u);
      VectorTools::interpolate(plate.get_mapping(),
                               plate.get_dof_handler(),
                               Field(scale),
                               u);
      return u;
    }

    ProbePoint
    probe(const char *name, const double x, const double y, const double z)
    {
      // The arguments in mm, the entry in m.
      ProbePoint p;
      p.name  = name;
      p.value = {{x * 1e-3, y * 1e-3, z * 1e-3}};
      return p;
    }

    /// StressRecovery's field at p: the nodal values interpolated in the
    /// first locally owned cell containing p (then shared over the ranks).
    SymmetricTensor<2, 3>
    recovered_at(const StressRecovery &recovery,
                 const PlateModel     &plate,
                 const Point<3>       &p)
    {
      const auto          cells = locally_owned_cells_containing(plate, p);
      std::vector<double> local(7, 0.), global(7);
      if (!cells.empty())
        {
          const auto &[cell, unit] = cells.front();
          const DoFHandler<3>::active_cell_iterator scalar_cell(
            &plate.get_dof_handler().get_triangulation(),
            cell->level(),
            cell->index(),
            &recovery.get_dof_handler());
          std::vector<types::global_dof_index> dofs(
            recovery.get_dof_handler().get_fe().n_dofs_per_cell());
          scalar_cell->get_dof_indices(dofs);
          for (unsigned int k = 0; k < dofs.size(); ++k)
            for (unsigned int s = 0; s < 6; ++s)
              local[s] +=
                recovery.get_dof_handler().get_fe().shape_value(k, unit) *
                recovery.field(static_cast<StressRecovery::Field>(s))(dofs[k]);
          local[6] = 1.;
        }
      Utilities::MPI::sum(ArrayView<const double>(local),
                          plate.get_mpi_communicator(),
                          ArrayView<double>(global));
      // Field order xx, yy, zz, xy, xz, yz (MPa); the first owner's value
      // if several ranks hold the point (the field is continuous).
      const unsigned int order[6][2] = {
        {0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};
      SymmetricTensor<2, 3> sigma;
      for (unsigned int s = 0; s < 6; ++s)
        sigma[order[s][0]][order[s][1]] = global[s] / global[6] * 1e6;
      return sigma;
    }

    bool
    nodal_and_recovered()
    {
      auto        c     = fgimpact_tests::make_plate(10, 6, 4, 1, 1.);
      const auto &plate = *c.plate;
      const auto  u = interpolate(plate, 1.), v = interpolate(plate, 2.),
                 a = interpolate(plate, -3.);

      // 1. A vertex (not on a symmetry line): x = 60 mm, y = 50 mm, z = 5 mm.
      const Point<3> node(0.06, 0.05, 0.005);
      ProbeSet       probes(plate, {probe("node", 60, 50, 5)});
      const auto     values      = probes.evaluate(u, v, a, false);
      double         nodal_error = 0, scale = 0;
      for (unsigned int d = 0; d < 3; ++d)
        {
          const auto dof = plate.nearest_vertex_dof(node, d).first;
          nodal_error    = std::max(
            {nodal_error,
                std::abs(values.displacement[0][d] - plate.dof_value(u, dof)),
                std::abs(values.velocity[0][d] - plate.dof_value(v, dof)),
                std::abs(values.acceleration[0][d] - plate.dof_value(a, dof))});
          scale = std::max(scale, std::abs(plate.dof_value(a, dof)));
        }
      const bool nodal_ok = nodal_error <= 1e-15 * scale;
      std::printf("1. probe at a node: max |probe - nodal value| of u, v, a "
                  "relative to the values <= 1e-15 (exact): %s\n",
                  nodal_ok ? "yes" : "NO");
      if (std::getenv("FGIMPACT_VERBOSE"))
        std::fprintf(stderr, "nodal error %.3e\n", nodal_error / scale);

      // 2. The recovered stress: against StressRecovery interpolated at
      // interior, face and edge points, and at the vertex against PointProbe.
      StressRecovery recovery(plate);
      recovery.recover(ghosted(plate, u));
      const std::vector<ProbePoint> list = {probe("inside", 47, 33, 7.3),
                                            probe("face", 60, 33, 7.3),
                                            probe("edge", 60, 50, 7.3),
                                            probe("top", 47, 33, 20),
                                            probe("vertex", 60, 50, 5)};
      ProbeSet                      set(plate, list);
      const auto                    s = set.evaluate(u, v, a, false).stress;
      double                        max_diff = 0;
      for (unsigned int p = 0; p < list.size(); ++p)
        {
          const auto reference =
            recovered_at(recovery, plate, set.locations()[p]);
          const double diff = (s[p] - reference).norm() / reference.norm();
          max_diff          = std::max(max_diff, diff);
          // The difference is round-off: its verdict, not its digits.
          std::printf("   %-6s sigma_xx %.6f, sigma_zz %.6f MPa; relative "
                      "difference from StressRecovery below 1e-12: %s\n",
                      list[p].name.c_str(),
                      s[p][0][0] * 1e-6,
                      s[p][2][2] * 1e-6,
                      diff < 1e-12 ? "yes" : "NO");
        }
      const auto   history     = PointProbe(plate, node).stress(u);
      const double vertex_diff = (s.back() - history).norm() / history.norm();
      const bool   stress_ok   = max_diff < 1e-12 && vertex_diff < 1e-12;
      std::printf("2. recovered stress = StressRecovery interpolated (to "
                  "1e-12), at the vertex = PointProbe (to 1e-12: %s): %s\n",
                  vertex_diff < 1e-12 ? "yes" : "NO",
                  stress_ok ? "yes" : "NO");
      return nodal_ok && stress_ok;
    }

    bool
    converge_to_exact()
    {
      const double h = 0.02, z = 0.8 * h;
      const auto   exact = fgimpact_exact::static_sinusoidal(
        fgimpact_exact::power_law_plate(1.), 1e6, 1, 1);
      const double sigma_exact = exact.sigma_xx(z);
      std::printf("3. static sinusoidal load, sigma_xx at (a/2, b/2, 0.8 h): "
                  "exact %.4f MPa\n",
                  sigma_exact * 1e-6);
      double previous[2] = {1e300, 1e300};
      bool   decreasing  = true;
      for (const unsigned int k : {1u, 2u, 4u})
        {
          const auto c = fgimpact_tests::make_plate(8 * k, 4 * k, 2 * k, 1, 1.);
          const auto                       &plate = *c.plate;
          EffectiveMatrixSolver::Parameters lp;
          lp.type = EffectiveMatrixSolver::Type::automatic;
          StaticAnalysis analysis(StaticAnalysis::Parameters(),
                                  lp,
                                  plate,
                                  Point<2>(0.1, 0.05));
          analysis.solve();
          const auto  &u = analysis.displacement();
          ProbeSet     set(plate, {probe("p", 100, 50, 16)});
          const double recovered = set.evaluate(u, u, u, false).stress[0][0][0];
          const double cell =
            PointProbe(plate, Point<3>(0.1, 0.05, z)).stress(u)[0][0];
          const double error[2] = {std::abs(recovered / sigma_exact - 1.),
                                   std::abs(cell / sigma_exact - 1.)};
          std::printf("   %2ux%2ux%2u: probe (recovered) %.4f MPa, error %.2e; "
                      "history probe (cell average) %.4f MPa, error %.2e\n",
                      8 * k,
                      4 * k,
                      2 * k,
                      recovered * 1e-6,
                      error[0],
                      cell * 1e-6,
                      error[1]);
          decreasing =
            decreasing && error[0] < previous[0] && error[1] < previous[1];
          previous[0] = error[0];
          previous[1] = error[1];
        }
      std::printf("   both errors decrease under refinement: %s\n",
                  decreasing ? "yes" : "NO");
      return decreasing;
    }

    /// int rho a_z dV (N) by Gauss quadrature.
    double
    inertia_z(const PlateModel &plate, const TrilinosWrappers::MPI::Vector &a)
    {
      // The FE model's density (graded interpolant), at more points than
      // the assembly's (the integrand is a polynomial both integrate
      // exactly).
      const auto                  a_ghosted = ghosted(plate, a);
      const QGauss<3>             quadrature(plate.get_fe().degree + 2);
      FEValues<3>                 fe_values(plate.get_mapping(),
                            plate.get_fe(),
                            quadrature,
                            update_values | update_JxW_values);
      PropertyInterpolator        properties(plate.get_fe().base_element(0),
                                      quadrature.get_points(),
                                      plate.get_material());
      std::vector<double>         E, nu, rho;
      std::vector<Vector<double>> values(quadrature.size(), Vector<double>(3));
      double                      sum = 0;
      for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
        if (cell->is_locally_owned())
          {
            fe_values.reinit(cell);
            properties.values(cell, E, nu, rho);
            fe_values.get_function_values(a_ghosted, values);
            for (unsigned int q = 0; q < quadrature.size(); ++q)
              sum += rho[q] * values[q][2] * fe_values.JxW(q);
          }
      return Utilities::MPI::sum(sum, plate.get_mpi_communicator());
    }

    /// bbar: the B-bar brick (Volumetric strain = cell mean), whose reaction
    /// weights carry its mean dilatation, on the plate with its bottom
    /// clamped too: the support field z_S then varies through the
    /// thickness (its divergence is not 0, as on the side faces alone) and
    /// kappa of the graded plate within a cell, so that every term of the
    /// weights counts (without (m_j - div phi_j) tr sigma / 3 the balance
    /// is off by far more than the tolerance).  modes: the brick with
    /// incompatible modes (bottom clamped as well), whose reaction weights
    /// take the modes' strain of z_S.
    bool
    momentum_balance(const bool bbar, const bool modes = false)
    {
      auto                    c     = fgimpact_tests::make_plate(8,
                                          4,
                                          2,
                                          1,
                                          1.,
                                          PropertyMode::graded,
                                          0.02,
                                          MPI_COMM_WORLD,
                                          0.3,
                                          bbar,
                                          bbar || modes ? SideSupport::clamped :
                                                                                 SideSupport::free,
                                          modes);
      const auto             &plate = *c.plate;
      Impactor::Parameters    ip;
      const Impactor          impactor(ip);
      const HertzContactLaw   law(HertzContactLaw::Parameters(),
                                plate.get_material(),
                                impactor);
      HertzNodeContact        contact_model(law,
                                     plate,
                                     impactor.impact_point(0.2, 0.1));
      TimeStepper::Parameters tp;
      tp.time_step = 1e-6;
      EffectiveMatrixSolver::Parameters sp;
      sp.type      = EffectiveMatrixSolver::Type::automatic;
      auto stepper = create_time_stepper(
        tp, sp, plate, contact_model, impactor.mass(), ip.initial_velocity);
      stepper->initialize(false);
      ContactCoupler coupler(*stepper,
                             contact_model,
                             tp.newmark,
                             impactor.mass(),
                             tp.newton,
                             MPI_COMM_WORLD);
      ProbeSet       probes(plate, {probe("mid", 100, 50, 10)});
      ImpactorState  ball;
      ball.v = ip.initial_velocity;
      ContactState contact;

      double max_error = 0, peak_force = 0, max_reaction = 0, max_inertia = 0;
      for (unsigned int step = 1; step <= 60; ++step)
        {
          coupler.advance(step, step * 1e-6, ball, contact);
          const double R = probes
                             .evaluate(stepper->displacement(),
                                       stepper->velocity(),
                                       stepper->acceleration(),
                                       stepper->has_lumped_mass())
                             .support_reaction_z;
          const double inertia = inertia_z(plate, stepper->acceleration());
          max_error =
            std::max(max_error, std::abs(R - (contact.force + inertia)));
          peak_force   = std::max(peak_force, contact.force);
          max_reaction = std::max(max_reaction, std::abs(R));
          max_inertia  = std::max(max_inertia, std::abs(inertia));
        }
      const bool ok = max_error < 1e-10 * peak_force;
      std::printf(
        "4. implicit impact%s, 60 steps: peak contact force %.1f N, "
        "max |support reaction| %.1f N, max |int rho a_z dV| %.1f N;\n"
        "   max |R - (F + int rho a_z dV)| / peak F < 1e-10: %s\n",
        bbar  ? " (B-bar, bottom clamped)" :
        modes ? " (incompatible modes, bottom clamped)" :
                "",
        peak_force,
        max_reaction,
        max_inertia,
        ok ? "yes" : "NO");
      if (std::getenv("FGIMPACT_VERBOSE"))
        std::fprintf(stderr, "balance error %.3e\n", max_error / peak_force);
      return ok;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    const bool root = Utilities::MPI::this_mpi_process(MPI_COMM_WORLD) == 0;
    if (!root)
      std::freopen("/dev/null", "w", stdout);
    bool ok = nodal_and_recovered();
    ok &= converge_to_exact();
    ok &= momentum_balance(false);
    ok &= momentum_balance(true);
    ok &= momentum_balance(false, true);
    std::printf("%s\n", ok ? "OK" : "FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::probe_points
