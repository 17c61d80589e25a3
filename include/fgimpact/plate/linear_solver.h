#ifndef fgimpact_linear_solver_h
#define fgimpact_linear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/base/selection.h>

#include <memory>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Solves many times with the constant, symmetric positive definite
   * effective matrix K + a0 M:
   *  - cholmod: supernodal sparse Cholesky (SuiteSparse CHOLMOD), factorized
   * once; fastest back-substitution measured here (doc/performance.md). Needs
   * all DoFs on one MPI rank.
   *  - klu, mumps: Trilinos Amesos direct solvers, factorized once.
   *  - cg: conjugate gradients started from the caller's initial guess (the
   *    previous step), with a Jacobi, SSOR or algebraic multigrid (Trilinos
   *    ML) preconditioner; for meshes too large to factorize.
   *  - auto: on one MPI rank cholmod if CHOLMOD's symbolic analysis says
   *    its factor fits in the memory available (resources.h), else cg; on
   *    several ranks mumps up to `Auto direct limit` DoFs, cg above.
   */
  class EffectiveMatrixSolver
  {
  public:
    /// Linear solver/Type.
    enum class Type
    {
      automatic,
      cholmod,
      klu,
      mumps,
      cg
    };
    /// Linear solver/Preconditioner (of cg).
    enum class Preconditioner
    {
      jacobi,
      ssor,
      amg
    };
    /// Linear solver/CHOLMOD ordering.
    enum class Ordering
    {
      automatic,
      amd,
      metis,
      nesdis
    };
    /// The names of the three selections.
    static const SelectionTable<Type> &
    type_names();
    static const SelectionTable<Preconditioner> &
    preconditioner_names();
    static const SelectionTable<Ordering> &
    ordering_names();

    struct Parameters
    {
      Type           type             = Type::automatic;
      Preconditioner preconditioner   = Preconditioner::jacobi;
      unsigned int   auto_limit       = 700000;
      Ordering       cholmod_ordering = Ordering::automatic;
      double         tolerance        = 1e-10;
      unsigned int   max_iterations   = 1000;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    explicit EffectiveMatrixSolver(const Parameters &parameters);
    ~EffectiveMatrixSolver();

    /**
     * Factorize or precondition A; A must outlive this object.  The DoF
     * handler, if given, supplies the translation modes that algebraic
     * multigrid needs for elasticity.
     */
    void
    initialize(const TrilinosWrappers::SparseMatrix &A,
               const DoFHandler<3>                  *dof_handler = nullptr);

    /// Solve A x = b; on input x is the initial guess of cg.
    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b);

    /// Whether solve_many() is available (cholmod: one MPI rank).
    bool
    can_solve_many() const
    {
      return cholmod != nullptr;
    }

    /**
     * X = A^{-1} B for k right-hand sides stored column after column in
     * arrays of n x k (n the number of DoFs): one blocked (BLAS-3)
     * back-substitution, much faster than k single solves.  cholmod only.
     */
    void
    solve_many(const std::size_t  n,
               const unsigned int k,
               const double      *B,
               double            *X);

    /// The solver actually used (auto resolved).
    Type
    type() const
    {
      return resolved_type;
    }

    /// Its name, for the log.
    const std::string &
    type_name() const
    {
      return type_names().name(resolved_type);
    }

    /// The factor's size against the memory available (cholmod and auto
    /// on one rank; empty otherwise), for the log.
    const std::string &
    memory_log() const
    {
      return memory_report;
    }

    /// CG iterations of the last solve (0 for direct solvers).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

  private:
    /// CHOLMOD's symbolic analysis of A (one rank only); false if it failed
    /// under Type = auto, which then falls back to cg.
    bool
    analyze_cholmod(const TrilinosWrappers::SparseMatrix &A,
                    const unsigned int                    n_ranks);

    /// Type cholmod or auto on one rank: the symbolic analysis, the
    /// memory check (auto falls back to cg if the factor does not fit or
    /// the analysis fails) and the factorization.
    void
    initialize_cholmod(const TrilinosWrappers::SparseMatrix &A,
                       const unsigned int                    n_ranks);

    /// Type cg: the preconditioner of Linear solver/Preconditioner.
    void
    initialize_preconditioner(const TrilinosWrappers::SparseMatrix &A,
                              const DoFHandler<3> *dof_handler);

    struct Cholmod; // pimpl: keeps CHOLMOD out of the headers

    const Parameters                      parameters;
    Type                                  resolved_type = Type::automatic;
    std::string                           memory_report;
    const TrilinosWrappers::SparseMatrix *matrix = nullptr;
    /// Amesos keeps a reference to a SolverControl it does not use.
    SolverControl                                       amesos_control;
    std::unique_ptr<Cholmod>                            cholmod;
    std::unique_ptr<TrilinosWrappers::SolverDirect>     amesos;
    std::unique_ptr<TrilinosWrappers::PreconditionBase> preconditioner;
    unsigned int                                        iterations = 0;
  };
} // namespace fgimpact

#endif
