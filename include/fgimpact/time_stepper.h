#ifndef fgimpact_time_stepper_h
#define fgimpact_time_stepper_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/contact_law.h>
#include <fgimpact/linear_solver.h>
#include <fgimpact/newmark.h>
#include <fgimpact/plate_model.h>

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

  /// Indentation alpha (m), contact force F (N) and the plate's z
  /// displacement at the contact node (m, positive up) at the current time,
  /// known on every MPI rank.
  struct ContactState
  {
    double       alpha             = 0;
    double       force             = 0;
    double       node_displacement = 0;
    unsigned int newton_iterations = 0;
  };

  /**
   * Advances the plate and the impactor by one time step, coupled through
   * the Hertz force at the contact node.  Two schemes (a selection plus the
   * factory create_time_stepper()):
   *
   * - implicit: Newmark (beta, gamma) with the block-eliminated contact
   *   Newton, one solve with the constant effective matrix per step;
   * - explicit: central difference (Newmark beta = 0, gamma = 1/2) with a
   *   row-sum lumped mass, one matrix-vector product per step, at a time
   *   step below the stability limit 2/omega_max.
   */
  class TimeStepper
  {
  public:
    struct Parameters
    {
      bool         explicit_scheme       = false;
      double       safety_factor         = 0.9;
      double       newton_tolerance      = 1e-3;
      unsigned int newton_max_iterations = 50;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    virtual ~TimeStepper() = default;

    /// Build matrices/factorizations; fixes the time step.
    virtual void
    initialize() = 0;

    /// The time step in use (s).
    virtual double
    time_step() const = 0;

    /// Advance from t_n to t_{n+1} = t (s); `step` and t only label errors.
    virtual void
    advance(const unsigned int step,
            const double       t,
            ImpactorState     &impactor,
            ContactState      &contact) = 0;

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

    /// Name of the scheme and linear solver, for the log.
    virtual std::string
    description() const = 0;

    /// Costs measured in initialize() for the benchmark (s): one
    /// matrix-vector product with the matrix of the step, and one solve
    /// (0 for the explicit scheme).
    double spmv_time          = 0;
    double solve_time         = 0;
    double factorization_time = 0;

  protected:
    /// The state every scheme keeps and advance() updates.
    TrilinosWrappers::MPI::Vector u, v;
    double                        kinetic = 0, strain = 0;
  };



  /// The factory: the scheme named in the parameters.
  std::unique_ptr<TimeStepper>
  create_time_stepper(const TimeStepper::Parameters           &parameters,
                      const NewmarkIntegrator::Parameters     &newmark,
                      const EffectiveMatrixSolver::Parameters &solver,
                      const PlateModel                        &plate,
                      const HertzContactLaw                   &contact_law,
                      const types::global_dof_index            contact_dof,
                      const double                             impactor_mass,
                      const double                             impact_velocity);
} // namespace fgimpact

#endif
