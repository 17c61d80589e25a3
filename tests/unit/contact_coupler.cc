// The ContactCoupler alone, without finite elements: a ball of mass m
// (V0 down) on a linear contact spring k over a one-degree-of-freedom
// plate (mass M on a spring K).  While in contact this is a linear
// two-degree-of-freedom system with a closed-form solution (its two normal
// modes, computed here); the coupler's ball, contact and plate steps must
// converge to it at second order, implicit (average acceleration) and
// explicit (central difference).  The same run is repeated with a plate
// that asks for a second iteration in every step (as a plastic plate
// would) and with a contact whose candidate set grows once: both must
// give the plain run's numbers exactly.

#include <deal.II/base/mpi.h>

#include <fgimpact/output/results.h>
#include <fgimpact/time/contact_coupler.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::contact_coupler
{

  using namespace fgimpact;

  namespace
  {
    const double m = 0.11, V0 = 1.; // ball: kg, m/s
    const double M = 0.3, K = 1e7;  // plate: kg, N/m
    const double k = 2e7;           // contact spring, N/m

    /// The plate: M u'' + K u = -lambda (u up), Newmark or central
    /// difference.  iterate: correct() declines the first try of each step.
    class OscillatorPlate : public PlateResponse
    {
    public:
      OscillatorPlate(const double dt, const bool explicit_scheme, bool iterate)
        : newmark(NewmarkIntegrator::Parameters(), dt)
        , dt(dt)
        , explicit_scheme(explicit_scheme)
        , iterate(iterate)
        , C(1, 1)
      {
        if (!explicit_scheme)
          C(0, 0) = 1. / (K + newmark.mass_factor() * M);
      }

      double
      time_step() const override
      {
        return dt;
      }
      bool
      explicit_contact() const override
      {
        return explicit_scheme;
      }

      Vector<double>
      predict(const unsigned int step,
              const double,
              const ContactState &) override
      {
        Vector<double> u_c(1);
        if (explicit_scheme)
          {
            u += dt * v + 0.5 * dt * dt * a;
            v += 0.5 * dt * a;
            u_c[0] = u;
          }
        else
          u_c[0] = M * newmark.predictor(u, v, a) * C(0, 0);
        u_free    = u_c[0];
        first_try = (step != last_step);
        last_step = step;
        return u_c;
      }

      const FullMatrix<double> &
      compliance() const override
      {
        return C;
      }

      bool
      correct(const unsigned int,
              const double,
              const ContactState &contact) override
      {
        if (iterate && first_try)
          {
            ++declined;
            return false; // nothing changed: the coupler must not either
          }
        const double lambda = contact.forces[0];
        if (explicit_scheme)
          {
            a = (-K * u - lambda) / M;
            v += 0.5 * dt * a;
          }
        else
          newmark.update(u_free - C(0, 0) * lambda, u, v, a);
        return true;
      }

      void
      set_contact_dofs(const std::vector<types::global_dof_index> &,
                       const std::vector<types::global_dof_index> &) override
      {
        ++handovers;
      }

      double
      kinetic_energy() const override
      {
        return 0.5 * M * v * v;
      }
      double
      strain_energy() const override
      {
        return 0.5 * K * u * u;
      }

      double       u = 0, v = 0, a = 0; // m, m/s, m/s^2 (up)
      unsigned int declined = 0, handovers = 0;

    private:
      const NewmarkIntegrator newmark;
      const double            dt;
      const bool              explicit_scheme, iterate;
      FullMatrix<double>      C;
      double                  u_free    = 0;
      unsigned int            last_step = 0;
      bool                    first_try = true;
    };

    /// lambda = k alpha_+, alpha = w + u_c; grow_at: the step whose first
    /// solve reports an exhausted candidate set (0: never).
    class SpringContact : public ContactModel
    {
    public:
      explicit SpringContact(const unsigned int grow_at)
        : grow_at(grow_at)
      {}

      const std::vector<types::global_dof_index> &
      contact_dofs() const override
      {
        return dofs;
      }

      void
      solve_implicit(const Vector<double>     &u_free,
                     const FullMatrix<double> &C,
                     const ColumnRequest &,
                     const double w_free,
                     const double c_b,
                     const NewtonControl &,
                     ContactState &state) const override
      {
        const double alpha_free = w_free + u_free[0];
        const double lambda =
          alpha_free > 0 ? k * alpha_free / (1. + k * (C(0, 0) + c_b)) : 0.;
        fill(state, alpha_free - (C(0, 0) + c_b) * lambda, lambda);
        state.node_displacement = u_free[0] - C(0, 0) * lambda;
        ++solves;
        state.candidates_exhausted = (solves == grow_at && !grown);
      }

      void
      evaluate_explicit(const Vector<double> &u_c,
                        const double          w,
                        ContactState         &state) const override
      {
        fill(state, w + u_c[0], k * std::max(w + u_c[0], 0.));
      }

      double
      potential(const ContactState &state) const override
      {
        return 0.5 * state.force * std::max(state.alpha, 0.);
      }
      double
      stiffness_bound(const double, const double) const override
      {
        return k;
      }
      std::string
      description() const override
      {
        return "spring";
      }
      std::string
      warning() const override
      {
        return "";
      }
      ContactConstants
      constants() const override
      {
        return {};
      }
      bool
      grow_candidates() override
      {
        grown = true;
        return true;
      }

      mutable unsigned int solves = 0;

    private:
      static void
      fill(ContactState &state, const double alpha, const double lambda)
      {
        state.alpha             = alpha;
        state.force             = lambda;
        state.forces            = {lambda};
        state.newton_iterations = 1;
      }

      const std::vector<types::global_dof_index> dofs = {0};
      const unsigned int                         grow_at;
      bool                                       grown = false;
    };

    /// The closed form while in contact: x = (w, d) with d = -u the plate's
    /// deflection, m w'' = -k (w - d), M d'' = k (w - d) - K d, x(0) = 0,
    /// w'(0) = V0: the modes of A = M^-1/2 Kmat M^-1/2 (2 x 2, symmetric).
    void
    exact(const double t, double &w, double &d)
    {
      const double a11 = k / m, a22 = (k + K) / M, a12 = -k / std::sqrt(m * M);
      const double mean = 0.5 * (a11 + a22);
      const double r = std::sqrt(0.25 * (a11 - a22) * (a11 - a22) + a12 * a12);
      const double y0[2] = {std::sqrt(m) * V0, 0.}; // M^1/2 x'(0)
      double       y[2]  = {0, 0};
      for (const double lambda : {mean - r, mean + r})
        {
          // Eigenvector of [[a11, a12], [a12, a22]] for lambda.
          double       phi[2] = {a12, lambda - a11};
          const double norm   = std::hypot(phi[0], phi[1]);
          phi[0] /= norm;
          phi[1] /= norm;
          const double omega = std::sqrt(lambda);
          const double c =
            (phi[0] * y0[0] + phi[1] * y0[1]) * std::sin(omega * t) / omega;
          y[0] += c * phi[0];
          y[1] += c * phi[1];
        }
      w = y[0] / std::sqrt(m);
      d = y[1] / std::sqrt(M);
    }

    struct Run
    {
      double       w = 0, d = 0, F = 0;
      unsigned int declined = 0, handovers = 0;
    };

    /// The coupled run to T = 60 us with n_steps steps.
    Run
    run(const unsigned int n_steps,
        const bool         explicit_scheme,
        const bool         iterate = false,
        const unsigned int grow_at = 0)
    {
      const double    dt = 60e-6 / n_steps;
      OscillatorPlate plate(dt, explicit_scheme, iterate);
      SpringContact   contact(grow_at);
      ContactCoupler  coupler(plate,
                             contact,
                             NewmarkIntegrator::Parameters(),
                             m,
                             NewtonControl(),
                             MPI_COMM_WORLD);
      ImpactorState   ball;
      ball.v = V0;
      ContactState state;
      for (unsigned int n = 1; n <= n_steps; ++n)
        coupler.advance(n, n * dt, ball, state);
      return {ball.w, -plate.u, state.force, plate.declined, plate.handovers};
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    double                           w_exact, d_exact;
    exact(60e-6, w_exact, d_exact);
    const double F_exact = k * (w_exact - d_exact);
    std::printf("closed form at 60 us: ball %.6f um, plate %.6f um, "
                "force %.4f N\n",
                w_exact * 1e6,
                d_exact * 1e6,
                F_exact);

    bool ok = true;
    for (const bool explicit_scheme : {false, true})
      {
        std::printf("%s:\n", explicit_scheme ? "explicit" : "implicit");
        double last_error = 0;
        for (const unsigned int n : {15u, 30u, 60u})
          {
            const Run    r     = run(n, explicit_scheme);
            const double error = std::abs(r.F - F_exact) / F_exact;
            std::printf("  %2u steps: force %.4f N, relative error %.3e, "
                        "ball %.3e, plate %.3e",
                        n,
                        r.F,
                        error,
                        std::abs(r.w - w_exact) / w_exact,
                        std::abs(r.d - d_exact) / d_exact);
            if (last_error > 0)
              {
                const double order = std::log2(last_error / error);
                std::printf(", order %.2f", order);
                ok = ok && order > 1.8 && order < 2.2;
              }
            std::printf("\n");
            last_error = error;
          }
        ok = ok && last_error < 1e-2;
      }

    // The coupler's loops must change nothing of the solution.
    const Run plain = run(30, false), iterated = run(30, false, true),
              grown = run(30, false, false, 4);
    // Verdicts of exact equality, not the differences.
    const bool same_iterated = iterated.F == plain.F && iterated.w == plain.w,
               same_grown    = grown.F == plain.F && grown.w == plain.w;
    std::printf("a plate declining each first try: %u declined, force and "
                "ball the plain run's exactly: %s\n",
                iterated.declined,
                same_iterated ? "yes" : "NO");
    std::printf("a candidate set grown at the 4th solve: %u hand-over, force "
                "and ball the plain run's exactly: %s\n",
                grown.handovers,
                same_grown ? "yes" : "NO");
    ok = ok && iterated.declined == 30 && same_iterated &&
         grown.handovers == 1 && same_grown;
    std::printf(ok ? "all checks passed\n" : "CHECK FAILED\n");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::contact_coupler
