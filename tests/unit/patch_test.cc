// Patch test: a homogeneous plate (free faces) under a linear displacement
// field u = u0 + G x (uniform strain) is in equilibrium, so the assembled
// K u vanishes at every interior DoF, and the probe stress equals
// lambda tr(eps) I + 2 mu eps exactly.  Q1 and Q2, on a mesh with unequal
// element sizes in the three directions.  Also: the probe evaluates the
// graded stress E(z) Lambda eps at a point between nodes exactly for n = 1.

#include <deal.II/base/function.h>
#include <deal.II/base/mpi.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/numerics/vector_tools.h>

#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/probes.h>

#include <cmath>
#include <cstdio>

namespace fgimpact_unit_tests::patch_test
{

  using namespace fgimpact;

  namespace
  {
    const Tensor<2, 3> G({{2e-4, 0.5e-4, -1e-4},
                          {1.5e-4, -3e-4, 0.2e-4},
                          {0.7e-4, -0.4e-4, 1e-4}});

    class LinearField : public Function<3>
    {
    public:
      LinearField()
        : Function<3>(3)
      {}
      double
      value(const Point<3> &p, const unsigned int c) const override
      {
        return 1e-5 * (c + 1) + (G * p)[c];
      }
    };

    bool
    run(const unsigned int degree,
        const double       n,
        const PropertyMode mode,
        const double       E_c)
    {
      PlateGeometry::Parameters gp;
      gp.subdivisions_x = 3;
      gp.subdivisions_y = 4;
      gp.subdivisions_z = 2;
      gp.supports.fill(SideSupport::free);
      const PlateGeometry                    geometry(gp);
      FunctionallyGradedMaterial::Parameters mp;
      mp.power_law_index        = n;
      mp.property_mode          = mode;
      mp.ceramic_youngs_modulus = E_c;
      const FunctionallyGradedMaterial material(mp, geometry.thickness());
      PlateModel::Parameters           fp;
      fp.degree = degree;
      PlateModel plate(fp, geometry, material, MPI_COMM_WORLD);
      plate.setup();

      TrilinosWrappers::MPI::Vector u, r;
      plate.initialize_vector(u);
      plate.initialize_vector(r);
      VectorTools::interpolate(plate.get_mapping(),
                               plate.get_dof_handler(),
                               LinearField(),
                               u);
      plate.stiffness_matrix().vmult(r, u);

      // Interior DoFs: those not on any boundary face.
      const IndexSet boundary =
        DoFTools::extract_boundary_dofs(plate.get_dof_handler());
      double interior = 0, all = 0;
      for (types::global_dof_index i = 0; i < plate.n_dofs(); ++i)
        {
          all = std::max(all, std::abs(r(i)));
          if (!boundary.is_element(i))
            interior = std::max(interior, std::abs(r(i)));
        }

      const SymmetricTensor<2, 3> eps = symmetrize(G);
      // A point between nodes (z = h/3 is not a node plane for nz = 2).
      const Point<3>   p(0.07, 0.031, geometry.thickness() / 3);
      const PointProbe probe(plate, p);
      const double     nu = material.poissons_ratio(p[2]);
      const double     E  = material.youngs_modulus(
        mode == PropertyMode::graded ? p[2] : geometry.thickness() / 4);
      const SymmetricTensor<2, 3> exact =
        E / (1. + nu) *
        (nu / (1. - 2. * nu) * trace(eps) * unit_symmetric_tensor<3>() + eps);
      const double stress_error =
        (probe.stress(u) - exact).norm() / exact.norm();

      const bool homogeneous = (E_c == 70e9);
      const bool pass =
        (!homogeneous || interior <= 1e-12 * all) && stress_error <= 1e-12;
      std::printf("Q%u, %s material, %s elements: %s%s\n",
                  degree,
                  homogeneous ? "homogeneous" : "n = 1 graded",
                  mode == PropertyMode::graded ? "graded" : "homogeneous",
                  homogeneous ?
                    (interior <= 1e-12 * all ? "interior residual zero, " :
                                               "INTERIOR RESIDUAL NONZERO, ") :
                    "",
                  stress_error <= 1e-12 ? "probe stress exact" :
                                          "PROBE STRESS WRONG");
      return pass;
    }
  } // namespace

  int
  test_main(int argc, char **argv)
  {
    Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
    bool                             ok = true;
    for (const unsigned int degree : {1u, 2u})
      for (const auto mode : {PropertyMode::graded, PropertyMode::homogeneous})
        ok = run(degree, 1., mode, 70e9) && ok;
    // Graded n = 1 material: the probe's E(z) is the exact linear interpolant.
    ok = run(1, 1., PropertyMode::graded, 380e9) && ok;
    std::printf("%s\n", ok ? "all checks passed" : "SOME CHECKS FAILED");
    return ok ? 0 : 1;
  }
} // namespace fgimpact_unit_tests::patch_test
