// The VTU writer (VtuWriter): snapshots in pieces, the peak fields, the
// recovered stresses; which fields, and their postprocessor, are in
// vtu_fields.cc.

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/numerics/data_out.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/output/mirrored_data_out.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <sstream>

namespace fgimpact
{
  namespace
  {
    /// Write `filename` with writer(stream); deal.II's own I/O error is
    /// several paragraphs: ExcOutputFailure with one line instead.
    void
    write_checked(const std::string                         &filename,
                  const std::function<void(std::ostream &)> &writer)
    {
      record_output_file(filename);
      std::ofstream out(filename);
      try
        {
          writer(out);
        }
      catch (const ExceptionBase &)
        {
          out.setstate(std::ios::badbit);
        }
      out.close();
      AssertThrow(!out.fail(),
                  ExcOutputFailure("cannot write " + filename +
                                   " (disk full or I/O error)."));
    }
  } // namespace



  VtuWriter::VtuWriter(
    const PlateModel                                 &plate,
    const std::string                                &directory,
    const DataOutBase::VtkFlags::ZlibCompressionLevel compression,
    const VtuFields                                  &fields)
    : plate(plate)
    , directory(directory)
    , fields(fields)
    , postprocessor(plate, fields.cell_stress, fields.material)
    , recovery(fields.recovered() ? std::make_unique<StressRecovery>(plate) :
                                    nullptr)
    , compression(compression)
  {
    // DataOut reads ghost values: ghosted copies, allocated once.
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(plate.get_dof_handler(), relevant);
    u_ghosted.reinit(plate.locally_owned_dofs(),
                     relevant,
                     plate.get_mpi_communicator());
    v_ghosted.reinit(u_ghosted);
    a_ghosted.reinit(u_ghosted);
    postprocessor.set_displacement(u_ghosted);
  }



  VtuWriter::~VtuWriter()
  {
    // Never throw from a destructor: errors surface through finish().
    if (pending.valid())
      pending.wait();
  }



  void
  VtuWriter::finish()
  {
    if (pending.valid())
      pending.get();
    if (!record_pending)
      return;
    record_pending = false;
    // Only rank 0 keeps the PVD, and it lists complete snapshots only, in
    // time order (an extra snapshot falls between regular ones; one of the
    // same name, the peak's, is replaced).
    add_pvd_entry(times_and_names, pending_record);
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, times_and_names);
    write_file_atomically(directory + "/solution.pvd", pvd.str());
  }



  std::vector<std::pair<double, std::string>>
  VtuWriter::records(const unsigned int step, bool &in_flight)
  {
    // An extra snapshot is waited for: the resumed run rewrites regular
    // snapshots only.
    in_flight =
      any_written && pending_step == step && pending.valid() && !pending_extra;
    if (!in_flight)
      finish();
    return times_and_names;
  }



  void
  VtuWriter::restore(const std::vector<std::pair<double, std::string>> &records)
  {
    times_and_names = records;
    any_written     = true; // every rank: a snapshot at step 0 at least
    if (!times_and_names.empty())
      {
        std::ostringstream pvd;
        DataOutBase::write_pvd_record(pvd, times_and_names);
        write_file_atomically(directory + "/solution.pvd", pvd.str());
      }
  }



  void
  VtuWriter::save_peaks(CheckpointWriter &out) const
  {
    const bool peaks = fields.peak && recovery;
    out.put(peaks);
    if (peaks)
      recovery->save_peaks(out);
  }



  void
  VtuWriter::load_peaks(CheckpointReader &in)
  {
    bool peaks = false;
    in.get(peaks);
    AssertThrow(peaks == (fields.peak && recovery),
                ExcMessage("--resume: the checkpoint's peak fields do not "
                           "match Output/Fields"));
    if (peaks)
      recovery->load_peaks(in);
  }



  void
  VtuWriter::attach_fields(MirroredDataOut                      &data_out,
                           const bool                            acceleration,
                           const std::pair<std::string, double> &constant_field,
                           Vector<double>                       &constant)
  {
    const std::vector<DataComponentInterpretation::DataComponentInterpretation>
      vector_field(3, DataComponentInterpretation::component_is_part_of_vector);
    data_out.attach_dof_handler(plate.get_dof_handler());
    if (fields.displacement)
      data_out.add_data_vector(u_ghosted,
                               std::vector<std::string>(3, "displacement_m"),
                               DataOut<3>::type_dof_data,
                               vector_field);
    if (fields.velocity)
      data_out.add_data_vector(v_ghosted,
                               std::vector<std::string>(3, "velocity_m_s"),
                               DataOut<3>::type_dof_data,
                               vector_field);
    if (acceleration)
      data_out.add_data_vector(a_ghosted,
                               std::vector<std::string>(3, "acceleration_m_s2"),
                               DataOut<3>::type_dof_data,
                               vector_field);
    if (fields.cell_stress || fields.material)
      data_out.add_data_vector(u_ghosted, postprocessor);
    add_recovered_fields(data_out);
    add_thermal_fields(data_out);
    if (plastic)
      {
        data_out.add_data_vector(plastic_strain,
                                 "equivalent_plastic_strain",
                                 DataOut<3>::type_cell_data);
        data_out.add_data_vector(yield_utilization,
                                 "von_mises_over_yield",
                                 DataOut<3>::type_cell_data);
      }
    if (!constant_field.first.empty())
      {
        constant.reinit(
          plate.get_dof_handler().get_triangulation().n_active_cells());
        constant = constant_field.second;
        data_out.add_data_vector(constant,
                                 constant_field.first,
                                 DataOut<3>::type_cell_data);
      }
  }



  void
  VtuWriter::write(const unsigned int                    step,
                   const double                          t,
                   const TrilinosWrappers::MPI::Vector  &u,
                   const TrilinosWrappers::MPI::Vector  &v,
                   const std::pair<std::string, double> &constant_field,
                   const TrilinosWrappers::MPI::Vector  *a)
  {
    write_snapshot("solution_" + Utilities::int_to_string(step, 5),
                   step,
                   t,
                   u,
                   v,
                   constant_field,
                   a);
    pending_extra = false;
  }



  void
  VtuWriter::write_extra(const std::string                   &name,
                         const unsigned int                   step,
                         const double                         t,
                         const TrilinosWrappers::MPI::Vector &u,
                         const TrilinosWrappers::MPI::Vector &v,
                         const TrilinosWrappers::MPI::Vector &a)
  {
    write_snapshot("solution_" + name, step, t, u, v, {}, &a);
    pending_extra = true;
  }



  bool
  VtuWriter::capture_fields(const TrilinosWrappers::MPI::Vector &u,
                            const TrilinosWrappers::MPI::Vector &v,
                            const TrilinosWrappers::MPI::Vector *a)
  {
    u_ghosted                    = u;
    v_ghosted                    = v;
    const bool with_acceleration = fields.acceleration && a != nullptr;
    if (with_acceleration)
      a_ghosted = *a;
    // Recovered here, not in the background: creating Trilinos vectors
    // calls MPI_Allreduce, and MPI from two threads crashed 1 run in ~40.
    if (recovery)
      recovery->recover(u_ghosted);
    if (plastic)
      {
        const Vector<float> cells = plastic->cell_plastic_strain();
        plastic_strain.reinit(cells.size());
        for (unsigned int c = 0; c < cells.size(); ++c)
          plastic_strain[c] = cells[c];
        const Vector<float> ratio = plastic->cell_yield_utilization();
        yield_utilization.reinit(ratio.size());
        for (unsigned int c = 0; c < ratio.size(); ++c)
          yield_utilization[c] = ratio[c];
      }
    return with_acceleration;
  }



  void
  VtuWriter::write_snapshot(
    const std::string                    &base,
    const unsigned int                    step,
    const double                          t,
    const TrilinosWrappers::MPI::Vector  &u,
    const TrilinosWrappers::MPI::Vector  &v,
    const std::pair<std::string, double> &constant_field,
    const TrilinosWrappers::MPI::Vector  *a)
  {
    finish(); // the previous snapshot still reads u_ghosted, v_ghosted
    any_written                  = true;
    const bool with_acceleration = capture_fields(u, v, a);

    const MPI_Comm     comm    = plate.get_mpi_communicator();
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  record  = "vtu/" + base + ".pvtu";

    // Patches and files, in the background on one rank. On several ranks
    // DataOut on the distributed mesh makes MPI calls of its own, which
    // collided with the time loop's collectives (MPI_ERR_TRUNCATE, or a
    // hang inside MUMPS): there the snapshot is written synchronously.
    auto write_files = [this,
                        t,
                        step,
                        rank,
                        n_ranks,
                        base,
                        constant_field,
                        with_acceleration]() {
      MirroredDataOut data_out(plate.get_geometry());
      Vector<double>  constant;
      attach_fields(data_out, with_acceleration, constant_field, constant);
      data_out.build_patches(plate.get_mapping(), plate.get_fe().degree);
      if (fields.mirror)
        data_out.mirror();

      DataOutBase::VtkFlags flags;
      flags.time  = t;
      flags.cycle = step;

      flags.compression_level = compression;
      data_out.set_vtk_flags(flags);

      write_pieces(data_out, base, "", rank, n_ranks);
    };
    if (n_ranks == 1)
      pending = std::async(std::launch::async, write_files);
    else
      write_files();

    // Listed in the PVD by finish(), once the files are complete.
    pending_record = {t, record};
    pending_step   = step;
    record_pending = (rank == 0);
    if (n_ranks > 1)
      finish();
  }



  void
  VtuWriter::add_recovered_fields(DataOut<3> &data_out)
  {
    // recover() was called by write(), in the calling thread.
    if (!recovery)
      return;
    using F = StressRecovery::Field;
    std::vector<F> selected;
    if (fields.stress)
      selected.insert(selected.end(),
                      {F::stress_xx,
                       F::stress_yy,
                       F::stress_zz,
                       F::stress_xy,
                       F::stress_xz,
                       F::stress_yz});
    if (fields.von_mises)
      selected.push_back(F::von_mises);
    if (fields.principal)
      selected.insert(selected.end(),
                      {F::principal_1, F::principal_2, F::principal_3});
    if (fields.strain)
      selected.insert(selected.end(),
                      {F::strain_xx,
                       F::strain_yy,
                       F::strain_zz,
                       F::strain_xy,
                       F::strain_xz,
                       F::strain_yz});
    for (const F f : selected)
      data_out.add_data_vector(recovery->get_dof_handler(),
                               recovery->field(f),
                               StressRecovery::name(f));
    if (recovery->plastic())
      {
        data_out.add_data_vector(recovery->get_dof_handler(),
                                 recovery->plastic_fields()[0],
                                 "equivalent_plastic_strain_nodal");
        data_out.add_data_vector(recovery->get_dof_handler(),
                                 recovery->plastic_fields()[1],
                                 "yield_stress_MPa");
      }
  }



  void
  VtuWriter::set_plasticity(const PlasticPlate &plasticity)
  {
    plastic = &plasticity;
    if (recovery)
      recovery->set_plasticity(plasticity);
    postprocessor.set_plasticity(plasticity);
  }



  void
  VtuWriter::write_peak_fields()
  {
    finish();
    // Every rank decides alike (times_and_names is kept on rank 0 only).
    if (!fields.peak || !recovery || !any_written)
      return;
    const MPI_Comm     comm    = plate.get_mpi_communicator();
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);

    MirroredDataOut data_out(plate.get_geometry());
    data_out.attach_dof_handler(recovery->get_dof_handler());
    for (const auto f :
         {StressRecovery::peak_von_mises, StressRecovery::peak_abs_stress_zz})
      data_out.add_data_vector(recovery->field(f), StressRecovery::name(f));
    data_out.build_patches(plate.get_mapping(), plate.get_fe().degree);
    if (fields.mirror)
      data_out.mirror();
    DataOutBase::VtkFlags flags;
    flags.compression_level = compression;
    data_out.set_vtk_flags(flags);
    // The record at the top, beside the PVD files; its pieces in vtu/.
    write_pieces(data_out, "peak_fields", "vtu/", rank, n_ranks);
  }



  void
  VtuWriter::write_pieces(const MirroredDataOut &data_out,
                          const std::string     &base,
                          const std::string     &piece_prefix,
                          const unsigned int     rank,
                          const unsigned int     n_ranks) const
  {
    // rank, n_ranks: from the caller (no MPI call in a background thread).
    const unsigned int n_pieces = data_out.n_pieces(); // alike on all ranks
    const auto         piece    = [&](const unsigned int k) {
      return base + "." + Utilities::int_to_string(k) + ".vtu";
    };
    const auto write_piece = [&](const unsigned int k) {
      write_checked(directory + "/vtu/" + piece(rank * n_pieces + k),
                    [&](std::ostream &out) {
                      data_out.write_vtu_piece(k, out);
                    });
    };
    ensure_piece_directory();
    // A mirrored part: its two halves written by two threads at once.
    std::future<void> other;
    if (n_pieces == 2)
      other = std::async(std::launch::async, write_piece, 1u);
    write_piece(0);
    if (other.valid())
      other.get();
    if (rank == 0)
      {
        std::vector<std::string> pieces;
        for (unsigned int k = 0; k < n_ranks * n_pieces; ++k)
          pieces.push_back(piece_prefix + piece(k));
        const std::string record = directory + "/" +
                                   (piece_prefix.empty() ? "vtu/" : "") + base +
                                   ".pvtu";
        write_checked(record, [&](std::ostream &out) {
          data_out.write_pvtu_record(out, pieces);
        });
      }
  }



  void
  VtuWriter::ensure_piece_directory() const
  {
    // Every rank writes its own pieces: each makes sure the folder exists
    // (a race between ranks is harmless: it exists either way).
    std::error_code error;
    std::filesystem::create_directories(directory + "/vtu", error);
    AssertThrow(std::filesystem::is_directory(directory + "/vtu"),
                ExcOutputFailure("cannot create " + directory + "/vtu (" +
                                 error.message() + ")."));
  }
} // namespace fgimpact
