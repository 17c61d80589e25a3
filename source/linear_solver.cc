#include <deal.II/lac/solver_cg.h>

#include <fgimpact/linear_solver.h>

namespace fgimpact
{
  void
  EffectiveMatrixSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      prm.declare_entry("Type",
                        "direct",
                        Patterns::Selection("direct|cg"),
                        "direct: factorize the effective matrix K + M/(beta "
                        "dt^2) once and back-substitute every step. cg: "
                        "conjugate gradients with SSOR, warm-started from "
                        "the previous displacement.");
      prm.declare_entry("Direct package",
                        "Amesos_Klu",
                        Patterns::Selection("Amesos_Klu|Amesos_Mumps"),
                        "Trilinos Amesos package of the direct solver.");
      prm.declare_entry("Tolerance",
                        "1e-12",
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
      type           = prm.get("Type");
      direct_package = prm.get("Direct package");
      tolerance      = prm.get_double("Tolerance");
      max_iterations = prm.get_integer("Max iterations");
    }
    prm.leave_subsection();
  }



  EffectiveMatrixSolver::EffectiveMatrixSolver(const Parameters &parameters)
    : parameters(parameters)
    , control(parameters.max_iterations, 0.)
  {}



  void
  EffectiveMatrixSolver::initialize(const TrilinosWrappers::SparseMatrix &A)
  {
    matrix = &A;
    if (parameters.type == "direct")
      {
        direct = std::make_unique<TrilinosWrappers::SolverDirect>(
          control,
          TrilinosWrappers::SolverDirect::AdditionalData(
            false, parameters.direct_package));
        direct->initialize(A);
      }
    else
      {
        preconditioner = std::make_unique<TrilinosWrappers::PreconditionSSOR>();
        preconditioner->initialize(A);
      }
  }



  void
  EffectiveMatrixSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                               const TrilinosWrappers::MPI::Vector &b)
  {
    if (direct)
      {
        direct->solve(x, b);
        iterations = 0;
        return;
      }
    // A relative tolerance; the caller catches SolverControl::NoConvergence.
    SolverControl cg_control(parameters.max_iterations,
                             parameters.tolerance * b.l2_norm());
    SolverCG<TrilinosWrappers::MPI::Vector> cg(cg_control);
    cg.solve(*matrix, x, b, *preconditioner);
    iterations = cg_control.last_step();
  }
} // namespace fgimpact
