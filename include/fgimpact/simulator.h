#ifndef fgimpact_simulator_h
#define fgimpact_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <fgimpact/accuracy_preset.h>
#include <fgimpact/contact_law.h>
#include <fgimpact/geometry.h>
#include <fgimpact/impactor.h>
#include <fgimpact/linear_solver.h>
#include <fgimpact/material.h>
#include <fgimpact/modal_analysis.h>
#include <fgimpact/newmark.h>
#include <fgimpact/plate_model.h>
#include <fgimpact/probes.h>
#include <fgimpact/static_analysis.h>
#include <fgimpact/time_stepper.h>

#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The results of an impact run, in SI units, as written to summary.txt.
   */
  struct ImpactResults
  {
    double       peak_contact_force      = 0; // N, parabola through 3 samples
    double       max_sampled_force       = 0; // N, largest sample
    double       time_of_peak_force      = 0; // s
    double       contact_duration        = 0; // s, NaN if still in contact
    double       departure_velocity      = 0; // m/s, rebound positive
    double       max_indentation         = 0; // m
    double       max_midplane_deflection = 0; // m
    double       max_top_deflection      = 0; // m
    double       contact_stiffness       = 0; // N/m^1.5 (beta K_h)
    double       contact_modulus         = 0; // Pa
    double       impactor_mass           = 0; // kg
    double       plate_mass              = 0; // kg
    double       impulse                 = 0; // N s, int F dt
    double       contact_node_offset     = 0; // m, node to impact point
    unsigned int contact_node_owner      = 0; // MPI rank owning its DoF
    unsigned int n_mpi_ranks             = 1;
    double       max_energy_drift        = 0; // relative
    double       momentum_balance_error  = 0; // relative
    unsigned int n_impacts               = 0;
    unsigned int n_dofs                  = 0;
    unsigned int n_time_steps            = 0;
    unsigned int max_newton_iterations   = 0;
    double       setup_time              = 0; // s
    double       factorization_time      = 0; // s
    double       time_loop_time          = 0; // s
    double       output_time             = 0; // s
    double       spmv_time               = 0; // s, one K_eff vmult
    double       solve_time              = 0; // s, one solve with K_eff
    double       wall_time               = 0; // s
  };



  /**
   * The low-velocity impact of a rigid (or elastic) sphere on the FGM plate:
   * Newmark time stepping of the plate (Eq. 3.16) and of the impactor's
   * displacement w_p, coupled through the Hertz force at the contact node
   * (Eqs. 3.12-3.15).
   *
   * Each step solves the coupled Newton system by block elimination: the
   * plate is linear and its effective matrix constant, so with the
   * contact-free response u* (one solve) and the precomputed response c to
   * a unit contact force, u = u* - F c, and Newton iterates only on the
   * indentation alpha.  Because all equations are linear in the plate
   * unknowns, these are exactly the iterates of Newton on the monolithic
   * system (doc/theory.md).
   */
  class ImpactSimulator
  {
  public:
    struct Parameters
    {
      AccuracyPreset::Parameters             accuracy;
      PlateGeometry::Parameters              geometry;
      FunctionallyGradedMaterial::Parameters material;
      HertzContactLaw::Parameters            contact;
      Impactor::Parameters                   impactor;
      NewmarkIntegrator::Parameters          time_integration;
      PlateModel::Parameters                 finite_element;
      EffectiveMatrixSolver::Parameters      linear_solver;
      TimeStepper::Parameters                time_stepper;
      std::string                            problem_type = "impact";
      StaticAnalysis::Parameters             static_analysis;
      ModalAnalysis::Parameters              modal;

      std::string  output_directory = "output";
      unsigned int vtu_interval     = 0;
      unsigned int log_interval     = 50;
      bool         print_timing     = true;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);

      /// Check consistency between entries (one-line messages naming the
      /// parameter); throws ExcMessage.
      void
      validate() const;
    };

    ImpactSimulator(const Parameters &parameters,
                    const MPI_Comm    mpi_communicator);

    /**
     * Build the mesh, matrices and time stepper, and check what can only be
     * checked then (the contact node, the explicit stability limit).
     * Writes no file, so a failure here leaves no output behind.
     */
    void
    setup();

    /// Run the simulation (calling setup() if not done) and write
    /// history.csv, summary.txt and VTU files into the output directory,
    /// which must exist.
    void
    run();

    const ImpactResults &
    get_results() const
    {
      return results;
    }

    /// The rows of history.csv (same columns and units) before rounding,
    /// on every MPI rank.
    const std::vector<std::vector<double>> &
    get_history() const
    {
      return history_rows;
    }

  private:
    void
    run_impact();
    void
    run_static();
    void
    run_modal();
    void
    write_summary() const;

    const Parameters                 parameters;
    const MPI_Comm                   mpi_communicator;
    ConditionalOStream               pcout;
    ImpactResults                    results;
    std::vector<std::vector<double>> history_rows;
    Timer                            total_timer;

    std::unique_ptr<PlateGeometry>              geometry_ptr;
    std::unique_ptr<FunctionallyGradedMaterial> material_ptr;
    std::unique_ptr<Impactor>                   impactor_ptr;
    std::unique_ptr<HertzContactLaw>            contact_law_ptr;
    std::unique_ptr<PlateModel>                 plate_ptr;
    std::unique_ptr<TimeStepper>                stepper;
    std::unique_ptr<PointProbe>                 mid_probe, top_probe;
    types::global_dof_index                     contact_dof = 0;
    double                                      dt          = 0;
    unsigned int                                n_steps     = 0;
  };
} // namespace fgimpact

#endif
