#ifndef fgimpact_resources_h
#define fgimpact_resources_h

#include <deal.II/base/mpi.h>

#include <fgimpact/base/memory.h>

#include <string>

namespace fgimpact
{
  struct Parameters;
  struct LocalRefinement;

  /**
   * The memory and time a run needs, estimated from the entries alone
   * (before the mesh exists): DoFs and matrix entries from the brick
   * grid's stencil, the Cholesky factor's entries from a nested-dissection
   * model of the grid (CHOLMOD's symbolic analysis gives the real count
   * later, EffectiveMatrixSolver::initialize()), vectors and VTU output.
   * The per-cell and per-entry byte counts are deal.II's, Epetra's and
   * CHOLMOD's storage (doc/robustness.md, "Resources").
   */
  struct ResourceEstimate
  {
    double n_cells = 0, n_dofs = 0, matrix_nnz = 0, factor_nnz = 0;
    /// Bytes, all ranks together; resident: this rank's resident set when
    /// estimated (libraries, MPI), not in total().
    double resident = 0;
    double mesh = 0, matrices = 0, factor = 0, vectors = 0, output = 0;
    /// A resolved contact: its candidates (the whole plate's, for the
    /// log), and the bytes of their dense compliance and of the unit
    /// responses the implicit stepper computes as the contact reaches
    /// them (counted as n_likely_active() vectors).
    double n_candidates = 0, contact = 0;
    /// Whether the run factorizes (implicit, or static/modal).
    bool factorizes = false;
    /// Wall time of one time step (s) and of the factorization (s), rough.
    double step_time = 0, factorization_time = 0;

    double
    total(const bool with_factor) const
    {
      return mesh + matrices + vectors + output + contact +
             (with_factor ? factor : 0.);
    }

    /// One line for the log.
    std::string
    describe() const;
  };

  /// Entries of the Cholesky factor of a nested-dissection ordering of a
  /// grid of n_x x n_y x n_z nodes with `components` DoFs per node.
  double
  nested_dissection_factor_nnz(double       nx,
                               double       ny,
                               double       nz,
                               unsigned int components = 3);

  /// The estimate for these parameters and the contact refinement
  /// (levels and the radius of its finest core, m:
  /// Simulator::contact_refinement()).
  ResourceEstimate
  estimate_resources(const Parameters      &parameters,
                     const LocalRefinement &refinement);

  /**
   * Refuse (ExcMessage, one line with both numbers and what to change) a
   * run whose estimate exceeds the memory available to the ranks of this
   * node; the factor counts only if the solver cannot fall back to cg
   * (Linear solver/Type = cholmod, klu or mumps).
   */
  void
  check_memory(const Parameters       &parameters,
               const ResourceEstimate &estimate,
               MPI_Comm                mpi_communicator);

  /// check_memory() of the estimate of `parameters` alone, before anything
  /// is built (scene_without_mesh()): what a study checks for every case,
  /// and Accuracy = converged for each level, before they start.
  void
  check_memory_before_setup(const Parameters &parameters,
                            MPI_Comm          mpi_communicator);
} // namespace fgimpact

#endif
