#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_control.h>

#include <fgimpact/time_stepper.h>

#include <cmath>
#include <limits>
#include <map>
#include <sstream>

namespace fgimpact
{
  void
  TimeStepper::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    {
      prm.declare_entry(
        "Scheme",
        "implicit",
        Patterns::Selection("implicit|explicit"),
        "implicit: Newmark with 'Newmark beta/gamma' and a Newton iteration "
        "on the contact (block-eliminated: one linear solve per step). "
        "explicit: central difference (beta = 0, gamma = 1/2) with a "
        "row-sum lumped mass; one matrix-vector product per step, time step "
        "limited by stability.");
      prm.declare_entry(
        "Stable step safety factor",
        "0.9",
        Patterns::Double(0.01, 1.),
        "explicit scheme: the automatic time step (Time step = 0) is this "
        "factor times the estimated stability limit 2/omega_max. "
        "Dimensionless.");
    }
    prm.leave_subsection();

    prm.enter_subsection("Newton");
    {
      prm.declare_entry("Tolerance",
                        "1e-3",
                        Patterns::Double(1e-15, 0.1),
                        "implicit scheme: Newton stops when the relative "
                        "change of the indentation between two iterations is "
                        "below this (the paper: 0.1 %). Newton converges "
                        "quadratically here, so the error left is about its "
                        "square. Dimensionless.");
      prm.declare_entry("Max iterations",
                        "50",
                        Patterns::Integer(1, 10000),
                        "Iteration cap per time step; reaching it stops the "
                        "run with an error naming the step.");
    }
    prm.leave_subsection();
  }



  void
  TimeStepper::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Time integration");
    explicit_scheme = (prm.get("Scheme") == "explicit");
    safety_factor   = prm.get_double("Stable step safety factor");
    prm.leave_subsection();

    prm.enter_subsection("Newton");
    newton_tolerance      = prm.get_double("Tolerance");
    newton_max_iterations = prm.get_integer("Max iterations");
    prm.leave_subsection();
  }



  namespace
  {
    std::string
    at_step(const unsigned int step, const double t)
    {
      std::ostringstream s;
      s << "time step " << step << " (t = " << t * 1e6 << " us)";
      return s.str();
    }



    /**
     * Solve alpha + s F(alpha) = alpha_tilde by Newton's method.
     * R(alpha) = alpha + s F(alpha) - alpha_tilde is increasing and convex
     * for alpha > 0 and R(alpha_tilde) >= 0, so Newton started at
     * alpha_tilde decreases monotonically to the root.  Returns the number
     * of iterations, or max() on failure.
     */
    unsigned int
    solve_contact_newton(const HertzContactLaw &law,
                         const double           s,
                         const double           alpha_tilde,
                         const double           tolerance,
                         const unsigned int     max_iterations,
                         double                &alpha)
    {
      alpha = alpha_tilde;
      if (alpha_tilde <= 0.)
        return 0; // no contact: F = 0 satisfies the equation exactly
      for (unsigned int it = 1; it <= max_iterations; ++it)
        {
          const double R     = alpha + s * law.force(alpha) - alpha_tilde;
          const double dR    = 1. + s * law.force_derivative(alpha);
          const double delta = -R / dR;
          alpha += delta;
          if (!std::isfinite(alpha))
            break;
          if (std::abs(delta) <= tolerance * std::abs(alpha))
            return it;
        }
      return std::numeric_limits<unsigned int>::max();
    }



    /**
     * Implicit Newmark.  The plate is linear and K_eff = K + a0 M constant,
     * so with the contact-free response u* = K_eff^{-1} M r_n and the unit
     * response c = K_eff^{-1} g (computed once), u_{n+1} = u* - F c and the
     * coupled Newton reduces to a scalar equation for alpha: exactly the
     * monolithic Newton's iterates (doc/theory.md, section 7).
     *
     * The products M u, M v, M a are carried along by the same linear
     * Newmark recursion as u, v, a, so a step costs one solve and one
     * matrix-vector product (M u_{n+1}), energies included.
     */
    class ImplicitNewmarkStepper : public TimeStepper
    {
    public:
      ImplicitNewmarkStepper(const Parameters                    &parameters,
                             const NewmarkIntegrator::Parameters &newmark,
                             const EffectiveMatrixSolver::Parameters &solver,
                             const PlateModel                        &plate,
                             const HertzContactLaw        &contact_law,
                             const types::global_dof_index contact_dof,
                             const double                  impactor_mass)
        : parameters(parameters)
        , newmark(newmark)
        , solver(solver)
        , plate(plate)
        , contact_law(contact_law)
        , contact_dof(contact_dof)
        , m_i(impactor_mass)
      {}

      void
      initialize() override
      {
        Timer timer;
        effective.copy_from(plate.stiffness_matrix());
        effective.add(newmark.mass_factor(), plate.mass_matrix());
        solver.initialize(effective, &plate.get_dof_handler());
        iterative = (solver.type() == "cg");

        for (auto *vector :
             {&u, &v, &a, &Mu, &Mv, &Ma, &u_new, &Mu_new, &rhs, &c, &g})
          plate.initialize_vector(*vector);
        // The unit contact load; only the owner of the contact DoF writes.
        if (g.locally_owned_elements().is_element(contact_dof))
          g(contact_dof) = 1.;
        g.compress(VectorOperation::insert);
        solver.solve(c, g);
        // chi = g^T K_eff^{-1} g > 0: the contact node's dynamic compliance
        // (m/N).
        chi                = plate.dof_value(c, contact_dof);
        factorization_time = timer.wall_time();

        // Reference costs, measured in this run.
        timer.restart();
        const unsigned int n_spmv = 20;
        for (unsigned int i = 0; i < n_spmv; ++i)
          effective.vmult(rhs, c);
        spmv_time = timer.wall_time() / n_spmv;
        timer.restart();
        const unsigned int n_solves = 3;
        for (unsigned int i = 0; i < n_solves; ++i)
          {
            u_new = 0.;
            solver.solve(u_new, g);
          }
        solve_time = timer.wall_time() / n_solves;
        rhs        = 0.;
        u_new      = 0.;
      }

      double
      time_step() const override
      {
        return newmark.time_step();
      }

      void
      advance(const unsigned int step,
              const double       t,
              ImpactorState     &impactor,
              ContactState      &contact) override
      {
        const double a0 = newmark.mass_factor();

        // Contact-free predictor: K_eff u* = M r_n, M r_n from the carried
        // products (no matrix-vector product).
        newmark.predictor(Mu, Mv, Ma, rhs);
        if (iterative)
          {
            // Warm start: u* = u_{n+1} + F c with the explicit predictor
            // u_{n+1} ~ u + dt v + dt^2/2 a and the last contact force.
            const double dt = newmark.time_step();
            u_new           = u;
            u_new.add(dt, v, 0.5 * dt * dt, a);
            u_new.add(contact.force, c);
          }
        try
          {
            solver.solve(u_new, rhs);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            AssertThrow(false,
                        ExcMessage("the linear solver did not converge at " +
                                   at_step(step, t) + " after " +
                                   std::to_string(e.last_step) +
                                   " iterations; raise Linear solver/Max "
                                   "iterations or use a direct solver."));
          }

        // Impactor: m a0 w = m r_p - F  =>  w = w~ - F/(m a0).
        const double w_tilde =
          newmark.predictor(impactor.w, impactor.v, impactor.a) / a0;
        // The only communication of the contact Newton: the owner's value
        // of u* at the contact node (one scalar all-reduce).
        const double W_star = -plate.dof_value(u_new, contact_dof);
        const double s      = 1. / (m_i * a0) + chi;

        contact.newton_iterations =
          solve_contact_newton(contact_law,
                               s,
                               w_tilde - W_star,
                               parameters.newton_tolerance,
                               parameters.newton_max_iterations,
                               contact.alpha);
        AssertThrow(
          contact.newton_iterations != std::numeric_limits<unsigned int>::max(),
          ExcMessage("Newton for the contact did not converge at " +
                     at_step(step, t) + " within " +
                     std::to_string(parameters.newton_max_iterations) +
                     " iterations; reduce Time integration/Time step or "
                     "raise Newton/Max iterations."));
        contact.force  = contact_law.force(contact.alpha);
        const double F = contact.force;

        // Back-substitute: plate and impactor at t_{n+1}.
        u_new.add(-F, c);
        contact.node_displacement = -W_star - F * chi;
        plate.mass_matrix().vmult(Mu_new, u_new);
        // u^T K u from K_eff u = M r_n - F g:  K u = M r_n - F g - a0 M u.
        strain = 0.5 * (u_new * rhs - F * contact.node_displacement -
                        a0 * (u_new * Mu_new));

        newmark.update(u_new, u, v, a);
        newmark.update(Mu_new, Mu, Mv, Ma);
        newmark.update(w_tilde - F / (m_i * a0),
                       impactor.w,
                       impactor.v,
                       impactor.a);
        // Refresh the carried products now and then against round-off.
        if (step % 64 == 0)
          {
            plate.mass_matrix().vmult(Mv, v);
            plate.mass_matrix().vmult(Ma, a);
          }
        kinetic = 0.5 * (v * Mv);

        AssertThrow(std::isfinite(contact.alpha) && std::isfinite(strain) &&
                      std::isfinite(kinetic),
                    ExcMessage("the solution is not finite (NaN or Inf) at " +
                               at_step(step, t) + "."));
      }

      std::string
      description() const override
      {
        std::ostringstream s;
        s << "implicit Newmark (beta = " << newmark.beta()
          << ", gamma = " << newmark.gamma() << "), linear solver "
          << solver.type();
        return s.str();
      }

    private:
      const Parameters        parameters;
      const NewmarkIntegrator newmark;
      // Declared before the solver, which refers to it: members are
      // destroyed in reverse order (Amesos_Mumps crashed otherwise).
      TrilinosWrappers::SparseMatrix effective;
      EffectiveMatrixSolver          solver;
      const PlateModel              &plate;
      const HertzContactLaw         &contact_law;
      const types::global_dof_index  contact_dof;
      const double                   m_i;
      TrilinosWrappers::MPI::Vector  a, Mu, Mv, Ma, u_new, Mu_new, rhs;
      TrilinosWrappers::MPI::Vector  c, g;
      double                         chi       = 0;
      bool                           iterative = false;
    };



    /**
     * Central difference (velocity Verlet form) with a row-sum lumped mass
     * M_L.  Per step: u_{n+1} = u_n + dt v_n + dt^2/2 a_n, then
     * a_{n+1} = M_L^{-1} (-F_{n+1} g - K u_{n+1}) and
     * v_{n+1} = v_n + dt/2 (a_n + a_{n+1}); the same for the impactor with
     * a = -F/m.  The contact force is explicit: no Newton.
     */
    class CentralDifferenceStepper : public TimeStepper
    {
    public:
      CentralDifferenceStepper(const Parameters                    &parameters,
                               const NewmarkIntegrator::Parameters &newmark,
                               const PlateModel                    &plate,
                               const HertzContactLaw               &contact_law,
                               const types::global_dof_index        contact_dof,
                               const double impactor_mass,
                               const double impact_velocity)
        : parameters(parameters)
        , requested_dt(newmark.time_step)
        , plate(plate)
        , contact_law(contact_law)
        , contact_dof(contact_dof)
        , m_i(impactor_mass)
        , V0(impact_velocity)
      {}

      void
      initialize() override
      {
        Timer timer;
        for (auto *vector :
             {&u, &v, &a, &Ku, &inverse_mass, &lumped_mass, &x, &y})
          plate.initialize_vector(*vector);
        owns_contact_dof = u.locally_owned_elements().is_element(contact_dof);

        // Row-sum lumping: M_L = M 1 (positive for FE_Q(1) and FE_Q(2)).
        x = 1.;
        plate.mass_matrix().vmult(inverse_mass, x);
        const auto &constraints = plate.get_constraints();
        for (const auto i : inverse_mass.locally_owned_elements())
          {
            AssertThrow(inverse_mass(i) > 0.,
                        ExcMessage("the lumped mass matrix has a "
                                   "non-positive entry"));
            // Constrained DoFs stay at rest: zero inverse mass.
            const bool constrained = constraints.is_constrained(i);
            lumped_mass(i)         = constrained ? 0. : inverse_mass(i);
            inverse_mass(i)        = constrained ? 0. : 1. / inverse_mass(i);
          }
        inverse_mass.compress(VectorOperation::insert);
        lumped_mass.compress(VectorOperation::insert);

        // Stability limit 2/omega_max, omega_max^2 the largest eigenvalue
        // of M_L^{-1} (K + k_c g g^T), where k_c = dF/dalpha at the
        // half-space maximum indentation (closed form) bounds the contact
        // spring's stiffening of the contact node.
        const double K_hertz   = contact_law.force(1.);
        const double alpha_max = std::pow(1.25 * m_i * V0 * V0 / K_hertz, 0.4);
        const double k_c       = contact_law.force_derivative(alpha_max);
        const double lambda    = largest_eigenvalue(k_c);
        stable_dt              = 2. / std::sqrt(lambda);

        if (requested_dt == 0.)
          dt = parameters.safety_factor * stable_dt;
        else
          {
            AssertThrow(requested_dt <= stable_dt,
                        ExcMessage(
                          "Time integration/Time step = " +
                          std::to_string(requested_dt * 1e6) +
                          " us exceeds the stability limit " +
                          std::to_string(stable_dt * 1e6) +
                          " us of the explicit scheme; use Time step = 0 "
                          "(automatic) or the implicit scheme."));
            dt = requested_dt;
          }
        factorization_time = timer.wall_time();

        timer.restart();
        const unsigned int n_spmv = 20;
        for (unsigned int i = 0; i < n_spmv; ++i)
          plate.stiffness_matrix().vmult(y, x);
        spmv_time = timer.wall_time() / n_spmv;
        x         = 0.;
        y         = 0.;
      }

      double
      time_step() const override
      {
        return dt;
      }

      void
      advance(const unsigned int step,
              const double       t,
              ImpactorState     &impactor,
              ContactState      &contact) override
      {
        // Positions.
        u.add(dt, v, 0.5 * dt * dt, a);
        v.add(0.5 * dt, a); // half step
        impactor.w += dt * impactor.v + 0.5 * dt * dt * impactor.a;
        impactor.v += 0.5 * dt * impactor.a;

        // Contact force at the new positions (alpha = w_p - W, W = -u_z).
        contact.node_displacement = plate.dof_value(u, contact_dof);
        contact.alpha             = impactor.w + contact.node_displacement;
        contact.force             = contact_law.force(contact.alpha);
        contact.newton_iterations = 0;

        // Accelerations and the second velocity half step.
        plate.stiffness_matrix().vmult(Ku, u);
        strain = 0.5 * (u * Ku);
        a.equ(-1., Ku);
        if (owns_contact_dof)
          a(contact_dof) -= contact.force;
        a.scale(inverse_mass);
        v.add(0.5 * dt, a);
        impactor.a = -contact.force / m_i;
        impactor.v += 0.5 * dt * impactor.a;

        // 1/2 v^T M_L v with the diagonal M_L: two vector operations.
        y = v;
        y.scale(lumped_mass);
        kinetic = 0.5 * (v * y);

        AssertThrow(std::isfinite(contact.alpha) && std::isfinite(strain) &&
                      std::abs(contact.alpha) < 1.,
                    ExcMessage("the explicit solution blew up (NaN, Inf or "
                               "an indentation above 1 m) at " +
                               at_step(step, t) +
                               "; reduce Time integration/Stable step "
                               "safety factor."));
      }

      std::string
      description() const override
      {
        std::ostringstream s;
        s << "explicit central difference, lumped mass, stability limit "
          << stable_dt * 1e6 << " us";
        return s.str();
      }

    private:
      /// Power iteration with Rayleigh quotients on M_L^{-1} (K + k_c g g^T)
      /// restricted to the unconstrained DoFs.
      double
      largest_eigenvalue(const double k_c)
      {
        // A deterministic start vector with all frequencies present, a
        // function of the DoFs' positions and components rather than of
        // their numbers, so that every partition (MPI rank count) finds
        // the same time step to round-off.
        const auto &dof_handler = plate.get_dof_handler();
        std::map<types::global_dof_index, Point<3>> support;
        DoFTools::map_dofs_to_support_points(plate.get_mapping(),
                                             dof_handler,
                                             support);
        std::vector<types::global_dof_index> dofs(
          dof_handler.get_fe().n_dofs_per_cell());
        for (const auto &cell : dof_handler.active_cell_iterators())
          if (cell->is_locally_owned())
            {
              cell->get_dof_indices(dofs);
              for (unsigned int k = 0; k < dofs.size(); ++k)
                if (x.locally_owned_elements().is_element(dofs[k]))
                  {
                    const Point<3>    &p = support.at(dofs[k]);
                    const unsigned int c =
                      dof_handler.get_fe().system_to_component_index(k).first;
                    // Positions in mm: O(1-100) arguments of the sine.
                    x(dofs[k]) =
                      (inverse_mass(dofs[k]) > 0. ?
                         std::sin(1.0 + 12.9898e3 * p[0] + 78.233e3 * p[1] +
                                  37.719e3 * p[2] + 2.3 * c) :
                         0.);
                  }
            }
        x.compress(VectorOperation::insert);
        double lambda = 0;
        for (unsigned int it = 0; it < 1000; ++it)
          {
            plate.stiffness_matrix().vmult(y, x); // y = (K + k_c g g^T) x
            if (owns_contact_dof)
              y(contact_dof) += k_c * x(contact_dof);
            Ku = x; // scratch: M_L x
            Ku.scale(lumped_mass);
            const double new_lambda = (x * y) / (x * Ku);
            y.scale(inverse_mass);
            x = y;
            x /= x.l2_norm();
            const bool converged =
              it > 20 && std::abs(new_lambda - lambda) < 1e-6 * new_lambda;
            lambda = new_lambda;
            if (converged)
              break;
          }
        Ku = 0.;
        return lambda;
      }

      const Parameters              parameters;
      const double                  requested_dt;
      const PlateModel             &plate;
      const HertzContactLaw        &contact_law;
      const types::global_dof_index contact_dof;
      const double                  m_i, V0;
      double                        dt = 0, stable_dt = 0;
      bool                          owns_contact_dof = false;
      TrilinosWrappers::MPI::Vector a, Ku, inverse_mass, lumped_mass, x, y;
    };
  } // namespace



  std::unique_ptr<TimeStepper>
  create_time_stepper(const TimeStepper::Parameters           &parameters,
                      const NewmarkIntegrator::Parameters     &newmark,
                      const EffectiveMatrixSolver::Parameters &solver,
                      const PlateModel                        &plate,
                      const HertzContactLaw                   &contact_law,
                      const types::global_dof_index            contact_dof,
                      const double                             impactor_mass,
                      const double                             impact_velocity)
  {
    if (parameters.explicit_scheme)
      return std::make_unique<CentralDifferenceStepper>(parameters,
                                                        newmark,
                                                        plate,
                                                        contact_law,
                                                        contact_dof,
                                                        impactor_mass,
                                                        impact_velocity);
    return std::make_unique<ImplicitNewmarkStepper>(parameters,
                                                    newmark,
                                                    solver,
                                                    plate,
                                                    contact_law,
                                                    contact_dof,
                                                    impactor_mass);
  }
} // namespace fgimpact
