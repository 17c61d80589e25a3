#ifndef fgimpact_initial_stress_h
#define fgimpact_initial_stress_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/material/thermal.h>
#include <fgimpact/plate/plate_model.h>

#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The state the analyses start from after the thermal step (Abaqus'
   * initial stress): the thermal displacement u0 and the mechanical
   * strain it leaves, eps0 = eps(u0) - alpha(z) (T(z) - T_ref) I (with
   * B-bar the cell's mean dilatation of u0), whose stress
   * sigma0 = C eps0 every written stress adds to the analysis's own
   * (linear superposition: doc/thermal.md).  Holds references: the
   * plate, the profile and u0 (ghosted, constraints distributed) outlive
   * it.
   */
  class InitialStress
  {
  public:
    InitialStress(const PlateModel                    &plate,
                  const TemperatureProfile            &temperature,
                  const TrilinosWrappers::MPI::Vector &u0);

    /// eps0 at the points of fe_values (reinitialized on the locally
    /// owned `cell`, with update_gradients | update_quadrature_points).
    void
    strain(const FEValues<3>                         &fe_values,
           const DoFHandler<3>::active_cell_iterator &cell,
           std::vector<SymmetricTensor<2, 3>>        &eps0) const;

    /// sigma0 (Pa) at a point of the plate: the average over the cells
    /// that contain it, as PointProbe averages.  Collective; NaN if no
    /// cell contains the point.
    SymmetricTensor<2, 3>
    stress_at(const Point<3> &location) const;

    const TemperatureProfile &
    temperature() const
    {
      return profile;
    }

    /// u0 (m), ghosted.
    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return u0;
    }

  private:
    const PlateModel                    &plate;
    const TemperatureProfile            &profile;
    const TrilinosWrappers::MPI::Vector &u0;
  };
} // namespace fgimpact

#endif
