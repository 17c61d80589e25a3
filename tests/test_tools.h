#ifndef fgimpact_test_tools_h
#define fgimpact_test_tools_h

// Shared by the whole-program tests: run an impact through the library
// exactly as the executable does, on a coarse mesh, with the simulator's
// log kept out of the test output.

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/app/input_file.h>
#include <fgimpact/app/run.h>
#include <fgimpact/study/simulator.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace fgimpact_tests
{
  /// What a quiet run returns: the results, and the rows of history.csv
  /// (its columns and units, before rounding) if asked for.
  struct RunOutput
  {
    fgimpact::ImpactResults          results;
    std::vector<std::vector<double>> history;
  };

  /// A whole file as it is on disk ("" if it cannot be read).
  inline std::string
  read_text(const std::string &filename)
  {
    std::ifstream     in(filename, std::ios::binary);
    std::stringstream buffer;
    buffer << in.rdbuf();
    return buffer.str();
  }

  /// Two histories' difference: the largest over the columns of max_i
  /// |a_ic - b_ic| / max_i |b_ic| (b the reference; columns of zeros are
  /// left out, since a column that crosses zero has no pointwise relative
  /// error); 1 if the row counts differ or b is empty.
  inline double
  history_difference(const std::vector<std::vector<double>> &a,
                     const std::vector<std::vector<double>> &b)
  {
    if (a.size() != b.size() || b.empty())
      return 1.;
    double worst = 0.;
    for (unsigned int c = 0; c < b[0].size(); ++c)
      {
        double scale = 0, difference = 0;
        for (unsigned int n = 0; n < b.size(); ++n)
          {
            scale      = std::max(scale, std::abs(b[n][c]));
            difference = std::max(difference, std::abs(a[n][c] - b[n][c]));
          }
        if (scale > 0)
          worst = std::max(worst, difference / scale);
      }
    return worst;
  }

  /// A CSV file's column `name` (history.csv, probes.csv), as numbers.
  inline std::vector<double>
  csv_column(const std::string &file, const std::string &name)
  {
    std::ifstream            in(file);
    std::string              line, cell;
    std::vector<std::string> header;
    std::getline(in, line);
    std::istringstream head(line);
    while (std::getline(head, cell, ','))
      header.push_back(cell);
    const auto k = std::find(header.begin(), header.end(), name);
    AssertThrow(k != header.end(),
                dealii::ExcMessage(name + " not in " + file));
    std::vector<double> values;
    while (std::getline(in, line))
      {
        std::istringstream row(line);
        for (long j = 0; j <= k - header.begin(); ++j)
          std::getline(row, cell, ',');
        values.push_back(std::stod(cell));
      }
    return values;
  }

  /// A numeric CSV file (convergence.csv, adaptation.csv): the header's
  /// names and the rows.
  inline std::pair<std::vector<std::string>, std::vector<std::vector<double>>>
  read_csv_rows(const std::string &file)
  {
    std::ifstream in(file);
    std::string   line;
    std::getline(in, line);
    const auto header = dealii::Utilities::split_string_list(line, ',');
    std::vector<std::vector<double>> rows;
    while (std::getline(in, line))
      {
        std::vector<double> row;
        for (const auto &item : dealii::Utilities::split_string_list(line, ','))
          row.push_back(std::stod(item));
        rows.push_back(row);
      }
    return {header, rows};
  }

  /// summary.txt's entries, key -> text (the provenance comments left
  /// out).
  inline std::map<std::string, std::string>
  read_summary(const std::string &file)
  {
    std::map<std::string, std::string> values;
    std::ifstream                      in(file);
    for (std::string line; std::getline(in, line);)
      if (const auto at = line.find(" = ");
          line[0] != '#' && at != std::string::npos)
        values[line.substr(0, at)] = line.substr(at + 3);
    return values;
  }

  /**
   * Remove a directory an earlier run of the test left (rank 0, then every
   * rank waits): the library's run does not clean its Output/Directory as
   * the executable does, so a test would otherwise read stale files.
   */
  inline void
  remove_output(const std::string &directory,
                const MPI_Comm     communicator = MPI_COMM_WORLD)
  {
    if (dealii::Utilities::MPI::this_mpi_process(communicator) == 0)
      std::filesystem::remove_all(directory);
    MPI_Barrier(communicator);
  }

  /**
   * Run the program through the library exactly as the executable does:
   * the defaults (with Geometry/Symmetry = none), then the file `prm_file`
   * (if not empty), then the .prm text `settings`; the log is kept out of
   * the test output.
   */
  inline RunOutput
  run_quietly(const std::string &prm_file,
              const std::string &settings,
              const MPI_Comm     communicator = MPI_COMM_WORLD,
              const bool         keep_history = false)
  {
    // The references of these tests are the whole plate: pin it (the
    // built-in default is Symmetry = auto); a file or the settings that
    // set Geometry/Symmetry still decide.  Read by the executable's reader.
    std::string text = "subsection Geometry\n set Symmetry = none\nend\n";
    if (!prm_file.empty())
      text += fgimpact::InputFile(prm_file).expanded() + "\n";
    text += settings;
    const fgimpact::InputFile input(prm_file.empty() ? "settings" : prm_file,
                                    text);
    dealii::ParameterHandler prm;
    fgimpact::Parameters     p;
    fgimpact::read_run_parameters(input, {}, prm, p);
    std::filesystem::create_directories(p.output.directory);

    RunOutput          output;
    std::ostringstream log;
    auto *const        old = std::cout.rdbuf(log.rdbuf());
    try
      {
        fgimpact::Simulator simulator(p, communicator);
        if (keep_history)
          simulator.add_history_observer(
            [&output](const std::vector<double> &row) {
              output.history.push_back(row);
            });
        simulator.run();
        std::cout.rdbuf(old);
        if (p.problem_type == fgimpact::ProblemType::impact)
          output.results = simulator.get_results();
        return output;
      }
    catch (...)
      {
        std::cout.rdbuf(old);
        throw;
      }
  }

  /**
   * Run the impact defined by `settings` (.prm text) on top of the
   * defaults, a 10 x 6 x 2 mesh (later entries in `settings` override it)
   * and a quiet output into ./out.
   */
  inline fgimpact::ImpactResults
  run_impact(const std::string &settings)
  {
    return run_quietly(
             "",
             "subsection Geometry\n set Subdivisions x = 10\n"
             " set Subdivisions y = 6\n set Subdivisions z = 2\nend\n"
             "subsection Output\n set Directory = out\n set Log interval = 0\n"
             " set Print timing = false\nend\n" +
               settings)
      .results;
  }


  /// A plate model with its geometry and material kept alive together.
  struct PlateCase
  {
    std::unique_ptr<fgimpact::PlateGeometry>              geometry;
    std::unique_ptr<fgimpact::FunctionallyGradedMaterial> material;
    std::unique_ptr<fgimpact::PlateModel>                 plate;
  };

  /**
   * The paper's plate (0.2 x 0.1 x thickness m, simply supported, default
   * constituents) with power-law index n, assembled on nx x ny x nz
   * elements of the given degree and property mode.
   */
  inline PlateCase
  make_plate(const unsigned int           nx,
             const unsigned int           ny,
             const unsigned int           nz,
             const unsigned int           degree,
             const double                 n,
             const fgimpact::PropertyMode mode = fgimpact::PropertyMode::graded,
             const double                 thickness       = 0.02,
             const MPI_Comm               communicator    = MPI_COMM_WORLD,
             const double                 poissons_ratio  = 0.3,
             const bool                   mean_dilatation = false,
             const fgimpact::SideSupport  bottom = fgimpact::SideSupport::free,
             const bool                   incompatible_modes = false)
  {
    fgimpact::PlateGeometry::Parameters gp;
    gp.thickness      = thickness;
    gp.subdivisions_x = nx;
    gp.subdivisions_y = ny;
    gp.subdivisions_z = nz;
    gp.bottom_support = bottom;
    fgimpact::FunctionallyGradedMaterial::Parameters mp;
    mp.power_law_index = n;
    mp.property_mode   = mode;
    mp.poissons_ratio  = poissons_ratio;
    fgimpact::PlateModel::Parameters fp;
    fp.degree             = degree;
    fp.mean_dilatation    = mean_dilatation;
    fp.incompatible_modes = incompatible_modes;

    PlateCase c;
    c.geometry = std::make_unique<fgimpact::PlateGeometry>(gp);
    c.material =
      std::make_unique<fgimpact::FunctionallyGradedMaterial>(mp, thickness);
    c.plate = std::make_unique<fgimpact::PlateModel>(fp,
                                                     *c.geometry,
                                                     *c.material,
                                                     communicator);
    c.plate->setup();
    return c;
  }
} // namespace fgimpact_tests

#endif
