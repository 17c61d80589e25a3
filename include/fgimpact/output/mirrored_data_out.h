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

    /// All patches: the part's, then (after mirror()) the reflections.
    const std::vector<DataOutBase::Patch<3, 3>> &
    get_patches() const override;

    /**
     * The number of VTU pieces write_vtu_piece() writes: 1, or 2 after
     * mirror() (the patches up to and after the reflection across the
     * last cut plane, half of them each), so that two threads can write
     * the whole plate in the time of one half.
     */
    unsigned int
    n_pieces() const
    {
      return split ? 2 : 1;
    }

    /// The VTU flags of every piece (and of write_vtu()).
    void
    set_vtk_flags(const DataOutBase::VtkFlags &flags)
    {
      set_flags(flags);
      vtk = flags;
    }

    /// Write piece k < n_pieces() (a VTU file of its patches) to out.
    void
    write_vtu_piece(const unsigned int k, std::ostream &out) const;

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
    const PlateGeometry &geometry;
    /// After mirror(): the part and its reflections but the last (first),
    /// the reflection of those across the last cut plane (second), and
    /// both together, built on demand by get_patches().
    std::vector<DataOutBase::Patch<3, 3>>         first, second;
    mutable std::vector<DataOutBase::Patch<3, 3>> whole;
    bool                                          mirrored = false;
    /// Whether mirror() reflected across a cut plane (two pieces, the
    /// same on every rank, also on one without cells).
    bool                  split = false;
    DataOutBase::VtkFlags vtk;
  };
} // namespace fgimpact

#endif
