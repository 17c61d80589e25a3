#ifndef fgimpact_probes_h
#define fgimpact_probes_h

#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/plastic_stress_correction.h>
#include <fgimpact/plate/plate_model.h>

#include <array>
#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// The locally owned cells that contain location (within 1e-10 of their
  /// size) and the point in each one's unit cell; on a face, edge or
  /// vertex there are several, possibly on several ranks.
  std::vector<std::pair<DoFHandler<3>::active_cell_iterator, Point<3>>>
  locally_owned_cells_containing(const PlateModel &plate,
                                 const Point<3>   &location);

  /// A linear functional of a DoF vector: (DoF, weight) at this rank's
  /// DoFs.
  using DofWeights = std::vector<std::pair<types::global_dof_index, double>>;

  /// sum_i w_i x_i over this rank's entries of w (sum over the ranks for
  /// the value).
  double
  local_dot(const DofWeights &w, const TrilinosWrappers::MPI::Vector &x);

  /**
   * The weights of the displacement's 3 components at `location` (m): the
   * one point evaluation of history.csv's and probes.csv's points.  The
   * displacement is continuous, so the average over the cells that contain
   * the point is each one's value.  Collective; throws `outside` if no
   * cell contains the point.
   */
  std::array<DofWeights, 3>
  displacement_weights(const PlateModel  &plate,
                       const Point<3>    &location,
                       const std::string &outside);

  /// The nonzero entries of a distributed vector at this rank's DoFs.
  std::vector<std::pair<types::global_dof_index, double>>
  owned_nonzeros(const PlateModel                    &plate,
                 const TrilinosWrappers::MPI::Vector &vector);

  /// N writable ghosted vectors on the plate's DoFs into which each rank
  /// adds the weights of its cells' DoFs; owned_weights() then sends each
  /// weight to the rank that owns its DoF, so that an evaluation needs no
  /// ghost values.
  template <std::size_t N>
  std::array<TrilinosWrappers::MPI::Vector, N>
  weight_vectors(const PlateModel &plate)
  {
    std::array<TrilinosWrappers::MPI::Vector, N> w;
    for (auto &vector : w)
      vector.reinit(plate.locally_owned_dofs(),
                    plate.locally_relevant_dofs(),
                    plate.get_mpi_communicator(),
                    /*vector_writable=*/true);
    return w;
  }

  /// The summed weight_vectors() as this rank's nonzeros. Collective.
  template <std::size_t N>
  std::array<DofWeights, N>
  owned_weights(const PlateModel                             &plate,
                std::array<TrilinosWrappers::MPI::Vector, N> &w)
  {
    std::array<DofWeights, N> weights;
    for (unsigned int k = 0; k < N; ++k)
      {
        w[k].compress(VectorOperation::add);
        weights[k] = owned_nonzeros(plate, w[k]);
      }
    return weights;
  }

  /**
   * Displacement and stress at a fixed point of the plate as linear
   * functionals of the DoF vector, with the weights computed once (no mesh
   * search in the time loop).  At a point on element boundaries, where the
   * Q_p stress is discontinuous, the stress is the average over all cells
   * that contain the point; E there is the graded interpolant or the
   * element value, as in the assembly.
   *
   * Under MPI each rank keeps the weights of the DoFs it owns, and an
   * evaluation is a local sum plus one small all-reduce (collective: every
   * rank must call it).
   */
  class PointProbe
  {
  public:
    PointProbe(const PlateModel &plate, const Point<3> &location);

    const Point<3> &
    location() const
    {
      return point;
    }

    /// Displacement (m).
    Tensor<1, 3>
    displacement(const TrilinosWrappers::MPI::Vector &u) const;

    /// Cauchy stress (Pa).
    SymmetricTensor<2, 3>
    stress(const TrilinosWrappers::MPI::Vector &u) const;

    /// A plastic run: the stress is the one the material carries, as the
    /// VTU's (PlasticStressCorrection).
    void
    set_plasticity(const PlasticPlate &plasticity)
    {
      plastic_correction.set_plasticity(plasticity);
    }

    /// A thermal run: the stress is the total, the analysis's plus the
    /// initial state's at the point (InitialStress::stress_at()).
    /// Collective.
    void
    set_prestress(const InitialStress &initial)
    {
      prestress     = initial.stress_at(point);
      has_prestress = true;
      plastic_correction.set_prestress(initial);
    }

  private:
    using Weights = std::vector<std::pair<types::global_dof_index, double>>;

    /// The N functionals at u, on every rank (collective).
    template <std::size_t N>
    std::array<double, N>
    apply(const std::array<Weights, N>        &weights,
          const TrilinosWrappers::MPI::Vector &u) const;

    Point<3>               point;
    MPI_Comm               mpi_communicator;
    std::array<Weights, 3> displacement_weights;
    /// Independent stress components in the order xx, yy, zz, yz, xz, xy.
    std::array<Weights, 6>  stress_weights;
    PlasticStressCorrection plastic_correction;
    /// set_prestress() (Pa); zero without.
    SymmetricTensor<2, 3> prestress;
    bool                  has_prestress = false;
  };
} // namespace fgimpact

#endif
