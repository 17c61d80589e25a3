#ifndef fgimpact_adaptive_run_h
#define fgimpact_adaptive_run_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/results.h>
#include <fgimpact/problem/parameters.h>

#include <array>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Geometry/Adaptive refinement cycles = N > 0: the mesh refined where a
   * pilot run's error indicator is largest, N times, before the run whose
   * outputs the user reads.
   *
   *  1. Cycle k = 0 .. N-1: the impact on the input's mesh refined by the
   *     cycles before, into Output/Directory/convergence/adaptive_cycle_k
   *     (history.csv, probes.csv, summary.txt; no VTU, no checkpoints),
   *     accumulating RefinementIndicator over every step; the Adaptive
   *     refinement fraction of the cells with the largest time integral
   *     are refined for the next run (their CellIds: the mesh is rebuilt
   *     from the input's by the same refinements, on any number of ranks).
   *  2. The final run on the mesh of all N cycles, with the user's
   *     outputs, into Output/Directory.
   *  3. adaptation.csv (one row per run) and, appended to summary.txt,
   *     the cycles, the fraction and each headline number's relative
   *     change from the last pilot run to the final one
   *     (KEY_change_last_adaptive_cycle): how much the last refinement
   *     still moved it, not an error bound.
   *  4. With Adaptive refinement estimate, three check runs into
   *     Output/Directory/convergence/adaptive_check_NAME (no VTU), one per
   *     source of error, each the final run with that source refined
   *     once: contact_zone (the cells one more contact level would split,
   *     MeshSplit), rest_of_plate (every other cell), time_step (half the
   *     step).  Each source's relative estimate is two_grid_estimate() of
   *     the final run, the coarser of its pair, for every number of
   *     ConvergedRun::quantities_of() (the headline numbers, the probes'
   *     peak stresses); summary.txt gets their sum (KEY_error_estimate)
   *     and the parts (KEY_error_estimate_NAME), and
   *     adaptive_estimate.csv the runs.  One refinement of every cell at
   *     once would not do: on the default scene with the modes, the cells
   *     at the contact and those around it move the indentation by about
   *     the same amount with opposite signs (doc/performance.md, section
   *     31).
   */
  class AdaptiveRun
  {
  public:
    AdaptiveRun(const Parameters                              &parameters,
                const MPI_Comm                                 communicator,
                SummaryFile                                   &summary,
                const std::vector<ImpactMonitor::RowObserver> &observers);
    ~AdaptiveRun();

    /// The first pilot run's set-up: checks the input; writes nothing.
    void
    setup();

    /// The pilot runs, the final run, adaptation.csv and summary.txt.
    void
    run();

    /// The final run's results.
    const ImpactResults &
    results() const
    {
      return runs.back().results;
    }

    /// Whether the final run (into Output/Directory) has started: it then
    /// writes summary.txt itself, also when it fails.
    bool
    final_run_started() const
    {
      return final_started;
    }

    /// The sources of the estimate, one check run each.
    enum Check : unsigned int
    {
      contact_zone,
      rest_of_plate,
      time_step,
      n_checks
    };

    /// A check's name: its directory (adaptive_check_NAME) and summary key
    /// (KEY_error_estimate_NAME).
    static std::string
    check_name(const unsigned int check);

    /// Factor of safety of a grid convergence index from two grids
    /// (Roache; ASME V&V 20-2009): no observed order, so 3, not the 1.25
    /// of three or more grids.
    static constexpr double two_grid_safety_factor = 3.;

    /// The relative error of `coarse`, the coarser of two runs a
    /// refinement of ratio 2 apart, for an assumed order p: Roache's
    /// coarse-grid GCI, 3 |fine - coarse| 2^p / (2^p - 1) / |coarse|.  It
    /// holds while the observed order is above about 0.26 for p = 1.
    static double
    two_grid_estimate(const double coarse,
                      const double fine,
                      const double order);

  private:
    /// One run: its mesh's size, time step and results.
    struct Run
    {
      unsigned int  n_cells = 0, n_refined = 0;
      double        time_step = 0; // s
      ImpactResults results;
      double        wall_time = 0; // s, set-up and run
    };

    /// The parameters of a run into Output/Directory/convergence/`name`
    /// (no VTU, no checkpoints), or with name "" the final run's (the
    /// user's outputs, no checkpoints).
    Parameters
    parameters_of(const std::string &name) const;

    /// Refuse in one line (naming the adaptive entries) a mesh of
    /// `n_cells` cells that does not fit the memory: the input's
    /// ResourceEstimate scaled to that many cells (the factor as n^{4/3},
    /// nested dissection in 3D).  `what` names the mesh.
    void
    check_fits(const double n_cells, const std::string &what) const;

    /// Pilot cycle k: its run and the cells it refines (appended to
    /// `refined`).
    void
    run_pilot(const unsigned int cycle);

    void
    run_final();

    /// Step 4: the check runs, after the sequence's outputs are written.
    void
    run_checks();

    /// Step 4: one check run, into convergence/adaptive_check_NAME.
    Run
    run_check(const unsigned int check);

    /// Each headline number's estimate, one part per check (relative).
    std::vector<std::array<double, n_checks>>
    estimates() const;

    /// The estimates' keys in summary.txt and the log's line.
    void
    write_estimates(SummaryWriter &out) const;

    /// adaptive_estimate.csv: the final run and the checks.
    void
    write_checks_csv() const;

    /// The keys appended to summary.txt, the log's line, adaptation.csv
    /// (and the estimate once every check has run); a non-empty `status`
    /// replaces the final run's (a check failed or was interrupted).
    void
    write_outputs(const std::string &status = "") const;

    /// adaptation.csv: one row per run, the final run last.
    void
    write_csv() const;

    const Parameters                              parameters;
    const MPI_Comm                                communicator;
    SummaryFile                                  &summary;
    const std::vector<ImpactMonitor::RowObserver> observers;
    ConditionalOStream                            pcout;
    /// The first pilot run, set up by setup().
    std::unique_ptr<class Simulator> first;
    /// The cells each cycle refined (CellId strings), in order.
    std::vector<std::vector<std::string>> refined;
    std::vector<Run>                      runs;
    /// The check runs (step 4), in Check's order.
    std::vector<Run> checks;
    SummaryEntries   summary_entries;
    bool             final_started = false;
  };
} // namespace fgimpact

#endif
