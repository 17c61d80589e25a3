// The block-eliminated contact Newton of the implicit time stepper against
// the paper's monolithic Newton on the coupled (u, w_p) system, implemented
// here independently: every Newton iteration assembles the bordered
// Jacobian [[K_eff + F' g g^T, F' g], [F' g^T, m a0 + F']] and solves it
// with UMFPACK.  Both converged to 1e-14; the histories must agree to
// round-off.

#include <deal.II/base/mpi.h>

#include <deal.II/lac/sparse_direct.h>
#include <deal.II/lac/sparse_matrix.h>
#include <deal.II/lac/sparsity_pattern.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::monolithic_newton
{

  using namespace fgimpact;

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);

    PlateGeometry::Parameters gp;
    gp.subdivisions_x = 8;
    gp.subdivisions_y = 4;
    gp.subdivisions_z = 2;
    const PlateGeometry                    geometry(gp);
    FunctionallyGradedMaterial::Parameters mp;
    const FunctionallyGradedMaterial       material(mp, geometry.thickness());
    Impactor::Parameters                   ip;
    ip.initial_velocity = 2.;
    const Impactor        impactor(ip);
    const HertzContactLaw law(HertzContactLaw::Parameters(),
                              material,
                              impactor);
    PlateModel            plate(PlateModel::Parameters(),
                     geometry,
                     material,
                     MPI_COMM_WORLD);
    plate.setup();
    HertzNodeContact contact_model(law, plate, impactor.impact_point(0.2, 0.1));
    const auto       contact_dof = contact_model.contact_dofs()[0];
    const double     m           = impactor.mass();

    TimeStepper::Parameters tp;
    tp.time_step        = 2e-6;
    tp.newton.tolerance = 1e-14;
    const NewmarkIntegrator newmark(tp.newmark, tp.time_step);
    const double            a0 = newmark.mass_factor();

    // The library's eliminated stepper.
    EffectiveMatrixSolver::Parameters sp;
    sp.type = EffectiveMatrixSolver::Type::cholmod;
    auto stepper =
      create_time_stepper(tp, sp, plate, contact_model, m, ip.initial_velocity);
    stepper->initialize(false);
    ContactCoupler coupler(
      *stepper, contact_model, tp.newmark, m, tp.newton, MPI_COMM_WORLD);
    ImpactorState ball;
    ball.v = ip.initial_velocity;
    ContactState contact;

    // The monolithic system: DoFs 0..n-1 the plate, n the impactor.
    const unsigned int     n = plate.n_dofs();
    DynamicSparsityPattern dsp(n + 1, n + 1);
    const auto            &K = plate.stiffness_matrix();
    const auto            &M = plate.mass_matrix();
    for (unsigned int i = 0; i < n; ++i)
      for (auto it = K.begin(i); it != K.end(i); ++it)
        dsp.add(i, it->column());
    dsp.add(contact_dof, n);
    dsp.add(n, contact_dof);
    dsp.add(n, n);
    SparsityPattern sparsity;
    sparsity.copy_from(dsp);
    SparseMatrix<double> J(sparsity);
    Vector<double> u(n), v(n), a(n), r(n), Mr(n), u_it(n), R(n + 1), dx(n + 1);
    double         w = 0, wv = ip.initial_velocity, wa = 0;

    double       max_u_difference = 0, max_F_difference = 0, peak_F = 0;
    unsigned int max_iterations = 0;
    for (unsigned int step = 1; step <= 100; ++step)
      {
        // Monolithic Newton from the previous state.
        newmark.predictor(u, v, a, r);
        for (unsigned int i = 0; i < n; ++i)
          {
            double s = 0;
            for (auto it = M.begin(i); it != M.end(i); ++it)
              s += it->value() * r(it->column());
            Mr(i) = s;
          }
        const double rp   = newmark.predictor(w, wv, wa);
        u_it              = u;
        double       w_it = w;
        unsigned int it   = 0;
        for (; it < 50; ++it)
          {
            const double alpha = w_it + u_it(contact_dof);
            const double F = law.force(alpha), dF = law.force_derivative(alpha);
            // Residuals and Jacobian.
            J = 0;
            for (unsigned int i = 0; i < n; ++i)
              {
                double s = 0;
                for (auto e = K.begin(i); e != K.end(i); ++e)
                  {
                    const double kij = e->value() + a0 * M.el(i, e->column());
                    J.set(i, e->column(), kij);
                    s += kij * u_it(e->column());
                  }
                R(i) = s - Mr(i);
              }
            R(contact_dof) += F;
            R(n) = m * a0 * w_it - m * rp + F;
            J.add(contact_dof, contact_dof, dF);
            J.set(contact_dof, n, dF);
            J.set(n, contact_dof, dF);
            J.set(n, n, m * a0 + dF);
            SparseDirectUMFPACK lu;
            lu.initialize(J);
            R *= -1.;
            lu.vmult(dx, R);
            for (unsigned int i = 0; i < n; ++i)
              u_it(i) += dx(i);
            w_it += dx(n);
            double x_norm = std::abs(w_it);
            for (unsigned int i = 0; i < n; ++i)
              x_norm = std::max(x_norm, std::abs(u_it(i)));
            if (dx.linfty_norm() <= 1e-14 * x_norm)
              break;
          }
        max_iterations = std::max(max_iterations, it + 1);
        newmark.update(u_it, u, v, a);
        newmark.update(w_it, w, wv, wa);
        const double F_mono = law.force(w + u(contact_dof));

        // The eliminated stepper.
        coupler.advance(step, step * tp.time_step, ball, contact);
        const auto &u_elim = stepper->displacement();
        double      diff = 0, scale = 0;
        for (unsigned int i = 0; i < n; ++i)
          {
            diff  = std::max(diff, std::abs(u_elim(i) - u(i)));
            scale = std::max(scale, std::abs(u(i)));
          }
        max_u_difference = std::max(max_u_difference, diff / scale);
        max_F_difference =
          std::max(max_F_difference, std::abs(contact.force - F_mono));
        peak_F = std::max(peak_F, F_mono);
      }

    const bool ok_u      = max_u_difference < 1e-10;
    const bool ok_F      = max_F_difference < 1e-10 * peak_F;
    const bool ok_newton = max_iterations <= 6;
    std::printf(
      "100 steps at V0 = 2 m/s (peak force %.0f N), monolithic Newton "
      "needs up to %s iterations\n",
      peak_F,
      ok_newton ? "6" : "MORE THAN 6");
    std::printf("displacements equal to 1e-10 relative: %s\n",
                ok_u ? "yes" : "NO");
    std::printf("contact forces equal to 1e-10 relative: %s\n",
                ok_F ? "yes" : "NO");
    return ok_u && ok_F && ok_newton ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::monolithic_newton
