#include <fgimpact/time/modified_mass.h>

#include <Epetra_CrsMatrix.h>
#include <algorithm>

namespace fgimpact
{
  ModifiedMass::ModifiedMass(const PlateModel &plate)
    : plate(plate)
  {}



  void
  ModifiedMass::build_effective_matrix(
    const double                                a0,
    const std::vector<types::global_dof_index> &massless,
    TrilinosWrappers::SparseMatrix             &effective)
  {
    effective.copy_from(plate.stiffness_matrix());
    effective.add(a0, plate.mass_matrix());
    modified     = !massless.empty();
    removed_mass = 0;
    owned.clear();
    if (!modified)
      return;
    std::vector<bool> zero(plate.n_dofs(), false);
    for (const auto dof : massless)
      {
        zero[dof] = true;
        if (plate.locally_owned_dofs().is_element(dof))
          owned.push_back(dof);
      }
    plate.initialize_vector(masked);

    // In place on the Epetra rows (deal.II's entry-wise set() on an
    // assembled Trilinos matrix costs a search per call); K, M and K_eff
    // share the plate's sparsity pattern.
    auto &matrix = const_cast<Epetra_CrsMatrix &>(effective.trilinos_matrix());
    const Epetra_CrsMatrix &K = plate.stiffness_matrix().trilinos_matrix();
    const Epetra_CrsMatrix &M = plate.mass_matrix().trilinos_matrix();
    double                  removed = 0; // kg: sum of the zeroed rows' entries
    for (int row = 0; row < matrix.NumMyRows(); ++row)
      {
        int     n = 0, n_K = 0, n_M = 0;
        double *values = nullptr, *k_values = nullptr, *m_values = nullptr;
        int    *columns = nullptr, *k_columns = nullptr, *m_columns = nullptr;
        matrix.ExtractMyRowView(row, n, values, columns);
        K.ExtractMyRowView(row, n_K, k_values, k_columns);
        M.ExtractMyRowView(row, n_M, m_values, m_columns);
        AssertThrow(n_K == n && n_M == n &&
                      std::equal(columns, columns + n, k_columns) &&
                      std::equal(columns, columns + n, m_columns),
                    ExcInternalError());
        const bool zero_row = zero[matrix.RowMap().GID(row)];
        for (int k = 0; k < n; ++k)
          if (zero_row || zero[matrix.ColMap().GID(columns[k])])
            {
              if (zero_row)
                removed += m_values[k];
              values[k] = k_values[k];
            }
      }
    removed_mass = Utilities::MPI::sum(removed, plate.get_mpi_communicator());
  }



  void
  ModifiedMass::vmult(TrilinosWrappers::MPI::Vector       &dst,
                      const TrilinosWrappers::MPI::Vector &src)
  {
    if (!modified)
      {
        plate.mass_matrix().vmult(dst, src);
        return;
      }
    masked = src;
    for (const auto dof : owned)
      masked(dof) = 0.;
    plate.mass_matrix().vmult(dst, masked);
    for (const auto dof : owned)
      dst(dof) = 0.;
  }
} // namespace fgimpact
