#ifndef fgimpact_plate_fields_h
#define fgimpact_plate_fields_h

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/plate_model.h>

namespace fgimpact
{
  using namespace dealii;

  class TimeStepper;

  /**
   * The plate's fields as a user sees them: displacement (m), velocity
   * (m/s) and acceleration (m/s^2) with every constraint applied.
   *
   * The time steppers work on condensed vectors (deal.II's
   * distribute_local_to_global): a hanging node's DoFs hold 0 there, not
   * the interpolation of its parent edge or face.  Energies and the
   * contact may read the condensed vectors (u^T K u is the same, the
   * contact candidates are unconstrained), but anything evaluated at a
   * point -- VTU snapshots, recovered and peak stresses, the history and
   * Output/Probe points probes, the support reaction -- must read these
   * copies, whatever the path (implicit, explicit, study, resume) and on
   * every rank (distribute() is collective).
   */
  class PlateFields
  {
  public:
    explicit PlateFields(const PlateModel &plate);

    /// Copy the stepper's displacement and distribute the constraints
    /// into it; with rates, its velocity and acceleration too.
    /// Collective.
    void
    update(const TimeStepper &stepper, const bool with_rates);

    /// The displacement only, from a condensed vector. Collective.
    void
    update_displacement(const TrilinosWrappers::MPI::Vector &condensed);

    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return u;
    }
    const TrilinosWrappers::MPI::Vector &
    velocity() const
    {
      return v;
    }
    const TrilinosWrappers::MPI::Vector &
    acceleration() const
    {
      return a;
    }

    /// Whether the stepper's mass matrix is lumped (the support reaction
    /// then carries no inertia).
    bool
    lumped_mass() const
    {
      return lumped;
    }

  private:
    const PlateModel             &plate;
    TrilinosWrappers::MPI::Vector u, v, a;
    bool                          lumped = false;
  };
} // namespace fgimpact

#endif
