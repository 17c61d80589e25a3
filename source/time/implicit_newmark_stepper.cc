// The implicit Newmark scheme with the contact block-eliminated
// (time_stepper.h, create_implicit_newmark_stepper()).

#include <deal.II/base/timer.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_control.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/patterns.h>
#include <fgimpact/contact/compliance.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/modified_mass.h>
#include <fgimpact/time/time_stepper.h>

#include <cmath>
#include <limits>
#include <sstream>

namespace fgimpact
{
  namespace
  {

    /**
     * Implicit Newmark.  The plate is linear and K_eff = K + a0 M constant,
     * so with the contact-free response u* = K_eff^{-1} M r_n and the unit
     * responses c_j = K_eff^{-1} g_j of the m contact DoFs (computed once),
     * u_{n+1} = u* - sum_j lambda_j c_j, and the coupled problem reduces to
     * the contact model's m unknowns with the dense compliance
     * C_ij = g_i^T c_j (for the Hertz node, m = 1 and Newton on the scalar
     * alpha: exactly the monolithic Newton's iterates, doc/theory.md,
     * section 7).
     *
     * The products M u, M v, M a are carried along by the same linear
     * Newmark recursion as u, v, a, so a step costs one solve and one
     * matrix-vector product (M u_{n+1}), energies included.
     */
    class ImplicitNewmarkStepper : public TimeStepper
    {
    public:
      ImplicitNewmarkStepper(const Parameters &parameters,
                             const EffectiveMatrixSolver::Parameters &solver,
                             const PlateModel                        &plate,
                             const ContactModel                      &contact)
        : newmark(parameters.newmark, parameters.time_step)
        , mass(plate)
        , solver(solver)
        , plate(plate)
        , contact_model(contact)
        , dofs(contact.contact_dofs())
        , massless(contact.massless_dofs())
      {}

      void
      initialize(const bool measure_reference_costs) override
      {
        mass.build_effective_matrix(newmark.mass_factor(), massless, effective);
        solver.initialize(effective, &plate.get_dof_handler());
        iterative = (solver.type() == EffectiveMatrixSolver::Type::cg);

        for (auto *vector : {&u, &v, &a, &Mu, &Mv, &Ma, &u_new, &Mu_new, &rhs})
          plate.initialize_vector(*vector);
        compute_compliance();
        if (measure_reference_costs)
          measure_costs();
      }

      double
      time_step() const override
      {
        return newmark.time_step();
      }

      void
      set_plasticity(PlasticPlate &plasticity, const double tolerance) override
      {
        plastic           = &plasticity;
        plastic_tolerance = tolerance;
      }

      double
      plastic_work() const override
      {
        return plastic ? plastic->plastic_work() : 0.;
      }

      double
      max_plastic_strain() const override
      {
        return plastic ? plastic->max_equivalent_plastic_strain() : 0.;
      }

      Vector<double>
      predict(const unsigned int  step,
              const double        t,
              const ContactState &previous) override
      {
        if (plastic && step != increment)
          {
            plastic->begin_increment();
            increment = step;
          }
        solve_contact_free(step, t, previous);
        u_free = plate.dof_values(u_new, dofs);
        return u_free;
      }

      const FullMatrix<double> &
      compliance() const override
      {
        return contact_compliance;
      }

      unsigned int
      require_compliance(const unsigned int n) override
      {
        // Whole blocks counted from 0: a column is bitwise the same
        // whenever it is asked for (a resumed run's are an uninterrupted
        // run's).
        const unsigned int block = compliance_block_size;
        const unsigned int end =
          std::min<std::size_t>(dofs.size(), (n + block - 1) / block * block);
        if (end > n_columns)
          {
            fgimpact::compute_compliance_columns(
              solver, plate, dofs, n_columns, end, contact_compliance, &c);
            n_columns = end;
          }
        return n_columns;
      }

      bool
      correct(const unsigned int  step,
              const double        t,
              const ContactState &contact) override
      {
        // Back-substitute: the plate at t_{n+1}; most candidates are
        // inactive (a zero force adds nothing: skipped).
        std::vector<unsigned int>           pressed;
        std::vector<double>                 weights;
        std::vector<const StoredResponse *> responses;
        for (unsigned int j = 0; j < dofs.size(); ++j)
          if (contact.forces[j] != 0.)
            {
              pressed.push_back(j);
              weights.push_back(-contact.forces[j]);
              responses.push_back(&response(j)); // collective if not stored
            }
        add_weighted_responses(u_new, weights, responses);
        double work = 0; // sum_j lambda_j u_j(t_{n+1}) = u^T (sum lambda g)
        for (const unsigned int j : pressed)
          {
            double u_j = u_free[j];
            for (unsigned int k = 0; k < dofs.size(); ++k)
              u_j -= contact_compliance(j, k) * contact.forces[k];
            work += contact.forces[j] * u_j;
          }
        double plastic_energy = 0; // - u^T f_p + 1/2 eps_p : D : eps_p
        if (plastic && !plastic_step_converged(contact, plastic_energy))
          return false;
        mass.vmult(Mu_new, u_new);
        // u^T K u from K_eff u = M r_n + f_p - sum lambda_j g_j, K_eff =
        // K + a0 M, with the f_p u was solved with;
        // with plastic strain, the elastic energy is 1/2 u^T K u - u^T f_p
        // + 1/2 int eps_p : D : eps_p.
        strain = 0.5 * (u_new * rhs - work -
                        newmark.mass_factor() * (u_new * Mu_new)) +
                 plastic_energy;

        newmark.update(u_new, u, v, a);
        newmark.update(Mu_new, Mu, Mv, Ma);
        // Refresh the carried products now and then against round-off.
        if (step % 64 == 0)
          {
            mass.vmult(Mv, v);
            mass.vmult(Ma, a);
          }
        kinetic = 0.5 * (v * Mv);

        AssertThrow(std::isfinite(contact.alpha) && std::isfinite(strain) &&
                      std::isfinite(kinetic),
                    ExcMessage("the solution is not finite (NaN or Inf) at " +
                               time_step_label(step, t) + "."));
        return true;
      }

      /// The contact set grew: its massless DoFs (a new K_eff, factorized
      /// again, and the carried products M u, M v, M a) and its
      /// compliance.
      void
      set_contact_dofs(
        const std::vector<types::global_dof_index> &contact_dofs,
        const std::vector<types::global_dof_index> &massless_dofs) override
      {
        dofs     = contact_dofs;
        massless = massless_dofs;
        if (!massless.empty())
          {
            mass.build_effective_matrix(newmark.mass_factor(),
                                        massless,
                                        effective);
            solver.initialize(effective, &plate.get_dof_handler());
            mass.vmult(Mu, u);
            mass.vmult(Mv, v);
            mass.vmult(Ma, a);
          }
        compute_compliance();
      }

      bool
      unit_response(const unsigned int      n_steps,
                    const ResponseObserver &observe) override
      {
        if (dofs.size() != 1 || iterative || plastic)
          return false;
        const ContactState no_force;
        for (unsigned int step = 1; step <= n_steps; ++step)
          {
            // As a coupled step with F_1 = 1 N and F_j = 0 after.
            solve_contact_free(step, step * newmark.time_step(), no_force);
            if (step == 1)
              add_weighted_responses(u_new, {-1.}, {&response(0)});
            mass.vmult(Mu_new, u_new);
            newmark.update(u_new, u, v, a);
            newmark.update(Mu_new, Mu, Mv, Ma);
            if (step % 64 == 0)
              {
                mass.vmult(Mv, v);
                mass.vmult(Ma, a);
              }
            observe(step, u, v, Mv);
          }
        for (auto *vector : {&u, &v, &a, &Mu, &Mv, &Ma})
          *vector = 0.;
        kinetic = strain = 0;
        return true;
      }

      std::string
      description() const override
      {
        std::ostringstream s;
        s << "implicit Newmark (beta = " << newmark.beta()
          << ", gamma = " << newmark.gamma() << "), linear solver "
          << solver.type_name();
        if (!massless.empty())
          s << "; modified mass: the contact candidates' z DoFs massless ("
            << mass.removed() << " kg removed)";
        if (contact_model.compliance_on_demand())
          s << "; the compliance's columns and unit responses computed as "
               "the contact reaches them, "
            << compliance_block_size << " contact DoFs at a time";
        return s.str();
      }

      void
      save(CheckpointWriter &out) const override
      {
        TimeStepper::save(out);
        for (const auto *vector : {&a, &Mu, &Mv, &Ma})
          out.put(*vector);
        if (plastic)
          plastic->save(out);
      }

      void
      load(CheckpointReader &in) override
      {
        TimeStepper::load(in);
        for (auto *vector : {&a, &Mu, &Mv, &Ma})
          in.get(*vector);
        if (plastic)
          plastic->load(in);
      }

      std::string
      solver_log() const override
      {
        return solver.memory_log();
      }

    private:
      /// The dense compliance C (m/N) and c_j = K_eff^{-1} g_j, stored:
      /// all of them now, or for a contact model that asks for them
      /// (compliance_on_demand()) those it reaches, a block at a time
      /// (the resolved contact at level 7 of the default scene reaches 320
      /// of its 849 candidates; their responses were 20 % of the run's
      /// memory and their solves 9 of its 50 s).
      void
      compute_compliance()
      {
        contact_compliance.reinit(dofs.size(), dofs.size());
        // A resolved contact (its columns on demand) stores hundreds of
        // responses: single precision (StoredResponse).
        c.assign(dofs.size(),
                 StoredResponse(contact_model.compliance_on_demand()));
        n_columns = 0;
        if (!contact_model.compliance_on_demand())
          require_compliance(dofs.size());
      }

      /// c_j, computed now if it was not stored (one solve, on every rank:
      /// the forces that ask for it are the same everywhere).
      const StoredResponse &
      response(const unsigned int j)
      {
        if (c[j].empty())
          {
            TrilinosWrappers::MPI::Vector column;
            fgimpact::compute_response(solver, plate, dofs[j], column);
            c[j].assign(column.begin(), column.end());
          }
        return c[j];
      }

      /// The contact-free response u_new = u* (K_eff u* = M r_n) and M r_n
      /// in rhs, from the carried products (no matrix-vector product).
      void
      solve_contact_free(const unsigned int  step,
                         const double        t,
                         const ContactState &contact)
      {
        newmark.predictor(Mu, Mv, Ma, rhs);
        if (plastic)
          rhs += plastic->plastic_force();
        if (iterative)
          {
            // Warm start: u* = u_{n+1} + sum lambda_j c_j with the explicit
            // predictor u_{n+1} ~ u + dt v + dt^2/2 a and the last forces.
            const double dt = newmark.time_step();
            u_new           = u;
            u_new.add(dt, v, 0.5 * dt * dt, a);
            std::vector<double>                 weights;
            std::vector<const StoredResponse *> responses;
            for (unsigned int j = 0; j < contact.forces.size(); ++j)
              if (contact.forces[j] != 0.)
                {
                  weights.push_back(contact.forces[j]);
                  responses.push_back(&response(j));
                }
            add_weighted_responses(u_new, weights, responses);
          }
        try
          {
            solver.solve(u_new, rhs);
          }
        catch (const SolverControl::NoConvergence &e)
          {
            AssertThrow(false,
                        linear_solver_failure("at " + time_step_label(step, t),
                                              e.last_step));
          }
        last_linear_iterations = solver.last_iterations();
      }

      /**
       * The plastic state at u_new, from the step's start: whether the
       * plastic force has settled (its change at most the tolerance times
       * the largest nodal force, contact or plastic).  If so, the state is
       * committed and energy gets -u^T f_p + 1/2 int eps_p : D : eps_p of
       * the plastic strain at u_new (f_p its load); if not, the next
       * predict() solves with the relaxed force.  Collective.
       */
      bool
      plastic_step_converged(const ContactState &contact, double &energy)
      {
        double scale = plastic->plastic_force().linfty_norm();
        for (const double f : contact.forces)
          scale = std::max(scale, std::abs(f));
        const double change = plastic->update(u_new);
        // The identity holds with the load of the plastic strain it
        // counts, f_p(u_new), not the force u_new was solved with.
        energy =
          plastic->eigenstrain_energy() - (u_new * plastic->updated_force());
        if (change > plastic_tolerance * scale)
          return false;
        plastic->commit();
        return true;
      }

      /// Reference costs for the benchmarks (Output/Instrumentation).
      void
      measure_costs()
      {
        TrilinosWrappers::MPI::Vector x, y;
        plate.initialize_vector(x);
        plate.initialize_vector(y);
        x = 1.;
        Timer              timer;
        const unsigned int n_spmv = 20;
        for (unsigned int i = 0; i < n_spmv; ++i)
          effective.vmult(y, x);
        measured_costs.spmv = timer.wall_time() / n_spmv;
        timer.restart();
        const unsigned int n_solves = 3;
        for (unsigned int i = 0; i < n_solves; ++i)
          {
            y = 0.;
            solver.solve(y, x);
          }
        measured_costs.solve = timer.wall_time() / n_solves;
      }

      const NewmarkIntegrator newmark;
      ModifiedMass            mass;
      // Declared before the solver, which refers to it: members are
      // destroyed in reverse order (Amesos_Mumps crashed otherwise).
      TrilinosWrappers::SparseMatrix       effective;
      EffectiveMatrixSolver                solver;
      const PlateModel                    &plate;
      const ContactModel                  &contact_model;
      std::vector<types::global_dof_index> dofs, massless;
      TrilinosWrappers::MPI::Vector        Mu, Mv, Ma, u_new, Mu_new, rhs;
      std::vector<StoredResponse>          c;
      FullMatrix<double>                   contact_compliance;
      /// The compliance's first n_columns columns (and their responses)
      /// are computed.
      unsigned int   n_columns = 0;
      Vector<double> u_free; // m, contact DoFs
      bool           iterative         = false;
      PlasticPlate  *plastic           = nullptr;
      double         plastic_tolerance = 0;
      /// The step whose increment the plastic state is in.
      unsigned int increment = numbers::invalid_unsigned_int;
    };
  } // namespace


  std::unique_ptr<TimeStepper>
  create_implicit_newmark_stepper(
    const TimeStepper::Parameters           &parameters,
    const EffectiveMatrixSolver::Parameters &solver,
    const PlateModel                        &plate,
    const ContactModel                      &contact)
  {
    return std::make_unique<ImplicitNewmarkStepper>(parameters,
                                                    solver,
                                                    plate,
                                                    contact);
  }
} // namespace fgimpact
