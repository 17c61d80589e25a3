#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <fgimpact/linear_solver.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cholmod.h>
#include <vector>

namespace fgimpact
{
  /**
   * CHOLMOD through its C interface: supernodal Cholesky, and
   * cholmod_solve2 with workspaces kept between calls, so that a solve
   * allocates nothing.
   */
  struct EffectiveMatrixSolver::Cholmod
  {
    explicit Cholmod(const std::string &ordering)
    {
      cholmod_start(&common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      if (ordering != "auto")
        {
          // One ordering instead of CHOLMOD's default trials.
          common.nmethods           = 1;
          common.method[0].ordering = (ordering == "amd"   ? CHOLMOD_AMD :
                                       ordering == "metis" ? CHOLMOD_METIS :
                                                             CHOLMOD_NESDIS);
          common.postorder          = true;
        }
    }

    ~Cholmod()
    {
      cholmod_free_factor(&factor, &common);
      cholmod_free_dense(&X, &common);
      cholmod_free_dense(&Y, &common);
      cholmod_free_dense(&E, &common);
      cholmod_finish(&common);
    }

    /// Factorize the symmetric matrix given by its lower triangle.
    void
    factorize(const size_t               n,
              const std::vector<int>    &rows,
              const std::vector<int>    &columns,
              const std::vector<double> &values)
    {
      cholmod_triplet *T = cholmod_allocate_triplet(
        n, n, values.size(), /*stype: lower*/ -1, CHOLMOD_REAL, &common);
      std::copy(rows.begin(), rows.end(), static_cast<int *>(T->i));
      std::copy(columns.begin(), columns.end(), static_cast<int *>(T->j));
      std::copy(values.begin(), values.end(), static_cast<double *>(T->x));
      T->nnz            = values.size();
      cholmod_sparse *A = cholmod_triplet_to_sparse(T, values.size(), &common);
      cholmod_free_triplet(&T, &common);
      factor = cholmod_analyze(A, &common);
      cholmod_factorize(A, factor, &common);
      cholmod_free_sparse(&A, &common);
      AssertThrow(common.status == CHOLMOD_OK && factor->minor == n,
                  ExcMessage("CHOLMOD could not factorize the effective "
                             "matrix (not positive definite?)."));
    }

    /// x = A^{-1} b for arrays of n x k (k columns, one after another).
    void
    solve(const size_t n, const double *b, double *x, const size_t k = 1)
    {
      cholmod_dense B;
      B.nrow  = n;
      B.ncol  = k;
      B.nzmax = n * k;
      B.d     = n;
      B.x     = const_cast<double *>(b);
      B.z     = nullptr;
      B.xtype = CHOLMOD_REAL;
      B.dtype = CHOLMOD_DOUBLE;
      cholmod_solve2(
        CHOLMOD_A, factor, &B, nullptr, &X, nullptr, &Y, &E, &common);
      const double *result = static_cast<const double *>(X->x);
      std::copy(result, result + n * k, x);
    }

    cholmod_common  common;
    cholmod_factor *factor = nullptr;
    cholmod_dense  *X = nullptr, *Y = nullptr, *E = nullptr;
  };



  void
  EffectiveMatrixSolver::Parameters::declare_parameters(ParameterHandler &prm)
  {
    prm.enter_subsection("Linear solver");
    {
      prm.declare_entry(
        "Type",
        "auto",
        Patterns::Selection("auto|cholmod|klu|mumps|cg"),
        "Solver for the constant effective matrix K + M/(beta dt^2). "
        "cholmod: supernodal Cholesky (SuiteSparse), factorized once. klu, "
        "mumps: Trilinos Amesos direct solvers. cg: preconditioned conjugate "
        "gradients warm-started from the previous step. auto: up to "
        "'Auto direct limit' DoFs cholmod on one MPI rank and mumps on "
        "several; cg above (doc/performance.md).");
      prm.declare_entry("Preconditioner",
                        "jacobi",
                        Patterns::Selection("jacobi|ssor|amg"),
                        "Preconditioner of cg. The effective matrix is "
                        "dominated by M/(beta dt^2) for small dt, where "
                        "jacobi is cheapest; amg (Trilinos ML) for large dt.");
      prm.declare_entry("Auto direct limit",
                        "700000",
                        Patterns::Integer(0, 1000000000),
                        "Largest number of DoFs for which 'auto' factorizes "
                        "(cholmod); above it 'auto' uses cg. cholmod was "
                        "faster than cg at every size measured (up to "
                        "665,091 DoFs, where its factor needs ~10 GB); the "
                        "limit is set by memory (doc/performance.md).");
      prm.declare_entry("CHOLMOD ordering",
                        "auto",
                        Patterns::Selection("auto|amd|metis|nesdis"),
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
      type             = prm.get("Type");
      preconditioner   = prm.get("Preconditioner");
      auto_limit       = prm.get_integer("Auto direct limit");
      cholmod_ordering = prm.get("CHOLMOD ordering");
      tolerance        = prm.get_double("Tolerance");
      max_iterations   = prm.get_integer("Max iterations");
    }
    prm.leave_subsection();
  }



  EffectiveMatrixSolver::EffectiveMatrixSolver(const Parameters &parameters)
    : parameters(parameters)
  {}



  EffectiveMatrixSolver::~EffectiveMatrixSolver() = default;



  void
  EffectiveMatrixSolver::initialize(const TrilinosWrappers::SparseMatrix &A,
                                    const DoFHandler<3> *dof_handler)
  {
    matrix        = &A;
    resolved_type = parameters.type;
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(A.get_mpi_communicator());
    // On one rank CHOLMOD; on several the distributed MUMPS, while the
    // factor fits (the same limit); CG above.
    if (resolved_type == "auto")
      resolved_type = (A.m() > parameters.auto_limit ? "cg" :
                       n_ranks == 1                  ? "cholmod" :
                                                       "mumps");

    if (resolved_type == "cholmod")
      {
        AssertThrow(n_ranks == 1,
                    ExcMessage("Linear solver/Type = cholmod runs on one MPI "
                               "rank only; use mumps, cg or auto on " +
                               std::to_string(n_ranks) + " ranks."));
        // The lower triangle, straight from the Epetra rows (deal.II's
        // entry iterators are much slower for this).
        const Epetra_CrsMatrix &epetra = A.trilinos_matrix();
        std::vector<int>        rows, columns;
        std::vector<double>     values;
        rows.reserve(epetra.NumMyNonzeros() / 2 + A.m());
        columns.reserve(rows.capacity());
        values.reserve(rows.capacity());
        for (int local_row = 0; local_row < epetra.NumMyRows(); ++local_row)
          {
            int     n_entries;
            double *row_values;
            int    *row_columns;
            epetra.ExtractMyRowView(local_row,
                                    n_entries,
                                    row_values,
                                    row_columns);
            const int row = epetra.RowMap().GID(local_row);
            for (int k = 0; k < n_entries; ++k)
              {
                const int column = epetra.ColMap().GID(row_columns[k]);
                if (column <= row)
                  {
                    rows.push_back(row);
                    columns.push_back(column);
                    values.push_back(row_values[k]);
                  }
              }
          }
        cholmod = std::make_unique<Cholmod>(parameters.cholmod_ordering);
        cholmod->factorize(A.m(), rows, columns, values);
      }
    else if (resolved_type == "klu" || resolved_type == "mumps")
      {
        amesos = std::make_unique<TrilinosWrappers::SolverDirect>(
          amesos_control,
          TrilinosWrappers::SolverDirect::AdditionalData(
            false, resolved_type == "klu" ? "Amesos_Klu" : "Amesos_Mumps"));
        amesos->initialize(A);
      }
    else
      {
        if (parameters.preconditioner == "jacobi")
          {
            auto p = std::make_unique<TrilinosWrappers::PreconditionJacobi>();
            p->initialize(A);
            preconditioner = std::move(p);
          }
        else if (parameters.preconditioner == "ssor")
          {
            auto p = std::make_unique<TrilinosWrappers::PreconditionSSOR>();
            p->initialize(A);
            preconditioner = std::move(p);
          }
        else
          {
            auto p = std::make_unique<TrilinosWrappers::PreconditionAMG>();
            TrilinosWrappers::PreconditionAMG::AdditionalData data;
            // The near null space of elasticity: at least the three
            // translations (rotations are not extracted by deal.II 9.4).
            if (dof_handler)
              DoFTools::extract_constant_modes(*dof_handler,
                                               ComponentMask(3, true),
                                               data.constant_modes);
            data.elliptic              = true;
            data.higher_order_elements = false;
            data.smoother_sweeps       = 2;
            data.aggregation_threshold = 0.02;
            p->initialize(A, data);
            preconditioner = std::move(p);
          }
      }
  }



  void
  EffectiveMatrixSolver::solve_many(const std::size_t  n,
                                    const unsigned int k,
                                    const double      *B,
                                    double            *X)
  {
    Assert(cholmod, ExcMessage("solve_many() needs the cholmod solver"));
    iterations = 0;
    cholmod->solve(n, B, X, k);
  }



  void
  EffectiveMatrixSolver::solve(TrilinosWrappers::MPI::Vector       &x,
                               const TrilinosWrappers::MPI::Vector &b)
  {
    iterations = 0;
    if (cholmod)
      {
        cholmod->solve(b.locally_owned_size(),
                       b.trilinos_vector()[0],
                       x.trilinos_vector()[0]);
        return;
      }
    if (amesos)
      {
        amesos->solve(x, b);
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
