// Snapshots between time steps: see snapshot_interpolation.h.

#include <fgimpact/output/snapshot_interpolation.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  void
  SnapshotInterpolator::push(const StepRecord &record)
  {
    Assert(record.fields, ExcInternalError());
    // The oldest frame's vectors are reused for the new one.
    std::rotate(frames.begin(), frames.begin() + 1, frames.end());
    State &s         = frames.back();
    s.t              = record.t;
    s.u              = record.fields->displacement();
    s.v              = record.fields->velocity();
    s.a              = record.fields->acceleration();
    s.ball           = *record.sample->ball;
    s.contact.force  = record.sample->contact->force;
    s.contact.forces = record.sample->contact->forces;
    n_frames         = std::min(n_frames + 1, 3u);
  }



  double
  SnapshotInterpolator::first_time() const
  {
    return n_frames >= 1 ? frames[3 - n_frames].t : 1.;
  }



  double
  SnapshotInterpolator::last_time() const
  {
    return n_frames >= 1 ? frames[2].t : 0.;
  }



  void
  SnapshotInterpolator::interpolate(const double t, State &state) const
  {
    AssertThrow(n_frames >= 1 && t >= first_time() && t <= last_time(),
                ExcInternalError());
    // One step recorded (the initial state): t is its time.
    if (n_frames == 1)
      {
        state = frames[2];
        return;
      }
    // The step [t_j, t_{j+1}] holding t, and Hermite's basis on it.
    const unsigned int j  = (n_frames == 3 && t <= frames[1].t) ? 0 : 1;
    const State       &p0 = frames[j], &p1 = frames[j + 1];
    const double       h = p1.t - p0.t, s = (t - p0.t) / h;
    const double h00 = (2 * s - 3) * s * s + 1, h10 = ((s - 2) * s + 1) * s,
                 h01 = (3 - 2 * s) * s * s, h11 = (s - 1) * s * s;
    const auto hermite = [&](auto       &x,
                             const auto &x0,
                             const auto &dx0,
                             const auto &x1,
                             const auto &dx1) {
      x = x0;
      x *= h00;
      x.add(h10 * h, dx0, h01, x1);
      x.add(h11 * h, dx1);
    };
    state.t = t;
    hermite(state.u, p0.u, p0.v, p1.u, p1.v);
    hermite(state.v, p0.v, p0.a, p1.v, p1.a);
    state.a = p0.a;
    state.a.sadd(1. - s, s, p1.a);
    state.ball.w = h00 * p0.ball.w + h10 * h * p0.ball.v + h01 * p1.ball.w +
                   h11 * h * p1.ball.v;
    state.ball.v = h00 * p0.ball.v + h10 * h * p0.ball.a + h01 * p1.ball.v +
                   h11 * h * p1.ball.a;
    state.ball.a = (1. - s) * p0.ball.a + s * p1.ball.a;
    interpolate_contact(t, state);
  }



  void
  SnapshotInterpolator::interpolate_contact(const double t, State &state) const
  {
    // Lagrange's parabola through the three steps (a line through two).
    const unsigned int first = 3 - n_frames;
    double             l[3]  = {0., 0., 0.};
    for (unsigned int k = first; k < 3; ++k)
      {
        l[k] = 1.;
        for (unsigned int m = first; m < 3; ++m)
          if (m != k)
            l[k] *= (t - frames[m].t) / (frames[k].t - frames[m].t);
      }
    state.contact.force = 0;
    for (unsigned int k = first; k < 3; ++k)
      state.contact.force += l[k] * frames[k].contact.force;
    // The candidate set may have grown: the newest step's length.
    const std::size_t n = frames[2].contact.forces.size();
    state.contact.forces.assign(n, 0.);
    for (unsigned int k = first; k < 3; ++k)
      for (std::size_t i = 0; i < std::min(n, frames[k].contact.forces.size());
           ++i)
        state.contact.forces[i] += l[k] * frames[k].contact.forces[i];
    // A node that is free at the peak has no tensile force.
    for (double &f : state.contact.forces)
      f = std::max(f, 0.);
  }



  void
  SnapshotInterpolator::save(CheckpointWriter &out) const
  {
    out.put(n_frames);
    for (unsigned int k = 3 - n_frames; k < 3; ++k)
      {
        const State &s = frames[k];
        out.put(s.t);
        out.put(s.u);
        out.put(s.v);
        out.put(s.a);
        for (const double value :
             {s.ball.w, s.ball.v, s.ball.a, s.contact.force})
          out.put(value);
        out.put(s.contact.forces);
      }
  }



  void
  SnapshotInterpolator::load(CheckpointReader &in)
  {
    in.get(n_frames);
    for (unsigned int k = 3 - n_frames; k < 3; ++k)
      {
        State &s = frames[k];
        for (auto *vector : {&s.u, &s.v, &s.a})
          plate.initialize_vector(*vector);
        in.get(s.t);
        in.get(s.u);
        in.get(s.v);
        in.get(s.a);
        for (double *value :
             {&s.ball.w, &s.ball.v, &s.ball.a, &s.contact.force})
          in.get(*value);
        in.get(s.contact.forces);
      }
  }
} // namespace fgimpact
