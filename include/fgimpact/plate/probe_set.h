#ifndef fgimpact_probe_set_h
#define fgimpact_probe_set_h

#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/point.h>
#include <deal.II/base/symmetric_tensor.h>
#include <deal.II/base/tensor.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/plastic_stress_correction.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/plate/probes.h>

#include <array>
#include <functional>
#include <string>
#include <utility>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * One named probe point of the entry Output/Probe points: each
   * coordinate either in mm or, with the suffix a (x), b (y) or h (z), as a
   * fraction of the plate's length, width or thickness.
   */
  struct ProbePoint
  {
    std::string           name;
    std::array<double, 3> value{};    // mm, or a fraction
    std::array<bool, 3>   fraction{}; // value is a fraction of a, b, h

    /// The point (m) on the plate a x b x h (m).
    Point<3>
    location(const double a, const double b, const double h) const;
  };

  /**
   * The entry "Probe points" of subsection Output:
   * `name: x, y, z; name2: x, y, z` (see declare_parameters()).  Parsing
   * checks the syntax; validate() checks that every point lies in the
   * plate.  Both throw a one-line error naming the entry.
   */
  struct ProbePoints
  {
    /// The entry's default: the centre of the mid-plane, the top and the
    /// bottom face.
    static constexpr const char *default_points =
      "mid: 0.5a, 0.5b, 0.5h; top: 0.5a, 0.5b, 1h; bottom: 0.5a, 0.5b, 0h";

    std::vector<ProbePoint> points = parse(default_points);

    /// Declares the entry in the current subsection (Output).
    static void
    declare_parameters(ParameterHandler &prm);
    /// Reads the entry from the current subsection (Output).
    void
    parse_parameters(ParameterHandler &prm);

    /// The points of a `name: x, y, z; ...` list (throws on bad syntax).
    static std::vector<ProbePoint>
    parse(const std::string &text);

    /// Throws if a point lies outside the plate a x b x h (m).
    void
    validate(const double a, const double b, const double h) const;
  };



  /// Everything a ProbeSet measures at one time, in SI units.
  struct ProbeValues
  {
    std::vector<Tensor<1, 3>>          displacement; // m, per point
    std::vector<Tensor<1, 3>>          velocity;     // m/s
    std::vector<Tensor<1, 3>>          acceleration; // m/s^2
    std::vector<SymmetricTensor<2, 3>> stress;       // Pa, recovered
    /// z component of the supports' total force on the plate (N, +z).
    double support_reaction_z = 0;
  };



  /**
   * Probes at any points of the plate: displacement, velocity and
   * acceleration, the recovered (nodal-averaged) stress exactly as
   * StressRecovery gives it (interpolated from the nodes of the cell that
   * contains the point, averaged over the cells on a face, edge or vertex),
   * and the total support reaction in z.  Every quantity is a linear
   * functional of u, v or a with weights computed once, so a time step
   * costs a few dot products and one all-reduce (collective under MPI:
   * every rank must call evaluate()).
   *
   * The support reaction is the sum over the Dirichlet-constrained z DoFs
   * of (K u + M a - f)_i with the unconstrained K and M, i.e. the force
   * the supports exert on the plate (positive up).  For a lumped mass
   * (explicit scheme, whose constrained DoFs have no mass) the M a part
   * is zero.
   */
  class ProbeSet
  {
  public:
    ProbeSet(const PlateModel &plate, const std::vector<ProbePoint> &points);

    /// Collective.  lumped_mass: the M a part of the reaction is zero.
    ProbeValues
    evaluate(const TrilinosWrappers::MPI::Vector &u,
             const TrilinosWrappers::MPI::Vector &v,
             const TrilinosWrappers::MPI::Vector &a,
             const bool                           lumped_mass) const;

    /// The columns of probes.csv: name (with unit) and decimals.
    std::vector<std::pair<std::string, int>>
    columns() const;

    /// A row of probes.csv at time t (s), in the units of columns().
    std::vector<double>
    row(const double t, const ProbeValues &values) const;

    /// A plastic run: the stresses are the ones the material carries, as
    /// the VTU's (PlasticStressCorrection), and the support reaction
    /// subtracts the plastic strain's load.
    void
    set_plasticity(const PlasticPlate &plasticity)
    {
      plastic_correction.set_plasticity(plasticity);
      plastic = &plasticity;
    }

    /// A thermal run: the stresses are the total, the analysis's plus
    /// the initial state's recovered at each point. Collective.
    void
    set_prestress(const PlateModel &plate, const InitialStress &initial);

    const std::vector<Point<3>> &
    locations() const
    {
      return points;
    }

    /// The probes' names (Output/Probe points), in the order of locations().
    const std::vector<std::string> &
    get_names() const
    {
      return names;
    }

  private:
    using Weights = DofWeights;

    void
    setup_point_weights(const PlateModel &plate);
    /// StressRecovery as a linear functional: sigma(x) = sum_j c_j
    /// sigma_j with c_j = N_j(x) (averaged over the cells containing x)
    /// and sigma_j = (1/n_j) sum over the n_j cells K at scalar node j of
    /// sigma_K(x_j).  First c (ghosted, so that every cell at node j sees
    /// it), then each cell's share of the nodal averages.
    void
    setup_stress_weights(const PlateModel &plate);

    /// What visit_read_nodes() gives per cell: each scalar node's probe
    /// factors (c_j / n_j of the probes that read it) and cut planes, and
    /// E, nu, rho there.
    struct NodeValues
    {
      std::vector<std::vector<std::pair<unsigned int, double>>> factors;
      std::vector<unsigned int>                                 planes;
      std::vector<double>                                       E, nu, rho;
    };
    using NodeVisitor =
      std::function<void(const DoFHandler<3>::active_cell_iterator &,
                         const FEValues<3> &,
                         const NodeValues &)>;

    /// visit(cell, fe_values, node) on every locally owned cell with a
    /// scalar node some probe reads, fe_values (gradients and points) at
    /// its scalar support points. Collective.
    void
    visit_read_nodes(const PlateModel &plate, const NodeVisitor &visit) const;
    /**
     * The support reaction's weights (source/plate/support_reaction.cc).
     * z_S is the conforming field that is 1 at the supported z DoFs (the
     * constrained ones without entries) and 0 at the free ones: a hanging
     * node between a supported and a free vertex (local refinement that
     * reaches a support) carries the weight its constraint put on the
     * supported masters, 1 minus the sum of its entries, since closing the
     * constraints drops the masters fixed at 0.  Then the supports' share
     * of the internal force, hanging nodes' shares included, is a(z_S, u)
     * + (rho z_S, a), with the unconstrained forms of the assembly.  Such
     * a node is also a vertex of cells off the boundary, so every cell is
     * looked at.  (Weighting the supported DoFs alone missed 0.8 % of the
     * peak force of an unloaded plastic indentation refined down to its
     * clamped bottom.)
     */
    void
    setup_reaction_weights(const PlateModel &plate);

    MPI_Comm                 mpi_communicator;
    std::vector<std::string> names;
    std::vector<Point<3>>    points;
    /// Per point: the 3 displacement components, then the 6 recovered
    /// stress components xx, yy, zz, xy, xz, yz (Pa per m).
    std::vector<std::array<Weights, 9>> weights;
    /// The reaction's stiffness (on u) and mass (on a) parts.
    Weights reaction_stiffness, reaction_mass;
    /// Its plastic part, -int sigma(z_S) : eps_p dV: at each Gauss point
    /// of a locally owned cell with supported DoFs, sigma(z_S) JxW (N/m,
    /// i.e. Pa m^3 per unit strain).
    struct ReactionPoint
    {
      unsigned int          active_index;
      Point<3>              unit_point;
      SymmetricTensor<2, 3> weighted_stress;
    };
    std::vector<ReactionPoint> reaction_points;
    /// The plastic part of the support reaction (N; 0 without plasticity).
    double
    plastic_reaction() const;

    PlasticStressCorrection plastic_correction;
    const PlasticPlate     *plastic = nullptr;
    /// set_prestress(): per point the 6 components (Pa); empty without.
    std::vector<double> prestress;
  };
} // namespace fgimpact

#endif
