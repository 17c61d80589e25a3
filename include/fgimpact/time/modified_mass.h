#ifndef fgimpact_modified_mass_h
#define fgimpact_modified_mass_h

#include <deal.II/lac/trilinos_sparse_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/plate_model.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The mass matrix of an implicit step: the plate's consistent mass
   * matrix M, or for a contact model with massless DoFs (the modified mass
   * method of Khenous, Laborde and Renard 2008) M with their rows and
   * columns zeroed: contact nodes without inertia cannot chatter, and the
   * removed mass, on the contact candidates alone, vanishes with the
   * element size (logged).  The modified matrix is not stored (a copy of M
   * was 3 % of the memory at level 7 of the default scene): vmult() zeroes
   * the massless entries around M's product, and the effective matrix
   * takes K's entries there.
   */
  class ModifiedMass
  {
  public:
    explicit ModifiedMass(const PlateModel &plate);

    /**
     * effective = K + a0 M_mod (a0 in 1/s^2): M's entries in the massless
     * DoFs' rows and columns are left out, so K_eff has K's entries there
     * (bitwise K + a0 0).  Sets the massless DoFs for vmult().  Collective.
     */
    void
    build_effective_matrix(const double                                a0,
                           const std::vector<types::global_dof_index> &massless,
                           TrilinosWrappers::SparseMatrix &effective);

    /// dst = M_mod src: the massless DoFs' terms are exact zeros either
    /// way, so the product is bitwise that of the modified matrix.
    void
    vmult(TrilinosWrappers::MPI::Vector       &dst,
          const TrilinosWrappers::MPI::Vector &src);

    /// The mass left out (kg, the part's), 0 without massless DoFs.
    double
    removed() const
    {
      return removed_mass;
    }

  private:
    const PlateModel &plate;
    bool              modified     = false;
    double            removed_mass = 0;
    /// The massless DoFs this rank owns.
    std::vector<types::global_dof_index> owned;
    /// vmult()'s copy of src with the massless entries zeroed.
    TrilinosWrappers::MPI::Vector masked;
  };
} // namespace fgimpact

#endif
