#ifndef fgimpact_rigid_modes_h
#define fgimpact_rigid_modes_h

#include <deal.II/base/types.h>

#include <fgimpact/plate/plate_model.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The DoFs to pin so that K u = f has one solution when the plate's
   * constraints (supports, symmetry cuts, hanging nodes) leave rigid-body
   * motions free, as a free plate does: the free motions t + w x (x - c)
   * are the null space of the constraints' residuals (a 6 x 6 Gram
   * matrix summed over the ranks), and one component at a corner of the
   * modelled part is chosen per free motion, each removing one motion the
   * earlier ones left (Gram-Schmidt).  A load with zero resultant force
   * and moment (a thermal load) puts no force on such pins, so any spring
   * there gives the same deformation.  Collective; the same on every
   * rank; empty if no motion is free.
   */
  std::vector<types::global_dof_index>
  rigid_motion_pins(const PlateModel &plate);
} // namespace fgimpact

#endif
