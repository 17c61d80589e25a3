#include <deal.II/dofs/dof_tools.h>

#include <deal.II/lac/solver_cg.h>
#include <deal.II/lac/solver_control.h>

#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/memory.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/plate/linear_solver.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>
#include <cholmod.h>
#include <cstdio>
#include <iomanip>
#include <sstream>
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
    explicit Cholmod(const Ordering ordering)
    {
      cholmod_start(&common);
      common.supernodal = CHOLMOD_SUPERNODAL;
      if (ordering != Ordering::automatic)
        {
          // One ordering instead of CHOLMOD's default trials.
          common.nmethods = 1;
          common.method[0].ordering =
            (ordering == Ordering::amd   ? CHOLMOD_AMD :
             ordering == Ordering::metis ? CHOLMOD_METIS :
                                           CHOLMOD_NESDIS);
          common.postorder = true;
        }
    }

    ~Cholmod()
    {
      cholmod_free_sparse(&A, &common);
      cholmod_free_factor(&factor, &common);
      cholmod_free_dense(&X, &common);
      cholmod_free_dense(&Y, &common);
      cholmod_free_dense(&E, &common);
      cholmod_finish(&common);
    }

    /// Symbolic analysis (ordering, supernodes, nnz(L)) of the symmetric
    /// matrix given by its lower triangle; the triplets are released.
    void
    analyze(const size_t         n,
            std::vector<int>    &rows,
            std::vector<int>    &columns,
            std::vector<double> &values)
    {
      cholmod_triplet *T = cholmod_allocate_triplet(
        n, n, values.size(), /*stype: lower*/ -1, CHOLMOD_REAL, &common);
      std::copy(rows.begin(), rows.end(), static_cast<int *>(T->i));
      std::copy(columns.begin(), columns.end(), static_cast<int *>(T->j));
      std::copy(values.begin(), values.end(), static_cast<double *>(T->x));
      T->nnz = values.size();
      for (auto *v : {&rows, &columns})
        std::vector<int>().swap(*v);
      std::vector<double>().swap(values);
      A = cholmod_triplet_to_sparse(T, T->nnz, &common);
      cholmod_free_triplet(&T, &common);
      factor = cholmod_analyze(A, &common);
      // Valid input that the machine cannot handle (CHOLMOD's status is
      // then mostly "out of memory"): a numerical failure, exit code 2.
      AssertThrow(common.status == CHOLMOD_OK && factor != nullptr,
                  ExcNumericalFailure(
                    "CHOLMOD's symbolic analysis of the effective matrix "
                    "failed (status " +
                    std::to_string(common.status) +
                    "); use a coarser Geometry/Subdivisions or Linear "
                    "solver/Type = cg."));
    }

    /// CHOLMOD's status of the last call (CHOLMOD_OK = 0).
    int
    status() const
    {
      return common.status;
    }

    /// Entries of L (CHOLMOD's count after the symbolic analysis).
    double
    factor_nnz() const
    {
      return common.lnz;
    }

    /// Bytes the numeric factor will hold: the supernodes' dense values
    /// (zeros included) and their row indices.
    double
    factor_bytes() const
    {
      if (factor->is_super)
        return 8. * factor->xsize +
               sizeof(int) * (factor->ssize + 4. * factor->n);
      return 12. * common.lnz + 4. * sizeof(int) * factor->n;
    }

    /// The numeric factorization of the analyzed matrix.
    void
    factorize()
    {
      const size_t n = A->nrow;
      cholmod_factorize(A, factor, &common);
      cholmod_free_sparse(&A, &common);
      // minor < n: a pivot that is not positive (the matrix is not
      // positive definite); otherwise CHOLMOD ran out of memory.
      AssertThrow(common.status == CHOLMOD_OK && factor->minor == n,
                  ExcNumericalFailure(
                    factor->minor < n ?
                      "CHOLMOD could not factorize the effective matrix "
                      "(not positive definite at column " +
                        std::to_string(factor->minor) + " of " +
                        std::to_string(n) +
                        "); check the Boundary conditions and Material, "
                        "or use Linear solver/Type = mumps." :
                      "CHOLMOD could not factorize the effective matrix "
                      "(status " +
                        std::to_string(common.status) +
                        "); use a coarser Geometry/Subdivisions or Linear "
                        "solver/Type = cg."));
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
    cholmod_sparse *A      = nullptr;
    cholmod_factor *factor = nullptr;
    cholmod_dense  *X = nullptr, *Y = nullptr, *E = nullptr;
  };



  EffectiveMatrixSolver::EffectiveMatrixSolver(const Parameters &parameters)
    : parameters(parameters)
  {}



  EffectiveMatrixSolver::~EffectiveMatrixSolver() = default;



  namespace
  {
    /// The lower triangle of A as triplets, straight from the Epetra rows
    /// (deal.II's entry iterators are much slower for this).
    void
    lower_triangle(const TrilinosWrappers::SparseMatrix &A,
                   std::vector<int>                     &rows,
                   std::vector<int>                     &columns,
                   std::vector<double>                  &values)
    {
      const Epetra_CrsMatrix &epetra = A.trilinos_matrix();
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
    }
  } // namespace



  void
  EffectiveMatrixSolver::initialize(const TrilinosWrappers::SparseMatrix &A,
                                    const DoFHandler<3> *dof_handler)
  {
    matrix        = &A;
    resolved_type = parameters.type;
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(A.get_mpi_communicator());
    // On several ranks the distributed MUMPS up to the DoF limit (no
    // symbolic analysis before its factorization), CG above.  On one rank
    // CHOLMOD's symbolic analysis decides below.
    if (resolved_type == Type::automatic && n_ranks > 1)
      resolved_type = (A.m() > parameters.auto_limit ? Type::cg : Type::mumps);

    if (resolved_type == Type::cholmod || resolved_type == Type::automatic)
      initialize_cholmod(A, n_ranks);
    if (resolved_type == Type::klu || resolved_type == Type::mumps)
      {
        // METIS (MUMPS's ordering) swallows SIGTERM: stop signals wait
        // until the factorization is done.
        const DeferStopSignals defer;
        amesos = std::make_unique<TrilinosWrappers::SolverDirect>(
          amesos_control,
          TrilinosWrappers::SolverDirect::AdditionalData(
            false, resolved_type == Type::klu ? "Amesos_Klu" : "Amesos_Mumps"));
        amesos->initialize(A);
      }
    else if (resolved_type == Type::cg)
      {
        // ML's aggregation may call METIS too.
        const DeferStopSignals defer;
        initialize_preconditioner(A, dof_handler);
      }
  }



  bool
  EffectiveMatrixSolver::analyze_cholmod(
    const TrilinosWrappers::SparseMatrix &A,
    const unsigned int                    n_ranks)
  {
    AssertThrow(n_ranks == 1,
                ExcMessage("Linear solver/Type = cholmod runs on one MPI "
                           "rank only; use mumps, cg or auto on " +
                           std::to_string(n_ranks) + " ranks."));
    std::vector<int>    rows, columns;
    std::vector<double> values;
    lower_triangle(A, rows, columns, values);
    cholmod = std::make_unique<Cholmod>(parameters.cholmod_ordering);
    {
      // METIS (the ordering) swallows SIGTERM: stop signals wait until the
      // analysis is done; during the numeric factorization below they only
      // set the flag, which the caller acts on right after it.
      const DeferStopSignals defer;
      try
        {
          cholmod->analyze(A.m(), rows, columns, values);
        }
      catch (const ExcNumericalFailure &e)
        {
          // A factor too large for CHOLMOD (more than 2^31 entries: status
          // -3) or the memory (-2): auto falls back to cg, as when the
          // factor does not fit; cholmod says so in one line.
          if (resolved_type != Type::automatic)
            throw;
          memory_report = "CHOLMOD symbolic analysis failed (status " +
                          std::to_string(cholmod->status()) +
                          ": the factor is too large); auto: cg";
          cholmod.reset();
          resolved_type = Type::cg;
          return false;
        }
    }
    return true;
  }



  void
  EffectiveMatrixSolver::initialize_cholmod(
    const TrilinosWrappers::SparseMatrix &A,
    const unsigned int                    n_ranks)
  {
    if (!analyze_cholmod(A, n_ranks))
      return;
    // The factor against what is left now (mesh, matrices and vectors
    // are allocated): CHOLMOD's numeric factorization needs the factor
    // plus a small workspace.
    const double          need      = cholmod->factor_bytes();
    const AvailableMemory available = available_memory();
    const bool            fits      = 1.1 * need < available.bytes;
    std::ostringstream    report;
    report << "CHOLMOD symbolic analysis: nnz(L) = " << std::setprecision(4)
           << cholmod->factor_nnz() << ", factor " << gigabytes(need) << ", "
           << gigabytes(available.bytes) << " available (" << available.source
           << ")";
    if (resolved_type == Type::automatic)
      {
        resolved_type = fits ? Type::cholmod : Type::cg;
        report << (fits ? "; auto: cholmod" :
                          "; auto: cg (the factor does not fit)");
      }
    else
      AssertThrow(fits,
                  ExcMessage("Linear solver/Type = cholmod: the factor "
                             "needs " +
                             gigabytes(1.1 * need) + " (nnz(L) = " +
                             std::to_string(
                               static_cast<long long>(cholmod->factor_nnz())) +
                             ") but " + gigabytes(available.bytes) +
                             " are available (" + available.source +
                             "); use Linear solver/Type = cg or auto, or "
                             "fewer Geometry/Subdivisions."));
    memory_report = report.str();
    if (resolved_type == Type::cholmod)
      {
        cholmod->factorize();
        note_blas_buffer_mapped();
      }
    else
      cholmod.reset();
  }



  void
  EffectiveMatrixSolver::initialize_preconditioner(
    const TrilinosWrappers::SparseMatrix &A,
    const DoFHandler<3>                  *dof_handler)
  {
    if (parameters.preconditioner == Preconditioner::jacobi)
      {
        auto p = std::make_unique<TrilinosWrappers::PreconditionJacobi>();
        p->initialize(A);
        preconditioner = std::move(p);
      }
    else if (parameters.preconditioner == Preconditioner::ssor)
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
