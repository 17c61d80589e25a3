#ifndef fgimpact_mirrored_data_out_h
#define fgimpact_mirrored_data_out_h

#include <deal.II/numerics/data_out.h>

#include <fgimpact/plate/geometry.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * DataOut that writes the whole plate when only a half or a quarter of
   * it is modelled (Geometry/Symmetry): after build_patches(), mirror()
   * appends the reflections of the part's patches across its cut planes
   * x = a/2 and y = b/2, so the VTU files (and the .pvtu record) hold the
   * whole plate as ParaView's Reflect filter would build it.  A reflection
   * across the plane normal to axis d maps x_d to 2 c_d - x_d, changes the
   * sign of a vector's component d, of the tensor components with exactly
   * one index d (e.g. sigma_xy and sigma_xz for d = x), and of the scalar
   * fields named like them ("sigma_xy_MPa", "strain_xz"); invariants (von
   * Mises, principal stresses, E, rho) keep theirs.  The points of a
   * reflected patch are reordered so that its cells keep a positive
   * orientation.  Without cut planes (or with mirror() not called) it is
   * DataOut<3>.
   */
  class MirroredDataOut : public DataOut<3>
  {
  public:
    explicit MirroredDataOut(const PlateGeometry &geometry);

    /// Append the reflections of the patches built by build_patches().
    void
    mirror();

    const std::vector<DataOutBase::Patch<3, 3>> &
    get_patches() const override;

    /**
     * The sign (+1 or -1) of each data set (scalar component, in the order
     * of get_dataset_names()) under the reflection across the plane normal
     * to axis d.
     */
    std::vector<float>
    reflection_signs(const unsigned int d) const;

    /// The data set names (one per scalar component), as written.
    std::vector<std::string>
    dataset_names() const
    {
      return get_dataset_names();
    }

  private:
    const PlateGeometry                  &geometry;
    std::vector<DataOutBase::Patch<3, 3>> whole;
    bool                                  mirrored = false;
  };
} // namespace fgimpact

#endif
