// Static/Load = sphere on a plastic plate: load steps up to the
// indentation and back, the contact and the plastic force iterated
// together at each (static_analysis.h).

#include <fgimpact/analysis/static_analysis.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/contact/compliance.h>
#include <fgimpact/output/validity_report.h>
#include <fgimpact/plate/probes.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <limits>

namespace fgimpact
{
  namespace
  {
    /// The area of the candidates that press (m^2, the modelled part's).
    double
    pressed_area(const ResolvedSphereContact &contact,
                 const ContactState          &state)
    {
      double area = 0;
      for (unsigned int j = 0; j < state.forces.size(); ++j)
        if (state.forces[j] > 0.)
          area += contact.candidate_areas()[j];
      return area;
    }
  } // namespace



  void
  StaticAnalysis::solve_plastic_indentation(EffectiveMatrixSolver &solver,
                                            ResolvedSphereContact &contact)
  {
    const unsigned int n     = parameters.load_steps;
    auto              &r     = results.plastic;
    const double       share = plate.get_geometry().share();
    r.modelled               = true;
    FullMatrix<double> C;
    compute_compliance(solver, plate, contact.contact_dofs(), C);
    // First yield is interpolated from the unloaded state: a thermal
    // pre-stress's own ratio (0 without; above 1: yield at zero load).
    double last_ratio = plastic->initial_yield_ratio(), last_force = 0;
    for (unsigned int k = 1; k <= 2 * n; ++k)
      {
        const double delta =
          parameters.indentation * (k <= n ? k : 2 * n - k) / n;
        const ContactState state =
          plastic_load_step(solver, contact, C, delta, k);
        const double force = state.force / share;
        if (std::isnan(r.first_yield_force) &&
            plastic->max_equivalent_plastic_strain() > 0.)
          {
            const double ratio  = plastic->max_trial_ratio();
            const double theta  = yield_crossing(last_ratio, ratio);
            r.first_yield_force = last_force + theta * (force - last_force);
          }
        last_ratio          = plastic->max_trial_ratio();
        last_force          = force;
        const double area   = pressed_area(contact, state) / share; // m^2
        const double radius = std::sqrt(area / numbers::PI);
        r.curve.push_back(
          {{delta, force, radius, plastic->max_equivalent_plastic_strain()}});
        if (k == n)
          {
            // The full indentation: the summary's contact.
            record_contact(contact, state, force, radius);
            r.contact_area = area;
          }
      }
    r.dissipation        = plastic->plastic_work() / share;
    r.max_plastic_strain = plastic->max_equivalent_plastic_strain();
    r.iterations         = plastic->n_iterations();
    judge_first_yield(contact.contact_modulus());
    warn_locked_pressure();
    r.permanent_indentation = permanent_indentation();
  }



  void
  StaticAnalysis::warn_locked_pressure()
  {
    auto &r = results.plastic;
    if (plate.get_fe().degree != 1 || plate.uses_mean_dilatation() ||
        r.max_plastic_strain <= 0.)
      return;
    const std::string text = locking_warning();
    r.warning += (r.warning.empty() ? "" : " | ") + text;
    if (Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
      std::cout << "  WARNING: " << text << ".\n";
  }



  double
  StaticAnalysis::permanent_indentation() const
  {
    // u holds the unloaded plate; solve() distributes its constraints
    // only after this, so distribute a copy.
    TrilinosWrappers::MPI::Vector u_distributed = u;
    plate.get_constraints().distribute(u_distributed);
    const double     h = plate.get_geometry().thickness();
    const PointProbe top(plate, Point<3>(load_point[0], load_point[1], h));
    const PointProbe mid(plate,
                         Point<3>(load_point[0], load_point[1], 0.5 * h));
    return mid.displacement(u_distributed)[2] -
           top.displacement(u_distributed)[2];
  }



  void
  StaticAnalysis::judge_first_yield(const double E_star)
  {
    // As for an impact (PlasticityReport): first yield spans a node or two
    // unless the mesh resolves Hertz's contact radius at first yield.
    auto                 &r = results.plastic;
    const double          h = plate.get_geometry().thickness();
    const Point<3>        top(load_point[0], load_point[1], h);
    const HertzFirstYield hertz =
      hertz_first_yield(E_star,
                        plastic->get_strength().yield_strength(h),
                        plate.get_material().poissons_ratio(h),
                        indenter.radius);
    r.first_yield_hertz_force = hertz.force;
    // Over the node spacing: Q2's mid-side nodes halve it.
    r.first_yield_resolution =
      hertz.contact_radius * plate.get_fe().degree / plate.cell_size_at(top);
    if (r.first_yield_resolution >= first_yield_min_resolution ||
        std::isnan(r.first_yield_force))
      return;
    const std::string text = first_yield_warning(r.first_yield_resolution,
                                                 r.first_yield_force,
                                                 r.first_yield_hertz_force,
                                                 /*with_time=*/false);
    r.warning              = text;
    r.first_yield_force    = std::numeric_limits<double>::quiet_NaN();
    if (Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
      std::cout << "  WARNING: " << text << ".\n";
  }



  ContactState
  StaticAnalysis::plastic_load_step(EffectiveMatrixSolver &solver,
                                    ResolvedSphereContact &contact,
                                    FullMatrix<double>    &C,
                                    const double           delta,
                                    const unsigned int     step)
  {
    // Enough for a perfectly plastic zone under Aitken's relaxation; more
    // means the step is too large.
    constexpr unsigned int        max_iterations = 500;
    TrilinosWrappers::MPI::Vector u_plastic, f;
    plate.initialize_vector(u_plastic);
    plate.initialize_vector(f);
    ContactState state;
    plastic->begin_increment();
    for (unsigned int iteration = 0;; ++iteration)
      {
        AssertThrow(iteration < max_iterations,
                    ExcMessage("Static/Load = sphere: the plastic iteration "
                               "did not converge at load step " +
                               std::to_string(step) + " within " +
                               std::to_string(max_iterations) +
                               " iterations; raise Static/Load steps."));
        throw_if_stop_signal(plate.get_mpi_communicator(),
                             "at load step " + std::to_string(step));
        // The plate under the plastic force alone, at the contact DoFs.
        const auto &dofs = contact.contact_dofs();
        u_plastic        = 0.;
        solver.solve(u_plastic, plastic->plastic_force());
        contact.solve_implicit(plate.dof_values(u_plastic, dofs),
                               C,
                               ColumnRequest(),
                               delta,
                               0.,
                               NewtonControl(),
                               state);
        check_indentation_contact(state,
                                  "at load step " + std::to_string(step));
        if (state.candidates_exhausted)
          {
            grow_contact(contact);
            compute_compliance(solver, plate, contact.contact_dofs(), C);
            continue;
          }
        // u = K^{-1} (f_p - sum_j lambda_j g_j).
        f = plastic->plastic_force();
        subtract_contact_forces(dofs, state.forces, f);
        u = 0.;
        solver.solve(u, f);
        double scale = plastic->plastic_force().linfty_norm();
        for (const double force : state.forces)
          scale = std::max(scale, std::abs(force));
        if (plastic->update(u) <= plastic_tolerance * scale)
          break;
      }
    plastic->commit();
    return state;
  }



  void
  StaticAnalysis::write_load_curve(const std::string &file_name) const
  {
    record_output_file(file_name);
    std::ofstream out(file_name);
    out << "indentation_um,contact_force_N,contact_radius_mm,"
           "max_plastic_strain\n";
    char line[128];
    for (const auto &row : results.plastic.curve)
      {
        std::snprintf(line,
                      sizeof(line),
                      "%.5f,%.4f,%.5f,%.6f\n",
                      row[0] * 1e6,
                      row[1],
                      row[2] * 1e3,
                      row[3]);
        out << line;
      }
    AssertThrow(out.good(),
                ExcOutputFailure("cannot write " + file_name +
                                 " (disk full or I/O error)."));
  }
} // namespace fgimpact
