// Total mass of the graded plate from the assembled consistent mass matrix,
// sum_ij M_ij over the x-displacement DoFs (free faces: no constraints),
// against
//  - the exact int rho(z) dV where the graded interpolant is exact
//    (n = 1 with Q1, n = 2 with Q2),
//  - the trapezoidal rule of the nodal values (n = 2, Q1 graded) and the
//    midpoint rule (homogeneous elements), which is what the interpolants
//    integrate to, and
//  - the exact value in the limit: the observed order of convergence.

#include <deal.II/base/mpi.h>

#include <fgimpact/plate/plate_model.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::plate_mass
{

  using namespace fgimpact;

  namespace
  {
    const double a = 0.2, b = 0.1, h = 0.02;

    double
    assembled_mass(const double       n,
                   const unsigned int nz,
                   const unsigned int degree,
                   const PropertyMode mode)
    {
      PlateGeometry::Parameters gp;
      gp.subdivisions_x = 4;
      gp.subdivisions_y = 2;
      gp.subdivisions_z = nz;
      gp.supports.fill(SideSupport::free);
      const PlateGeometry                    geometry(gp);
      FunctionallyGradedMaterial::Parameters mp;
      mp.power_law_index = n;
      mp.property_mode   = mode;
      const FunctionallyGradedMaterial material(mp, h);
      PlateModel::Parameters           fp;
      fp.degree = degree;
      PlateModel plate(fp, geometry, material, MPI_COMM_WORLD);
      plate.setup();

      TrilinosWrappers::MPI::Vector ones;
      plate.initialize_vector(ones);
      const auto                          &fe = plate.get_fe();
      std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
      for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
        {
          cell->get_dof_indices(dofs);
          for (unsigned int i = 0; i < dofs.size(); ++i)
            if (fe.system_to_component_index(i).first == 0)
              ones(dofs[i]) = 1.;
        }
      ones.compress(VectorOperation::insert);
      const double from_matrix = plate.mass_matrix().matrix_norm_square(ones);
      // The quadrature sum reported in summary.txt must agree.
      AssertThrow(std::abs(plate.total_mass() / from_matrix - 1) < 1e-13,
                  ExcInternalError());
      return from_matrix;
    }

    double
    rho(const double z, const double n)
    {
      return 3800. + (2707. - 3800.) * std::pow(z / h, n);
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;
    auto                             report =
      [&](const char *what, const double value, const double exact) {
        const bool pass = std::abs(value / exact - 1) < 1e-13;
        ok              = ok && pass;
        std::printf("%-58s %s\n", what, pass ? "exact" : "WRONG");
        if (!pass)
          std::printf("  got %.15g, expected %.15g\n", value, exact);
      };

    const double exact_n1 = a * b * h * (3800. + 2707.) / 2;
    report("n = 1, Q1 graded: M total = int rho dV",
           assembled_mass(1, 4, 1, PropertyMode::graded),
           exact_n1);
    const double exact_n2 = a * b * h * (3800. + (2707. - 3800.) / 3.);
    report("n = 2, Q2 graded: M total = int rho dV",
           assembled_mass(2, 2, 2, PropertyMode::graded),
           exact_n2);

    // Trapezoidal and midpoint rules of rho(z) on nz layers.
    auto trapezoid = [](const double n, const unsigned int nz) {
      double s = 0;
      for (unsigned int k = 0; k < nz; ++k)
        s += 0.5 * (rho(k * h / nz, n) + rho((k + 1) * h / nz, n)) * h / nz;
      return a * b * s;
    };
    auto midpoint = [](const double n, const unsigned int nz) {
      double s = 0;
      for (unsigned int k = 0; k < nz; ++k)
        s += rho((k + 0.5) * h / nz, n) * h / nz;
      return a * b * s;
    };
    report("n = 2, Q1 graded: M total = trapezoidal rule of nodal rho",
           assembled_mass(2, 4, 1, PropertyMode::graded),
           trapezoid(2, 4));
    report("n = 2, Q1 homogeneous: M total = midpoint rule of rho",
           assembled_mass(2, 4, 1, PropertyMode::homogeneous),
           midpoint(2, 4));

    std::printf("n = 2, Q1: error of M total against int rho dV\n");
    std::printf("  nz   graded     order   homogeneous order\n");
    double previous[2] = {0, 0};
    for (const unsigned int nz : {2u, 4u, 8u, 16u})
      {
        const double e[2] = {
          std::abs(assembled_mass(2, nz, 1, PropertyMode::graded) / exact_n2 -
                   1),
          std::abs(assembled_mass(2, nz, 1, PropertyMode::homogeneous) /
                     exact_n2 -
                   1)};
        if (nz == 2)
          std::printf("  %2u   %.2e          %.2e\n", nz, e[0], e[1]);
        else
          {
            const double o0 = std::log2(previous[0] / e[0]),
                         o1 = std::log2(previous[1] / e[1]);
            ok = ok && std::abs(o0 - 2) < 0.01 && std::abs(o1 - 2) < 0.01;
            std::printf(
              "  %2u   %.2e   %.2f   %.2e   %.2f\n", nz, e[0], o0, e[1], o1);
          }
        previous[0] = e[0];
        previous[1] = e[1];
      }
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::plate_mass
