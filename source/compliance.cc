#include <fgimpact/compliance.h>

namespace fgimpact
{
  void
  compute_compliance(EffectiveMatrixSolver                      &solver,
                     const PlateModel                           &plate,
                     const std::vector<types::global_dof_index> &dofs,
                     FullMatrix<double>                         &C,
                     std::vector<TrilinosWrappers::MPI::Vector> *responses)
  {
    const unsigned int m = dofs.size();
    C.reinit(m, m);
    if (responses != nullptr)
      responses->resize(m);
    TrilinosWrappers::MPI::Vector g, c;
    for (unsigned int j = 0; j < m; ++j)
      {
        plate.initialize_vector(g);
        plate.initialize_vector(c);
        // Only the owner of the contact DoF writes.
        if (g.locally_owned_elements().is_element(dofs[j]))
          g(dofs[j]) = 1.;
        g.compress(VectorOperation::insert);
        solver.solve(c, g);
        const Vector<double> column = plate.dof_values(c, dofs);
        for (unsigned int i = 0; i < m; ++i)
          C(i, j) = column[i];
        if (responses != nullptr)
          (*responses)[j].swap(c);
      }
  }
} // namespace fgimpact
