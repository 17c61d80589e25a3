#ifndef fgimpact_time_stepper_h
#define fgimpact_time_stepper_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/selection.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/time/newmark.h>
#include <fgimpact/time/plate_response.h>

#include <functional>
#include <memory>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The finite element plate's response in time (a PlateResponse, which
   * the ContactCoupler couples to the ball), with its fields u, v, a.  Two
   * schemes (a selection plus the factory create_time_stepper()):
   *
   * - implicit: Newmark (beta, gamma); the contact is block-eliminated
   *   with the plate's compliance at the contact DoFs, so a step costs one
   *   solve with the constant effective matrix;
   * - explicit: central difference (Newmark beta = 0, gamma = 1/2) with a
   *   row-sum lumped mass, one matrix-vector product per step, at a time
   *   step below the stability limit 2/omega_max.
   */
  class TimeStepper : public PlateResponse
  {
  public:
    enum class Scheme
    {
      implicit_newmark,
      central_difference
    };

    /// The names of Time integration/Scheme.
    static const SelectionTable<Scheme> &
    scheme_names();

    /// The help of Time integration/Scheme: every scheme's description.
    static std::string
    scheme_help();

    /// Subsections "Time integration" (scheme, time control, Newmark's
    /// beta and gamma) and "Newton" (the contact iteration).
    struct Parameters
    {
      Scheme scheme    = Scheme::implicit_newmark;
      double time_step = 1e-6; // s, 0: auto
      /// End time = auto: the run stops when the ball has left for good
      /// (AutoEndTime), at the latest at end_time = Maximum end time.
      bool                          auto_end_time = true;
      double                        end_time      = 2e-3; // s
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
     * matrices and factorization as a coupled step (one solve per step).  The
     * plate is linear and time-invariant, so any force history's response
     * is the convolution of these (the study engine).  Leaves the stepper
     * at rest.  Returns false, observing nothing, where this does not
     * reproduce the coupled step (explicit scheme, iterative solver, several
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
    /// plate (J), kept up to date by correct() without extra matrix-vector
    /// products.
    double
    kinetic_energy() const override
    {
      return kinetic;
    }
    double
    strain_energy() const override
    {
      return strain;
    }

    /**
     * Material/Plasticity = J2: the plate's plastic state, which the step
     * iterates on (initial stiffness: the elastic factorization and
     * compliance serve every iteration) until the plastic force changes by
     * less than `tolerance` times the largest nodal force (contact or
     * plastic).  The stepper keeps the reference.  Only the implicit
     * scheme iterates.
     */
    virtual void
    set_plasticity(PlasticPlate &plasticity, const double tolerance)
    {
      (void)plasticity;
      (void)tolerance;
      AssertThrow(false,
                  ExcMessage("Material/Plasticity = J2 needs Time "
                             "integration/Scheme = implicit."));
    }

    /// The plastic work done on the plate so far (J, the part modelled).
    virtual double
    plastic_work() const
    {
      return 0.;
    }

    /// The largest equivalent plastic strain so far (0 if elastic).
    virtual double
    max_plastic_strain() const
    {
      return 0.;
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

    /// The layout of save()'s checkpoint section.
    static constexpr std::uint32_t checkpoint_version = 1;

    /// The state after a time step, for a checkpoint: u, v, the energies
    /// and what the scheme carries (a; M u, M v, M a).  The factorization
    /// is not stored.
    virtual void
    save(CheckpointWriter &out) const;

    /// Restore save()'s state after initialize() and after a grown contact
    /// set was handed over (ContactCoupler::load()).  Collective.
    virtual void
    load(CheckpointReader &in);

    /// The linear solver's memory report (may be empty), for the log.
    virtual std::string
    solver_log() const
    {
      return "";
    }

  protected:
    /// The state every scheme keeps and correct() updates.
    TrilinosWrappers::MPI::Vector u, v, a;
    double                        kinetic = 0, strain = 0;
    unsigned int                  last_linear_iterations = 0;
    Costs                         measured_costs;
  };



  /// The implicit scheme (source/time/implicit_newmark_stepper.cc): Newmark
  /// with the contact's Newton block-eliminated.
  std::unique_ptr<TimeStepper>
  create_implicit_newmark_stepper(
    const TimeStepper::Parameters           &parameters,
    const EffectiveMatrixSolver::Parameters &solver,
    const PlateModel                        &plate,
    const ContactModel                      &contact);

  /// The explicit scheme (source/time/central_difference_stepper.cc);
  /// contact_stiffness (N/m) bounds the contact's stiffening of the
  /// contact DoFs (ContactModel::stiffness_bound()).
  std::unique_ptr<TimeStepper>
  create_central_difference_stepper(
    const TimeStepper::Parameters              &parameters,
    const PlateModel                           &plate,
    const std::vector<types::global_dof_index> &contact_dofs,
    const double                                contact_stiffness);

  /**
   * The factory: the scheme named in the parameters, for the contact's
   * DoFs (and massless DoFs, and for the explicit stability limit its
   * stiffness during an impact of a ball of mass impactor_mass, kg, the
   * part's share, at impact_velocity, m/s).  The stepper keeps no
   * reference to the contact model.
   */
  std::unique_ptr<TimeStepper>
  create_time_stepper(const TimeStepper::Parameters           &parameters,
                      const EffectiveMatrixSolver::Parameters &solver,
                      const PlateModel                        &plate,
                      const ContactModel                      &contact,
                      const double                             impactor_mass,
                      const double                             impact_velocity);
} // namespace fgimpact

#endif
