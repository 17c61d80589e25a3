#ifndef fgimpact_converged_run_h
#define fgimpact_converged_run_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/mpi.h>

#include <fgimpact/output/monitor.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/results.h>
#include <fgimpact/problem/parameters.h>

#include <array>
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  class Simulator;

  /**
   * Accuracy = converged: the impact run repeated at increasing contact
   * refinement levels, base meshes and time steps until the sum of every
   * headline number's error estimates, one per discretization source, is
   * below Accuracy tolerance.
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
   *  2. The base mesh, at the finest level: Geometry/Subdivisions x and
   *     y doubled (into convergence/base_NXxNYxNZ_level_L), and doubled
   *     again while a number changes by the source's change tolerance or
   *     more (the finer mesh then becomes the base); then Subdivisions z
   *     the same way; then the contact levels again on that base, one
   *     more while a number changes by their change tolerance or more.
   *     The contact levels refine only near the ball: the plate's bending
   *     and its waves are resolved by the base mesh (default scene: the
   *     mid-plane deflection 2 % low on 40 x 20 x 4, which no contact
   *     level changes).
   *  3. The sum controlled (control_sum()): each source's change
   *     tolerance starts at Accuracy tolerance; while a number's estimates
   *     (below) add up to more than the tolerance, the source with the
   *     largest share of the worst number is refined once more (its change
   *     tolerance set to its chain's last change), and step 2 repeated
   *     (runs made before are taken, not repeated).
   *  4. The last level and base mesh before the last refinement of each
   *     chain at half the time step (then a quarter, ... while the time
   *     step's estimate is the largest share of a sum above the
   *     tolerance), with the user's outputs, into Output/Directory: the
   *     run whose files the user reads.
   *  5. convergence.csv (one row per run) and, appended to summary.txt,
   *     for each quantity its relative error estimate, the sum of one per
   *     source, each from that source's own refinement times
   *     safety_factor:
   *     - contact levels (on the final base), in plane, through the
   *       thickness: the final run is the coarser of its chain's last
   *       pair, so its error is bounded by their difference plus the
   *       finer one's error (coarser_error()), Richardson with the
   *       observed order p where the last three values are monotone with
   *       changes that shrink with p >= min_order (|d2| / (2^p - 1)),
   *       otherwise the last change |d2| (refinement_error()); with two
   *       values twice their difference (first order);
   *     - time step: |q(dt/2^k) - q(dt/2^(k-1))| / 3 (Richardson for the
   *       second-order Newmark rule).
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

    /// quantities_of() for the run of parameters p (the adaptive mesh's
    /// estimate uses them too).
    static std::vector<Quantity>
    quantities_of(const Parameters &p, const ImpactResults &r);

    /// A base mesh: Geometry/Subdivisions x and y times in_plane,
    /// Subdivisions z times thickness.
    struct BaseMesh
    {
      unsigned int in_plane = 1, thickness = 1;
    };

    /// One run of the sequence.
    struct Level
    {
      unsigned int  levels = 0;
      BaseMesh      base;
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

    /// Whether a final run (into Output/Directory) is under way or the
    /// last one made: it then writes summary.txt itself, also when it
    /// fails.
    bool
    final_run_started() const
    {
      return final_started;
    }

    /// The error (absolute) of the last of values at successive
    /// refinements (each halving the element size), and how it was made:
    /// Richardson with the observed order, or the last change.
    static std::pair<double, std::string>
    refinement_error(const std::vector<double> &values);

    /// The error (absolute) of the second-to-last of values at successive
    /// refinements: its difference from the last plus the last's error.
    static double
    coarser_error(const std::vector<double> &values);

    /// "0.123 %": a relative number as the log prints it.
    static std::string
    percent(const double relative);

    /// ",v1,v2,...": each quantity's value of r in its column's unit, 10
    /// significant digits (convergence.csv, adaptation.csv,
    /// adaptive_estimate.csv).
    static std::string
    csv_values(const std::vector<Quantity> &quantities, const ImpactResults &r);

    /// The least observed order Richardson extrapolates with.
    static constexpr double min_order = 0.5;

    /// Each source's estimate is its chain's error bound times this factor
    /// of safety, Roache's for a grid convergence index (GCI) from three or
    /// more grids (ASME V&V 20-2009): the bound assumes first order from
    /// two values, and the test scene of converged_accuracy (10 x 6 x 2,
    /// 3 %) converges at about first order from below it, its peak force
    /// 0.44 % and mid-plane deflection 2.7 % off the converged value
    /// (extrapolated from 40 x 24 x 8 and 80 x 48 x 16) against estimates
    /// of 0.37 % and 2.45 % without it.
    static constexpr double safety_factor = 1.25;

    /// The discretization sources of an error estimate.
    enum Source : unsigned int
    {
      contact_levels,
      in_plane,
      thickness,
      time_step,
      n_sources
    };

    /// A source's name in summary.txt (KEY_error_estimate_NAME) and in
    /// the log ("base_mesh_in_plane").
    static std::string
    source_name(const unsigned int source);

  private:
    /// The parameters of a level run (final: the user's outputs into
    /// Output/Directory at Time step / 2^time_halvings).
    Parameters
    parameters_of(const unsigned int levels,
                  const bool         final,
                  const BaseMesh    &base) const;

    /// "NXxNYxNZ": the subdivisions of a base mesh.
    std::string
    mesh_name(const BaseMesh &base) const;

    /// Set up and run level `levels` on `base` (not the final run).
    Level
    run_level(const unsigned int levels, const BaseMesh &base);

    /// Step 2, one direction: from `start`, the runs refined by `finer`
    /// (a base direction doubled, or one contact level more) until a
    /// refinement changes every steering number by less than
    /// `tolerance`; `start` first.  The final run is the second-to-last's.
    std::vector<Level>
    refine(const Level                        &start,
           const std::string                  &name,
           const std::function<void(Level &)> &finer,
           const double                        tolerance);

    /// Append `next` to `chain`: the run made before with its mesh and
    /// level, else a new one (checked to fit; `reached` names what was not
    /// reached, for the message); whether it was made before.
    bool
    take_or_run(std::vector<Level> &chain,
                const Level        &next,
                const std::string  &reached);

    /// run() without the translation of a signal's message: steps 1-5.
    void
    run_sequence();

    /// The estimates of a steering number that add up to the most, and
    /// their largest share.
    struct Worst
    {
      double       total = 0; // relative
      std::string  key;
      unsigned int source = contact_levels;
      double       part   = 0; // relative
    };

    /// Each source's estimate of q (relative), from the chains and, with
    /// `final_run`, its time step; without, the time step's estimate of
    /// the last final run made (0 before any).
    std::array<double, n_sources>
    parts_of(const Quantity &q, const Level *final_run) const;

    /// The steering number whose estimates add up to the most.
    Worst
    worst_sum(const Level *final_run) const;

    /// Step 3's one more refinement of worst.source: its chain's change
    /// tolerance set to the chain's last change, or, for the time step,
    /// the final run again at half its step.
    void
    refine_source(const Worst &worst, const Level *final_run);

    /// Step 1: the contact levels on the input's mesh.
    void
    run_input_levels();

    /// Step 2: the base mesh's chains, and the contact levels on it.
    void
    refine_base_mesh();

    /// Step 4: the final run (at Time step / 2^time_halvings).
    Level
    run_final();

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

    /// The refinements a chain's steering numbers still need to change by
    /// less than `tolerance`, from their last two changes and the observed
    /// order: the most of them.
    struct Needed
    {
      double      more = 0; // refinements
      std::string key;
      double      last = 0, p = 0; // the last relative change, the order
      /// "KEY changed by C WHERE with an observed order p = P, and the
      /// tolerance needs about N more refinements".
      std::string
      describe(const std::string &where) const;
    };
    Needed
    refinements_needed(const std::vector<Level> &chain,
                       const double              tolerance) const;

    /// After a base-mesh chain's run: stop with one line if a number's
    /// changes, extrapolated with their observed order, need more
    /// doublings than `room` (a factor) allows.
    void
    refuse_unreachable(const std::vector<Level> &chain,
                       const std::string        &name,
                       const unsigned int        room,
                       const double              tolerance) const;

    /// The largest relative change of a steering quantity from a to b.
    std::pair<double, std::string>
    largest_change(const ImpactResults &a, const ImpactResults &b) const;

    /// Stop with one line if level `levels` on `base` does not fit the
    /// memory; `reached`: what was not reached, for the message.
    void
    check_fits(const unsigned int levels,
               const BaseMesh    &base,
               const std::string &reached) const;

    /// The error estimates of each quantity into `out` and the log.
    void
    write_estimates(SummaryWriter &out, const Level &final_run) const;

    /// convergence.csv: every run, the final one last.
    void
    write_csv(const Level &final_run) const;

    void
    write_outputs(const Level &final_run);

    const Parameters                              parameters;
    const MPI_Comm                                communicator;
    SummaryFile                                  &summary;
    const std::vector<ImpactMonitor::RowObserver> observers;
    ConditionalOStream                            pcout;
    unsigned int                                  first_levels = 0;
    /// The contact refinement levels of the run under way.
    unsigned int               running_levels = 0;
    std::string                running_mesh;
    double                     first_setup_time = 0; // s
    std::unique_ptr<Simulator> first;
    std::vector<Level>         sequence;
    /// Steps 2 and 3: each direction's chain (its start first).
    std::vector<Level> in_plane_chain, thickness_chain, contact_chain;
    /// Every run of steps 2 and 3, in order (for convergence.csv).
    std::vector<Level> refinement_runs;
    /// Step 3: each spatial source's change tolerance (relative; a chain
    /// stops at its first change below it), Accuracy tolerance at first.
    std::array<double, time_step> change_tolerance = {};
    /// Step 4: the final run's time step is Time step / 2^time_halvings;
    /// the final runs before it, in order (on the same mesh and level at
    /// twice the step: the time step's reference).
    unsigned int       time_halvings = 1;
    std::vector<Level> time_chain;
    /// Each number's time-step estimate from the last final run: its
    /// share of the sum before the next final run is made.
    std::map<std::string, double> last_time_part;
    ImpactResults                 final_results;
    /// The final run's summary.txt, to which the estimates are appended.
    SummaryEntries summary_entries;
    bool           final_started = false;
  };
} // namespace fgimpact

#endif
