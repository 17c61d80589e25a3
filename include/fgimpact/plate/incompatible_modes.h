#ifndef fgimpact_incompatible_modes_h
#define fgimpact_incompatible_modes_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/grid/tria.h>

#include <deal.II/lac/full_matrix.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Wilson and Taylor's incompatible modes of the 8-node brick (Abaqus'
   * C3D8I; Taylor, Beresford and Wilson 1976): each displacement component
   * c gains the three bubbles 1 - xi_d^2 (xi in [-1, 1] along the cell's
   * unit direction d), nine internal unknowns alpha per cell.  They add
   * the strains of a linear-in-z bending field that the trilinear brick
   * can only take as a parasitic shear, so a brick with one or two layers
   * through the thickness bends without locking.  The modes are internal:
   * alpha = H u_K with H = -K_aa^{-1} K_au is condensed out of the cell
   * stiffness, the mass has no share in them (they are strain
   * enhancements, not motion).  Their gradients are taken with the
   * Jacobian at the cell's centre (Taylor's form, which passes the patch
   * test on parallelepipeds; the plate's cells are boxes).
   */
  namespace IncompatibleModes
  {
    /// Nine modes: a = 3 c + d for component c, direction d.
    constexpr unsigned int n_modes = 9;

    /// The inverse of the Jacobian dx/dxhat at the cell's centre (m^-1
    /// per unit coordinate), from the cell's vertices (trilinear map).
    Tensor<2, 3>
    centre_inverse_jacobian(const Triangulation<3>::cell_iterator &cell);

    /// The strain of mode a (unit amplitude, m) at a unit-cell point of a
    /// cell with centre_inverse_jacobian() J0inv: sym(e_c (x) grad N_d),
    /// grad N_d = J0inv^T dN_d/dxhat (1/m).
    SymmetricTensor<2, 3>
    mode_strain(const unsigned int  a,
                const Point<3>     &unit_point,
                const Tensor<2, 3> &J0inv);

    /**
     * Condense the modes out of one Q1 cell's stiffness: with the cell's
     * quadrature (fe_values: gradients, JxW), its E (Pa) and nu at the
     * points and J0inv, cell_K -= K_au^T K_aa^{-1} K_au; and if H is not
     * null, H = -K_aa^{-1} K_au (n_modes x dofs per cell, the modes'
     * amplitudes per unit DoF value).
     */
    void
    condense(const FEValues<3>         &fe_values,
             const std::vector<double> &E,
             const std::vector<double> &nu,
             const Tensor<2, 3>        &J0inv,
             FullMatrix<double>        &cell_K,
             FullMatrix<double>        *H);
  } // namespace IncompatibleModes
} // namespace fgimpact

#endif
