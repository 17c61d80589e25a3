#ifndef fgimpact_modal_analysis_h
#define fgimpact_modal_analysis_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>
#include <deal.II/base/timer.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/problem/analysis_parameters.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// A subspace iteration's start block: p deterministic vectors with all
  /// length scales present (X) and p of the same layout (Y), on the
  /// plate's owned DoFs (modal and thermal buckling solves).
  void
  subspace_start_block(const PlateModel                           &plate,
                       const unsigned int                          p,
                       std::vector<TrilinosWrappers::MPI::Vector> &X,
                       std::vector<TrilinosWrappers::MPI::Vector> &Y);

  /**
   * The lowest natural frequencies and mode shapes of K phi = omega^2 M phi
   * by subspace iteration with shift-invert: each iteration applies
   * (K - sigma M)^{-1} M to a block of vectors through one factorization
   * (CHOLMOD), followed by a Rayleigh-Ritz projection solved with LAPACK.
   * Constrained DoFs are kept at zero.
   */
  class ModalAnalysis
  {
  public:
    using Parameters = ModalAnalysisParameters;

    struct Mode
    {
      double frequency;  ///< Hz
      double w_fraction; ///< share of the kinetic energy in w (flexural)
    };

    ModalAnalysis(const Parameters                        &parameters,
                  const EffectiveMatrixSolver::Parameters &solver,
                  const PlateModel                        &plate);

    /// Print the estimated and measured cost of a long iteration (the
    /// executable: Output/Print timing; off by default, as it depends on
    /// the machine).
    void
    report_costs(const bool report);

    void
    solve();

    const std::vector<Mode> &
    get_modes() const
    {
      return modes;
    }

    unsigned int
    n_iterations() const
    {
      return iterations;
    }

    /// summary.txt's entries (every rank), which the run's SummaryFile
    /// writes (the one writer of summary.txt) and keeps for a study.
    SummaryWriter
    summary() const;

    /// frequencies.csv and one VTU per mode shape.
    void
    write_output(const std::string &directory,
                 const DataOutBase::VtkFlags::ZlibCompressionLevel
                   vtu_compression       = DataOutBase::VtkFlags::best_speed,
                 const VtuFields &fields = VtuFields()) const;

  private:
    /// One block solve of the subspace iteration, Y = (K - sigma M)^{-1}
    /// M X on the unconstrained DoFs (mask); in the first iteration
    /// (first) the cost estimate from its first solve.
    void
    apply_inverse(EffectiveMatrixSolver                            &solver,
                  const TrilinosWrappers::MPI::Vector              &mask,
                  const std::vector<TrilinosWrappers::MPI::Vector> &X,
                  std::vector<TrilinosWrappers::MPI::Vector>       &Y,
                  TrilinosWrappers::MPI::Vector                    &Mx,
                  const bool                                        first,
                  const Timer &first_iteration) const;

    /// modes and shapes from the converged block X and its Ritz values.
    void
    collect_modes(const std::vector<TrilinosWrappers::MPI::Vector> &X,
                  const std::vector<double>                        &lambda,
                  const TrilinosWrappers::MPI::Vector              &w_mask);

    /// A log line when the first iteration took long (seconds, block
    /// size), with the bound that Max iterations puts on the whole.
    void
    report_iteration_cost(const double seconds, const unsigned int block) const;

    /// Before the first iteration: its estimated cost from the first of
    /// its `block` solves (seconds) and the time of a dot product of x and
    /// y (timed here), when that is long.  Collective.
    void
    report_estimated_cost(const double                         solve_seconds,
                          const TrilinosWrappers::MPI::Vector &x,
                          const TrilinosWrappers::MPI::Vector &y,
                          const unsigned int                   block) const;

    const Parameters                           parameters;
    bool                                       print_costs = false;
    const EffectiveMatrixSolver::Parameters    solver_parameters;
    const PlateModel                          &plate;
    std::vector<Mode>                          modes;
    std::vector<TrilinosWrappers::MPI::Vector> shapes;
    unsigned int                               iterations = 0;
  };
} // namespace fgimpact

#endif
