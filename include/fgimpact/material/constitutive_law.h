#ifndef fgimpact_constitutive_law_h
#define fgimpact_constitutive_law_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe.h>

#include <deal.II/grid/tria.h>

#include <fgimpact/material/material.h>

#include <map>
#include <memory>
#include <mutex>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * How badly graded elements with sampled nodal values
   * (GradedNodalValues::sampled, the paper's Eq. 3.3) read the profile:
   * over the n_layers equal element layers of the thickness h (m), the
   * largest relative difference between the exact layer average of E(z)
   * and the layer average of its nodal interpolant of degree `degree`
   * (trapezoid rule for 1, Simpson's for 2).  0 for a profile linear in
   * each layer (n = 0, 1); about 0.05 and 0.11 for n = 3 and 5 on 4
   * layers; above 1 for a boundary layer thinner than an element
   * (n -> 0+: the bottom nodes sample the ceramic's E while the layer is
   * almost all metal).  Returns the difference and the layer index
   * (0 = bottom).
   */
  std::pair<double, unsigned int>
  sampled_layer_error(const FunctionallyGradedMaterial &material,
                      const double                      h,
                      const unsigned int                n_layers,
                      const unsigned int                degree);



  /**
   * The graded material at a point of an element: E(z), nu(z) and rho(z) at
   * fixed unit-cell points of any cell, either graded (nodal values of the
   * scalar base element interpolated with its shape functions, Eq. 3.3),
   * homogeneous (the value at the cell centre) or pointwise (E(z), nu(z),
   * rho(z) at the points themselves).  Assembly, probes and the VTU output
   * all take the material from here, so the three see the same material.
   *
   * Graded elements interpolate E and nu (not lambda and mu): with a
   * constant nu this is the paper's Eq. 3.3 on E, and nu is then used
   * exactly, not interpolated; nu stays bounded where lambda would not
   * (nu -> 1/2).  The nodal values are the profile sampled at the nodes or,
   * with GradedNodalValues::layer_average, its element-wise L2 projection
   * in z (computed once per element layer and cached).
   *
   * The shape function table is computed once; cells must be axis-aligned
   * bricks (all cells of this program are).
   */
  class PropertyInterpolator
  {
  public:
    PropertyInterpolator(const FiniteElement<3>           &scalar_fe,
                         const std::vector<Point<3>>      &unit_points,
                         const FunctionallyGradedMaterial &material);

    /// E (Pa), nu and rho (kg/m^3) at the unit points of cell.
    void
    values(const typename Triangulation<3>::cell_iterator &cell,
           std::vector<double>                            &E,
           std::vector<double>                            &nu,
           std::vector<double>                            &rho) const;

    /// E (Pa), nu and rho (kg/m^3) at a real point p inside cell (shape
    /// functions evaluated on the fly: for output, not for loops over
    /// quadrature points).
    IsotropicProperties
    value_at(const typename Triangulation<3>::cell_iterator &cell,
             const Point<3>                                 &p) const;

  private:
    /// The graded nodal values (one per scalar support point) of the
    /// element layer [z0, z0 + hz].
    const std::vector<IsotropicProperties> &
    nodal_values(const double z0, const double hz) const;

    const FiniteElement<3>           &scalar_fe;
    const FunctionallyGradedMaterial &material;
    /// nodal_values() per element layer (z0, hz); shared by copies and
    /// guarded, since DataOut evaluates value_at() on several threads.
    struct Cache
    {
      std::mutex mutex;
      std::map<std::pair<double, double>, std::vector<IsotropicProperties>>
        layers;
    };
    std::shared_ptr<Cache> cache;
    /// z coordinate of each evaluation point on the unit cell.
    std::vector<double> unit_point_z;
    /// z coordinate of each scalar support point on the unit cell.
    std::vector<double> unit_support_z;
    /// shape_values[k][q] = N_k(unit point q).
    std::vector<std::vector<double>> shape_values;
  };



  /**
   * Hooke's law of the isotropic graded material, with E(z) and nu(z) from
   * PropertyInterpolator:
   *
   *   sigma = lambda tr(eps) I + 2 mu eps,
   *   lambda = E nu / ((1 + nu)(1 - 2 nu)),  mu = E / (2 (1 + nu)).
   *
   * E, lambda, mu and sigma in Pa.  The stiffness assembly uses the
   * component form of the same law (lambda div u div v + 2 mu eps:eps, as
   * in step-8) with lambda() and mu(); the probes and the VTU stress use
   * stress().
   */
  class HookeLaw
  {
  public:
    explicit HookeLaw(const FunctionallyGradedMaterial &) {}

    /// Lame's first parameter lambda at Young's modulus E (Pa) and nu.
    static double
    lambda(const double E, const double nu)
    {
      // lambda/E first, then times E: the rounding of the constant-nu
      // program, whose numbers the default scene keeps.
      return nu / ((1. + nu) * (1. - 2. * nu)) * E;
    }

    /// The shear modulus mu at Young's modulus E (Pa) and nu.
    static double
    mu(const double E, const double nu)
    {
      return 1. / (2. * (1. + nu)) * E;
    }

    /// Cauchy stress (Pa) for the strain eps at E (Pa) and nu.
    static SymmetricTensor<2, 3>
    stress(const double E, const double nu, const SymmetricTensor<2, 3> &eps)
    {
      return lambda(E, nu) * trace(eps) * unit_symmetric_tensor<3>() +
             2. * mu(E, nu) * eps;
    }
  };
} // namespace fgimpact

#endif
