#ifndef fgimpact_adaptive_run_h
#define fgimpact_adaptive_run_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/results.h>
#include <fgimpact/problem/parameters.h>

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

  private:
    /// One run: its mesh's size and its results.
    struct Run
    {
      unsigned int  n_cells = 0, n_refined = 0;
      ImpactResults results;
      double        wall_time = 0; // s, set-up and run
    };

    /// The parameters of pilot cycle k (final: the user's outputs).
    Parameters
    parameters_of(const unsigned int cycle, const bool final) const;

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

    /// The keys appended to summary.txt, the log's line, adaptation.csv.
    void
    write_outputs() const;

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
    SummaryEntries                        summary_entries;
    bool                                  final_started = false;
  };
} // namespace fgimpact

#endif
