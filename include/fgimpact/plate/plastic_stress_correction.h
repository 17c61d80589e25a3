#ifndef fgimpact_plastic_stress_correction_h
#define fgimpact_plastic_stress_correction_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/ghost_import.h>
#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>

#include <memory>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * What a plastic run adds to the probes' stresses (PointProbe,
   * ProbeSet), whose elastic part is a linear functional of u: at each
   * (cell, unit point) a probe averages, the difference between the
   * stress the material carries and Hooke's of the total strain,
   *
   *   admissible(C (eps - eps_p)) - C eps,
   *
   * with the same plastic strain (PlasticPlate::plastic_state()) and the
   * same return onto the yield surface (J2Plasticity::admissible_stress())
   * as StressRecovery, so that a probe at a vertex reads the VTU's value.
   * Each rank handles its locally owned cells.
   */
  class PlasticStressCorrection
  {
  public:
    explicit PlasticStressCorrection(const PlateModel &plate);

    /// A point of a locally owned cell that enters the probes' averages:
    /// `weights` lists (slot, factor), the slot's stress getting factor
    /// times the point's difference; the components odd under the cut
    /// planes `planes` (odd_under_reflection()) are left out.
    void
    add_point(const DoFHandler<3>::active_cell_iterator      &cell,
              const Point<3>                                 &unit_point,
              const std::vector<std::pair<unsigned, double>> &weights,
              const unsigned int                              planes = 0);

    void
    set_plasticity(const PlasticPlate &plasticity);

    /// A thermal run: the total strain at each point adds the initial
    /// state's eps0 (the probes' linear part adds its stress).
    void
    set_prestress(const InitialStress &initial);

    bool
    active() const
    {
      return plasticity != nullptr;
    }

    /// Add the differences (Pa) to local[slot * stride + offset + s] for
    /// the components s in the order xx, yy, zz, xy, xz, yz.  u: the
    /// locally owned displacement (m), constraints distributed.
    void
    add_to(const TrilinosWrappers::MPI::Vector &u,
           std::vector<double>                 &local,
           const unsigned int                   stride,
           const unsigned int                   offset) const;

  private:
    struct Record
    {
      unsigned int                             active_index;
      Point<3>                                 unit_point;
      double                                   E, nu, z;
      unsigned int                             planes;
      std::vector<std::pair<unsigned, double>> weights;
      std::vector<int>                         local_index; // per cell DoF
      std::vector<SymmetricTensor<2, 3>>       strain;      // per unit DoF
      SymmetricTensor<2, 3>                    eps0;        // set_prestress()
    };

    const PlateModel                     &plate;
    const PlasticPlate                   *plasticity = nullptr;
    std::vector<Record>                   records;
    bool                                  prestressed = false;
    mutable TrilinosWrappers::MPI::Vector u_ghosted;
    mutable GhostImporter                 importer;
  };
} // namespace fgimpact

#endif
