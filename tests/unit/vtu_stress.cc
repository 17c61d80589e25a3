// The VTU stress (StressPostprocessor, what ParaView shows) against the
// history probe (PointProbe) at the same point, for a smooth non-linear
// displacement field on a graded plate: both must evaluate the same
// constitutive law (PropertyInterpolator + HookeLaw).  At a mesh vertex,
// where the Q1 stress jumps, the probe averages the adjacent cells, so the
// postprocessor's values are averaged over the same cells; inside a cell,
// with pointwise E(z), no averaging is involved.
// B-bar (Finite element/Volumetric strain = cell mean): the VTU and the
// probe again, and the trace of their stress against 3 kappa(z) theta, with
// theta the cell's mean of div u integrated here by its own Gauss rule and
// kappa from E(z), nu of the material.

#include <deal.II/base/function.h>
#include <deal.II/base/quadrature.h>
#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/grid_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <fgimpact/output/postprocessing.h>
#include <fgimpact/plate/probes.h>

#include <cmath>
#include <cstdio>
#include <postprocessor_tools.h>
#include <test_tools.h>

namespace fgimpact_unit_tests::vtu_stress
{

  using namespace dealii;
  using namespace fgimpact;

  namespace
  {
    /// u = 1e-6 m * (x y/a b, y z^2/b h^2, sin(x/a) z/h) in m.
    class Field : public Function<3>
    {
    public:
      Field()
        : Function<3>(3)
      {}
      double
      value(const Point<3> &p, const unsigned int c) const override
      {
        const double x = p[0] / 0.2, y = p[1] / 0.1, z = p[2] / 0.02;
        const double v[3] = {x * y, y * z * z, std::sin(x) * z};
        return 1e-6 * v[c];
      }
    };

    /// The postprocessor's stress (MPa) at p, averaged over the cells that
    /// contain p, and the number of those cells.
    SymmetricTensor<2, 3>
    vtu_stress(const PlateModel                    &plate,
               const TrilinosWrappers::MPI::Vector &u_ghosted,
               const Point<3>                      &p,
               unsigned int                        &n_cells)
    {
      StressPostprocessor postprocessor(plate);
      postprocessor.set_displacement(u_ghosted);
      SymmetricTensor<2, 3> sum;
      n_cells = 0;
      for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
        {
          bool inside = true;
          for (unsigned int d = 0; d < 3; ++d)
            inside = inside && p[d] >= cell->vertex(0)[d] - 1e-12 &&
                     p[d] <= cell->vertex(7)[d] + 1e-12;
          if (!inside)
            continue;
          const Point<3> unit = GeometryInfo<3>::project_to_unit_cell(
            plate.get_mapping().transform_real_to_unit_cell(cell, p));
          sum += fgimpact_tests::postprocessed_stress(
            plate, postprocessor, u_ghosted, cell, unit);
          ++n_cells;
        }
      return sum / static_cast<double>(n_cells);
    }

    /// (1/|K|) int_K div u over the cell that holds p, by QGauss(2).
    double
    mean_divergence(const PlateModel                    &plate,
                    const TrilinosWrappers::MPI::Vector &u_ghosted,
                    const Point<3>                      &p)
    {
      const auto cell =
        GridTools::find_active_cell_around_point(plate.get_mapping(),
                                                 plate.get_dof_handler(),
                                                 p);
      const QGauss<3> quadrature(2);
      FEValues<3>     fe_values(plate.get_mapping(),
                            plate.get_fe(),
                            quadrature,
                            update_gradients | update_JxW_values);
      fe_values.reinit(cell.first);
      std::vector<std::vector<Tensor<1, 3>>> grad(quadrature.size(),
                                                  std::vector<Tensor<1, 3>>(3));
      fe_values.get_function_gradients(u_ghosted, grad);
      double integral = 0, volume = 0;
      for (unsigned int q = 0; q < quadrature.size(); ++q)
        {
          integral +=
            (grad[q][0][0] + grad[q][1][1] + grad[q][2][2]) * fe_values.JxW(q);
          volume += fe_values.JxW(q);
        }
      return integral / volume;
    }

    bool
    compare(const char        *label,
            const PropertyMode mode,
            const Point<3>    &p,
            const bool         bbar = false)
    {
      auto c = fgimpact_tests::make_plate(
        10, 6, 4, 1, 1., mode, 0.02, MPI_COMM_WORLD, 0.3, bbar);
      const auto                   &plate = *c.plate;
      TrilinosWrappers::MPI::Vector u, u_ghosted;
      plate.initialize_vector(u);
      VectorTools::interpolate(plate.get_mapping(),
                               plate.get_dof_handler(),
                               Field(),
                               u);
      u_ghosted.reinit(plate.locally_owned_dofs(),
                       plate.locally_relevant_dofs(),
                       plate.get_mpi_communicator());
      u_ghosted = u;

      unsigned int                n_cells = 0;
      const SymmetricTensor<2, 3> vtu =
        vtu_stress(plate, u_ghosted, p, n_cells);
      const SymmetricTensor<2, 3> probe =
        PointProbe(plate, p).stress(u) * 1e-6; // MPa
      const double error = (vtu - probe).norm() / probe.norm();
      std::printf("%s: %u cells\n", label, n_cells);
      for (unsigned int a = 0; a < 3; ++a)
        std::printf("  sigma_%c%c  VTU %11.6f MPa  probe %11.6f MPa\n",
                    "xyz"[a],
                    "xyz"[a],
                    vtu[a][a],
                    probe[a][a]);
      std::printf("  sigma_xz  VTU %11.6f MPa  probe %11.6f MPa\n",
                  vtu[0][2],
                  probe[0][2]);
      bool pass = error < 1e-12;
      std::printf("  |VTU - probe| / |probe| below 1e-12: %s\n",
                  pass ? "yes" : "NO");
      if (bbar)
        {
          // tr sigma = 3 kappa theta, kappa = E / (3 (1 - 2 nu)).
          const double E        = plate.get_material().youngs_modulus(p[2]);
          const double nu       = plate.get_material().poissons_ratio(p[2]);
          const double theta    = mean_divergence(plate, u_ghosted, p);
          const double expected = 3. * E / (3. * (1. - 2. * nu)) * theta * 1e-6;
          const double trace_error = std::abs(trace(vtu) / expected - 1.);
          // The pointwise trace at p differs (else the check is void).
          const auto cell =
            GridTools::find_active_cell_around_point(plate.get_mapping(),
                                                     plate.get_dof_handler(),
                                                     p);
          const double div_p = [&] {
            FEValues<3> fe_values(plate.get_mapping(),
                                  plate.get_fe(),
                                  Quadrature<3>(
                                    std::vector<Point<3>>{cell.second}),
                                  update_gradients);
            fe_values.reinit(cell.first);
            std::vector<std::vector<Tensor<1, 3>>> grad(
              1, std::vector<Tensor<1, 3>>(3));
            fe_values.get_function_gradients(u_ghosted, grad);
            return grad[0][0][0] + grad[0][1][1] + grad[0][2][2];
          }();
          const bool differs = std::abs(div_p / theta - 1.) > 1e-2;
          std::printf("  trace: VTU %.6f MPa, 3 kappa(z) theta %.6f MPa "
                      "(theta the cell's mean of div u), relative "
                      "difference below 1e-10: %s; the pointwise div u at "
                      "the point differs from theta by more than 1 %%: %s\n",
                      trace(vtu),
                      expected,
                      trace_error < 1e-10 ? "yes" : "NO",
                      differs ? "yes" : "NO");
          pass = pass && trace_error < 1e-10 && differs;
        }
      return pass;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;
    // A vertex inside the plate (8 cells), graded elements (Eq. 3.3).
    ok &= compare("graded, at a vertex",
                  PropertyMode::graded,
                  Point<3>(0.1, 0.05, 0.01));
    // A point inside one cell, pointwise E(z).
    ok &= compare("pointwise, inside a cell",
                  PropertyMode::pointwise,
                  Point<3>(0.0731, 0.0377, 0.0123));
    // The same point with B-bar.
    ok &= compare("B-bar, pointwise, inside a cell",
                  PropertyMode::pointwise,
                  Point<3>(0.0731, 0.0377, 0.0123),
                  true);
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::vtu_stress
