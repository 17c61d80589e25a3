#include <deal.II/base/exceptions.h>

#include <fgimpact/base/memory.h>
#include <fgimpact/contact/resolved_contact.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/problem/resources.h>
#include <fgimpact/problem/scene.h>
#include <fgimpact/problem/symmetry.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <sstream>
#include <sys/resource.h>
#include <unistd.h>

namespace fgimpact
{
  namespace
  {
    // Storage per item, bytes (calibrated against the peak resident size
    // of runs of 3,200 to 86,400 cells: doc/robustness.md, "Resources").
    // A p::d::Triangulation<3> cell with its faces, lines, p4est quadrant,
    // DoF indices and the per-cell caches of the assembly.
    constexpr double bytes_per_cell = 2000;
    // Per matrix entry: the Trilinos pattern (4), the stiffness, mass and
    // effective matrices (8 + 4 each), CHOLMOD's copy of the lower
    // triangle (6) and assembly/extraction transients (6).
    constexpr double bytes_per_entry = 52;
    // Per DoF: about 40 distributed and ghosted vectors.
    constexpr double bytes_per_dof = 320;
    // Per cell and VTU snapshot: the DataOut patches (8 vertices, about 16
    // values each) and the compressed buffer.
    constexpr double bytes_per_output_cell = 2200;
    // Supernodal storage holds explicit zeros: xsize / nnz(L) measured
    // 1.1 to 1.3 with CHOLMOD's METIS/AMD orderings.
    constexpr double supernode_padding = 1.25;
    // Effective memory bandwidth of a back-substitution and a sparse
    // matrix-vector product (B/s), and the dense flop rate of the
    // factorization (flop/s): fitted to 3.1 ms and 0.31 ms per step at
    // 12,915 DoFs (issue 11).
    constexpr double bandwidth = 20e9, flop_rate = 5e9;

    /**
     * Nested dissection of a box of a x b x c nodes whose `border` nodes
     * (earlier separators) are ordered after it: the separator halving the
     * longest side is a dense triangle coupled to the border, and the two
     * halves recurse with half the border plus the separator.  Adds the
     * factorization's flops.
     */
    double
    dissect(double             a,
            double             b,
            double             c,
            const double       border,
            const unsigned int components,
            double            &flops)
    {
      if (a < b)
        std::swap(a, b);
      if (a < c)
        std::swap(a, c);
      const double nodes = a * b * c;
      if (nodes <= 64 || a < 3)
        {
          const double m = components * nodes, r = components * border;
          flops += m * m * m / 3. + m * m * r;
          return m * (m + 1) / 2. + m * r;
        }
      const double m = components * b * c, r = components * border;
      flops += m * m * m / 3. + m * m * r;
      const double half = (a - 1.) / 2.;
      return m * (m + 1) / 2. + m * r +
             2. * dissect(half, b, c, border / 2. + b * c, components, flops);
    }
  } // namespace



  double
  nested_dissection_factor_nnz(const double       nx,
                               const double       ny,
                               const double       nz,
                               const unsigned int components)
  {
    double flops = 0;
    return dissect(nx, ny, nz, 0., components, flops);
  }



  namespace
  {
    /// A resolved contact's own memory (bytes), for n_dofs DoFs of the
    /// part (its share of the plate) whose coarse cells are hx x hy (m),
    /// refined refinement.levels times at the top face: the candidates are its
    /// top nodes within the candidate radius (ContactModelParameters: 1.5 times
    /// the expected contact radius plus two elements), each a column of the
    /// dense compliance (an elastic ball adds its own); the implicit stepper
    /// computes the columns and stores the unit responses, n_dofs floats
    /// each, of the candidates the contact reaches, counted as those
    /// within 2/3 of that radius (ContactModel::n_likely_active(); level 7
    /// of the default scene: 386 counted, 384 computed).
    /// n_candidates: set to the whole plate's count.
    double
    resolved_contact_bytes(const Parameters      &parameters,
                           const LocalRefinement &refinement,
                           const double           n_dofs,
                           const double           share,
                           double                 hx,
                           double                 hy,
                           double                &n_candidates)
    {
      n_candidates = 0;
      if (!parameters.uses_resolved_contact())
        return 0.;
      const double finest = std::pow(2., refinement.levels);
      hx /= finest;
      hy /= finest;
      const double factor = ResolvedSphereContact::candidate_radius_factor;
      const double r_c    = parameters.contact_model.candidate_radius > 0. ?
                              parameters.contact_model.candidate_radius :
                              factor * refinement.contact_radius + 2. * hx;
      n_candidates        = M_PI * r_c * r_c / (hx * hy) + 1.;
      const double part   = share * n_candidates + 1.;
      const double stored = part / (factor * factor) + 1.;
      const double balls  = parameters.impactor.elastic ? 2. : 1.;
      // The compliance in double, the stored responses in single
      // precision (StoredResponse).
      return 8. * balls * part * part + 4. * stored * n_dofs;
    }

    /// Cells: the brick grid's `grid_cells` plus, per contact refinement
    /// pass k, 7 new cells for every cell of size h_k = hx/2^k that
    /// refine_locally() refines: those within the core radius + 2 h_k of
    /// the impact point (box distance, so one more h_k), counted in a
    /// half-ball clipped to the thickness (a cylinder once the ball is
    /// deeper than the plate), its `share` on a symmetric part.
    double
    refined_cells(const PlateGeometry::Parameters &g,
                  const LocalRefinement           &refinement,
                  const double                     share,
                  const double                     grid_cells)
    {
      const double hx = g.length / g.subdivisions_x,
                   hy = g.width / g.subdivisions_y,
                   hz = g.thickness / g.subdivisions_z;
      double n_cells  = grid_cells;
      for (unsigned int k = 0; k < refinement.levels; ++k)
        {
          const double h_k    = hx / std::pow(2., k);
          const double cell   = hx * hy * hz / std::pow(8., k);
          const double d      = refinement.radius + 3. * h_k;
          const double volume = d <= g.thickness ? 2. / 3. * M_PI * d * d * d :
                                                   M_PI * d * d * g.thickness;
          n_cells += 7. * std::min(share * volume / cell, n_cells);
        }
      return n_cells;
    }
  } // namespace



  ResourceEstimate
  estimate_resources(const Parameters      &parameters,
                     const LocalRefinement &refinement)
  {
    const auto        &g = parameters.geometry;
    const unsigned int p = parameters.finite_element.degree;
    ResourceEstimate   e;
    // A symmetric part (Geometry/Symmetry, resolved with the parameters):
    // half the subdivisions across each cut, and the cut share of the
    // refined half-ball.
    const SymmetricPart part  = resolve_symmetry(parameters);
    const double        share = part.share();
    const double        sx    = g.subdivisions_x * (part.cut[0] ? 0.5 : 1.),
                 sy           = g.subdivisions_y * (part.cut[1] ? 0.5 : 1.),
                 sz           = g.subdivisions_z;
    const double hx           = g.length / g.subdivisions_x,
                 hy           = g.width / g.subdivisions_y;
    e.n_cells          = refined_cells(g, refinement, share, sx * sy * sz);
    const double scale = std::cbrt(e.n_cells / (sx * sy * sz));
    // Nodes per direction and the 1D coupling count: a node couples with
    // 3 (Q1) or 8 (Q2, averaged) nodes per direction.
    double       nodes[3], couplings = 9;
    const double n[3] = {sx * scale, sy * scale, sz * scale};
    for (unsigned int d = 0; d < 3; ++d)
      {
        nodes[d] = p * n[d] + 1;
        couplings *= (p == 1 ? 3 * n[d] + 1 : 8 * n[d] + 1);
      }
    e.n_dofs     = 3 * nodes[0] * nodes[1] * nodes[2];
    e.matrix_nnz = couplings;
    double flops = 0;
    e.factor_nnz = dissect(nodes[0], nodes[1], nodes[2], 0., 3, flops);

    const bool impact = parameters.problem_type == ProblemType::impact;
    const bool explicit_scheme =
      impact && parameters.time_integration.scheme ==
                  TimeStepper::Scheme::central_difference;
    e.factorizes = !explicit_scheme && parameters.linear_solver.type !=
                                         EffectiveMatrixSolver::Type::cg;
    e.mesh     = bytes_per_cell * e.n_cells;
    e.matrices = bytes_per_entry * e.matrix_nnz;
    e.vectors  = bytes_per_dof * e.n_dofs;
    e.factor   = e.factorizes ? 8. * supernode_padding * e.factor_nnz : 0.;
    // (End time = auto's factor of K is freed before K_eff's is made.)
    // A mirrored part's VTU holds the whole plate's cells.
    const double output_cells =
      parameters.output.vtu_fields.mirror ? e.n_cells / share : e.n_cells;
    e.output  = parameters.output.vtu_interval > 0 ?
                  bytes_per_output_cell * output_cells :
                  0.;
    e.contact = resolved_contact_bytes(
      parameters, refinement, e.n_dofs, share, hx, hy, e.n_candidates);
    e.factorization_time = e.factorizes ? flops / flop_rate : 0.;
    // A step: two passes over the factor (implicit) or over the matrix
    // (explicit, cg per iteration), plus a few matrix-vector products.
    e.step_time = (e.factorizes ? 16. * e.factor_nnz : 0.) / bandwidth +
                  12. * e.matrix_nnz / bandwidth;
    e.resident = resident_memory();
    return e;
  }



  std::string
  ResourceEstimate::describe() const
  {
    char text[600];
    std::snprintf(
      text,
      sizeof(text),
      "resource estimate: %.3g DoFs, %.3g matrix entries%s; "
      "peak memory ~%s (%s resident now + mesh %s, matrices %s, "
      "vectors %s, factor %s, output %s%s); %s%.2g ms per %s",
      n_dofs,
      matrix_nnz,
      factorizes ?
        (", nnz(L) ~ " + std::to_string(static_cast<long long>(factor_nnz)))
          .c_str() :
        "",
      gigabytes(resident + total(true)).c_str(),
      gigabytes(resident).c_str(),
      gigabytes(mesh).c_str(),
      gigabytes(matrices).c_str(),
      gigabytes(vectors).c_str(),
      gigabytes(factor).c_str(),
      gigabytes(output).c_str(),
      contact > 0 ? (", contact " + gigabytes(contact) + " for ~" +
                     std::to_string(std::lround(n_candidates)) + " candidates")
                      .c_str() :
                    "",
      factorizes ? ("factorization ~" +
                    std::to_string(factorization_time).substr(0, 6) + " s, ")
                     .c_str() :
                   "",
      step_time * 1e3,
      factorizes ? "step" : "step or cg iteration");
    return text;
  }



  void
  check_memory(const Parameters       &parameters,
               const ResourceEstimate &estimate,
               const MPI_Comm          mpi_communicator)
  {
    // The ranks on this node share its MemAvailable; the address-space
    // limit is per process.
    MPI_Comm node;
    MPI_Comm_split_type(
      mpi_communicator, MPI_COMM_TYPE_SHARED, 0, MPI_INFO_NULL, &node);
    int ranks_on_node = 1, n_ranks = 1;
    MPI_Comm_size(node, &ranks_on_node);
    MPI_Comm_free(&node);
    MPI_Comm_size(mpi_communicator, &n_ranks);

    // Only a solver that cannot fall back to cg needs its factor to fit.
    using Type      = EffectiveMatrixSolver::Type;
    const Type type = parameters.linear_solver.type;
    const bool must_factor =
      estimate.factorizes && type != Type::automatic && type != Type::cg;
    const double total = estimate.total(must_factor);

    AvailableMemory available = available_memory();
    const bool      node_wide = available.source.find("MemAvailable") == 0;
    const double    need = total / n_ranks * (node_wide ? ranks_on_node : 1);
    if (need <= available.bytes)
      return;
    std::ostringstream text;
    const auto        &g = parameters.geometry;
    text << "the run needs about " << gigabytes(need)
         << (n_ranks > 1 ? (node_wide ? " on this node" : " per rank") : "")
         << " (Geometry/Subdivisions " << g.subdivisions_x << " x "
         << g.subdivisions_y << " x " << g.subdivisions_z << ", "
         << std::setprecision(3) << estimate.n_dofs << " DoFs: mesh "
         << gigabytes(estimate.mesh) << ", matrices "
         << gigabytes(estimate.matrices) << ", vectors "
         << gigabytes(estimate.vectors)
         << (estimate.contact > 0 ?
               ", resolved contact " + gigabytes(estimate.contact) :
               std::string())
         << (must_factor ?
               ", " + EffectiveMatrixSolver::type_names().name(type) +
                 " factor " + gigabytes(estimate.factor) :
               std::string())
         << ") but " << gigabytes(available.bytes) << " are available ("
         << available.source << "); use fewer Geometry/Subdivisions"
         << (must_factor ? " or Linear solver/Type = auto or cg" : "")
         << ", or more memory or nodes.";
    AssertThrow(false, ExcMessage(text.str()));
  }



  void
  check_memory_before_setup(const Parameters &parameters,
                            const MPI_Comm    mpi_communicator)
  {
    check_memory(parameters,
                 estimate_resources(parameters,
                                    contact_refinement_of(parameters,
                                                          scene_without_mesh(
                                                            parameters))),
                 mpi_communicator);
  }
} // namespace fgimpact
