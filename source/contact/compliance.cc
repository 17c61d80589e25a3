#include <fgimpact/contact/compliance.h>

#include <algorithm>

namespace fgimpact
{
  namespace
  {
    /// One rank, cholmod: blocks of unit loads solved together (BLAS-3).
    void
    compliance_by_blocks(EffectiveMatrixSolver                      &solver,
                         const PlateModel                           &plate,
                         const std::vector<types::global_dof_index> &dofs,
                         const unsigned int                          first,
                         const unsigned int                          last,
                         FullMatrix<double>                         &C,
                         std::vector<StoredResponse>                *responses)
    {
      const unsigned int m     = dofs.size();
      const std::size_t  n     = plate.locally_owned_dofs().n_elements();
      const unsigned int block = compliance_block_size;
      // B is zeroed once; each block sets its k unit entries and clears
      // them after (zeroing all of B per block was 1.3 s of the level-7
      // set-up: 48 MB a block).
      std::vector<double> B(n * std::min(block, last - first), 0.), X;
      for (unsigned int j0 = first; j0 < last; j0 += block)
        {
          const unsigned int k = std::min(block, last - j0);
          X.resize(n * k);
          for (unsigned int c = 0; c < k; ++c)
            B[c * n + dofs[j0 + c]] = 1.;
          solver.solve_many(n, k, B.data(), X.data());
          for (unsigned int c = 0; c < k; ++c)
            B[c * n + dofs[j0 + c]] = 0.;
          for (unsigned int c = 0; c < k; ++c)
            {
              const double *column = X.data() + c * n;
              for (unsigned int i = 0; i < m; ++i)
                C(i, j0 + c) = column[dofs[i]];
              if (responses != nullptr)
                (*responses)[j0 + c].assign(column, column + n);
            }
        }
    }
  } // namespace



  void
  compute_compliance(EffectiveMatrixSolver                      &solver,
                     const PlateModel                           &plate,
                     const std::vector<types::global_dof_index> &dofs,
                     FullMatrix<double>                         &C)
  {
    C.reinit(dofs.size(), dofs.size());
    compute_compliance_columns(solver, plate, dofs, 0, dofs.size(), C, nullptr);
  }



  void
  compute_compliance_columns(EffectiveMatrixSolver                      &solver,
                             const PlateModel                           &plate,
                             const std::vector<types::global_dof_index> &dofs,
                             const unsigned int                          first,
                             const unsigned int                          last,
                             FullMatrix<double>                         &C,
                             std::vector<StoredResponse> *responses)
  {
    const unsigned int m = dofs.size();
    AssertDimension(C.m(), m);
    AssertDimension(C.n(), m);
    Assert(responses == nullptr || responses->size() == m,
           ExcDimensionMismatch(responses->size(), m));
    if (first >= last)
      return;
    if (solver.can_solve_many())
      {
        compliance_by_blocks(solver, plate, dofs, first, last, C, responses);
        return;
      }
    TrilinosWrappers::MPI::Vector c;
    for (unsigned int j = first; j < last; ++j)
      {
        compute_response(solver, plate, dofs[j], c);
        const Vector<double> column = plate.dof_values(c, dofs);
        for (unsigned int i = 0; i < m; ++i)
          C(i, j) = column[i];
        if (responses != nullptr)
          (*responses)[j].assign(c.begin(), c.end());
      }
  }



  void
  compute_response(EffectiveMatrixSolver         &solver,
                   const PlateModel              &plate,
                   const types::global_dof_index  dof,
                   TrilinosWrappers::MPI::Vector &c)
  {
    TrilinosWrappers::MPI::Vector g;
    plate.initialize_vector(g);
    plate.initialize_vector(c);
    // Only the owner of the contact DoF writes.
    if (g.locally_owned_elements().is_element(dof))
      g(dof) = 1.;
    g.compress(VectorOperation::insert);
    solver.solve(c, g);
  }



  namespace
  {
    /// add_weighted_responses() on responses of one precision T.
    template <typename T>
    void
    add_weighted(double *const                 to,
                 const std::size_t             n,
                 const std::vector<double>    &w,
                 const std::vector<const T *> &y)
    {
      constexpr std::size_t block = 32768; // rows: 256 KB of x
      const std::size_t     m     = w.size();
      for (std::size_t i0 = 0; i0 < n; i0 += block)
        {
          const std::size_t i1 = std::min(n, i0 + block);
          std::size_t       k  = 0;
          for (; k + 4 <= m; k += 4)
            {
              const double w0 = w[k], w1 = w[k + 1], w2 = w[k + 2],
                           w3 = w[k + 3];
              const T *y0 = y[k], *y1 = y[k + 1], *y2 = y[k + 2],
                      *y3 = y[k + 3];
              for (std::size_t i = i0; i < i1; ++i)
                {
                  double sum = to[i];
                  sum        = sum + w0 * y0[i];
                  sum        = sum + w1 * y1[i];
                  sum        = sum + w2 * y2[i];
                  sum        = sum + w3 * y3[i];
                  to[i]      = sum;
                }
            }
          for (; k < m; ++k)
            {
              const double weight = w[k];
              const T     *from   = y[k];
              for (std::size_t i = i0; i < i1; ++i)
                to[i] = to[i] + weight * from[i];
            }
        }
    }
  } // namespace



  void
  add_weighted_responses(TrilinosWrappers::MPI::Vector             &x,
                         const std::vector<double>                 &w,
                         const std::vector<const StoredResponse *> &y)
  {
    const std::size_t n = x.locally_owned_size();
    // One stepper stores every response alike.
    std::vector<const float *>  narrow;
    std::vector<const double *> wide;
    for (const StoredResponse *r : y)
      {
        AssertDimension(r->size(), n);
        if (r->single())
          narrow.push_back(r->single_data());
        else
          wide.push_back(r->double_data());
      }
    Assert(narrow.empty() || wide.empty(),
           ExcMessage("responses of both precisions"));
    if (narrow.empty())
      add_weighted(x.begin(), n, w, wide);
    else
      add_weighted(x.begin(), n, w, narrow);
  }



  double
  largest_static_compliance(
    const PlateModel                           &plate,
    const EffectiveMatrixSolver::Parameters    &solver_parameters,
    const std::vector<types::global_dof_index> &dofs)
  {
    EffectiveMatrixSolver solver(solver_parameters);
    solver.initialize(plate.stiffness_matrix(), &plate.get_dof_handler());
    const std::size_t n = std::min<std::size_t>(dofs.size(), 8);
    std::vector<types::global_dof_index> sample;
    for (std::size_t k = 0; k < n; ++k)
      sample.push_back(dofs[n == 1 ? 0 : k * (dofs.size() - 1) / (n - 1)]);
    FullMatrix<double> C;
    compute_compliance(solver, plate, sample, C);
    double largest = 0;
    for (unsigned int i = 0; i < C.m(); ++i)
      largest = std::max(largest, C(i, i));
    return largest;
  }
} // namespace fgimpact
