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
    double last_ratio = 0, last_force = 0;
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
        last_ratio  = plastic->max_trial_ratio();
        last_force  = force;
        double area = 0; // m^2, the part's
        for (unsigned int j = 0; j < state.forces.size(); ++j)
          if (state.forces[j] > 0.)
            area += contact.candidate_areas()[j];
        area /= share;
        r.curve.push_back({{delta,
                            force,
                            std::sqrt(area / numbers::PI),
                            plastic->max_equivalent_plastic_strain()}});
        if (k == n)
          {
            // The full indentation: the summary's contact.
            const auto &dofs        = contact.contact_dofs();
            results.contact_force   = force;
            results.contact_radius  = std::sqrt(area / numbers::PI);
            r.contact_area          = area;
            results.max_pressure    = state.max_pressure;
            results.n_contact_nodes = state.n_active;
            results.node_radius     = contact.candidate_radii();
            results.node_pressure.resize(dofs.size());
            for (unsigned int j = 0; j < dofs.size(); ++j)
              results.node_pressure[j] =
                state.forces[j] / contact.candidate_areas()[j];
          }
      }
    r.dissipation        = plastic->plastic_work() / share;
    r.max_plastic_strain = plastic->max_equivalent_plastic_strain();
    r.iterations         = plastic->n_iterations();
    judge_first_yield(contact.contact_modulus());
    // The locked brick's pressure, as in an impact (PlasticityReport).
    if (plate.get_fe().degree == 1 && !plate.uses_mean_dilatation() &&
        r.max_plastic_strain > 0.)
      {
        const std::string text = locking_warning();
        r.warning += (r.warning.empty() ? "" : " | ") + text;
        if (Utilities::MPI::this_mpi_process(plate.get_mpi_communicator()) == 0)
          std::cout << "  WARNING: " << text << ".\n";
      }
    // The crater: the plate's thinning under the load point (u holds the
    // unloaded plate, constraints distributed by update()'s caller below).
    TrilinosWrappers::MPI::Vector u_distributed = u;
    plate.get_constraints().distribute(u_distributed);
    const double     h = plate.get_geometry().thickness();
    const PointProbe top(plate, Point<3>(load_point[0], load_point[1], h));
    const PointProbe mid(plate,
                         Point<3>(load_point[0], load_point[1], 0.5 * h));
    r.permanent_indentation =
      mid.displacement(u_distributed)[2] - top.displacement(u_distributed)[2];
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
            AssertThrow(contact.grow_candidates(),
                        ExcMessage("Static/Indentation: the contact reaches "
                                   "the sphere's radius; reduce the "
                                   "indentation, or raise Geometry/Contact "
                                   "refinement levels."));
            compute_compliance(solver, plate, contact.contact_dofs(), C);
            continue;
          }
        // u = K^{-1} (f_p - sum_j lambda_j g_j).
        f = plastic->plastic_force();
        for (unsigned int j = 0; j < dofs.size(); ++j)
          if (f.locally_owned_elements().is_element(dofs[j]))
            f(dofs[j]) -= state.forces[j];
        f.compress(VectorOperation::add);
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
