#ifndef fgimpact_strength_check_h
#define fgimpact_strength_check_h

#include <deal.II/base/point.h>
#include <deal.II/base/tensor.h>

#include <deal.II/dofs/dof_handler.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/full_matrix.h>
#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/material/strength.h>
#include <fgimpact/material/thermal.h>
#include <fgimpact/plate/ghost_import.h>
#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>

#include <array>
#include <map>
#include <memory>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * The elastic stresses against the graded strengths (GradedStrength),
   * at every step: the von Mises stress over the TTO yield strength in the
   * metal-rich part and the largest principal stress over the tensile
   * strength in the ceramic-rich part, at the scalar support points of
   * every locally owned cell (the vertices for Q1, where a brick's
   * strain is largest), each cell's own stress (not averaged: the
   * largest of the discontinuous field).  The largest ratio of each is
   * kept with its point and time.
   *
   * The cells with a vertex within `excluded_radius` of `excluded_centre`
   * are skipped: the Hertz models load one node with a point force, whose
   * stress has no limit (it grows as 1/r^2 under refinement); there the
   * caller puts Hertz's closed form instead.
   *
   * Every cell is a brick (PropertyInterpolator's assumption too): the
   * shape gradients at the points depend only on its extents, so one table
   * per extent serves all cells of that size.
   */
  class StrengthCheck
  {
  public:
    StrengthCheck(const PlateModel     &plate,
                  const GradedStrength &strength,
                  const Point<3>       &excluded_centre,
                  const double          excluded_radius);

    /// The stresses of the displacement u (m, constraints distributed,
    /// locally owned) at time t (s).  Not collective.
    void
    evaluate(const TrilinosWrappers::MPI::Vector &u, const double t);

    /// The peaks over all ranks so far (collective); ratio NaN if no
    /// point of that part is checked (no such part, or its strength 0).
    StrengthPeak
    metal_peak() const;
    StrengthPeak
    ceramic_peak() const;

    /// Start from peaks found before (a resumed run).
    void
    set_peaks(const StrengthPeak &metal, const StrengthPeak &ceramic);

    /// A plastic run: the stress checked is the one the material carries,
    /// C (eps - eps_p), with each cell's plastic strain at its support
    /// points (PlasticPlate::plastic_state()), and a metal point's
    /// strength is its current yield stress Y(z) + H(z) eps_bar.  Without
    /// it (and in an elastic run) the stress is C eps: what an elastic
    /// material would carry.
    void
    set_plasticity(const PlasticPlate &plasticity);

    /**
     * A thermal pre-stress (Thermal/Temperature field): every stress
     * checked is the total, C (eps(u) + eps0), with the thermal step's
     * mechanical strain eps0 = eps(u_th) - alpha (T - T_ref) I at each
     * point, so that the indices are those of the stress the material
     * carries (source/plate/strength_check_prestress.cc); with
     * plasticity, C (eps(u) + eps0 - eps_p).  u_th ghosted, constraints
     * distributed.
     */
    void
    set_prestress(const TrilinosWrappers::MPI::Vector &u_th,
                  const TemperatureProfile            &temperature);

  private:
    /// u into u_ghosted (the layout of local_index); its values.
    const double *
    gather(const TrilinosWrappers::MPI::Vector &u);

    /// G += eps0 at checked point k (set_prestress()).
    void
    add_prestrain(const unsigned int k, double G[3][3]) const;

    /// The cell data for the cells that are checked.
    void
    setup(const Point<3> &excluded_centre, const double excluded_radius);

    /// A new extent's shape gradients at the support points (fe_values
    /// reinitialized on `cell`) and mean divergence.
    void
    add_table(const DoFHandler<3>::active_cell_iterator &cell,
              const FEValues<3>                         &fe_values,
              const std::array<double, 3>               &extent);

    /// Each extent's bound of |grad u| / |D| over its points.
    void
    set_gradient_bounds();

    /// Incompatible modes (source/plate/strength_check_modes.cc): cell
    /// c's H (PlateModel::mode_amplitudes(), columns in the order s * 3 +
    /// component), one per extent and height of its centre (the material
    /// depends on z only).
    void
    add_mode_table(const DoFHandler<3>::active_cell_iterator &cell,
                   const std::array<double, 3>               &extent);

    /// Incompatible modes: cell c's mode amplitudes alpha = H cell_u (m);
    /// false (alpha untouched) without modes.
    bool
    mode_amplitudes(const unsigned int         c,
                    const std::vector<double> &cell_u,
                    std::array<double, 9>     &alpha) const;

    /// Incompatible modes: G += the modes' displacement gradient at point
    /// q of cell c, alpha_(3 a + d) dN_d/dx_d in G[a][d] (boxes).
    void
    add_mode_gradient(const unsigned int           c,
                      const unsigned int           q,
                      const std::array<double, 9> &alpha,
                      double                       G[3][3]) const;

    /// Whether cell c (its displacements cell_u, [s * 3 + component])
    /// cannot beat the peaks: for Q1, its strain at the centre (exact, the
    /// rigid rotation removed) plus a bound of the trilinear variation;
    /// otherwise |grad u| <= |D| gradient_bound.
    /// With incompatible modes (alpha not null) each entry's variation
    /// grows by its mode's largest gradient 4 |alpha| / h (their centre
    /// gradient is 0).
    bool
    can_skip(const unsigned int           c,
             const std::vector<double>   &cell_u,
             const std::array<double, 9> *alpha) const;

    /// One checked point (Lame constants and strength from E (Pa), nu).
    void
    add_point(const Point<3> &x, const double E, const double nu);

    /// The displacement gradient at point q of owned cell c (cell_u in the
    /// order s * 3 + c); with theta (B-bar), its trace replaced by it.
    void
    displacement_gradient(const unsigned int         c,
                          const unsigned int         q,
                          const std::vector<double> &cell_u,
                          const double *const        theta,
                          double                     G[3][3]) const;

    /// The point k's stress from its displacement gradient G at time t
    /// (with the plastic strain taken off), against its strength, or for
    /// a plastic metal point against `yield_stress` (Pa) if positive.
    void
    check_point(const unsigned int k,
                const double       G[3][3],
                const double       t,
                const double       yield_stress = 0.);

    StrengthPeak
    global_peak(const StrengthPeak &local, const unsigned int n_local) const;

    /// Whether peak a is to be kept over b: the larger ratio; a tie
    /// (mirror images, relative 1e-12) goes to the smaller (x, y, z), then
    /// the earlier time.
    static bool
    precedes(const StrengthPeak &a, const StrengthPeak &b);

    const PlateModel     &plate;
    const GradedStrength &strength;
    unsigned int          n_points = 0;
    /// The scalar element's support points (= its shape functions).
    unsigned int n_scalar = 0;
    /// Shape gradients of the scalar element per cell extent:
    /// [table][(q * n_scalar + s) * 3 + d].
    std::vector<std::vector<double>> gradients;
    /// Per table: max over the points of |(sum_s |dN_s/dx_d|)_d|, so that
    /// |grad u| <= |D| of the cell, D_c = max_s |u_sc - mean_s u_sc|
    /// (the shape functions sum to 1).
    std::vector<double> gradient_bound;
    /// Per table: the cell's extents (m).
    std::vector<std::array<double, 3>> extents;
    /// Per table, with B-bar (PlateModel::mean_divergence()): the weights
    /// of the cell's mean dilatation over its DoFs, in the order s * 3 + c.
    std::vector<std::vector<double>> mean_divergences;
    /// Incompatible modes: the H tables (add_mode_table()) and each
    /// checked cell's.
    std::vector<FullMatrix<double>> mode_tables;
    std::map<std::pair<std::array<double, 3>, double>, unsigned int> mode_keys;
    std::vector<unsigned int>                                        mode_table;
    /// Per checked cell, over its points (strength included, so the
    /// factors bound ratios): the von Mises stress per |dev eps| of the
    /// metal-rich points; of the ceramic-rich points sigma_1 per
    /// |tr eps|, per |dev eps|, and per |eps|.  A cell whose bound cannot
    /// beat the peaks is skipped (can_skip()).
    struct CellFactors
    {
      double metal = 0, ceramic_trace = 0, ceramic_deviator = 0,
             ceramic_norm = 0;
    };
    std::vector<CellFactors> factors;
    /// set_prestress(): eps0 per checked point (xx, yy, zz, xy, xz, yz);
    /// per checked cell the largest |dev eps0|, |tr eps0| and |eps0| of
    /// its points, which can_skip() adds to its bounds.  Empty without.
    std::vector<std::array<double, 6>> prestrain;
    std::vector<double> prestrain_dev, prestrain_trace, prestrain_norm;
    /// Per checked cell: its table, and the local indices in u_ghosted of
    /// its DoFs in the order [s * 3 + component].
    std::vector<unsigned int> table;
    std::vector<int>          local_index;
    /// Per checked cell: its active_cell_index() (for the plastic state).
    std::vector<unsigned int> active_index;
    /// The scalar element's unit support points (the points checked).
    std::vector<Point<3>> unit_support;
    const PlasticPlate   *plasticity = nullptr;
    /// Per checked cell and point: Lame's lambda and 2 mu (Pa), 1/strength
    /// (1/Pa, 0 if the check is off), whether metal-rich, the point (m).
    std::vector<double>   lambda, two_mu, inverse_strength;
    std::vector<bool>     metal;
    std::vector<Point<3>> points;

    TrilinosWrappers::MPI::Vector u_ghosted;
    /// The owned-to-ghosted import, built once (deal.II's assignment
    /// builds one per call, which cost more than the check itself).
    GhostImporter importer;
    StrengthPeak  metal_local, ceramic_local;
    /// The points checked on this rank, per part.
    unsigned int n_metal = 0, n_ceramic = 0;
  };
} // namespace fgimpact

#endif
