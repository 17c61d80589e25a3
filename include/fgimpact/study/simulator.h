#ifndef fgimpact_simulator_h
#define fgimpact_simulator_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/timer.h>

#include <fgimpact/analysis/impact_driver.h>
#include <fgimpact/material/material.h>
#include <fgimpact/material/thermal.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/geometry.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/refinement_indicator.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/problem/resources.h>
#include <fgimpact/problem/scene.h>

#include <memory>

namespace fgimpact
{
  using namespace dealii;

  class AdaptiveRun;
  class ConvergedRun;
  class ThermalStep;

  /**
   * The program: parameters -> plate model (geometry, material, mesh and
   * matrices, shared by all problem types) -> the driver of the problem
   * type (impact, static or modal), which writes the outputs.
   */
  class Simulator
  {
  public:
    Simulator(const Parameters &parameters, const MPI_Comm mpi_communicator);

    /**
     * Build the mesh, matrices and the driver (for an impact: the contact
     * and the time stepper), and check what can only be checked then (the
     * contact node, the explicit stability limit).  Writes no file, so a
     * failure here leaves no output behind; after a numerical failure of
     * valid input the caller writes the start files and
     * write_failed_summary().
     */
    void
    setup();

    /// Only the first part of setup(): geometry, material, mesh and
    /// matrices (for a study engine that drives the plate itself).
    const PlateModel &
    setup_plate();

    /// Run (calling setup() if not done) and write the outputs into the
    /// output directory, which must exist.
    void
    run();

    /// After a failure that left no summary.txt (set-up, or a
    /// static or modal run): summary.txt with status = failed, best effort
    /// (a failure to write it is swallowed: the first failure counts).
    void
    write_failed_summary(const std::string &status = "failed") const;

    /// The impact's results (Problem type = impact only).
    const ImpactResults &
    get_results() const;

    /// The memory and time estimated before the mesh was built (setup()).
    const ResourceEstimate &
    get_resource_estimate() const
    {
      return resource_estimate;
    }

    /// Receive every row of history.csv (its columns and units, before
    /// rounding) on every rank; impact only, before run().
    void
    add_history_observer(const ImpactMonitor::RowObserver &observer);

    /// Checkpoints of an impact run: the parameters' text to store in
    /// them, and whether to resume; before setup().
    void
    set_checkpointing(const CheckpointSettings &settings);

    /// Build the mesh with the cells of each adaptive cycle refined
    /// (PlateGeometry::refine_cells()), then the cells of `split`
    /// (PlateGeometry::split_cells()); before setup().
    void
    set_adaptive_mesh(const std::vector<std::vector<std::string>> &cycles,
                      const MeshSplit split = MeshSplit::none)
    {
      adaptive_mesh = cycles;
      mesh_split    = split;
    }

    /// An impact run accumulates the plate's RefinementIndicator; before
    /// setup().
    void
    record_refinement_indicator()
    {
      indicator_wanted = true;
    }

    /// After run() with record_refinement_indicator(): the indicator
    /// accumulated over the impact.
    const RefinementIndicator &
    refinement_indicator() const
    {
      return *indicator;
    }

    /// The plate's active cells (after setup()).
    unsigned int
    n_active_cells() const
    {
      return plate->n_active_cells();
    }

    /// summary.txt as last written (every rank; empty before).
    const SummaryFile &
    summary() const
    {
      return summary_file;
    }

    ~Simulator();

  private:
    /// The plate's material; named constituents bound to T(z)
    /// (source/study/simulator_thermal.cc).
    void
    make_material();

    /// Thermal/Temperature field: the thermal step, its log lines and
    /// summary keys, and with Geometric stiffness its K_sigma into K.
    void
    run_thermal_step();

    /// Graded elements with sampled nodal values: a log warning if they
    /// misread the profile by more than 25 % in an element layer (a
    /// boundary layer, n -> 0+), naming the entries that fix it.
    void
    warn_sampled_boundary_layer() const;

    const Parameters   parameters;
    const MPI_Comm     mpi_communicator;
    ConditionalOStream pcout;
    Timer              total_timer;
    ResourceEstimate   resource_estimate;

    std::unique_ptr<PlateGeometry>              geometry;
    std::unique_ptr<FunctionallyGradedMaterial> material;
    /// Named constituents: the material before it is bound to T(z), and
    /// T(z).
    std::unique_ptr<FunctionallyGradedMaterial> unbound_material;
    std::unique_ptr<TemperatureProfile>         temperature_profile;
    std::unique_ptr<Scene>                      scene;
    std::unique_ptr<PlateModel>                 plate;
    std::unique_ptr<ThermalStep>                thermal;
    std::unique_ptr<ProblemDriver>              driver;
    std::vector<ImpactMonitor::RowObserver>     observers;
    CheckpointSettings                          checkpoint_settings;
    /// Accuracy = converged: the sequence of runs that replaces the
    /// driver.
    std::unique_ptr<ConvergedRun> converged;
    /// Geometry/Adaptive refinement cycles > 0: the pilot runs and the
    /// final one, which replace the driver.
    std::unique_ptr<AdaptiveRun>          adaptive;
    std::vector<std::vector<std::string>> adaptive_mesh;
    MeshSplit                             mesh_split       = MeshSplit::none;
    bool                                  indicator_wanted = false;
    std::unique_ptr<RefinementIndicator>  indicator;
    mutable SummaryFile                   summary_file;
  };
} // namespace fgimpact

#endif
