#ifndef fgimpact_results_h
#define fgimpact_results_h

#include <fgimpact/contact/contact_model.h>
#include <fgimpact/material/strength.h>

#include <array>
#include <limits>
#include <string>
#include <vector>

namespace fgimpact
{
  /**
   * What an impact run modelled (summary.txt and every row of study.csv):
   * the choices that decide its accuracy, as the run resolved them.
   */
  struct ModelDescription
  {
    std::string  contact_model;                 // Contact/Model
    unsigned int contact_refinement_levels = 0; // as applied (auto resolved)
    double       element_size_under_ball   = 0; // m, in-plane, at the point
    double       time_step                 = 0; // s
    std::string  scheme;                        // implicit | explicit
    unsigned int element_degree = 1;
    /// standard | incompatible modes | mean dilatation (Finite element/
    /// Incompatible modes, Volumetric strain): what the element is beyond
    /// its degree.
    std::string element_technology = "standard";
    std::string symmetry;      // the part modelled: none | half | quarter
    std::string property_mode; // graded | homogeneous | pointwise
    std::string gradation;     // power law | exponential | sigmoid | ...
    double      power_law_index = 0;
    std::string homogenization;
    /// For the validity checks (not written): the ball's radius and the
    /// plate's thickness (m).
    double impactor_radius = 0, thickness = 0;
  };

  /**
   * The results of an impact run, in SI units, as written to summary.txt
   * (impact_summary() scales them).
   */
  struct ImpactResults
  {
    /// The contact model's constants (its candidate count where the
    /// model counts the whole plate's).
    void
    set_contact_constants(const ContactConstants &c)
    {
      contact_modulus     = c.contact_modulus;
      contact_stiffness   = c.contact_stiffness;
      contact_node_offset = c.contact_node_offset;
      contact_node_owner  = c.contact_node_owner;
      if (c.n_contact_candidates > 0)
        n_contact_candidates = c.n_contact_candidates;
    }

    double       peak_contact_force      = 0; // N, parabola through 3 samples
    double       max_sampled_force       = 0; // N, largest sample
    double       time_of_peak_force      = 0; // s
    double       contact_duration        = 0; // s, NaN if still in contact
    double       departure_velocity      = 0; // m/s, rebound positive
    double       max_indentation         = 0; // m, the contact law's alpha
    double       max_approach            = 0; // m, w_ball - W_mid
    double       max_contact_radius      = 0; // m (resolved contact)
    double       max_contact_pressure    = 0; // Pa (resolved contact)
    unsigned int max_contact_nodes       = 0; // (resolved contact)
    double       max_midplane_deflection = 0; // m
    double       max_top_deflection      = 0; // m
    double       contact_stiffness       = 0; // N/m^1.5 (beta K_h)
    double       contact_modulus         = 0; // Pa
    double       impactor_mass           = 0; // kg
    double       plate_mass              = 0; // kg
    double       impulse                 = 0; // N s, int F dt
    double       contact_node_offset     = 0; // m, node to impact point
    unsigned int contact_node_owner      = 0; // MPI rank owning its DoF
    unsigned int n_contact_candidates    = 1; // DoFs of the contact model
    unsigned int n_mpi_ranks             = 1;
    double       max_energy_drift        = 0; // relative
    /// |int F dt - m (V0 - v_end)| / (m V0): an identity of the impactor's
    /// update for gamma = 1/2 (round-off only), a consistency check of the
    /// impulse bookkeeping, not of the physics.
    double       impulse_identity_error = 0;
    unsigned int n_impacts              = 0;
    unsigned int n_dofs                 = 0;
    unsigned int n_time_steps           = 0;
    unsigned int max_newton_iterations  = 0;
    /// Iterations of the linear solver (0 for the direct solvers).
    unsigned long long linear_iterations     = 0; // summed over the run
    unsigned int       max_linear_iterations = 0; // in one step
    double             setup_time            = 0; // s
    double             factorization_time    = 0; // s
    double             time_loop_time        = 0; // s
    double             output_time           = 0; // s
    /// Reference costs, measured only with Output/Instrumentation (s).
    double spmv_time  = 0; // one matrix-vector product
    double solve_time = 0; // one solve with K_eff
    double wall_time  = 0; // s
    /// What was modelled (set-up), and the warnings of the finished run
    /// (one line each, naming what to change).
    ModelDescription         model;
    std::vector<std::string> warnings;

    /// The validity report (ValidityMonitor): the largest von Mises stress
    /// over the graded yield strength in the metal-rich part, and the
    /// largest principal stress over the tensile strength in the
    /// ceramic-rich part, where and when; ratio NaN when not checked (a
    /// strength of 0, or no such part).
    StrengthPeak yield_peak = StrengthPeak::unchecked();
    /// The von Mises stress an elastic metal would carry (C eps, the
    /// plastic strain not taken off) over the initial yield strength: in
    /// an elastic run the same as yield_peak.
    StrengthPeak elastic_yield_peak = StrengthPeak::unchecked();
    StrengthPeak tension_peak       = StrengthPeak::unchecked();
    /// How much a rigid ball raises Hertz's E* above the elastic ball's
    /// of Impactor/Young's modulus (relative; 0 for an elastic ball, NaN
    /// when not reported).
    double rigid_ball_modulus_excess = std::numeric_limits<double>::quiet_NaN();
    /// Whether the stress fields were scanned (false for the study's
    /// convolution engine, which has none: only Hertz's closed form).
    bool stress_fields_checked = false;

    /// Material/Plasticity = J2 (PlasticityReport): the whole plate's
    /// values; first yield NaN if the plate stayed elastic.
    struct Plastic
    {
      bool   modelled              = false;
      double dissipation           = 0; // J, the plastic work
      double permanent_indentation = 0; // m, W_top - W_mid at the end
      /// m: where the top face's thinning changes sign (NaN: no rim
      /// within the line searched); the deepest and the farthest Gauss
      /// point with plastic strain, below the top face and from the
      /// impact axis.
      double crater_diameter     = std::numeric_limits<double>::quiet_NaN();
      double plastic_zone_depth  = 0;
      double plastic_zone_radius = 0;
      double max_plastic_strain  = 0; // equivalent plastic strain
      double first_yield_time  = std::numeric_limits<double>::quiet_NaN(); // s
      double first_yield_force = std::numeric_limits<double>::quiet_NaN(); // N
      /// Hertz's first yield on a half-space of the top face: the force
      /// (N) at which the largest von Mises stress under the ball reaches
      /// the top's yield strength, and its contact radius over the element
      /// size under the ball (below 4 the computed first yield is
      /// unresolved, and first_yield_* are NaN).
      double first_yield_hertz_force = std::numeric_limits<double>::quiet_NaN();
      double first_yield_resolution  = std::numeric_limits<double>::quiet_NaN();
      double restitution             = std::numeric_limits<double>::quiet_NaN();
      /// The plate's iterations per step: mean and largest.
      double       mean_iterations = 0;
      unsigned int max_iterations  = 0;
    } plastic;

    /// Output/Probe points (ProbeWriter): the largest von Mises stress of
    /// the recovered stress at each probe over the run, and when.
    struct ProbePeak
    {
      std::string           name;
      std::array<double, 3> location{};    // m
      double                von_mises = 0; // Pa
      double                time      = 0; // s
    };
    std::vector<ProbePeak> probe_peaks;
  };
} // namespace fgimpact

#endif
