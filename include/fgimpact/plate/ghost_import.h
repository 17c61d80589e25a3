#ifndef fgimpact_ghost_import_h
#define fgimpact_ghost_import_h

#include <deal.II/base/exceptions.h>

#include <deal.II/lac/trilinos_vector.h>

#include <Epetra_Import.h>
#include <memory>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Copies a distributed vector's values into a ghosted vector of another
   * layout (the locally relevant entries a cell loop reads by local index)
   * with an Epetra_Import built on the first call and reused.  Not
   * operator=, whose Epetra map comparison is collective on some ranks
   * only: a resumed 2-rank J2 run deadlocked in it (issue 40).  Every
   * call must see vectors of the same two layouts.
   */
  class GhostImporter
  {
  public:
    /// to <- from; the first of to's local values (its local indices).
    const double *
    import(const TrilinosWrappers::MPI::Vector &from,
           TrilinosWrappers::MPI::Vector       &to)
    {
      if (!importer)
        importer =
          std::make_unique<Epetra_Import>(to.trilinos_vector().Map(),
                                          from.trilinos_vector().Map());
      const int error =
        to.trilinos_vector().Import(from.trilinos_vector(), *importer, Insert);
      AssertThrow(error == 0, ExcTrilinosError(error));
      return to.trilinos_vector()[0];
    }

  private:
    std::unique_ptr<Epetra_Import> importer;
  };
} // namespace fgimpact

#endif
