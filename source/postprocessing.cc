#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/numerics/data_out.h>

#include <fgimpact/postprocessing.h>
#include <fgimpact/run_control.h>

#include <cmath>
#include <cstdio>
#include <sstream>

namespace fgimpact
{
  StressPostprocessor::StressPostprocessor(const PlateModel &plate)
    : properties(plate.get_fe().base_element(0), {}, plate.get_material())
    , hooke(plate.get_material())
  {}



  std::vector<std::string>
  StressPostprocessor::get_names() const
  {
    std::vector<std::string> names(9, "stress_MPa");
    names.emplace_back("von_mises_MPa");
    names.emplace_back("youngs_modulus_GPa");
    names.emplace_back("density_kg_m3");
    return names;
  }



  std::vector<DataComponentInterpretation::DataComponentInterpretation>
  StressPostprocessor::get_data_component_interpretation() const
  {
    std::vector<DataComponentInterpretation::DataComponentInterpretation>
      interpretation(9,
                     DataComponentInterpretation::component_is_part_of_tensor);
    interpretation.resize(12, DataComponentInterpretation::component_is_scalar);
    return interpretation;
  }



  UpdateFlags
  StressPostprocessor::get_needed_update_flags() const
  {
    return update_gradients | update_quadrature_points;
  }



  void
  StressPostprocessor::evaluate_vector_field(
    const DataPostprocessorInputs::Vector<3> &inputs,
    std::vector<Vector<double>>              &computed_quantities) const
  {
    const auto cell = inputs.template get_cell<3>();
    for (unsigned int p = 0; p < inputs.solution_gradients.size(); ++p)
      {
        const auto [E, rho] =
          properties.value_at(cell, inputs.evaluation_points[p]);

        SymmetricTensor<2, 3> eps;
        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = a; b < 3; ++b)
            eps[a][b] = 0.5 * (inputs.solution_gradients[p][a][b] +
                               inputs.solution_gradients[p][b][a]);
        const SymmetricTensor<2, 3> sigma = hooke.stress(E, eps);
        const SymmetricTensor<2, 3> s     = deviator(sigma);

        for (unsigned int a = 0; a < 3; ++a)
          for (unsigned int b = 0; b < 3; ++b)
            computed_quantities[p][3 * a + b] = sigma[a][b] * 1e-6;
        computed_quantities[p][9]  = std::sqrt(1.5 * (s * s)) * 1e-6;
        computed_quantities[p][10] = E * 1e-9;
        computed_quantities[p][11] = rho;
      }
  }



  VtuWriter::VtuWriter(
    const PlateModel                                 &plate,
    const std::string                                &directory,
    const DataOutBase::VtkFlags::ZlibCompressionLevel compression)
    : plate(plate)
    , directory(directory)
    , postprocessor(plate)
    , compression(compression)
  {
    // DataOut reads ghost values: ghosted copies, allocated once.
    IndexSet relevant;
    DoFTools::extract_locally_relevant_dofs(plate.get_dof_handler(), relevant);
    u_ghosted.reinit(plate.locally_owned_dofs(),
                     relevant,
                     plate.get_mpi_communicator());
    v_ghosted.reinit(u_ghosted);
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
    // Only rank 0 keeps the PVD, and it lists complete snapshots only.
    times_and_names.push_back(pending_record);
    std::ostringstream pvd;
    DataOutBase::write_pvd_record(pvd, times_and_names);
    write_file_atomically(directory + "/solution.pvd", pvd.str());
  }



  void
  VtuWriter::write(const unsigned int                   step,
                   const double                         t,
                   const TrilinosWrappers::MPI::Vector &u,
                   const TrilinosWrappers::MPI::Vector &v)
  {
    finish(); // the previous snapshot still reads u_ghosted, v_ghosted
    u_ghosted = u;
    v_ghosted = v;

    const MPI_Comm     comm    = plate.get_mpi_communicator();
    const unsigned int rank    = Utilities::MPI::this_mpi_process(comm);
    const unsigned int n_ranks = Utilities::MPI::n_mpi_processes(comm);
    const std::string  base   = "solution_" + Utilities::int_to_string(step, 5);
    const std::string  record = base + ".pvtu";

    // Patches and files, in the background on one rank. On several ranks
    // DataOut on the distributed mesh makes MPI calls of its own, which
    // collided with the time loop's collectives (MPI_ERR_TRUNCATE, or a
    // hang inside MUMPS): there the snapshot is written synchronously.
    auto write_files = [this, t, step, rank, n_ranks, base, record]() {
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
                 vector_field(3,
                     DataComponentInterpretation::component_is_part_of_vector);
      DataOut<3> data_out;
      data_out.attach_dof_handler(plate.get_dof_handler());
      data_out.add_data_vector(u_ghosted,
                               std::vector<std::string>(3, "displacement_m"),
                               DataOut<3>::type_dof_data,
                               vector_field);
      data_out.add_data_vector(v_ghosted,
                               std::vector<std::string>(3, "velocity_m_s"),
                               DataOut<3>::type_dof_data,
                               vector_field);
      data_out.add_data_vector(u_ghosted, postprocessor);
      data_out.build_patches(plate.get_mapping(), plate.get_fe().degree);

      DataOutBase::VtkFlags flags;
      flags.time  = t;
      flags.cycle = step;

      flags.compression_level = compression;
      data_out.set_flags(flags);

      // deal.II's own I/O error is several paragraphs: one line instead.
      const auto write_checked = [](const std::string &filename,
                                    const auto        &writer) {
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
      };
      write_checked(directory + "/" + base + "." +
                      Utilities::int_to_string(rank) + ".vtu",
                    [&](std::ostream &out) { data_out.write_vtu(out); });
      if (rank == 0)
        {
          std::vector<std::string> pieces;
          for (unsigned int r = 0; r < n_ranks; ++r)
            pieces.push_back(base + "." + Utilities::int_to_string(r) + ".vtu");
          write_checked(directory + "/" + record, [&](std::ostream &out) {
            data_out.write_pvtu_record(out, pieces);
          });
        }
    };
    if (n_ranks == 1)
      pending = std::async(std::launch::async, write_files);
    else
      write_files();

    // Listed in the PVD by finish(), once the files are complete.
    pending_record = {t, record};
    record_pending = (rank == 0);
    if (n_ranks > 1)
      finish();
  }



  CsvWriter::CsvWriter(const std::string                              &filename,
                       const std::vector<std::pair<std::string, int>> &columns)
    : filename(filename)
    , out(filename, std::ios::binary)
  {
    AssertThrow(out, ExcOutputFailure("cannot write " + filename + "."));
    for (unsigned int i = 0; i < columns.size(); ++i)
      {
        buffer += (i ? ", " : "") + columns[i].first;
        decimals.push_back(columns[i].second);
      }
    buffer += '\n';
    flush();
  }



  CsvWriter::~CsvWriter()
  {
    try
      {
        flush();
      }
    catch (...)
      {}
  }



  void
  CsvWriter::write_row(const std::vector<double> &values)
  {
    Assert(values.size() == decimals.size(),
           ExcDimensionMismatch(values.size(), decimals.size()));
    char buffer_row[64];
    for (unsigned int i = 0; i < values.size(); ++i)
      {
        // Print -0.000 as 0.000: a sign flip of round-off is not a change.
        const double scale = std::pow(10., decimals[i]);
        const double v = (std::abs(values[i]) * scale < 0.5) ? 0. : values[i];
        std::snprintf(buffer_row, sizeof(buffer_row), "%.*f", decimals[i], v);
        if (i > 0)
          buffer += ", ";
        buffer += buffer_row;
      }
    buffer += '\n';
    if (buffer.size() > (1u << 20) ||
        std::chrono::steady_clock::now() - last_flush > std::chrono::seconds(2))
      flush();
  }



  void
  CsvWriter::flush()
  {
    last_flush = std::chrono::steady_clock::now();
    if (buffer.empty() || !out.good())
      {
        AssertThrow(out.good(),
                    ExcOutputFailure("cannot write " + filename +
                                     " (disk full or I/O error)."));
        return;
      }
    out.write(buffer.data(), buffer.size());
    out.flush();
    buffer.clear();
    AssertThrow(out.good(),
                ExcOutputFailure("cannot write " + filename +
                                 " (disk full or I/O error)."));
  }



  void
  SummaryWriter::add(const std::string &name,
                     const double       value,
                     const int          decimals)
  {
    char buffer[200];
    if (std::isfinite(value))
      std::snprintf(
        buffer, sizeof(buffer), "%s = %.*f\n", name.c_str(), decimals, value);
    else
      std::snprintf(buffer, sizeof(buffer), "%s = none\n", name.c_str());
    text += buffer;
  }



  void
  SummaryWriter::add_scientific(const std::string &name, const double value)
  {
    if (!std::isfinite(value))
      return add(name, value, 0);
    char buffer[200];
    std::snprintf(buffer, sizeof(buffer), "%s = %.6e\n", name.c_str(), value);
    text += buffer;
  }



  void
  SummaryWriter::add_text(const std::string &name, const std::string &value)
  {
    text += name + " = " + value + '\n';
  }



  void
  SummaryWriter::write(const std::string &filename) const
  {
    write_file_atomically(filename, preamble() + text);
  }


  std::string &
  SummaryWriter::preamble()
  {
    static std::string lines;
    return lines;
  }



  void
  SummaryWriter::set_preamble(const std::string &comment_lines)
  {
    preamble() = comment_lines;
  }
} // namespace fgimpact
