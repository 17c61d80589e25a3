// Geometry/Symmetry's VTU output of the whole plate (MirroredDataOut):
// the quarter model's patches and their reflections across x = a/2 and
// y = b/2 against the whole plate's patches, for a displacement field with
// the scene's symmetry (u_x odd about x = a/2, u_y odd about y = b/2, u_z
// even about both), interpolated on both meshes.  Every whole-plate cell
// must appear once among the mirrored patches with the same vertices, in
// the same (positively oriented) order, and the same values of every data
// set: the displacement and velocity vectors, the per-cell stress tensor
// and von Mises stress, E and rho, and all recovered (nodal-averaged)
// stress, strain, von Mises and principal fields.  The recovered fields on
// the cut planes test StressRecovery's symmetry: there the shear components
// odd under the reflection must vanish, as the whole plate's average of
// both sides gives.  The verdicts on the largest differences are printed
// (float data: relative to each data set's largest magnitude), not the
// differences, whose digits are round-off and depend on the CPU.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/numerics/vector_tools.h>

#include <fgimpact/output/mirrored_data_out.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/plate/stress_recovery.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <test_tools.h>

namespace fgimpact_unit_tests::symmetry_mirror
{

  using namespace fgimpact;

  namespace
  {
    constexpr double a = 0.2, b = 0.1, h = 0.02;

    /// A displacement (m) with the symmetry of a central impact.
    class SymmetricField : public Function<3>
    {
    public:
      SymmetricField()
        : Function<3>(3)
      {}

      double
      value(const Point<3> &p, const unsigned int c) const override
      {
        const double x = p[0] - a / 2, y = p[1] - b / 2, z = p[2] / h;
        const double even = std::cos(M_PI * x / a) * std::cos(M_PI * y / b);
        switch (c)
          {
            case 0:
              return 1e-6 * std::sin(2 * M_PI * x / a) *
                     (1 + 4 * y * y / (b * b)) * (1 + z) *
                     std::cos(M_PI * y / b);
            case 1:
              return 2e-6 * std::sin(2 * M_PI * y / b) * (1 + 0.3 * z) *
                     std::cos(M_PI * x / a);
            default:
              return -5e-6 * even * (1 + 0.2 * z * z);
          }
      }
    };

    struct Model
    {
      std::unique_ptr<PlateGeometry>              geometry;
      std::unique_ptr<FunctionallyGradedMaterial> material;
      std::unique_ptr<PlateModel>                 plate;
    };

    Model
    make_model(const bool quarter)
    {
      PlateGeometry::Parameters gp;
      gp.length         = a;
      gp.width          = b;
      gp.thickness      = h;
      gp.subdivisions_x = 12;
      gp.subdivisions_y = 6;
      gp.subdivisions_z = 2;
      FunctionallyGradedMaterial::Parameters mp;
      mp.power_law_index = 2;
      PlateModel::Parameters fp;
      fp.degree = 1;
      Model m;
      m.geometry = std::make_unique<PlateGeometry>(
        gp, std::array<bool, 2>{{quarter, quarter}});
      m.material = std::make_unique<FunctionallyGradedMaterial>(mp, h);
      m.plate    = std::make_unique<PlateModel>(fp,
                                             *m.geometry,
                                             *m.material,
                                             MPI_COMM_WORLD);
      m.plate->setup();
      return m;
    }

    /// The patches (whole plate or mirrored part) and the data set names.
    std::vector<DataOutBase::Patch<3, 3>>
    patches(const Model &m, std::vector<std::string> &names)
    {
      const PlateModel             &plate = *m.plate;
      TrilinosWrappers::MPI::Vector owned(
        plate.get_dof_handler().locally_owned_dofs(), MPI_COMM_WORLD);
      VectorTools::interpolate(plate.get_mapping(),
                               plate.get_dof_handler(),
                               SymmetricField(),
                               owned);
      TrilinosWrappers::MPI::Vector u(
        plate.get_dof_handler().locally_owned_dofs(),
        plate.locally_relevant_dofs(),
        MPI_COMM_WORLD);
      u = owned;
      StressPostprocessor postprocessor(plate);
      StressRecovery      recovery(plate);
      recovery.recover(u);

      MirroredDataOut data_out(*m.geometry);
      data_out.attach_dof_handler(plate.get_dof_handler());
      const std::vector<
        DataComponentInterpretation::DataComponentInterpretation>
        vector(3, DataComponentInterpretation::component_is_part_of_vector);
      data_out.add_data_vector(u,
                               std::vector<std::string>(3, "displacement_m"),
                               DataOut<3>::type_dof_data,
                               vector);
      data_out.add_data_vector(u, postprocessor);
      for (unsigned int f = 0; f < StressRecovery::peak_von_mises; ++f)
        data_out.add_data_vector(
          recovery.get_dof_handler(),
          recovery.field(static_cast<StressRecovery::Field>(f)),
          StressRecovery::name(static_cast<StressRecovery::Field>(f)));
      data_out.build_patches(plate.get_mapping(), 1);
      data_out.mirror();
      names = data_out.dataset_names();
      return data_out.get_patches();
    }

    Point<3>
    centroid(const DataOutBase::Patch<3, 3> &p)
    {
      Point<3> c;
      for (const auto &v : p.vertices)
        c += v / 8.;
      return c;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    std::vector<std::string>         names, part_names;
    const auto                       whole = patches(make_model(false), names);
    const auto mirror = patches(make_model(true), part_names);

    // The mirrored patches by centroid (mm, rounded).
    std::map<std::array<long, 3>, const DataOutBase::Patch<3, 3> *> by_centre;
    const auto key = [](const Point<3> &c) {
      return std::array<long, 3>{{std::lround(c[0] * 1e4),
                                  std::lround(c[1] * 1e4),
                                  std::lround(c[2] * 1e4)}};
    };
    for (const auto &p : mirror)
      by_centre[key(centroid(p))] = &p;

    std::vector<float> scale(names.size(), 0.f), diff(names.size(), 0.f);
    double             vertex_error = 0;
    unsigned int       matched      = 0;
    for (const auto &p : whole)
      {
        const auto it = by_centre.find(key(centroid(p)));
        if (it == by_centre.end())
          continue;
        ++matched;
        const auto &q = *it->second;
        for (unsigned int v = 0; v < 8; ++v)
          vertex_error =
            std::max(vertex_error, p.vertices[v].distance(q.vertices[v]));
        for (unsigned int r = 0; r < names.size(); ++r)
          for (unsigned int j = 0; j < p.data.n_cols(); ++j)
            {
              scale[r] = std::max(scale[r], std::abs(p.data(r, j)));
              diff[r] =
                std::max(diff[r], std::abs(p.data(r, j) - q.data(r, j)));
            }
      }

    bool ok = names == part_names && matched == whole.size() &&
              mirror.size() == whole.size() && vertex_error < 1e-12;
    std::printf("whole plate %zu cells, quarter mirrored %zu patches, matched "
                "%u, largest vertex distance below 1e-12 m: %s\n",
                whole.size(),
                mirror.size(),
                matched,
                ok ? "yes" : "NO");
    unsigned int component = 0;
    for (unsigned int r = 0; r < names.size(); ++r)
      {
        component = (r > 0 && names[r] == names[r - 1]) ? component + 1 : 0;
        const double rel = scale[r] > 0 ? diff[r] / scale[r] : diff[r];
        const bool   hit = rel < 1e-5;
        ok               = ok && hit;
        std::printf("  %-22s component %u: max relative difference below "
                    "1e-5: %s\n",
                    names[r].c_str(),
                    component,
                    hit ? "yes" : "NO");
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::symmetry_mirror
