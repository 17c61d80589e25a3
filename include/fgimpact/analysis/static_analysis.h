#ifndef fgimpact_static_analysis_h
#define fgimpact_static_analysis_h

#include <deal.II/base/data_out_base.h>
#include <deal.II/base/parameter_handler.h>

#include <deal.II/lac/trilinos_vector.h>

#include <fgimpact/contact/resolved_contact.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/plate/linear_solver.h>
#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/problem/analysis_parameters.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// The sphere of Static/Load = sphere.
  struct SphereIndenter
  {
    double radius           = 0.015; // R, m
    double candidate_radius = 0;     // m, 0: 1.5 sqrt(R delta)
    bool   paraboloid_gap   = false;
    /// E_i/(1 - nu_i^2) of an elastic sphere (Pa); infinite: rigid.
    double modulus = std::numeric_limits<double>::infinity();
  };

  /// Static/Load = sphere: stop with one line if the contact's
  /// complementarity problem was not solved (ContactState's
  /// newton_iterations invalid), as an impact step does; `where` names
  /// the load step.
  void
  check_indentation_contact(const ContactState &state,
                            const std::string  &where);

  /**
   * Static deflection of the plate, K u = f, under a load on the top face:
   * a sinusoidal pressure q0 sin(pi x/a) sin(pi y/b) (which has an exact 3D
   * solution for simply supported plates), a uniform pressure q0, or a
   * point force P at the top node nearest to a point.  Loads act downward
   * (-z).
   */
  class StaticAnalysis
  {
  public:
    using Load       = StaticAnalysisParameters::Load;
    using Parameters = StaticAnalysisParameters;

    /// Results at the plate centre, deflection positive downward (m),
    /// stresses (Pa) at the bottom, middle and top of the centre line.
    struct Results
    {
      double       deflection[3]; // z = 0, h/2, h
      double       sigma_xx[3], sigma_yy[3], sigma_zz[3];
      unsigned int n_dofs;
      /// Load = sphere: total force (N), contact radius (m, the farthest
      /// node in contact), largest nodal pressure (Pa), and
      /// per candidate node its distance from the centre (m) and nodal
      /// pressure lambda_j / A_j (Pa).
      double              contact_force   = 0;
      double              contact_radius  = 0;
      double              max_pressure    = 0;
      unsigned int        n_contact_nodes = 0;
      std::vector<double> node_radius, node_pressure;

      /// Load = sphere on a plastic plate (set_plasticity()): at the full
      /// indentation the contact area (m^2, the whole plate's: the active
      /// nodes' tributary areas) and after unloading the plate's thinning
      /// under the load point, W_top - W_mid (m); first yield (N, between
      /// the load steps whose largest trial stress crosses the yield
      /// stress, linearly; NaN if none); the plastic work (J) and largest
      /// equivalent plastic strain; per load step (indentation m, force N,
      /// contact radius m of the contact area, largest equivalent plastic
      /// strain) for load_curve.csv.
      struct Plastic
      {
        bool   modelled              = false;
        double contact_area          = 0;
        double permanent_indentation = 0;
        double first_yield_force     = std::numeric_limits<double>::quiet_NaN();
        /// Hertz's first-yield force (N) and its contact radius over the
        /// element size under the load (hertz_first_yield()); below
        /// first_yield_min_resolution first_yield_force is NaN (none).
        double first_yield_hertz_force =
          std::numeric_limits<double>::quiet_NaN();
        double first_yield_resolution =
          std::numeric_limits<double>::quiet_NaN();
        std::string                        warning;
        double                             dissipation        = 0;
        double                             max_plastic_strain = 0;
        unsigned int                       iterations         = 0;
        std::vector<std::array<double, 4>> curve;
      } plastic;
    };


    StaticAnalysis(const Parameters                        &parameters,
                   const EffectiveMatrixSolver::Parameters &solver,
                   const PlateModel                        &plate,
                   const Point<2>                          &load_point,
                   const SphereIndenter &indenter = SphereIndenter());

    /// A thermal run: the stresses written (summary.txt's sigma_* keys,
    /// the VTU's) are the total, the initial state's plus the load's, and
    /// the VTU has the thermal fields.  Before solve().
    void
    set_prestress(const InitialStress &initial_stress)
    {
      initial = &initial_stress;
    }

    /// Material/Plasticity = J2 (Load = sphere): load and unload in
    /// Parameters::load_steps steps each, every step iterated to a plastic
    /// force settled to `tolerance` of the largest nodal force.
    void
    set_plasticity(PlasticPlate &plasticity, const double tolerance)
    {
      plastic           = &plasticity;
      plastic_tolerance = tolerance;
    }

    /// Assemble the load and solve.
    void
    solve();

    const Results &
    get_results() const
    {
      return results;
    }

    const TrilinosWrappers::MPI::Vector &
    displacement() const
    {
      return u;
    }

    /// summary.txt's entries (every rank), which the run's SummaryFile
    /// writes (the one writer of summary.txt) and keeps for a study.
    SummaryWriter
    summary() const;

    /// Write the CSV files and a VTU file of the fields into directory.
    void
    write_output(const std::string &directory,
                 const DataOutBase::VtkFlags::ZlibCompressionLevel
                   vtu_compression       = DataOutBase::VtkFlags::best_speed,
                 const VtuFields &fields = VtuFields()) const;

  private:
    void
    assemble_load(TrilinosWrappers::MPI::Vector &f) const;

    /// contact_pressure.csv: r (mm) and nodal pressure (MPa) per node.
    void
    write_pressure_csv(const std::string &file_name) const;

    /// Load = sphere: the LCP with the compliance of K, then u.
    void
    solve_indentation(EffectiveMatrixSolver &solver);

    /// The contact's force (N, whole plate), radius (m), pressures and
    /// nodes into the results.
    void
    record_contact(const ResolvedSphereContact &contact,
                   const ContactState          &state,
                   const double                 force,
                   const double                 contact_radius);

    /// The contact has reached its candidates' edge: grow them, or throw
    /// (the contact reaches the sphere's radius).
    static void
    grow_contact(ResolvedSphereContact &contact);

    /// f(dofs[j]) -= forces[j] on this rank's DoFs: the contact forces
    /// (N, pressing down) on the plate's load vector.
    static void
    subtract_contact_forces(const std::vector<types::global_dof_index> &dofs,
                            const std::vector<double>                  &forces,
                            TrilinosWrappers::MPI::Vector              &f);

    /// The same on a plastic plate: load steps up and down
    /// (source/analysis/plastic_indentation.cc).
    void
    solve_plastic_indentation(EffectiveMatrixSolver &solver,
                              ResolvedSphereContact &contact);

    /// One load step of it at indentation delta (m): contact and plastic
    /// force iterated together; grows the candidates if the contact
    /// reaches their edge.  Returns the contact state.
    ContactState
    plastic_load_step(EffectiveMatrixSolver &solver,
                      ResolvedSphereContact &contact,
                      FullMatrix<double>    &C,
                      const double           delta,
                      const unsigned int     step);

    /// The warning of a Q1 brick without B-bar that has yielded: its
    /// pressure locks (as PlasticityReport says for an impact).
    void
    warn_locked_pressure();

    /// The crater: the plate's thinning under the load point (m) after
    /// unloading.
    double
    permanent_indentation() const;

    /// Hertz's first yield beside the computed one, which becomes NaN
    /// (with a warning) where the mesh does not resolve it; E_star: Hertz's
    /// modulus of plate and ball (Pa).
    void
    judge_first_yield(const double E_star);

    /// load_curve.csv of a plastic indentation.
    void
    write_load_curve(const std::string &file_name) const;

    const Parameters                        parameters;
    const EffectiveMatrixSolver::Parameters solver_parameters;
    const PlateModel                       &plate;
    const Point<2>                          load_point;
    const SphereIndenter                    indenter;
    TrilinosWrappers::MPI::Vector           u;
    Results                                 results;
    PlasticPlate                           *plastic           = nullptr;
    const InitialStress                    *initial           = nullptr;
    double                                  plastic_tolerance = 1e-3;
  };
} // namespace fgimpact

#endif
