#ifndef fgimpact_stress_recovery_h
#define fgimpact_stress_recovery_h

#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>

#include <array>
#include <map>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  class CheckpointReader;
  class CheckpointWriter;

  /**
   * (row, column) of the six independent stress or strain components in
   * the order of the VTU fields and probes.csv: xx, yy, zz, xy, xz, yz.
   */
  inline constexpr unsigned int stress_component[6][2] =
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {0, 2}, {1, 2}};

  /**
   * Whether the stress or strain component s (order xx, yy, zz, xy, xz,
   * yz) changes sign under the reflections across the cut planes in
   * `planes` (bit d: the plane normal to axis d): exactly one of its
   * indices is such a d.  On a cut plane such a component of a nodal
   * average is zero, as the whole plate's average of both sides gives.
   */
  bool
  odd_under_reflection(const unsigned int s, const unsigned int planes);

  /**
   * The scalar DoFs (of the locally owned and ghost cells) on the cut
   * planes of Geometry/Symmetry, each with its bit mask of planes (bit 0:
   * x = a/2, bit 1: y = b/2); empty for a whole plate.
   */
  std::map<types::global_dof_index, unsigned int>
  dofs_on_cut_planes(const PlateGeometry &geometry,
                     const DoFHandler<3> &scalar_dofs);



  /**
   * Continuous (recovered) stress and strain by nodal averaging: at every
   * support point of the scalar element FE_Q(p) (the mesh vertices for
   * p = 1), the average over the cells meeting there of each cell's strain
   * and stress evaluated at that point.  E comes from the same
   * PropertyInterpolator and the stress from the same HookeLaw as in the
   * assembly and PointProbe, so at a vertex the recovered stress is the
   * probe's value (the probe also averages over the adjacent cells).
   *
   * The fields live on a scalar DoFHandler on the plate's mesh (ghosted,
   * ready for DataOut).  Field order: the stress components xx, yy, zz, xy,
   * xz, yz (MPa), von Mises (MPa), the principal stresses
   * sigma_1 >= sigma_2 >= sigma_3 (MPa), the strain components xx, yy, zz,
   * xy, xz, yz (tensor components, dimensionless), and the peak over the
   * recover() calls so far of von Mises and of |sigma_zz| (MPa).
   *
   * On a symmetric part (Geometry/Symmetry) the cut planes are inner
   * planes of the whole plate: there the shear components that change sign
   * under the reflection (xy, xz on x = a/2; xy, yz on y = b/2) are zero,
   * as the whole plate's average over both sides gives.
   *
   * recover() is collective under MPI.
   */
  class StressRecovery
  {
  public:
    enum Field : unsigned int
    {
      stress_xx,
      stress_yy,
      stress_zz,
      stress_xy,
      stress_xz,
      stress_yz,
      von_mises,
      principal_1,
      principal_2,
      principal_3,
      strain_xx,
      strain_yy,
      strain_zz,
      strain_xy,
      strain_xz,
      strain_yz,
      peak_von_mises,
      peak_abs_stress_zz,
      n_fields
    };

    explicit StressRecovery(const PlateModel &plate);

    /// A plastic run (Material/Plasticity = J2): every recovered stress
    /// is C (eps - eps_p), with each cell's plastic strain at its support
    /// points (PlasticPlate::plastic_state()), and the nodal averages of
    /// the equivalent plastic strain and of the current yield stress are
    /// recovered too (plastic_fields()).  The strain fields stay the total
    /// strain.
    void
    set_plasticity(const PlasticPlate &plasticity);

    /// A thermal run: every recovered stress is the total,
    /// C (eps + eps0) with the initial state's eps0; the strain fields
    /// stay the strain of the analysis's displacement.
    void
    set_prestress(const InitialStress &initial_stress)
    {
      initial = &initial_stress;
    }

    /// Whether set_plasticity() was called.
    bool
    plastic() const
    {
      return plasticity != nullptr;
    }

    /// A plastic run's recovered equivalent plastic strain (continuous,
    /// for ParaView's Contour) and current yield stress Y(z) + H(z)
    /// eps_bar (MPa; 0 in the ceramic-rich, elastic part), ghosted.
    const std::array<TrilinosWrappers::MPI::Vector, 2> &
    plastic_fields() const
    {
      return plastic_ghosted;
    }

    /// Recover all fields from the ghosted displacement u (m) and update
    /// the peak fields.
    void
    recover(const TrilinosWrappers::MPI::Vector &u_ghosted);

    /// The scalar DoFHandler the fields live on.
    const DoFHandler<3> &
    get_dof_handler() const
    {
      return dof_handler;
    }

    /// A field (ghosted), in the units above.
    const TrilinosWrappers::MPI::Vector &
    field(const Field f) const
    {
      return ghosted[f];
    }

    /// The name of a field as written to VTU (unit in the name).
    static std::string
    name(const Field f);

    /// The recovered stress tensor (Pa) at a locally relevant scalar DoF.
    SymmetricTensor<2, 3>
    stress(const types::global_dof_index dof) const;

    /**
     * For a checkpoint: the number of recoveries so far and this rank's
     * owned values of the peak fields (MPa), so that a resumed run's
     * peak_fields hold the maxima over the whole run, not only over the
     * snapshots after the resume.
     */
    void
    save_peaks(CheckpointWriter &out) const;

    /// On resume: what save_peaks() wrote (same partition: a checkpoint is
    /// resumed on as many ranks as wrote it).
    void
    load_peaks(CheckpointReader &in);

  private:
    /// sums: every locally owned cell's stress (MPa) and strain at its
    /// scalar support points, added per scalar DoF (then compressed).
    void
    accumulate_cell_values(const TrilinosWrappers::MPI::Vector &u_ghosted);

    /// One cell's values at scalar DoF `dof` into sums: sigma (Pa, summed
    /// in MPa), eps, and with plasticity the equivalent plastic strain.
    void
    add_to_sums(const types::global_dof_index dof,
                const SymmetricTensor<2, 3>  &sigma,
                const SymmetricTensor<2, 3>  &eps,
                const double                  eps_bar);

    /// A plastic run's stress at a cell's unit point (at height z, m)
    /// from the total strain eps: C (eps - eps_p) (E in Pa), returned onto
    /// the yield surface of the point's current yield stress where the
    /// extrapolation overshoots it (J2Plasticity::admissible_stress());
    /// adds the point's eps_bar to eps_bar_sum.
    SymmetricTensor<2, 3>
    carried_stress(const DoFHandler<3>::active_cell_iterator &cell,
                   const Point<3>                            &unit_point,
                   const double                               z,
                   const double                               E,
                   const double                               nu,
                   const SymmetricTensor<2, 3>               &eps,
                   double &eps_bar_sum) const;

    /// The owned fields from the sums: averages (odd components zero on a
    /// cut plane), von Mises, principal stresses and the peaks.
    void
    average_and_derive();

    const PlateModel    &plate;
    const PlasticPlate  *plasticity = nullptr;
    const InitialStress *initial    = nullptr;
    DoFHandler<3>        dof_handler;
    IndexSet             owned, relevant;
    /// 1 / (number of cells sharing each owned scalar DoF).
    TrilinosWrappers::MPI::Vector inverse_count;
    /// Per-cell sums (writable ghosts), 6 stress + 6 strain components.
    std::array<TrilinosWrappers::MPI::Vector, 12> sums;
    /// A plastic run: the sums of eps_bar, and the owned and ghosted
    /// plastic fields.
    TrilinosWrappers::MPI::Vector                plastic_sum;
    std::array<TrilinosWrappers::MPI::Vector, 2> plastic_owned, plastic_ghosted;
    /// The height (m) of each owned scalar DoF, in the order of `owned`.
    std::vector<double>                                 support_z;
    std::array<TrilinosWrappers::MPI::Vector, n_fields> owned_values;
    std::array<TrilinosWrappers::MPI::Vector, n_fields> ghosted;
    unsigned int                                        n_recovered = 0;
    /// dofs_on_cut_planes() of the scalar DoFHandler.
    std::map<types::global_dof_index, unsigned int> cut_planes;
    /// The scalar field's hanging-node constraints: a hanging node's
    /// recovered value is its parents' interpolation (a conforming field).
    AffineConstraints<double> hanging;
  };

  /// The hanging-node constraints of a scalar DoFHandler on the plate's
  /// mesh (empty without local refinement), closed, on the locally
  /// relevant DoFs.
  AffineConstraints<double>
  scalar_hanging_constraints(const DoFHandler<3> &dof_handler);
} // namespace fgimpact

#endif
