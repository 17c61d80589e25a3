#ifndef fgimpact_impact_study_engine_h
#define fgimpact_impact_study_engine_h

#include <deal.II/base/conditional_ostream.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/lapack_full_matrix.h>

#include <fgimpact/output/monitor.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/problem/scene.h>

#include <string>
#include <vector>

namespace fgimpact
{
  class TimeStepper;

  using namespace dealii;

  /**
   * The one-process engine of a parameter study: impact cases that share
   * the plate, its mesh and the time step and differ only in the impactor
   * (velocity, mass, density, radius, material), the Hertz law's constants
   * and Newton's control.
   *
   * With the Hertz node model and implicit Newmark the plate is linear,
   * time-invariant and starts at rest, and the ball touches it at one DoF.
   * prepare() computes once, with the time stepper's own matrices and
   * factorization, the plate's discrete response to a unit force at step 1
   * (TimeStepper::unit_response(): one pass of N solves): the contact DoF's
   * displacement g_j, every history.csv probe value and the Gram matrix
   * G_ij = v_i^T M v_j of the velocity responses.  A case is then the
   * scalar convolution u_c(n+1) = sum_k g_{n+2-k} F_k (the contact-free
   * displacement the stepper would have solved for), a PlateResponse that
   * the ContactCoupler of a normal run couples to the ball and the contact
   * model (same calls, same tolerances), so its history equals a separate
   * run's up to round-off; the probes are convolved the same way; the plate's
   * kinetic energy is 1/2 F^T G F, its strain energy the work of the
   * contact force (trapezoidal, exact for average acceleration) minus the
   * kinetic energy.  The case's history.csv and summary.txt are written by
   * an ImpactMonitor, as in a normal run (no VTU: it needs the fields).
   *
   * Memory: 2 N n_dofs doubles for the velocity responses and M times
   * them (the Gram matrix is one matrix product), N^2 for G; a case costs
   * about N^3/3 multiply-adds (the kinetic energy's quadratic form).
   */
  class ImpactStudyEngine
  {
  public:
    /// The plate (set up) and the clock of the whole study.
    ImpactStudyEngine(const PlateModel &plate, const Timer &total_timer);

    /**
     * Why these parameters cannot be run by convolution (one line), or ""
     * if they can: problem type impact, Hertz node contact, implicit
     * Newmark with beta = 1/4, gamma = 1/2 (the energy identity), no VTU
     * output, and the responses within memory_limit bytes per rank.
     */
    static std::string
    unsupported(const Parameters &parameters,
                const PlateModel &plate,
                const double      memory_limit = 2e9);

    /**
     * The unit response pass with the stepper built for `parameters` (the
     * group's first case); returns false (with the reason in
     * fallback_reason()) if the stepper cannot provide it (an iterative
     * solver).  Collective.
     */
    bool
    prepare(const Parameters &parameters);

    const std::string &
    fallback_reason() const
    {
      return reason;
    }

    /**
     * Run one case (whose parameters differ from prepare()'s only in the
     * entries listed above) and write its history.csv and summary.txt into
     * its Output/Directory, which must exist (summary.txt through
     * `summary`, which keeps its entries).  Throws ExcMessage if its
     * contact DoF is not the group's; a stop signal (SIGINT, SIGTERM, ...)
     * ends the case's files (status = interrupted) and throws
     * RunInterrupted, as does one during prepare().  Collective.
     */
    const ImpactResults &
    run_case(const Parameters &parameters, SummaryFile &summary);

    /// Receive every history row of the following cases (as
    /// ImpactMonitor::add_row_observer()).
    void
    add_row_observer(const ImpactMonitor::RowObserver &observer)
    {
      observers.push_back(observer);
    }

    /// What the cases share (s): the factorization (with the compliance
    /// solve), the unit response pass, the Gram matrix.
    std::string
    preparation_timing() const;

  private:
    /// A stop signal after steps_done steps of a case: its files finished
    /// (status = interrupted), then RunInterrupted on every rank.
    [[noreturn]] void
    stop_case(ImpactMonitor       &monitor,
              const ImpactorState &ball,
              const unsigned int   steps_done,
              const int            stop,
              const double         loop_time) const;

    /// A case's monitor, started: history.csv and summary.txt (no
    /// probes.csv: its probes need the fields), the validity checks that
    /// need no fields, the row observers.
    std::unique_ptr<ImpactMonitor>
    start_monitor(const Parameters   &p,
                  const Scene        &scene,
                  const ContactModel &contact,
                  SummaryFile        &summary);

    /// prepare()'s pass of unit responses: the contact DoF's and the
    /// history probes' values per step, and the steps' local velocities
    /// (V) and M times them (MV), one column per step; false if the
    /// stepper has none (an iterative solver).  A signal stops it
    /// (RunInterrupted).
    bool
    record_unit_response(TimeStepper              &stepper,
                         LAPACKFullMatrix<double> &V,
                         LAPACKFullMatrix<double> &MV);

    /// The Gram matrix of the unit velocities, G_ij = v_i^T M v_j, summed
    /// over the ranks.
    void
    compute_gram(const LAPACKFullMatrix<double> &V,
                 const LAPACKFullMatrix<double> &MV);

    /// A case must share the group's contact node and number of steps
    /// (the unit responses are theirs): else refused in one line.
    void
    check_case(const Parameters &p, const ContactModel &contact) const;

    /// results for a new case: the plate's and the set-up's entries, the
    /// contact model's, the model description; the history's are the
    /// monitor's.
    void
    start_results(const Parameters   &p,
                  const Scene        &scene,
                  const ContactModel &contact);

    const PlateModel &plate;
    const Timer      &total_timer;
    /// Rank 0's standard output (the validity monitor's log lines).
    const ConditionalOStream pcout;
    std::string              reason;

    std::vector<types::global_dof_index> dofs;
    double                               dt = 0, compliance = 0;
    unsigned int                         n_steps            = 0;
    double                               factorization_time = 0;
    double                               prepare_time       = 0;
    double setup_time = 0, response_time = 0, gram_time = 0;

    /// Unit responses, index j - 1 for step j: contact DoF displacement
    /// (m, positive up) and the probes.
    std::vector<double>      contact_response;
    std::vector<PlateSample> probe_response;
    /// G_ij = v_i^T M v_j (J/N^2 times 2).
    FullMatrix<double> gram;

    ImpactResults                           results;
    std::vector<ImpactMonitor::RowObserver> observers;
  };
} // namespace fgimpact

#endif
