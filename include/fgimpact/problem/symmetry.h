#ifndef fgimpact_symmetry_h
#define fgimpact_symmetry_h

#include <fgimpact/plate/geometry.h>
#include <fgimpact/problem/parameters.h>

#include <array>
#include <string>

namespace fgimpact
{
  /// The part of the plate a run models (resolve_symmetry()).
  struct SymmetricPart
  {
    /// The symmetry planes cut: x = a/2 (0), y = b/2 (1).
    std::array<bool, 2> cut = {{false, false}};
    /// A line for the log ("" if nothing to say).
    std::string note;

    /// The part's share of the plate: 1, 1/2 or 1/4.
    double
    share() const
    {
      return part_share(cut);
    }
  };

  /**
   * Decide Geometry/Symmetry for the whole scene: the planes x = a/2,
   * y = b/2 the model is cut at, and a line for the log.  Parameters keep
   * only what the user wrote; this is derived from them when the plate is
   * built (and checked by Parameters::validate()).  A plane is
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
  SymmetricPart
  resolve_symmetry(const Parameters &parameters);
} // namespace fgimpact

#endif
