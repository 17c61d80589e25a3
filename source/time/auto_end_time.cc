#include <fgimpact/time/auto_end_time.h>

#include <cmath>
#include <cstdio>

namespace fgimpact
{
  void
  AutoEndTime::record(const double t, const double force)
  {
    if (force > 0)
      {
        if (first_contact < 0)
          first_contact = t;
        last_contact = t;
      }
  }



  bool
  AutoEndTime::left_for_good(const double                   t,
                             const double                   w,
                             const double                   v,
                             const double                   force,
                             const double                   plate_energy,
                             const std::function<double()> &compliance)
  {
    record(t, force);
    // In contact, not yet touched, or approaching (the contact will recur).
    if (force > 0 || first_contact < 0 || v >= 0)
      return false;
    if (t - last_contact < wait_fraction * (last_contact - first_contact))
      return false;
    if (C == 0)
      C = compliance();
    rise     = std::sqrt(2. * std::max(plate_energy, 0.) * C);
    distance = -w;
    if (distance < margin * rise)
      return false;
    stop_time = t;
    return true;
  }



  std::string
  AutoEndTime::reason() const
  {
    char text[400];
    std::snprintf(text,
                  sizeof(text),
                  "End time = auto: stopped at t = %.3f us; the last contact "
                  "ended at %.3f us and the ball has risen %.4f um, more than "
                  "%.1f times the largest rise of the plate under it, "
                  "sqrt(2 E C) = %.4f um (static compliance C = %.4g m/N).",
                  stop_time * 1e6,
                  last_contact * 1e6,
                  distance * 1e6,
                  margin,
                  rise * 1e6,
                  C);
    return text;
  }



  void
  AutoEndTime::save(CheckpointWriter &out) const
  {
    out.put(first_contact);
    out.put(last_contact);
    out.put(C);
  }



  void
  AutoEndTime::load(CheckpointReader &in)
  {
    in.get(first_contact);
    in.get(last_contact);
    in.get(C);
  }
} // namespace fgimpact
