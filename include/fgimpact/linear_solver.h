#ifndef fgimpact_linear_solver_h
#define fgimpact_linear_solver_h

#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/solver_control.h>
#include <deal.II/lac/trilinos_precondition.h>
#include <deal.II/lac/trilinos_solver.h>
#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <memory>
#include <string>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Solves with the constant, symmetric positive definite effective matrix
   * K + a0 M many times: a sparse direct factorization computed once
   * (Trilinos Amesos: KLU or MUMPS), or preconditioned CG started from the
   * caller's initial guess.
   */
  class EffectiveMatrixSolver
  {
  public:
    struct Parameters
    {
      std::string  type           = "direct";
      std::string  direct_package = "Amesos_Klu";
      double       tolerance      = 1e-12;
      unsigned int max_iterations = 1000;

      static void
      declare_parameters(ParameterHandler &prm);
      void
      parse_parameters(ParameterHandler &prm);
    };

    explicit EffectiveMatrixSolver(const Parameters &parameters);

    /// Factorize or precondition A; A must outlive this object.
    void
    initialize(const TrilinosWrappers::SparseMatrix &A);

    /// Solve A x = b; x on input is the initial guess of CG.
    void
    solve(TrilinosWrappers::MPI::Vector       &x,
          const TrilinosWrappers::MPI::Vector &b);

    /// CG iterations of the last solve (0 for direct).
    unsigned int
    last_iterations() const
    {
      return iterations;
    }

  private:
    const Parameters                                    parameters;
    const TrilinosWrappers::SparseMatrix               *matrix = nullptr;
    SolverControl                                       control;
    std::unique_ptr<TrilinosWrappers::SolverDirect>     direct;
    std::unique_ptr<TrilinosWrappers::PreconditionSSOR> preconditioner;
    unsigned int                                        iterations = 0;
  };
} // namespace fgimpact

#endif
