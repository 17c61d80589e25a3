#ifndef fgimpact_snapshot_interpolation_h
#define fgimpact_snapshot_interpolation_h

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/output/postprocessor.h>
#include <fgimpact/plate/plate_model.h>

#include <array>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The state of an impact run between two time steps, for snapshots at
   * times that are not on the step grid (Output/Snapshot times, the peak
   * of the contact force).  It keeps the last three recorded steps
   * (t_{k-1}, t_k, t_{k+1}: the plate's u, v, a, the ball and the contact)
   * and interpolates:
   * - u, v and the ball's w, w' by cubic Hermite interpolation on the step
   *   [t_j, t_{j+1}] holding the time (u from u and v at both ends, v from
   *   v and a; fourth-order accurate for a smooth motion), a linearly;
   * - the contact force and the nodal forces by the parabola through the
   *   three steps, the one through which the peak force is found (so the
   *   force at the peak's time is the reported peak force).
   */
  class SnapshotInterpolator
  {
  public:
    explicit SnapshotInterpolator(const PlateModel &plate)
      : plate(plate)
    {}

    /// What a snapshot shows at one time.
    struct State
    {
      double                        t = 0; // s
      TrilinosWrappers::MPI::Vector u, v, a;
      ImpactorState                 ball;
      ContactState                  contact; // force, forces only
    };

    /// Record the step of `record` (its fields with the rates).
    void
    push(const StepRecord &record);

    /// The times (s) that can be interpolated now: [t_{k-1}, t_{k+1}]
    /// (from the oldest step kept; an empty interval, t_first > t_last,
    /// before any step is recorded).
    double
    first_time() const;
    double
    last_time() const;

    /// The state at time t in [first_time(), last_time()].
    void
    interpolate(const double t, State &state) const;

    /// The recorded steps (for a checkpoint: the resumed run continues
    /// to interpolate across the checkpoint's step).
    void
    save(CheckpointWriter &out) const;
    void
    load(CheckpointReader &in);

  private:
    /// interpolate()'s contact forces: Lagrange's parabola through the
    /// three steps (a line through two), no tensile force at a node.
    void
    interpolate_contact(const double t, State &state) const;

    const PlateModel &plate;
    /// The last three steps, oldest first; n_frames of them valid.
    std::array<State, 3> frames;
    unsigned int         n_frames = 0;
  };
} // namespace fgimpact

#endif
