#ifndef fgimpact_converged_run_h
#define fgimpact_converged_run_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <fgimpact/app/parameters.h>
#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/results.h>

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  class Simulator;

  /**
   * Accuracy = converged: the impact run repeated at increasing contact
   * refinement levels until its headline numbers settle, then checked
   * once in time, with an error estimate for each number.
   *
   *  1. Levels L0, L0 + 1, ... (L0 = one below the scene's automatic
   *     level: the automatic level is expected within about 1 %, and a
   *     change needs a coarser run before it), each a plain run at the
   *     given time step into Output/Directory/convergence/level_L
   *     (history.csv, probes.csv, summary.txt; no VTU, no checkpoints),
   *     until every quantity changes by less than Accuracy tolerance
   *     (relative) from the level before (the probes' peak stresses too,
   *     unless on the contact surface: quantities_of()).  A next level
   *     that does not fit the memory stops the run with one line naming
   *     the tolerance and the memory.
   *  2. The finest level at half the time step, with the user's outputs,
   *     into Output/Directory: the run whose files the user reads.
   *  3. convergence.csv (one row per run) and, appended to summary.txt,
   *     for each quantity its relative error estimate: from the levels,
   *     Richardson with the observed order p where the last three values
   *     are monotone with changes that shrink with p >= min_order
   *     (error |d2| / (2^p - 1)), otherwise the last change |d2|; plus
   *     the time step's, |q(dt/2) - q(dt)| / 3 (Richardson for the
   *     second-order Newmark rule); and which method gave it.
   */
  class ConvergedRun
  {
  public:
    /// One quantity whose convergence is checked: its summary.txt key
    /// (without the unit), column name with the unit, and scale to it;
    /// whether its change decides when the sequence stops.
    struct Quantity
    {
      std::string                                  key;
      std::string                                  column;
      double                                       scale;
      std::function<double(const ImpactResults &)> value;
      bool                                         steers = true;
    };

    /// The five headline numbers.
    static const std::vector<Quantity> &
    quantities();

    /// The headline numbers and each probe's peak von Mises stress of r.
    /// A probe on the top face within the contact (r's largest contact
    /// radius plus the element size under the ball) does not steer: the
    /// recovered stress there averages a field that jumps at the contact's
    /// edge (a point force's is singular), and converges far more slowly
    /// than the rest (default scene, levels 4-6: 13 %, 9 % per level).
    std::vector<Quantity>
    quantities_of(const ImpactResults &r) const;

    /// One run of the sequence.
    struct Level
    {
      unsigned int  levels    = 0;
      double        time_step = 0; // s
      ImpactResults results;
      double        wall_time = 0; // s, set-up and run
    };

    /// `summary`: the summary.txt of Output/Directory, which gets the
    /// estimates; `observers` watch the final run's history rows.
    ConvergedRun(const Parameters                              &parameters,
                 const MPI_Comm                                 communicator,
                 SummaryFile                                   &summary,
                 const std::vector<ImpactMonitor::RowObserver> &observers);
    ~ConvergedRun();

    /// The first level's set-up: checks the input; writes nothing.
    void
    setup();

    /// The sequence, the time step check, the final run, convergence.csv
    /// and the estimates in summary.txt.  A signal stops it with one line
    /// naming the level (RunInterrupted; the sequence is not resumable).
    void
    run();

    /// The final run's results.
    const ImpactResults &
    results() const;

    /// Whether the final run (into Output/Directory) has begun: it then
    /// writes summary.txt itself, also when it fails.
    bool
    final_run_started() const
    {
      return final_started;
    }

    /// The estimate of one quantity (relative) and how it was made, from
    /// the values at successive levels (same time step) and at half the
    /// time step on the finest level.
    static std::pair<double, std::string>
    estimate(const std::vector<double> &at_levels, const double at_half_step);

    /// The least observed order Richardson extrapolates with.
    static constexpr double min_order = 0.5;

  private:
    /// The parameters of a level run (final: the user's outputs into
    /// Output/Directory at half the time step).
    Parameters
    parameters_of(const unsigned int levels, const bool final) const;

    /// run() without the translation of a signal's message.
    void
    run_sequence();

    /// Run `simulator` (set up) with its directory prepared; its row.
    Level
    run_one(Simulator &simulator, const Parameters &p);

    /// After the first level: a steering quantity without a value (the
    /// ball still in contact at End time) is refused in one line naming
    /// End time (ExcNumericalFailure: exit code 2, summary.txt failed).
    void
    refuse_unfinished_contact() const;

    /// The largest relative change of a quantity between the last two
    /// levels, and its key.
    std::pair<double, std::string>
    largest_change() const;

    /// Stop with one line if level `levels` does not fit the memory.
    void
    check_fits(const unsigned int levels) const;

    void
    write_outputs(const Level &final_run);

    const Parameters                              parameters;
    const MPI_Comm                                communicator;
    SummaryFile                                  &summary;
    const std::vector<ImpactMonitor::RowObserver> observers;
    ConditionalOStream                            pcout;
    unsigned int                                  first_levels = 0;
    /// The contact refinement levels of the run under way.
    unsigned int               running_levels   = 0;
    double                     first_setup_time = 0; // s
    std::unique_ptr<Simulator> first;
    std::vector<Level>         sequence;
    ImpactResults              final_results;
    /// The final run's summary.txt, to which the estimates are appended.
    SummaryEntries summary_entries;
    bool           final_started = false;
  };
} // namespace fgimpact

#endif
