#include <deal.II/base/quadrature_lib.h>

#include <deal.II/dofs/dof_tools.h>

#include <deal.II/fe/fe_q.h>
#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_sparsity_pattern.h>

#include <deal.II/numerics/vector_tools.h>

#include <fgimpact/plate/cell_matrices.h>
#include <fgimpact/plate/incompatible_modes.h>
#include <fgimpact/plate/plate_model.h>

#include <algorithm>
#include <array>
#include <limits>

namespace fgimpact
{
  PlateModel::PlateModel(const Parameters                 &parameters,
                         const PlateGeometry              &geometry,
                         const FunctionallyGradedMaterial &material,
                         const MPI_Comm                    mpi_communicator)
    : parameters(parameters)
    , geometry(geometry)
    , material(material)
    , mpi_communicator(mpi_communicator)
    , triangulation(mpi_communicator)
    , fe(FE_Q<3>(parameters.degree), 3)
    , mapping(1)
    , dof_handler(triangulation)
  {}



  unsigned int
  PlateModel::n_active_cells() const
  {
    return triangulation.n_global_active_cells();
  }



  double
  PlateModel::smallest_cell_size() const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        h = std::min(h, cell->extent_in_direction(0));
    return Utilities::MPI::min(h, mpi_communicator);
  }



  double
  PlateModel::cell_size_at(const Point<3> &p) const
  {
    double h = std::numeric_limits<double>::max();
    for (const auto &cell : triangulation.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          const BoundingBox<3> box       = cell->bounding_box();
          const double         tolerance = 1e-10 * cell->diameter();
          bool                 inside    = true;
          for (unsigned int d = 0; d < 3; ++d)
            inside = inside && p[d] >= box.lower_bound(d) - tolerance &&
                     p[d] <= box.upper_bound(d) + tolerance;
          if (inside)
            h = std::min(
              {h, cell->extent_in_direction(0), cell->extent_in_direction(1)});
        }
    return Utilities::MPI::min(h, mpi_communicator);
  }



  void
  PlateModel::setup(
    const LocalRefinement                       &refinement,
    const std::vector<std::vector<std::string>> &adaptive_cycles,
    const MeshSplit                              split)
  {
    this->refinement = refinement;
    geometry.create_triangulation(triangulation);
    PlateGeometry::refine_locally(triangulation, refinement);
    PlateGeometry::refine_cells(triangulation, adaptive_cycles);
    PlateGeometry::split_cells(triangulation, refinement, split);
    dof_handler.distribute_dofs(fe);
    locally_owned = dof_handler.locally_owned_dofs();
    DoFTools::extract_locally_relevant_dofs(dof_handler, locally_relevant);
    setup_constraints();

    const TrilinosWrappers::SparsityPattern sparsity = sparsity_pattern();
    stiffness.reinit(sparsity);
    mass.reinit(sparsity);
    if (parameters.mean_dilatation)
      mean_divergences.assign(triangulation.n_active_cells() *
                                fe.n_dofs_per_cell(),
                              0.);
    assemble();
    if (geometry.is_cut(0) || geometry.is_cut(1))
      assemble_cut_mass_coupling();
  }



  void
  PlateModel::assemble_cut_mass_coupling()
  {
    // The whole plate's row-sum lumped mass is C_w^T M C_w 1, the part's
    // condensed mass_matrix() gives C_p^T M C_p 1: the part's constraints
    // C_p also set the cut's normal DoFs to zero, and with them half of a
    // hanging node whose coarse edge ends on a cut.  The difference that
    // restores the whole plate's lumped mass on the part is
    // C_p^T M (e - C_p 1) with e = C_w 1, the ones under the constraints
    // of the supports and hanging nodes alone (the whole plate's, which
    // are mirror-symmetric).  It is non-zero next to the cuts
    // only (a hanging node's cells need not touch the cut).
    AffineConstraints<double> whole_plate;
    make_constraints(whole_plate, /*with_cuts=*/false);
    TrilinosWrappers::MPI::Vector e_owned, c_owned;
    initialize_vector(e_owned);
    initialize_vector(c_owned);
    e_owned = 1.;
    c_owned = 1.;
    whole_plate.distribute(e_owned);
    constraints.distribute(c_owned);
    TrilinosWrappers::MPI::Vector difference(locally_owned,
                                             locally_relevant,
                                             mpi_communicator);
    e_owned -= c_owned;
    difference = e_owned;

    const QGauss<3>                      quadrature(fe.degree + 1);
    FEValues<3>                          fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_JxW_values);
    PropertyInterpolator                 properties(fe.base_element(0),
                                    quadrature.get_points(),
                                    material);
    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    Vector<double>                       cell_r(dofs_per_cell);
    Vector<double>                       cell_d(dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<double>                  E, nu, rho;
    initialize_vector(cut_coupling);
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          cell->get_dof_values(difference, cell_d);
          if (cell_d.linfty_norm() == 0.)
            continue;
          fe_values.reinit(cell);
          properties.values(cell, E, nu, rho);
          cell_r = 0;
          add_cell_mass_product(fe_values, rho, cell_d, cell_r);
          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_r,
                                                 local_dofs,
                                                 cut_coupling);
        }
    cut_coupling.compress(VectorOperation::add);
  }



  ComponentMask
  PlateModel::support_mask(const unsigned int face) const
  {
    // On x = const faces (ids 0, 1) the tangential in-plane component is
    // v (index 1); on y = const faces (ids 2, 3) it is u (index 0); on the
    // bottom (id 4) simply supported constrains w alone.  A symmetry cut
    // (x = a/2 is id 1, y = b/2 id 3 of the part) is no support.
    ComponentMask mask(3, false);
    if (face > 4 || (face == 1 && geometry.is_cut(0)) ||
        (face == 3 && geometry.is_cut(1)))
      return mask;
    const SideSupport support =
      (face < 4 ? geometry.get_parameters().supports[face] :
                  geometry.get_parameters().bottom_support);
    switch (support)
      {
        case SideSupport::free:
          break;
        case SideSupport::clamped:
          mask = ComponentMask(3, true);
          break;
        case SideSupport::simply_supported:
          mask.set(2, true);
          if (face < 4)
            mask.set(face < 2 ? 1 : 0, true);
          break;
      }
    return mask;
  }



  void
  PlateModel::setup_constraints()
  {
    const bool cuts = geometry.is_cut(0) || geometry.is_cut(1);
    edge_columns.clear();
    make_constraints(constraints, cuts);
    if (geometry.get_parameters().immovable_edges)
      {
        // The immovable sides' columns need the supports first, and widen
        // the relevant set: the constraints once more, with their lines.
        collect_edge_columns(constraints);
        make_constraints(constraints, cuts);
      }
  }



  void
  PlateModel::make_constraints(AffineConstraints<double> &c,
                               const bool                 with_cuts) const
  {
    c.clear();
    c.reinit(locally_relevant);
    DoFTools::make_hanging_node_constraints(dof_handler, c);

    for (unsigned int face = 0; face < 5; ++face)
      {
        ComponentMask mask = support_mask(face);
        // A symmetry cut: the normal displacement vanishes, the tangential
        // ones are free.
        if (with_cuts && ((face == 1 && geometry.is_cut(0)) ||
                          (face == 3 && geometry.is_cut(1))))
          mask.set(face == 1 ? 0 : 1, true);
        if (mask.n_selected_components() == 0)
          continue;
        VectorTools::interpolate_boundary_values(
          mapping, dof_handler, face, Functions::ZeroFunction<3>(3), c, mask);
      }
    add_immovable_edges(c);
    c.close();
  }



  TrilinosWrappers::SparsityPattern
  PlateModel::sparsity_pattern() const
  {
    // Rows of the ghost DoFs writable: a rank adds its cells' entries to
    // rows other ranks own.
    TrilinosWrappers::SparsityPattern sparsity(locally_owned,
                                               locally_owned,
                                               locally_relevant,
                                               mpi_communicator);
    DoFTools::make_sparsity_pattern(dof_handler,
                                    sparsity,
                                    constraints,
                                    /*keep_constrained_dofs=*/false,
                                    Utilities::MPI::this_mpi_process(
                                      mpi_communicator));
    sparsity.compress();
    return sparsity;
  }



  void
  PlateModel::assemble()
  {
    const QGauss<3>      quadrature(fe.degree + 1);
    FEValues<3>          fe_values(mapping,
                          fe,
                          quadrature,
                          update_values | update_gradients | update_JxW_values);
    PropertyInterpolator properties(fe.base_element(0),
                                    quadrature.get_points(),
                                    material);

    const unsigned int                   dofs_per_cell = fe.n_dofs_per_cell();
    FullMatrix<double>                   cell_K(dofs_per_cell, dofs_per_cell);
    FullMatrix<double>                   cell_M(dofs_per_cell, dofs_per_cell);
    std::vector<types::global_dof_index> local_dofs(dofs_per_cell);
    std::vector<double>                  E, nu, rho;

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          properties.values(cell, E, nu, rho);
          cell_K = 0;
          cell_M = 0;

          add_elastic_cell_matrices(fe_values, E, nu, rho, cell_K, cell_M);
          if (parameters.mean_dilatation)
            replace_dilatation(fe_values, E, nu, cell, cell_K);
          if (parameters.incompatible_modes)
            IncompatibleModes::condense(
              fe_values,
              E,
              nu,
              IncompatibleModes::centre_inverse_jacobian(cell),
              cell_K,
              nullptr);
          cell->get_dof_indices(local_dofs);
          constraints.distribute_local_to_global(cell_K, local_dofs, stiffness);
          constraints.distribute_local_to_global(cell_M, local_dofs, mass);
        }
    stiffness.compress(VectorOperation::add);
    mass.compress(VectorOperation::add);
  }



  void
  PlateModel::initialize_vector(TrilinosWrappers::MPI::Vector &v) const
  {
    v.reinit(locally_owned, mpi_communicator);
  }



  std::pair<types::global_dof_index, Point<3>>
  PlateModel::nearest_top_vertex_dof(const Point<2>    &xy,
                                     const unsigned int component) const
  {
    return nearest_vertex(Point<3>(xy[0], xy[1], geometry.thickness()),
                          component,
                          /*boundary_cells_only=*/true);
  }



  std::pair<types::global_dof_index, Point<3>>
  PlateModel::nearest_vertex_dof(const Point<3>    &target,
                                 const unsigned int component) const
  {
    return nearest_vertex(target, component, false);
  }



  std::pair<types::global_dof_index, Point<3>>
  PlateModel::nearest_vertex(const Point<3>    &target,
                             const unsigned int component,
                             const bool         boundary_cells_only) const
  {
    // The best candidate of this rank: (distance, x, y, z, dof), compared
    // lexicographically so that every partition picks the same vertex.
    using Candidate = std::array<double, 5>;
    Candidate best  = {{std::numeric_limits<double>::max(), 0, 0, 0, -1.}};

    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned() &&
          (cell->at_boundary() || !boundary_cells_only))
        for (const unsigned int v : cell->vertex_indices())
          {
            const Point<3> &p = cell->vertex(v);
            const Candidate candidate{
              {p.distance(target),
               p[0],
               p[1],
               p[2],
               static_cast<double>(cell->vertex_dof_index(v, component))}};
            if (std::lexicographical_compare(candidate.begin(),
                                             candidate.begin() + 4,
                                             best.begin(),
                                             best.begin() + 4))
              best = candidate;
          }

    const std::vector<Candidate> all =
      Utilities::MPI::all_gather(mpi_communicator, best);
    for (const auto &candidate : all)
      if (std::lexicographical_compare(candidate.begin(),
                                       candidate.begin() + 4,
                                       best.begin(),
                                       best.begin() + 4))
        best = candidate;
    return {static_cast<types::global_dof_index>(best[4]),
            Point<3>(best[1], best[2], best[3])};
  }



  double
  PlateModel::dof_value(const TrilinosWrappers::MPI::Vector &v,
                        const types::global_dof_index        dof) const
  {
    const double local = locally_owned.is_element(dof) ? v(dof) : 0.;
    return Utilities::MPI::sum(local, mpi_communicator);
  }



  Vector<double>
  PlateModel::dof_values(const TrilinosWrappers::MPI::Vector        &v,
                         const std::vector<types::global_dof_index> &dofs) const
  {
    Vector<double> local(dofs.size()), global(dofs.size());
    for (unsigned int j = 0; j < dofs.size(); ++j)
      if (locally_owned.is_element(dofs[j]))
        local[j] = v(dofs[j]);
    Utilities::MPI::sum(ArrayView<const double>(local.begin(), local.size()),
                        mpi_communicator,
                        ArrayView<double>(global.begin(), global.size()));
    return global;
  }



  unsigned int
  PlateModel::dof_owner(const types::global_dof_index dof) const
  {
    const unsigned int local =
      locally_owned.is_element(dof) ?
        Utilities::MPI::this_mpi_process(mpi_communicator) :
        0;
    return Utilities::MPI::max(local, mpi_communicator);
  }



  double
  PlateModel::total_mass() const
  {
    const QGauss<3>      quadrature(fe.degree + 1);
    FEValues<3>          fe_values(mapping, fe, quadrature, update_JxW_values);
    PropertyInterpolator properties(fe.base_element(0),
                                    quadrature.get_points(),
                                    material);
    std::vector<double>  E, nu, rho;
    double               m = 0;
    for (const auto &cell : dof_handler.active_cell_iterators())
      if (cell->is_locally_owned())
        {
          fe_values.reinit(cell);
          properties.values(cell, E, nu, rho);
          for (unsigned int q = 0; q < quadrature.size(); ++q)
            m += rho[q] * fe_values.JxW(q);
        }
    return Utilities::MPI::sum(m, mpi_communicator);
  }
} // namespace fgimpact
