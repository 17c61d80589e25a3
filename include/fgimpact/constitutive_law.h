#ifndef fgimpact_constitutive_law_h
#define fgimpact_constitutive_law_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe.h>

#include <deal.II/grid/tria.h>

#include <fgimpact/material.h>

#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The graded material at a point of an element: E(z) and rho(z) at fixed
   * unit-cell points of any cell, either graded (nodal values of the scalar
   * base element interpolated with its shape functions, Eq. 3.3),
   * homogeneous (the value at the cell centre) or pointwise (E(z), rho(z)
   * at the points themselves).  Assembly, probes and the VTU output all
   * take E from here, so the three see the same material.
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

    /// E (Pa) and rho (kg/m^3) at the unit points of cell.
    void
    values(const typename Triangulation<3>::cell_iterator &cell,
           std::vector<double>                            &E,
           std::vector<double>                            &rho) const;

    /// E (Pa) and rho (kg/m^3) at a real point p inside cell (shape
    /// functions evaluated on the fly: for output, not for loops over
    /// quadrature points).
    std::pair<double, double>
    value_at(const typename Triangulation<3>::cell_iterator &cell,
             const Point<3>                                 &p) const;

  private:
    const FiniteElement<3>           &scalar_fe;
    const FunctionallyGradedMaterial &material;
    /// z coordinate of each evaluation point on the unit cell.
    std::vector<double> unit_point_z;
    /// z coordinate of each scalar support point on the unit cell.
    std::vector<double> unit_support_z;
    /// shape_values[k][q] = N_k(unit point q).
    std::vector<std::vector<double>> shape_values;
  };



  /**
   * Hooke's law of the isotropic graded material, with Poisson's ratio
   * constant through the thickness and E(z) from PropertyInterpolator:
   *
   *   sigma = lambda(E) tr(eps) I + 2 mu(E) eps,
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
    explicit HookeLaw(const FunctionallyGradedMaterial &material)
      : lambda_per_E(material.lambda_per_E())
      , mu_per_E(material.mu_per_E())
    {}

    /// Lame's first parameter lambda at Young's modulus E (Pa).
    double
    lambda(const double E) const
    {
      return lambda_per_E * E;
    }

    /// The shear modulus mu at Young's modulus E (Pa).
    double
    mu(const double E) const
    {
      return mu_per_E * E;
    }

    /// Cauchy stress (Pa) for the strain eps at Young's modulus E (Pa).
    SymmetricTensor<2, 3>
    stress(const double E, const SymmetricTensor<2, 3> &eps) const
    {
      return lambda(E) * trace(eps) * unit_symmetric_tensor<3>() +
             2. * mu(E) * eps;
    }

  private:
    const double lambda_per_E;
    const double mu_per_E;
  };
} // namespace fgimpact

#endif
