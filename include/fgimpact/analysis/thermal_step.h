#ifndef fgimpact_thermal_step_h
#define fgimpact_thermal_step_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/analysis/thermal_buckling.h>
#include <fgimpact/material/thermal.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plate_model.h>

#include <memory>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The static thermal step (Abaqus' thermal pre-step): K u = f_th with
   * the thermal load of the temperature field (assemble_thermal_load()),
   * on the plate's own supports; rigid-body motions they leave free (a
   * free plate) are pinned where the self-equilibrated load puts no force
   * (rigid_motion_pins()).  The stress is C (eps(u) - alpha (T - T_ref) I).
   * In linear elasticity the analyses that follow add their response to
   * this state (superposition); the summary gives the state's stress at
   * the centres of the top and bottom faces.
   */
  class ThermalStep
  {
  public:
    ThermalStep(const ThermalParameters                 &parameters,
                const PlateModel                        &plate,
                const EffectiveMatrixSolver::Parameters &solver);

    /// Assemble, solve, evaluate the face centres' stress; with
    /// Thermal/Geometric stiffness the initial-stress stiffness and the
    /// buckling factor (refused at or below 1). Collective.
    void
    run();

    /// K_sigma of the thermal pre-stress (Geometric stiffness; run()).
    const TrilinosWrappers::SparseMatrix &
    geometric_stiffness() const
    {
      return K_sigma;
    }

    /// The multiple of T - T_ref at which the plate buckles (+inf: never;
    /// NaN without Geometric stiffness).
    double
    buckling_factor() const
    {
      return buckling.factor;
    }

    /// The largest |T - T_ref| over the thickness (K): the change the
    /// buckling factor multiplies into the buckling temperature change.
    double
    largest_change() const;

    /// The thermal displacement (m), ghosted, constraints distributed.
    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return u;
    }

    /// The state the analyses start from (run()).
    const InitialStress &
    initial_stress() const
    {
      return *initial;
    }

    /// C (eps(u) - eps_th) (Pa) at a point. Collective.
    SymmetricTensor<2, 3>
    stress_at(const Point<3> &p) const;

    /// The stress (Pa) at the centres (a/2, b/2) of the top and bottom
    /// faces (run()).
    const SymmetricTensor<2, 3> &
    top_stress() const
    {
      return top;
    }
    const SymmetricTensor<2, 3> &
    bottom_stress() const
    {
      return bottom;
    }

    const TemperatureProfile &
    temperature() const
    {
      return profile;
    }

    /// Wall time of run() (s).
    double
    wall_time() const
    {
      return seconds;
    }

    /// summary.txt's thermal keys.
    SummaryWriter
    summary() const;

    /// The log's lines (with_time: the step's wall time, Output/Print
    /// timing).
    void
    print(ConditionalOStream &out, const bool with_time) const;

  private:
    /// The thermal displacement: K u = f_th with solver (K or K pinned).
    void
    solve_displacement(EffectiveMatrixSolver &solver);

    /// The buckling factor, refused at or below 1.
    void
    solve_buckling(const TrilinosWrappers::SparseMatrix &K,
                   EffectiveMatrixSolver                &solver);

    const PlateModel                       &plate;
    const TemperatureProfile                profile;
    const EffectiveMatrixSolver::Parameters solver_parameters;
    TrilinosWrappers::MPI::Vector           u;
    std::unique_ptr<InitialStress>          initial;
    SymmetricTensor<2, 3>                   top, bottom;
    TrilinosWrappers::SparseMatrix          K_sigma;
    BucklingResult                          buckling;
    unsigned int                            n_pins  = 0;
    double                                  seconds = 0;
  };
} // namespace fgimpact

#endif
