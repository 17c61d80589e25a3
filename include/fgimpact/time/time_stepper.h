#ifndef fgimpact_time_stepper_h
#define fgimpact_time_stepper_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/contact/contact_model.h>
#include <fgimpact/output/checkpoint.h>
#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/time/newmark.h>

#include <functional>
#include <memory>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  /// The impactor's scalar unknown: displacement w (m), velocity v (m/s),
  /// acceleration a (m/s^2), positive in the impact direction (-z).
  struct ImpactorState
  {
    double w = 0, v = 0, a = 0;
  };

  /**
   * Advances the plate and the impactor by one time step, coupled through
   * a ContactModel.  Two schemes (a selection plus the factory
   * create_time_stepper()):
   *
   * - implicit: Newmark (beta, gamma); the contact is block-eliminated
   *   with the plate's compliance at the contact DoFs, so a step costs one
   *   solve with the constant effective matrix;
   * - explicit: central difference (Newmark beta = 0, gamma = 1/2) with a
   *   row-sum lumped mass, one matrix-vector product per step, at a time
   *   step below the stability limit 2/omega_max.
   */
  class TimeStepper
  {
  public:
    enum class Scheme
    {
      implicit_newmark,
      central_difference
    };

    /// Subsections "Time integration" (scheme, time control, Newmark's
    /// beta and gamma) and "Newton" (the contact iteration).
    struct Parameters
    {
      Scheme                        scheme        = Scheme::implicit_newmark;
      double                        time_step     = 1e-6;   // s, 0: auto
      double                        end_time      = 400e-6; // s
      double                        safety_factor = 0.9;
      NewmarkIntegrator::Parameters newmark;
      NewtonControl                 newton;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Steps of length dt to reach end_time (the last may end past it
      /// by round-off); dt may differ from time_step (explicit, automatic).
      unsigned int
      n_steps(const double dt) const;
    };

    /// Wall-clock costs (s).  The reference costs of one matrix-vector
    /// product and one solve are measured only if asked for (benchmarks).
    struct Costs
    {
      double spmv  = 0;
      double solve = 0;
    };

    virtual ~TimeStepper() = default;

    /// Build matrices/factorizations and the contact compliance; fixes the
    /// time step.  With measure_reference_costs, also times 20
    /// matrix-vector products and 3 solves (costs()).
    virtual void
    initialize(const bool measure_reference_costs) = 0;

    /// The time step in use (s).
    virtual double
    time_step() const = 0;

    /// Advance from t_n to t_{n+1} = t (s); `step` and t only label errors.
    virtual void
    advance(const unsigned int step,
            const double       t,
            ImpactorState     &impactor,
            ContactState      &contact) = 0;

    /// Receives step j, u_j (m), v_j (m/s) and M v_j of a unit response.
    using ResponseObserver =
      std::function<void(const unsigned int,
                         const TrilinosWrappers::MPI::Vector &,
                         const TrilinosWrappers::MPI::Vector &,
                         const TrilinosWrappers::MPI::Vector &)>;

    /**
     * The plate's discrete response, from rest, to a unit contact force
     * (1 N down on the single contact DoF) at step 1 and none after:
     * observe() gets steps 1..n_steps, computed by the same recursion,
     * matrices and factorization as advance() (one solve per step).  The
     * plate is linear and time-invariant, so any force history's response
     * is the convolution of these (the study engine).  Leaves the stepper
     * at rest.  Returns false, observing nothing, where this does not
     * reproduce advance() (explicit scheme, iterative solver, several
     * contact DoFs).
     */
    virtual bool
    unit_response(const unsigned int n_steps, const ResponseObserver &observe)
    {
      (void)n_steps;
      (void)observe;
      return false;
    }

    /// Plate displacement (m) and velocity (m/s) at the current time.
    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return u;
    }
    const TrilinosWrappers::MPI::Vector &
    velocity() const
    {
      return v;
    }

    /// Plate acceleration (m/s^2) at the current time.
    const TrilinosWrappers::MPI::Vector &
    acceleration() const
    {
      return a;
    }

    /// Whether the scheme's mass matrix is lumped (diagonal, zero at the
    /// constrained DoFs): their reactions then carry no inertia.
    virtual bool
    has_lumped_mass() const
    {
      return false;
    }

    /// Kinetic energy 1/2 v^T M v and strain energy 1/2 u^T K u of the
    /// plate (J), kept up to date by advance() without extra matrix-vector
    /// products.
    double
    kinetic_energy() const
    {
      return kinetic;
    }
    double
    strain_energy() const
    {
      return strain;
    }

    /// Iterations of the linear solver in the last step (0 if direct).
    unsigned int
    linear_iterations() const
    {
      return last_linear_iterations;
    }

    const Costs &
    costs() const
    {
      return measured_costs;
    }

    /// Name of the scheme and linear solver, for the log.
    virtual std::string
    description() const = 0;

    /// The state after a time step, for a checkpoint: u, v, the energies
    /// and what the scheme carries (a; M u, M v, M a; the contact set's
    /// size after growth).  The factorization is not stored.
    virtual void
    save(CheckpointWriter &out) const;

    /// Restore save()'s state after initialize() (grows the contact set
    /// and factorizes again if it had grown).  Collective.
    virtual void
    load(CheckpointReader &in);

    /// The linear solver's memory report (may be empty), for the log.
    virtual std::string
    solver_log() const
    {
      return "";
    }

  protected:
    /// The state every scheme keeps and advance() updates.
    TrilinosWrappers::MPI::Vector u, v, a;
    double                        kinetic = 0, strain = 0;
    unsigned int                  last_linear_iterations = 0;
    Costs                         measured_costs;
  };



  /// "time step N (t = T us)", for messages.
  std::string
  time_step_label(const unsigned int step, const double t);

  /// An implicit step's contact solve failed (ContactState::
  /// newton_iterations invalid): throws ExcMessage naming the step and the
  /// parameters to change (for the resolved contact's LCP, whose
  /// iterations are not Newton's, the time step).  No-op if it converged.
  void
  check_contact_converged(const ContactState  &state,
                          const unsigned int   step,
                          const double         t,
                          const NewtonControl &newton);

  /// The explicit scheme (source/time/central_difference_stepper.cc).
  std::unique_ptr<TimeStepper>
  create_central_difference_stepper(const TimeStepper::Parameters &parameters,
                                    const PlateModel              &plate,
                                    ContactModel                  &contact,
                                    const double impactor_mass,
                                    const double impact_velocity);

  /// The factory: the scheme named in the parameters.
  std::unique_ptr<TimeStepper>
  create_time_stepper(const TimeStepper::Parameters           &parameters,
                      const EffectiveMatrixSolver::Parameters &solver,
                      const PlateModel                        &plate,
                      ContactModel                            &contact,
                      const double                             impactor_mass,
                      const double                             impact_velocity);
} // namespace fgimpact

#endif
