#ifndef fgimpact_plastic_plate_h
#define fgimpact_plastic_plate_h

#include <deal.II/base/quadrature.h>

#include <deal.II/fe/fe_values.h>

#include <deal.II/lac/trilinos_vector.h>
#include <deal.II/lac/vector.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/material/plasticity.h>
#include <fgimpact/material/strength.h>
#include <fgimpact/plate/ghost_import.h>
#include <fgimpact/plate/initial_stress.h>
#include <fgimpact/plate/plate_model.h>

#include <array>
#include <memory>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// Where between two increments first yield came: the fraction in
  /// [0, 1] at which the largest trial ratio, `before` and `after` (the
  /// first above 1), crosses 1 if it varies linearly.
  double
  yield_crossing(const double before, const double after);

  /**
   * The plastic state of the plate's metal-rich part at the Gauss points
   * (Material/Plasticity = J2): J2Plasticity with the TTO-graded yield
   * strength and hardening of GradedStrength; the ceramic-rich part
   * (V_m < 1/2) stays elastic.
   *
   * The plate's linear solvers keep the elastic matrix: the plastic strain
   * enters as the load f_p = int B^T D eps_p (N, an eigenstrain), so that
   *
   *   K u = f_ext + f_p(u)
   *
   * is solved by the initial-stiffness iteration: solve with f_p fixed,
   * update() the return map from the committed state at the new u, and
   * solve again with the new f_p until it stops changing.  Aitken's
   * relaxation (Irons & Tuck 1969) accelerates the iteration, which
   * converges slowly for a perfectly plastic zone.  The elastic
   * factorization and the contact compliance serve every iteration.
   *
   * Every cell is a brick (as for PropertyInterpolator): the shape
   * gradients at the Gauss points depend only on the cell's extents.
   * Cells whose elastic trial stress cannot reach the yield strength (a
   * bound from the spread of their nodal displacements) and that hold no
   * plastic strain are skipped.
   */
  class PlasticPlate
  {
  public:
    PlasticPlate(const PlateModel &plate, const GradedStrength &strength);

    /// The graded strengths the plate yields with.
    const GradedStrength &
    get_strength() const
    {
      return strength;
    }

    /// Start an increment (a time step or a load step): the relaxation
    /// starts afresh from the committed plastic force.
    void
    begin_increment();

    /**
     * The return map at every point for the displacement u (m; condensed,
     * locally owned: the constraints are distributed here), from the
     * committed state.  The next plastic_force() is the relaxed update of
     * the one u was computed with.  Returns the change |f_p(u) - f_p|_inf
     * (N), the iteration's residual.  Collective.
     */
    double
    update(const TrilinosWrappers::MPI::Vector &u);

    /// The plastic force f_p (N, condensed) to solve with next.
    const TrilinosWrappers::MPI::Vector &
    plastic_force() const
    {
      return force;
    }

    /// f_p(u) of the last update(), unrelaxed (N, condensed): the load of
    /// its plastic strain, which the elastic energy identity needs.
    const TrilinosWrappers::MPI::Vector &
    updated_force() const
    {
      return new_force;
    }

    /// Accept the last update() as the end of the increment.  Collective.
    void
    commit();

    /// The plastic work done so far (J, the part modelled; the hardening
    /// energy included), up to the last commit().
    double
    plastic_work() const
    {
      return work;
    }

    /// 1/2 int eps_p : D : eps_p (J, the part) of the last update(): the
    /// elastic strain energy is 1/2 u^T K u - u^T f_p + this.
    double
    eigenstrain_energy() const
    {
      return trial_eigenstrain_energy;
    }

    /// The largest equivalent plastic strain committed, over all ranks.
    double
    max_equivalent_plastic_strain() const
    {
      return max_plastic_strain;
    }

    /// The largest von Mises stress over the yield stress of the elastic
    /// trial state of the last update(), over all ranks (above 1: the
    /// increment yields; its first crossing gives first yield).
    double
    max_trial_ratio() const
    {
      return trial_ratio;
    }

    /// Iterations (update() calls) over all increments committed, and the
    /// most in one increment.
    unsigned long long
    n_iterations() const
    {
      return total_iterations;
    }
    unsigned int
    max_increment_iterations() const
    {
      return max_iterations;
    }

    /// The equivalent plastic strain per active cell (the largest of its
    /// Gauss points; 0 where elastic or not locally owned), indexed by
    /// active_cell_index() (this rank's triangulation), for the VTU output.
    Vector<float>
    cell_plastic_strain() const;

    /// The committed state's von Mises stress over the current yield
    /// stress (Y + H eps_bar) per active cell, the largest of its Gauss
    /// points (0 where no point is plastic or the cell is not locally
    /// owned), indexed as cell_plastic_strain(): the return map's own
    /// verdict, at most 1 up to the iteration's tolerance.
    Vector<float>
    cell_yield_utilization() const;

    /// Whether the locally owned active cell (active_cell_index() of this
    /// rank's triangulation) holds committed plastic strain.
    bool
    holds_plastic_strain(const unsigned int active_cell_index) const;

    /**
     * The committed plastic strain eps_p and equivalent plastic strain of
     * the locally owned active cell at the point `unit_point` of its
     * reference cell: the tensor-product Lagrange interpolant through its
     * Gauss points (trilinear for Q1; at a vertex the extrapolation of
     * the Gauss-point values that Abaqus and ANSYS use for nodal
     * results).  Zero for a cell without plastic strain.  With it, every
     * stress the program writes is sigma = C(x) (eps(x) - eps_p(x)).
     */
    PlasticState
    plastic_state(const unsigned int active_cell_index,
                  const Point<3>    &unit_point) const;

    /// The plastic zone of the committed state: the largest depth below
    /// the top face z = `top` (m) and the largest horizontal distance
    /// from `centre` (m) of a Gauss point with plastic strain, over all
    /// ranks (0 and 0 without one).  Collective.
    std::array<double, 2>
    plastic_zone_extent(const Point<3> &centre, const double top) const;

    /// The current yield stress Y(z) + H(z) eps_bar (Pa) at height z (m)
    /// for the equivalent plastic strain eps_bar (infinite where the
    /// plate is ceramic-rich, i.e. elastic).
    double
    yield_stress(const double z, const double equivalent_plastic_strain) const;

    /**
     * A thermal run (plastic_plate_prestress.cc): plasticity starts from
     * the initial state.  The return map sees the total mechanical strain
     * eps(u) + eps0 at every Gauss point, the cell-skipping bound adds the
     * cell's largest |dev eps0|, and eigenstrain_energy() adds
     * -int sigma0 : eps_p dV: with int B^T sigma0 dV = 0 (the thermal
     * step's equilibrium) the total elastic energy changes from the
     * thermal state's by 1/2 u^T K u - u^T f_p + 1/2 int eps_p : D : eps_p
     * - int sigma0 : eps_p, so that the energy balance closes with the
     * plastic work of the total stress.  Before the first update().
     * Collective.
     */
    void
    set_prestress(const InitialStress &initial);

    /// An impact (after set_prestress()): throws, in one line saying where
    /// and how far, if the initial state's von Mises stress exceeds the
    /// yield strength at a Gauss point (the thermal step is elastic).
    void
    refuse_yielding_prestress() const;

    /// The initial state's largest von Mises stress over the yield
    /// strength (set_prestress(); 0 without): the trial ratio at zero
    /// load, from which first yield is interpolated.
    double
    initial_yield_ratio() const
    {
      return prestress_yield.first;
    }

    /// The committed state (this rank's points) and the work.
    void
    save(CheckpointWriter &out) const;
    void
    load(CheckpointReader &in);

  private:
    /// to = from on the owned entries (same owned DoFs, same order).  Not
    /// operator=, whose Epetra map comparison is collective on some ranks
    /// only: a resumed 2-rank J2 run deadlocked in it.
    static void
    copy_owned(const TrilinosWrappers::MPI::Vector &from,
               TrilinosWrappers::MPI::Vector       &to);

    /// Whether any quadrature point of fe_values is metal-rich enough to
    /// yield (GradedStrength::metal_rich()).
    bool
    any_metal_rich(const FEValues<3> &fe_values) const;

    /// A plastic cell's DoFs into dofs and their indices in u_ghosted into
    /// local_index (point-major: 3 s + component).
    void
    add_cell_dofs(const DoFHandler<3>::active_cell_iterator &cell);

    /// u with its constraints distributed, imported into u_ghosted: its
    /// values, indexed by local_index.
    const double *
    ghosted_values(const TrilinosWrappers::MPI::Vector &u);

    /// The trial state of an elastic cell c that update() skipped: no
    /// plastic strain, work or utilization.
    void
    clear_trial(const unsigned int c);

    void
    setup();

    /// gauss_1d and gauss_index of the cells' quadrature (QGauss<3>).
    void
    setup_interpolation(const Quadrature<3> &quadrature);

    /// The shape gradient tables of a new cell extent (fe_values on a cell
    /// of that extent, m).
    void
    add_table(const FEValues<3>           &fe_values,
              const Quadrature<3>         &quadrature,
              const std::array<double, 3> &extent);

    /// A cell's points: Lame's constants from E (Pa), nu; the graded
    /// strengths; JxW; the cell's skip bound.
    void
    add_points(const FEValues<3>         &fe_values,
               const std::vector<double> &E,
               const std::vector<double> &nu);

    /// Whether cell c (its displacements cell_u, [s * 3 + component])
    /// holds no point whose trial stress can reach half its yield stress.
    bool
    can_skip(const unsigned int c, const std::vector<double> &cell_u) const;

    /// One cell's return map at its points: the trial states, its plastic
    /// force [s * 3 + component] (N), eigenstrain energy (J), largest trial
    /// ratio, and whether any point is plastic.
    struct CellResult
    {
      std::vector<double> force;
      double              energy = 0, ratio = 0;
      bool                plastic = false;
    };
    void
    evaluate_cell(const unsigned int         c,
                  const std::vector<double> &cell_u,
                  CellResult                &result);

    /// The relaxation of the new force: Aitken's factor from the last two
    /// residuals.
    void
    relax();

    const PlateModel     &plate;
    const GradedStrength &strength;
    unsigned int          n_points = 0, n_dofs = 0;
    /// Per extent: shape gradients at the Gauss points
    /// [(q * n_scalar + s) * 3 + d], and the bound
    /// max_q |(sum_s |dN_s/dx_d|)_d| of |grad u| per nodal spread.
    std::vector<std::vector<double>> gradients;
    std::vector<double>              gradient_bound;
    /// Per extent: the cell mean of each shape gradient [s * 3 + d] and
    /// the support points from the centre, x_s - x_c (m).
    std::vector<std::vector<double>> mean_gradients, offsets;
    std::vector<double>              weights; // JxW per point (m^3)
    /// Per cell (metal-rich only): its table, DoFs (global, in the
    /// element's order), their local indices in the ghosted vector in the
    /// order [s * 3 + component], its active index, and
    /// min_q sigma_y / (sqrt 6 mu) (m/m: the skip bound).
    std::vector<unsigned int>            table;
    std::vector<types::global_dof_index> dofs;
    std::vector<int>                     local_index;
    std::vector<unsigned int>            active_index;
    std::vector<double>                  skip_strain;
    /// Per active cell of this rank's triangulation: its index c in the
    /// tables above, or -1 (not metal-rich, not locally owned).
    std::vector<int> cell_of_active;
    /// The Gauss points' 1D coordinates (unit cell) and, per point q, the
    /// index of each of its coordinates among them (for plastic_state()).
    std::vector<double>                      gauss_1d;
    std::vector<std::array<unsigned int, 3>> gauss_index;
    /// Per point: Lame's constants, yield strength, hardening (Pa).
    std::vector<double> lambda, mu, yield, hardening;
    /// Per point: its position (m).
    std::vector<Point<3>> position;
    /// Per point: the committed and the trial state; per cell: whether
    /// any point of it is plastic (committed).
    std::vector<PlasticState> committed, trial;
    std::vector<double>       trial_work; // J/m^3 times the point's volume
    /// Per point: von Mises over the yield stress of the trial and the
    /// committed state where plastic (0 elsewhere).
    std::vector<double> trial_utilization, utilization;
    std::vector<bool>   plastic_cell;
    /// set_prestress(): per point eps0, per cell the largest |dev eps0|
    /// (empty without).
    std::vector<SymmetricTensor<2, 3>> prestrain;
    std::vector<double>                prestrain_dev;
    /// The returned von Mises stress of point k over its new yield stress
    /// (0 where elastic).
    double
    utilization_of(const PlasticUpdate &update, const unsigned int k) const;
    /// set_prestress(): the largest von Mises / yield strength of the
    /// initial state over the ranks, and where (m).
    std::pair<double, Point<3>> prestress_yield = {0., Point<3>()};

    TrilinosWrappers::MPI::Vector u_distributed, u_ghosted;
    GhostImporter                 importer;
    /// f_p to solve with, the last update's unrelaxed f_p(u), the last
    /// residual (for Aitken), the committed f_p.
    TrilinosWrappers::MPI::Vector force, new_force, residual, last_residual,
      committed_force;
    double omega           = 1; // Aitken's relaxation factor
    bool   first_iteration = true;

    double work = 0, trial_eigenstrain_energy = 0, max_plastic_strain = 0,
           trial_ratio                  = 0;
    unsigned long long total_iterations = 0;
    unsigned int       iterations = 0, max_iterations = 0;
  };
} // namespace fgimpact

#endif
