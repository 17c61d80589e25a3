// Subsection "Linear solver": the entries of EffectiveMatrixSolver and the
// names of its selections (the solvers are in linear_solver.cc).

#include <fgimpact/base/parameter_table.h>
#include <fgimpact/plate/linear_solver.h>

namespace fgimpact
{
  const SelectionTable<EffectiveMatrixSolver::Type> &
  EffectiveMatrixSolver::type_names()
  {
    static const SelectionTable<Type> names = {{"auto", Type::automatic},
                                               {"cholmod", Type::cholmod},
                                               {"klu", Type::klu},
                                               {"mumps", Type::mumps},
                                               {"cg", Type::cg}};
    return names;
  }



  const SelectionTable<EffectiveMatrixSolver::Preconditioner> &
  EffectiveMatrixSolver::preconditioner_names()
  {
    static const SelectionTable<Preconditioner> names = {
      {"jacobi", Preconditioner::jacobi},
      {"ssor", Preconditioner::ssor},
      {"amg", Preconditioner::amg}};
    return names;
  }



  const SelectionTable<EffectiveMatrixSolver::Ordering> &
  EffectiveMatrixSolver::ordering_names()
  {
    static const SelectionTable<Ordering> names = {
      {"auto", Ordering::automatic},
      {"amd", Ordering::amd},
      {"metis", Ordering::metis},
      {"nesdis", Ordering::nesdis}};
    return names;
  }



  namespace
  {
    /// The entries of EffectiveMatrixSolver::Parameters that set a member as
    /// they stand.
    const ParameterTable<EffectiveMatrixSolver::Parameters> &
    solver_table()
    {
      using P                              = EffectiveMatrixSolver::Parameters;
      static const ParameterTable<P> table = [] {
        ParameterTable<P> t;
        t.add(
          "Type",
          &P::type,
          EffectiveMatrixSolver::type_names(),
          "Solver for the constant effective matrix K + M/(beta dt^2). "
          "cholmod: supernodal Cholesky (SuiteSparse), factorized once. klu, "
          "mumps: Trilinos Amesos direct solvers. cg: preconditioned conjugate "
          "gradients warm-started from the previous step. auto: on one MPI "
          "rank cholmod if its factor (nnz(L) from CHOLMOD's symbolic "
          "analysis) fits in the memory available, else cg; on several "
          "ranks mumps up to 'Auto direct limit' DoFs, cg above "
          "(doc/performance.md).");
        t.add("Preconditioner",
              &P::preconditioner,
              EffectiveMatrixSolver::preconditioner_names(),
              "Preconditioner of cg. The effective matrix is "
              "dominated by M/(beta dt^2) for small dt, where "
              "jacobi is cheapest; amg (Trilinos ML) for large dt.");
        t.add("Auto direct limit",
              &P::auto_limit,
              Patterns::Integer(0, 1000000000),
              "Largest number of DoFs for which 'auto' factorizes "
              "on several MPI ranks (mumps); above it 'auto' uses "
              "cg. On one rank the memory decides. cholmod was "
              "faster than cg at every size measured (up to "
              "665,091 DoFs, where its factor needs ~10 GB); the "
              "limit is set by memory (doc/performance.md).");
        t.add("CHOLMOD ordering",
              &P::cholmod_ordering,
              EffectiveMatrixSolver::ordering_names(),
              "Fill-reducing ordering of cholmod. auto: CHOLMOD "
              "tries AMD and METIS and keeps the smaller factor; "
              "forcing amd was up to 2x slower to factorize and "
              "used 40 % more memory from 89,667 DoFs up "
              "(doc/performance.md).");
        t.add("Tolerance",
              &P::tolerance,
              Patterns::Double(1e-16, 1e-2),
              "Relative residual tolerance of cg, |r| <= tol |b|. "
              "Dimensionless.");
        t.add("Max iterations",
              &P::max_iterations,
              Patterns::Integer(1, 1000000),
              "Iteration cap of cg; reaching it stops the run with "
              "an error naming the time step.");
        return t;
      }();
      return table;
    }
  } // namespace



  void
  EffectiveMatrixSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      solver_table().declare(prm);
    }
    prm.leave_subsection();
  }



  void
  EffectiveMatrixSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      solver_table().parse(prm, *this);
    }
    prm.leave_subsection();
  }
} // namespace fgimpact
