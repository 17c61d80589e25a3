#ifndef fgimpact_parameter_checks_h
#define fgimpact_parameter_checks_h

#include <fgimpact/problem/parameters.h>

namespace fgimpact
{
  /// Material/Plasticity = J2 where it is modelled: an impact with the
  /// resolved contact (a point force has no converged stress under it) and
  /// the implicit scheme, or a static sphere load; a yield strength.
  void
  check_plasticity(const Parameters &p);

  /// Geometry/Adaptive refinement cycles > 0: an impact with the resolved
  /// sphere, without Accuracy = converged.
  void
  check_adaptive_mesh(const Parameters &p);

  /// Accuracy = converged refines the contact: it needs an impact whose
  /// contact converges under refinement, and the implicit scheme.
  void
  check_converged_accuracy(const Parameters &p);

  /// An impact with Contact/Model = resolved sphere needs Finite
  /// element/Degree = 1: on quadratic faces its peak force does not
  /// converge under contact refinement.
  void
  check_resolved_contact_degree(const Parameters &p);

  /// Finite element/Incompatible modes = true: Degree 1, elastic, no
  /// B-bar, no thermal field.
  void
  check_incompatible_modes(const Parameters &p);

  /// Named constituents: their temperature laws physical (E > 0, k > 0,
  /// -1 < nu < 1/2) over the field's temperatures.
  void
  check_named_materials(const Parameters &p);
} // namespace fgimpact

#endif
