#include <fgimpact/time/plate_fields.h>
#include <fgimpact/time/time_stepper.h>

namespace fgimpact
{
  PlateFields::PlateFields(const PlateModel &plate)
    : plate(plate)
  {
    plate.initialize_vector(u);
    plate.initialize_vector(v);
    plate.initialize_vector(a);
  }



  void
  PlateFields::update_displacement(
    const TrilinosWrappers::MPI::Vector &condensed)
  {
    u = condensed;
    plate.get_constraints().distribute(u);
  }



  void
  PlateFields::update(const TimeStepper &stepper, const bool with_rates)
  {
    update_displacement(stepper.displacement());
    lumped = stepper.has_lumped_mass();
    if (!with_rates)
      return;
    // Rates of the constraints: they are linear and homogeneous (hanging
    // nodes, supports, cut planes), so v and a are distributed alike.
    v = stepper.velocity();
    plate.get_constraints().distribute(v);
    a = stepper.acceleration();
    plate.get_constraints().distribute(a);
  }
} // namespace fgimpact
