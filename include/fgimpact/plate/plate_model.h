#ifndef fgimpact_plate_model_h
#define fgimpact_plate_model_h

#include <deal.II/base/array_view.h>
#include <deal.II/base/index_set.h>
#include <deal.II/base/mpi.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/distributed/tria.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_system.h>
#include <deal.II/fe/fe_values.h>
#include <deal.II/fe/mapping_q.h>

#include <deal.II/lac/affine_constraints.h>
#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_sparsity_pattern.h>
#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/material/material.h>
#include <fgimpact/plate/geometry.h>

#include <memory>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The linear elastic FGM plate discretized with FESystem(FE_Q(p), 3): the
   * mesh, degrees of freedom, support constraints and the constant stiffness
   * and consistent mass matrices (Eqs. 3.10-3.11), as Trilinos objects on a
   * p4est triangulation so that the same code runs under MPI.
   */
  class PlateModel
  {
  public:
    struct Parameters
    {
      unsigned int degree = 1;

      /// B-bar (Finite element/Volumetric strain = cell mean): the
      /// volumetric strain is the cell's mean (Simo-Hughes' mean
      /// dilatation, Abaqus' selectively reduced C3D8).
      bool mean_dilatation = false;

      /// Finite element/Incompatible modes: Wilson-Taylor bubbles
      /// condensed out of each Q1 cell (incompatible_modes.h; Abaqus'
      /// C3D8I), so the brick bends without parasitic shear.
      bool incompatible_modes = false;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    PlateModel(const Parameters                 &parameters,
               const PlateGeometry              &geometry,
               const FunctionallyGradedMaterial &material,
               const MPI_Comm                    mpi_communicator);

    /// Make the mesh (refined near the impact point as asked, then the
    /// cells of each adaptive cycle: PlateGeometry::refine_cells(), then
    /// `split`: PlateGeometry::split_cells()), distribute DoFs, build
    /// constraints and assemble K, M.
    void
    setup(const LocalRefinement                       &refinement      = {},
          const std::vector<std::vector<std::string>> &adaptive_cycles = {},
          const MeshSplit                              split = MeshSplit::none);

    /// The smallest cell edge along x (m), over all ranks.
    double
    smallest_cell_size() const;

    /// The smallest in-plane edge (m) of the cells that touch p, over all
    /// ranks (the element size under the ball at the impact point).
    double
    cell_size_at(const Point<3> &p) const;

    /// The contact refinement the mesh was made with (setup()).
    const LocalRefinement &
    contact_refinement() const
    {
      return refinement;
    }

    types::global_dof_index
    n_dofs() const
    {
      return dof_handler.n_dofs();
    }
    unsigned int
    n_active_cells() const;

    const TrilinosWrappers::SparseMatrix &
    stiffness_matrix() const
    {
      return stiffness;
    }
    const TrilinosWrappers::SparseMatrix &
    mass_matrix() const
    {
      return mass;
    }

    /**
     * On a symmetric part (Geometry/Symmetry): row sums of the mass
     * couplings the cuts remove (to u_x on x = a/2 and u_y on y = b/2, and
     * to the hanging nodes they constrain through them), which the
     * condensed mass_matrix() drops and the whole plate's keeps;
     * mass_matrix() 1 plus this vector is the whole plate's row-sum lumped
     * mass restricted to the part.  Empty without cuts.
     */
    const TrilinosWrappers::MPI::Vector &
    cut_mass_coupling() const
    {
      return cut_coupling;
    }

    /// K += K_sigma: the initial-stress stiffness of a pre-stress
    /// (assemble_geometric_stiffness(), on K's sparsity), before any
    /// analysis reads K.
    void
    add_initial_stress_stiffness(const TrilinosWrappers::SparseMatrix &K_sigma)
    {
      stiffness.add(1., K_sigma);
    }

    /// The sparsity of K and M (constraints condensed), for another
    /// matrix assembled on the same couplings under MPI.
    TrilinosWrappers::SparsityPattern
    sparsity_pattern() const;

    /// Reinit v as a (non-ghosted) vector of locally owned DoFs.
    void
    initialize_vector(TrilinosWrappers::MPI::Vector &v) const;

    /**
     * The top-surface (z = h) vertex nearest to (x, y) and the global index
     * of its DoF of the given component, the same on every MPI rank (ties
     * are broken by the vertex coordinates, not by the DoF numbering, which
     * depends on the partition).  The point force of the contact law acts
     * there, as in the paper.
     */
    std::pair<types::global_dof_index, Point<3>>
    nearest_top_vertex_dof(const Point<2>    &xy,
                           const unsigned int component) const;

    /// The vertex nearest to a point anywhere in the plate and its DoF of
    /// the given component, the same on every MPI rank.
    std::pair<types::global_dof_index, Point<3>>
    nearest_vertex_dof(const Point<3>    &target,
                       const unsigned int component) const;

    /**
     * The value of a (non-ghosted) distributed vector at one DoF, on every
     * rank: the owner contributes it to a sum over the ranks (one scalar
     * all-reduce).  Collective.
     */
    double
    dof_value(const TrilinosWrappers::MPI::Vector &v,
              const types::global_dof_index        dof) const;

    /// dof_value() at several DoFs with one all-reduce. Collective.
    Vector<double>
    dof_values(const TrilinosWrappers::MPI::Vector        &v,
               const std::vector<types::global_dof_index> &dofs) const;

    /**
     * B-bar (Parameters::mean_dilatation): in every strain the plate
     * evaluates, the cell's mean volumetric strain theta = (1/|K|) int_K
     * div u replaces the pointwise div u, so that a nearly incompressible
     * (plastic) flow does not lock the element's pressure.  These are the
     * weights of theta over the cell's DoFs, (1/|K|) int_K div phi_i in
     * the cell's DoF order (1/m); empty when the strain is pointwise.
     * Locally owned cells only.
     */
    ArrayView<const double>
    mean_divergence(const DoFHandler<3>::active_cell_iterator &cell) const;

    /// True if the plate's strains take the cell's mean dilatation.
    bool
    uses_mean_dilatation() const
    {
      return parameters.mean_dilatation;
    }

    /// theta of a ghosted vector on a locally owned cell (0 without
    /// B-bar: use with_mean_dilatation() only when it applies).
    double
    mean_dilatation(const DoFHandler<3>::active_cell_iterator &cell,
                    const TrilinosWrappers::MPI::Vector       &u) const;

    /// With B-bar, every eps of a locally owned cell with its trace
    /// replaced by the cell's mean dilatation of the ghosted u; else
    /// nothing.
    void
    apply_mean_dilatation(const DoFHandler<3>::active_cell_iterator &cell,
                          const TrilinosWrappers::MPI::Vector       &u,
                          std::vector<SymmetricTensor<2, 3>>        &eps) const;

    /// True if the plate's bricks have incompatible modes
    /// (Parameters::incompatible_modes).
    bool
    uses_incompatible_modes() const
    {
      return parameters.incompatible_modes;
    }

    /// What the element is beyond its degree, as summary.txt's
    /// element_technology and the log's header name it: standard |
    /// incompatible modes | mean dilatation.
    std::string
    element_technology() const
    {
      return uses_incompatible_modes() ? "incompatible modes" :
             uses_mean_dilatation()    ? "mean dilatation" :
                                         "standard";
    }

    /**
     * Incompatible modes (incompatible_modes.h): H = -K_aa^{-1} K_au of a
     * locally owned cell, the modes' amplitudes per unit value of each of
     * its DoFs (n_modes x DoFs per cell), recomputed from the cell's graded
     * material as assemble() condensed it; empty without modes.
     */
    FullMatrix<double>
    mode_amplitudes(const DoFHandler<3>::active_cell_iterator &cell) const;

    /// Incompatible modes: eps[k] += the modes' strain of the ghosted u at
    /// unit_points[k] of a locally owned cell, so that eps is the strain
    /// the stiffness has; nothing without modes.
    void
    add_mode_strains(const DoFHandler<3>::active_cell_iterator &cell,
                     const std::vector<Point<3>>               &unit_points,
                     const TrilinosWrappers::MPI::Vector       &u,
                     std::vector<SymmetricTensor<2, 3>>        &eps) const;

    /// The modes' strain of each DoF of a locally owned cell at each unit
    /// point, [k][i] (1/m per unit DoF value), to add to shape_strain();
    /// zero without incompatible modes.
    std::vector<std::vector<SymmetricTensor<2, 3>>>
    mode_shape_strains(const DoFHandler<3>::active_cell_iterator &cell,
                       const std::vector<Point<3>> &unit_points) const;

    /// eps with its trace replaced by theta: eps + (theta - tr eps)/3 1.
    static SymmetricTensor<2, 3>
    with_dilatation(const SymmetricTensor<2, 3> &eps, const double theta)
    {
      return eps + ((theta - trace(eps)) / 3.) * unit_symmetric_tensor<3>();
    }

    /// The strain of vector shape function i at point q of fe_values: its
    /// component c's symmetric gradient, sym(e_c (x) grad N_i), with the
    /// cell's mean dilatation if mean_div (mean_divergence()) is not empty
    /// (B-bar). Unit: 1/m per unit DoF value.
    static SymmetricTensor<2, 3>
    shape_strain(const FEValues<3>             &fe_values,
                 const unsigned int             i,
                 const unsigned int             q,
                 const ArrayView<const double> &mean_div)
    {
      const unsigned int c =
        fe_values.get_fe().system_to_component_index(i).first;
      const Tensor<1, 3>    g = fe_values.shape_grad(i, q);
      SymmetricTensor<2, 3> eps;
      for (unsigned int d = 0; d < 3; ++d)
        eps[c][d] += (c == d ? 1. : 0.5) * g[d];
      return mean_div.size() > 0 ? with_dilatation(eps, mean_div[i]) : eps;
    }

    /// The MPI rank that owns a DoF. Collective.
    unsigned int
    dof_owner(const types::global_dof_index dof) const;

    /// Sum of all mass matrix entries of one displacement component, i.e.
    /// the total mass of the plate in kg (partition of unity).
    double
    total_mass() const;

    const DoFHandler<3> &
    get_dof_handler() const
    {
      return dof_handler;
    }
    const AffineConstraints<double> &
    get_constraints() const
    {
      return constraints;
    }
    const Mapping<3> &
    get_mapping() const
    {
      return mapping;
    }
    const FESystem<3> &
    get_fe() const
    {
      return fe;
    }
    const PlateGeometry &
    get_geometry() const
    {
      return geometry;
    }
    const FunctionallyGradedMaterial &
    get_material() const
    {
      return material;
    }
    const IndexSet &
    locally_owned_dofs() const
    {
      return locally_owned;
    }
    const IndexSet &
    locally_relevant_dofs() const
    {
      return locally_relevant;
    }
    MPI_Comm
    get_mpi_communicator() const
    {
      return mpi_communicator;
    }

  private:
    /// Both searches above: ties broken by the coordinates.
    std::pair<types::global_dof_index, Point<3>>
    nearest_vertex(const Point<3>    &target,
                   const unsigned int component,
                   const bool         boundary_cells_only) const;

    /// The components a support fixes on boundary face id (0-4); none on
    /// a free face, a symmetry cut or the top.
    ComponentMask
    support_mask(const unsigned int face) const;

    void
    setup_constraints();

    /// Hanging nodes and supports into c, and with_cuts the symmetry cuts.
    void
    make_constraints(AffineConstraints<double> &c, const bool with_cuts) const;
    /**
     * Boundary conditions/In-plane edges = immovable
     * (source/plate/edge_constraints.cc): on every column of nodes through
     * the thickness of a simply supported side, the mean over z of the
     * normal in-plane displacement vanishes (a distributed coupling: the
     * side may rotate about its mid-plane, not translate).  Holding the
     * mid-plane nodes alone would be a line support on a 3D body, whose
     * restraint softens under refinement (u ~ log r).
     */
    void
    add_immovable_edges(AffineConstraints<double> &c) const;

    /// One column's constraint, column = (z, DoF) pairs sorted by z: the
    /// node nearest the mid-plane as minus the weighted others.
    void
    add_mean_constraint(const std::vector<std::pair<double, double>> &column,
                        AffineConstraints<double>                    &c) const;

    /// In-plane edges = immovable: the columns of the simply supported
    /// sides' normal-component DoFs that the supports and hanging nodes of
    /// c leave free, gathered from their owners; their DoFs join
    /// locally_relevant.  Collective.
    void
    collect_edge_columns(const AffineConstraints<double> &c);
    void
    assemble();
    /// B-bar: the pointwise dilatation of cell_K replaced by the cell's
    /// mean (source/plate/mean_dilatation.cc); its weights into
    /// mean_divergences.
    void
    replace_dilatation(const FEValues<3>                         &fe_values,
                       const std::vector<double>                 &E,
                       const std::vector<double>                 &nu,
                       const DoFHandler<3>::active_cell_iterator &cell,
                       FullMatrix<double>                        &cell_K);

    const Parameters                  parameters;
    const PlateGeometry              &geometry;
    const FunctionallyGradedMaterial &material;
    const MPI_Comm                    mpi_communicator;

    parallel::distributed::Triangulation<3> triangulation;
    const FESystem<3>                       fe;
    const MappingQ<3>                       mapping;
    DoFHandler<3>                           dof_handler;
    IndexSet                                locally_owned, locally_relevant;
    AffineConstraints<double>               constraints;
    TrilinosWrappers::SparseMatrix          stiffness, mass;
    TrilinosWrappers::MPI::Vector           cut_coupling;
    LocalRefinement                         refinement;
    /// collect_edge_columns(): (z, DoF) per node, each column sorted by z.
    std::vector<std::vector<std::pair<double, double>>> edge_columns;
    /// mean_divergence() of every locally owned cell, by active index.
    std::vector<double> mean_divergences;

    void
    assemble_cut_mass_coupling();
  };
} // namespace fgimpact

#endif
