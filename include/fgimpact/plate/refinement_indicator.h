#ifndef fgimpact_refinement_indicator_h
#define fgimpact_refinement_indicator_h

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/plate_model.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Where the plate's mesh is too coarse over a whole impact: per active
   * cell, the time integral of Kelly's indicator squared,
   *
   *   eta_K^2 = int_0^T sum_{F in dK} h_K / 24 int_F |[E(z) du/dn]|^2 dt,
   *   (h_K the cell's diagonal: deal.II's cell_diameter_over_24)
   *
   * the jump of the displacement gradient across the cell's faces weighted
   * by the graded modulus E(z) (GPa), a traction jump for a constant
   * Poisson's ratio (deal.II's KellyErrorEstimator, step-6; the faces on
   * the plate's boundary count nothing).  Integrated in time because the
   * pilot run's mesh has to serve every instant of the next run: the
   * contact's edge early, the bending wave later.
   *
   * The gradient is the 8-node brick's: with Finite element/Incompatible
   * modes the bending jumps the modes remove still count, so the indicator
   * over-weights the bending zone there (it still ranks the cells).
   */
  class RefinementIndicator
  {
  public:
    explicit RefinementIndicator(const PlateModel &plate);

    /// Add eta_K(u)^2 * weight (weight: the step's length, s) for the
    /// displacement u (m) with the constraints distributed (owned
    /// entries).  Collective.
    void
    add(const TrilinosWrappers::MPI::Vector &u, const double weight);

    /// This rank's accumulated eta_K^2, by active cell index.
    const Vector<double> &
    indicators() const
    {
      return accumulated;
    }

    /// The CellId strings of the fraction `fraction` (0..1] of all active
    /// cells with the largest indicators (ties broken by the cell's id, so
    /// the choice is the same on any number of ranks), on every rank.
    /// Collective.
    std::vector<std::string>
    cells_to_refine(const double fraction) const;

  private:
    const PlateModel             &plate;
    TrilinosWrappers::MPI::Vector ghosted;
    Vector<float>                 step_indicator;
    Vector<double>                accumulated;
  };
} // namespace fgimpact

#endif
