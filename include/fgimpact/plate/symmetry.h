#ifndef fgimpact_symmetry_h
#define fgimpact_symmetry_h

#include <fgimpact/app/parameters.h>

#include <string>

namespace fgimpact
{
  /**
   * Decide Geometry/Symmetry for the whole scene: set
   * parameters.geometry.cut (the planes x = a/2, y = b/2 the model is cut
   * at) and return a line for the log ("" if nothing to say).  A plane is
   * a symmetry plane of the scene if the impact (or static load) point
   * lies on it, the supports of the two faces parallel to it are equal and
   * the subdivisions across it are even (so the cut runs along element
   * faces and the impact node lies on it); the material varies through the
   * thickness only.  A modal problem is never cut (its modes of the other
   * symmetry classes would be missing), nor an explicit run with the
   * automatic step (a part's stable step sees its symmetric modes only;
   * at a given step its history is the whole plate's).  auto takes
   * every symmetry plane, half the first of x and y that is one, quarter both;
   * half and quarter throw ExcMessage naming what breaks the symmetry.
   */
  std::string
  resolve_symmetry(Parameters &parameters);
} // namespace fgimpact

#endif
