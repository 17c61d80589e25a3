// Subsection "Linear solver": the entries of EffectiveMatrixSolver and the
// names of its selections (the solvers are in linear_solver.cc).

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



  void
  EffectiveMatrixSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      prm.declare_entry(
        "Type",
        "auto",
        type_names().pattern(),
        "Solver for the constant effective matrix K + M/(beta dt^2). "
        "cholmod: supernodal Cholesky (SuiteSparse), factorized once. klu, "
        "mumps: Trilinos Amesos direct solvers. cg: preconditioned conjugate "
        "gradients warm-started from the previous step. auto: on one MPI "
        "rank cholmod if its factor (nnz(L) from CHOLMOD's symbolic "
        "analysis) fits in the memory available, else cg; on several "
        "ranks mumps up to 'Auto direct limit' DoFs, cg above "
        "(doc/performance.md).");
      prm.declare_entry("Preconditioner",
                        "jacobi",
                        preconditioner_names().pattern(),
                        "Preconditioner of cg. The effective matrix is "
                        "dominated by M/(beta dt^2) for small dt, where "
                        "jacobi is cheapest; amg (Trilinos ML) for large dt.");
      prm.declare_entry("Auto direct limit",
                        "700000",
                        Patterns::Integer(0, 1000000000),
                        "Largest number of DoFs for which 'auto' factorizes "
                        "on several MPI ranks (mumps); above it 'auto' uses "
                        "cg. On one rank the memory decides. cholmod was "
                        "faster than cg at every size measured (up to "
                        "665,091 DoFs, where its factor needs ~10 GB); the "
                        "limit is set by memory (doc/performance.md).");
      prm.declare_entry("CHOLMOD ordering",
                        "auto",
                        ordering_names().pattern(),
                        "Fill-reducing ordering of cholmod. auto: CHOLMOD "
                        "tries AMD and METIS and keeps the smaller factor; "
                        "forcing amd was up to 2x slower to factorize and "
                        "used 40 % more memory from 89,667 DoFs up "
                        "(doc/performance.md).");
      prm.declare_entry("Tolerance",
                        "1e-10",
                        Patterns::Double(1e-16, 1e-2),
                        "Relative residual tolerance of cg, |r| <= tol |b|. "
                        "Dimensionless.");
      prm.declare_entry("Max iterations",
                        "1000",
                        Patterns::Integer(1, 1000000),
                        "Iteration cap of cg; reaching it stops the run with "
                        "an error naming the time step.");
    }
    prm.leave_subsection();
  }



  void
  EffectiveMatrixSolver::Parameters::parse_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      type           = type_names().value(prm.get("Type"));
      preconditioner = preconditioner_names().value(prm.get("Preconditioner"));
      auto_limit     = prm.get_integer("Auto direct limit");
      cholmod_ordering = ordering_names().value(prm.get("CHOLMOD ordering"));
      tolerance        = prm.get_double("Tolerance");
      max_iterations   = prm.get_integer("Max iterations");
    }
    prm.leave_subsection();
  }
} // namespace fgimpact
