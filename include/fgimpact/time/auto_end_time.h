#ifndef fgimpact_auto_end_time_h
#define fgimpact_auto_end_time_h

#include <fgimpact/base/checkpoint.h>

#include <cstdint>
#include <functional>
#include <string>

namespace fgimpact
{
  /**
   * Time integration/End time = auto: whether the ball has left the plate
   * for good, so that the run may stop.  It knows nothing of finite
   * elements: after each step it sees the time, the ball's displacement w
   * and velocity v (m, m/s, positive down, w = 0 where the ball first
   * touches), the contact force (N) and the plate's energy E (J), and it
   * asks once for the plate's static compliance C (m/N) at the contact.
   *
   * The rule: after a step with no contact force in which the ball moves
   * away (v < 0), and at least wait_fraction of the contact's duration
   * after the last contact, the run stops when the ball's lowest point
   * has risen above its position at first touch by
   *
   *   -w >= margin sqrt(2 E C).
   *
   * Why the contact cannot recur then: the plate moves freely, so its
   * energy E = 1/2 u^T K u + 1/2 v^T M v stays (average acceleration
   * Newmark conserves it exactly; gamma > 1/2 and the explicit scheme's
   * step keep it within the margin), and a point of the plate can rise at
   * most |e^T u| <= sqrt(e^T K^-1 e) sqrt(u^T K u) <= sqrt(2 E C)
   * (Cauchy-Schwarz in the K inner product, C = e^T K^-1 e), while the
   * ball, free of force, keeps rising.  A resolved contact's other
   * candidates start farther away (the sphere curves up) and C is the
   * largest over a sample of them (ImpactDriver).
   *
   * Every input is the same on every MPI rank, so every rank decides
   * alike.  The state (the contact's first and last time, C) is part of
   * the checkpoint.
   */
  class AutoEndTime
  {
  public:
    /// The factor on sqrt(2 E C) and the wait after the last contact, as
    /// a fraction of the time from first to last contact.
    static constexpr double margin        = 1.2;
    static constexpr double wait_fraction = 0.25;

    /// Record a step that ended at t (s) with this contact force (N): the
    /// contact's first and last time (a run with a fixed End time records
    /// only this, so that End time can become auto on resume).
    void
    record(const double t, const double force);

    /// Record a step (as record()) that ended at t (s).  `compliance` (m/N) is
    /// called at most once, when the distance is first compared (collective in
    /// a parallel run: every rank reaches it at the same step).  Returns
    /// whether the run may stop after this step.
    bool
    left_for_good(const double                   t,
                  const double                   w,
                  const double                   v,
                  const double                   force,
                  const double                   plate_energy,
                  const std::function<double()> &compliance);

    /// For the log: when the ball left and why the contact cannot recur
    /// (after left_for_good() returned true).
    std::string
    reason() const;

    /// Whether left_for_good() has returned true.
    bool
    has_stopped() const
    {
      return stop_time > 0;
    }

    static constexpr std::uint32_t checkpoint_version = 1;

    void
    save(CheckpointWriter &out) const;
    void
    load(CheckpointReader &in);

  private:
    double first_contact = -1; // s, -1: no contact yet
    double last_contact  = -1; // s, the end of the last step with contact
    double C             = 0;  // m/N, 0: not yet computed
    double rise          = 0;  // m
    double distance      = 0;  // m, -w at the decision
    double stop_time     = 0;  // s
  };
} // namespace fgimpact

#endif
