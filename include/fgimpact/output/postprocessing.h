#ifndef fgimpact_postprocessing_h
#define fgimpact_postprocessing_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <deal.II/numerics/data_out.h>
#include <deal.II/numerics/data_postprocessor.h>

#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/stress_recovery.h>

#include <fstream>
#include <future>
#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  class MirroredDataOut;

  using namespace dealii;

  /**
   * Stress tensor (MPa), von Mises stress (MPa), E (GPa) and rho (kg/m^3)
   * from the displacement, for DataOut.  E and the stress come from the
   * same PropertyInterpolator and HookeLaw as the assembly and the probes.
   * This is the per-cell (discontinuous) stress; the continuous one is
   * StressRecovery's.  The tensor's components 0..8 are xx, xy, xz, yx,
   * yy, yz, zx, zy, zz (row by row).  With with_stress = false only E and
   * rho, with with_material = false only the stress and von Mises.
   */
  class StressPostprocessor : public DataPostprocessor<3>
  {
  public:
    explicit StressPostprocessor(const PlateModel &plate,
                                 const bool        with_stress   = true,
                                 const bool        with_material = true);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<3> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

    /// A plastic run: the stress is C (eps - eps_p).
    void
    set_plasticity(const PlasticPlate &plasticity)
    {
      plastic = &plasticity;
    }

    /// A thermal run: the stress is the total, C (eps + eps0) with the
    /// initial state's eps0 at each point.
    void
    set_prestress(const InitialStress &initial_stress)
    {
      initial = &initial_stress;
    }

    /// The ghosted displacement DataOut evaluates, whose cell means give
    /// the dilatation of a plate with B-bar (PlateModel::mean_dilatation())
    /// and its incompatible modes (PlateModel::add_mode_strains()).
    void
    set_displacement(const TrilinosWrappers::MPI::Vector &u_ghosted)
    {
      displacement = &u_ghosted;
    }

  private:
    /// Incompatible modes: their strain of the displacement at the
    /// evaluation points of a cell, so that the stress is the one the
    /// brick's stiffness has (zero without modes or stress).
    std::vector<SymmetricTensor<2, 3>>
    mode_strains(const DoFHandler<3>::active_cell_iterator &cell,
                 const std::vector<Point<3>>               &points) const;

    /// The initial state's eps0 at the evaluation points of a cell.
    std::vector<SymmetricTensor<2, 3>>
    initial_strain(const DoFHandler<3>::active_cell_iterator &cell,
                   const std::vector<Point<3>>               &points) const;

    const PlateModel                    &plate;
    const Mapping<3>                    &mapping;
    const PropertyInterpolator           properties;
    const HookeLaw                       hooke;
    const bool                           with_stress, with_material;
    const PlasticPlate                  *plastic      = nullptr;
    const InitialStress                 *initial      = nullptr;
    const TrilinosWrappers::MPI::Vector *displacement = nullptr;
  };



  /**
   * The thermal step's fields for DataOut, attached to its displacement
   * u0: the temperature T(z) (temperature_K, K), the expansion
   * coefficient alpha(z) at T(z) (thermal_expansion_per_K, 1/K) and the
   * initial state's per-cell stress C eps0 (thermal_stress_MPa, a tensor
   * as StressPostprocessor's, MPa) with E, nu as in the assembly.
   */
  class ThermalPostprocessor : public DataPostprocessor<3>
  {
  public:
    ThermalPostprocessor(const PlateModel &plate, const InitialStress &initial);

    void
    evaluate_vector_field(
      const DataPostprocessorInputs::Vector<3> &inputs,
      std::vector<Vector<double>> &computed_quantities) const override;

    std::vector<std::string>
    get_names() const override;

    std::vector<DataComponentInterpretation::DataComponentInterpretation>
    get_data_component_interpretation() const override;

    UpdateFlags
    get_needed_update_flags() const override;

  private:
    const PlateModel          &plate;
    const InitialStress       &initial;
    const PropertyInterpolator properties;
  };



  /**
   * Entry "Fields" of subsection "Output": which fields the VTU files
   * hold (a comma-separated list).
   */
  struct VtuFields
  {
    bool displacement = true;  // displacement_m (m)
    bool velocity     = true;  // velocity_m_s (m/s)
    bool acceleration = false; // acceleration_m_s2 (m/s^2, impact runs)
    bool stress       = true;  // recovered sigma_xx_MPa ... sigma_yz_MPa
    bool von_mises    = true;  // recovered von_mises_MPa
    bool principal    = true;  // recovered sigma_1_MPa >= sigma_2 >= sigma_3
    bool strain       = false; // recovered strain_xx ... strain_yz
    bool cell_stress  = false; // per-cell stress_MPa tensor, von Mises
    bool material     = true;  // youngs_modulus_GPa, density_kg_m3
    bool peak         = true;  // peak_fields.vtu at the end of an impact
    bool thermal      = true;  // thermal step's fields (temperature field)
    /// Entry "Mirror symmetric part": a half or quarter model's VTU files
    /// show the whole plate (MirroredDataOut).
    bool mirror = true;

    /// Declare "Fields" and "Mirror symmetric part" in the current
    /// subsection.
    static void
    declare_parameters(ParameterHandler &prm);
    /// Parse "Fields" and "Mirror symmetric part" of the current
    /// subsection.
    void
    parse_parameters(ParameterHandler &prm);

    /// Whether any recovered (nodal) field is needed.
    bool
    recovered() const
    {
      return stress || von_mises || principal || strain || peak;
    }
  };



  /**
   * Writes VTU files (one piece per MPI rank plus a .pvtu record) of the
   * displacement, velocity, stresses and material fields, and keeps the PVD
   * time series file up to date so that a run stopped early still opens in
   * ParaView: the PVD (written to a temporary name and renamed) lists a
   * snapshot only once its files are complete.  A failed write throws
   * ExcOutputFailure naming the file.
   */
  class VtuWriter
  {
  public:
    /// Material/Plasticity = J2: every stress written is C (eps - eps_p)
    /// (StressRecovery::set_plasticity()), and every snapshot has the cell
    /// fields equivalent_plastic_strain and von_mises_over_yield (the
    /// largest of each cell's Gauss points) and the recovered point fields
    /// equivalent_plastic_strain_nodal and yield_stress_MPa.
    void
    set_plasticity(const PlasticPlate &plasticity);

    /// A thermal run: every stress written is the total, the analysis's
    /// plus the initial state's (StressRecovery::set_prestress()), and
    /// with the field "thermal" every snapshot has the thermal step's
    /// displacement (thermal_displacement_m) and ThermalPostprocessor's
    /// fields.
    void
    set_prestress(const InitialStress &initial);

    VtuWriter(const PlateModel                                 &plate,
              const std::string                                &directory,
              const DataOutBase::VtkFlags::ZlibCompressionLevel compression =
                DataOutBase::VtkFlags::best_speed,
              const VtuFields &fields = VtuFields());

    /// Waits for the last snapshot to be written.
    ~VtuWriter();

    /**
     * Write one snapshot at time t (s); u, v in m and m/s.  The vectors
     * are copied and the patches are built and written in a background
     * task, off the time loop's critical path; the next call (or the
     * destructor) waits for it.  A non-empty constant_field (name, value)
     * adds a field of that value on every cell (the modal analysis's
     * frequency_Hz).  The acceleration a (m/s^2; impact runs) is written
     * if the fields include "acceleration".
     */
    void
    write(const unsigned int                    step,
          const double                          t,
          const TrilinosWrappers::MPI::Vector  &u,
          const TrilinosWrappers::MPI::Vector  &v,
          const std::pair<std::string, double> &constant_field = {},
          const TrilinosWrappers::MPI::Vector  *a              = nullptr);

    /**
     * An extra snapshot at time t (the PVD time) between the regular ones,
     * as Directory/vtu/solution_<name>.pvtu (and pieces), listed in the
     * PVD in time order; an earlier snapshot of the same name is replaced
     * (the peak force's, when a higher peak comes).  step: the time step
     * it was written at (for a checkpoint).
     */
    void
    write_extra(const std::string                   &name,
                const unsigned int                   step,
                const double                         t,
                const TrilinosWrappers::MPI::Vector &u,
                const TrilinosWrappers::MPI::Vector &v,
                const TrilinosWrappers::MPI::Vector &a);

    /// Wait for the pending snapshot, rethrowing its errors, and list it
    /// in the PVD.
    void
    finish();

    /**
     * If the fields include "peak" and snapshots were written: write
     * peak_fields.vtu (and .pvtu), the nodal maxima over the snapshots of
     * the recovered von Mises stress and |sigma_zz| (MPa).  Waits for the
     * pending snapshot first.
     */
    void
    write_peak_fields();

    /**
     * For a checkpoint after step `step`: the PVD entries (time in s,
     * .pvtu name; rank 0 only, empty elsewhere).  A snapshot of this very
     * step still being written is not waited for (that would cost the
     * background write's time): it is left out and in_flight set, and the
     * resumed run writes it again from the restored state.
     */
    std::vector<std::pair<double, std::string>>
    records(const unsigned int step, bool &in_flight);

    /// On resume: the checkpoint's entries; rank 0 rewrites the PVD with
    /// them (dropping snapshots written after the checkpoint).
    void
    restore(const std::vector<std::pair<double, std::string>> &records);

    /// For a checkpoint: the peak fields' state so far (a flag, then
    /// StressRecovery::save_peaks()); load_peaks() on resume.
    void
    save_peaks(CheckpointWriter &out) const;
    void
    load_peaks(CheckpointReader &in);

  private:
    /// The selected Output/Fields of the ghosted copies (and a constant
    /// cell field, stored in `constant`) into data_out.
    void
    attach_fields(MirroredDataOut                      &data_out,
                  const bool                            acceleration,
                  const std::pair<std::string, double> &constant_field,
                  Vector<double>                       &constant);

    void
    add_recovered_fields(DataOut<3> &data_out);

    /// set_prestress() and the field "thermal": the thermal step's fields.
    void
    add_thermal_fields(DataOut<3> &data_out);

    /// Copy the fields of a snapshot into the ghosted vectors and cell
    /// fields that the background writer reads; true if the acceleration
    /// is among them.
    bool
    capture_fields(const TrilinosWrappers::MPI::Vector &u,
                   const TrilinosWrappers::MPI::Vector &v,
                   const TrilinosWrappers::MPI::Vector *a);

    /// Write the snapshot Directory/vtu/<base>.pvtu (see write()).
    void
    write_snapshot(const std::string                    &base,
                   const unsigned int                    step,
                   const double                          t,
                   const TrilinosWrappers::MPI::Vector  &u,
                   const TrilinosWrappers::MPI::Vector  &v,
                   const std::pair<std::string, double> &constant_field,
                   const TrilinosWrappers::MPI::Vector  *a);

    /**
     * This rank's pieces of data_out (1, or 2 for a mirrored part,
     * written by two threads) as Directory/vtu/base.K.vtu (K numbering
     * the pieces of all ranks) and, on rank 0, the record base.pvtu that
     * lists them: in vtu/ beside them (piece_prefix empty), or at the top
     * with piece_prefix "vtu/".
     */
    void
    write_pieces(const MirroredDataOut &data_out,
                 const std::string     &base,
                 const std::string     &piece_prefix,
                 const unsigned int     rank,
                 const unsigned int     n_ranks) const;

    /// Create Directory/vtu if missing (throws ExcOutputFailure).
    void
    ensure_piece_directory() const;

    const PlateModel                           &plate;
    const std::string                           directory;
    const VtuFields                             fields;
    StressPostprocessor                         postprocessor;
    std::unique_ptr<StressRecovery>             recovery;
    TrilinosWrappers::MPI::Vector               u_ghosted, v_ghosted, a_ghosted;
    std::vector<std::pair<double, std::string>> times_and_names;
    std::pair<double, std::string>              pending_record;
    bool                                        record_pending = false;
    unsigned int                                pending_step   = 0;
    bool                                        pending_extra  = false;
    std::future<void>                           pending;
    bool                                        any_written = false;

    const DataOutBase::VtkFlags::ZlibCompressionLevel compression;
    const PlasticPlate                               *plastic = nullptr;
    /// set_prestress(): the thermal fields' postprocessor (field thermal).
    std::unique_ptr<ThermalPostprocessor> thermal;
    const InitialStress                  *initial = nullptr;
    /// Its cell values at the snapshot being written.
    Vector<double> plastic_strain, yield_utilization;
  };
} // namespace fgimpact

#endif
