#include <deal.II/base/quadrature_lib.h>

#include <deal.II/fe/fe_values.h>

#include <fgimpact/analysis/static_analysis.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/files.h>
#include <fgimpact/contact/compliance.h>
#include <fgimpact/contact/contact_law.h>
#include <fgimpact/contact/resolved_contact.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/plate/probes.h>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace fgimpact
{
  void
  check_indentation_contact(const ContactState &state, const std::string &where)
  {
    AssertThrow(state.newton_iterations != numbers::invalid_unsigned_int,
                ExcMessage("Static/Load = sphere: the contact's "
                           "complementarity problem (active set, then "
                           "projected Gauss-Seidel) was not solved " +
                           where +
                           "; raise Geometry/Contact refinement levels or "
                           "lower Static/Indentation."));
  }



  StaticAnalysis::StaticAnalysis(
    const Parameters                        &parameters,
    const EffectiveMatrixSolver::Parameters &solver,
    const PlateModel                        &plate,
    const Point<2>                          &load_point,
    const SphereIndenter                    &indenter)
    : parameters(parameters)
    , solver_parameters(solver)
    , plate(plate)
    , load_point(load_point)
    , indenter(indenter)
  {}



  void
  StaticAnalysis::assemble_load(TrilinosWrappers::MPI::Vector &f) const
  {
    plate.initialize_vector(f);
    if (parameters.load == Load::point)
      {
        const auto dof = plate.nearest_top_vertex_dof(load_point, 2).first;
        if (plate.locally_owned_dofs().is_element(dof))
          f(dof) = -parameters.point_force *
                   plate.get_geometry().share(); // a symmetric part's share
        f.compress(VectorOperation::insert);
        return;
      }

    const auto                          &fe = plate.get_fe();
    const double                         a  = plate.get_geometry().length();
    const double                         b  = plate.get_geometry().width();
    const QGauss<2>                      quadrature(fe.degree + 2);
    FEFaceValues<3>                      fe_face(plate.get_mapping(),
                            fe,
                            quadrature,
                            update_values | update_quadrature_points |
                              update_JxW_values);
    Vector<double>                       cell_f(fe.n_dofs_per_cell());
    std::vector<types::global_dof_index> dofs(fe.n_dofs_per_cell());
    for (const auto &cell : plate.get_dof_handler().active_cell_iterators())
      if (cell->is_locally_owned())
        for (const auto face : cell->face_indices())
          if (cell->face(face)->at_boundary() &&
              cell->face(face)->boundary_id() == 5) // top, z = h
            {
              fe_face.reinit(cell, face);
              cell_f = 0;
              for (unsigned int q = 0; q < quadrature.size(); ++q)
                {
                  const Point<3> &p = fe_face.quadrature_point(q);
                  const double    q_load =
                    parameters.pressure *
                    (parameters.load == Load::sinusoidal ?
                       std::sin(M_PI * p[0] / a) * std::sin(M_PI * p[1] / b) :
                       1.);
                  for (unsigned int i = 0; i < fe.n_dofs_per_cell(); ++i)
                    if (fe.system_to_component_index(i).first == 2)
                      cell_f(i) -=
                        q_load * fe_face.shape_value(i, q) * fe_face.JxW(q);
                }
              cell->get_dof_indices(dofs);
              plate.get_constraints().distribute_local_to_global(cell_f,
                                                                 dofs,
                                                                 f);
            }
    f.compress(VectorOperation::add);
  }



  void
  StaticAnalysis::solve_indentation(EffectiveMatrixSolver &solver)
  {
    const double          R     = indenter.radius;
    const double          delta = parameters.indentation;
    ResolvedSphereContact contact(
      plate,
      R,
      load_point,
      indenter.candidate_radius > 0. ? indenter.candidate_radius :
                                       1.5 * std::sqrt(R * delta),
      create_sphere_profile(R, indenter.paraboloid_gap),
      top_face_modulus(plate.get_material(), plate.get_geometry().thickness()),
      /*massless_candidates=*/false,
      indenter.modulus);
    if (plastic)
      {
        solve_plastic_indentation(solver, contact);
        return;
      }
    // The sphere is displacement-driven: w = delta (its centre's
    // approach), no rigid-body compliance; an elastic sphere's surface
    // compliance is in the contact's LCP.
    // A contact that reaches the candidate set's edge grows the set.
    FullMatrix<double> C;
    ContactState       state;
    for (;;)
      {
        compute_compliance(solver, plate, contact.contact_dofs(), C);
        contact.solve_implicit(Vector<double>(contact.contact_dofs().size()),
                               C,
                               ColumnRequest(),
                               delta,
                               0.,
                               NewtonControl(),
                               state);
        check_indentation_contact(state, "at the full indentation");
        if (!state.candidates_exhausted)
          break;
        grow_contact(contact);
      }
    record_contact(contact,
                   state,
                   state.force / plate.get_geometry().share(),
                   state.contact_radius);

    // u = K^{-1} (-sum_j lambda_j g_j): one more solve.
    TrilinosWrappers::MPI::Vector f;
    plate.initialize_vector(f);
    subtract_contact_forces(contact.contact_dofs(), state.forces, f);
    solver.solve(u, f);
  }



  void
  StaticAnalysis::record_contact(const ResolvedSphereContact &contact,
                                 const ContactState          &state,
                                 const double                 force,
                                 const double                 contact_radius)
  {
    const auto &dofs        = contact.contact_dofs();
    results.contact_force   = force;
    results.contact_radius  = contact_radius;
    results.max_pressure    = state.max_pressure;
    results.n_contact_nodes = state.n_active;
    results.node_radius     = contact.candidate_radii();
    results.node_pressure.resize(dofs.size());
    for (unsigned int j = 0; j < dofs.size(); ++j)
      results.node_pressure[j] = state.forces[j] / contact.candidate_areas()[j];
  }



  void
  StaticAnalysis::grow_contact(ResolvedSphereContact &contact)
  {
    AssertThrow(contact.grow_candidates(),
                ExcMessage("Static/Indentation: the contact reaches the "
                           "sphere's radius; reduce the indentation, or "
                           "raise Geometry/Contact refinement levels if "
                           "the elements under the ball are coarser "
                           "than the contact radius."));
  }



  void
  StaticAnalysis::subtract_contact_forces(
    const std::vector<types::global_dof_index> &dofs,
    const std::vector<double>                  &forces,
    TrilinosWrappers::MPI::Vector              &f)
  {
    for (unsigned int j = 0; j < dofs.size(); ++j)
      if (f.locally_owned_elements().is_element(dofs[j]))
        f(dofs[j]) -= forces[j];
    f.compress(VectorOperation::add);
  }



  void
  StaticAnalysis::solve()
  {
    plate.initialize_vector(u);
    EffectiveMatrixSolver solver(solver_parameters);
    solver.initialize(plate.stiffness_matrix());
    if (parameters.load == Load::sphere)
      solve_indentation(solver);
    else
      {
        TrilinosWrappers::MPI::Vector f;
        assemble_load(f);
        solver.solve(u, f);
      }
    plate.get_constraints().distribute(u);

    const double h = plate.get_geometry().thickness();
    for (unsigned int k = 0; k < 3; ++k)
      {
        PointProbe probe(plate, plate.get_geometry().centre(0.5 * k * h));
        if (initial)
          probe.set_prestress(*initial);
        if (plastic) // the stress the material carries, as the VTU's
          probe.set_plasticity(*plastic);
        const SymmetricTensor<2, 3> sigma = probe.stress(u);
        results.deflection[k]             = -probe.displacement(u)[2];
        results.sigma_xx[k]               = sigma[0][0];
        results.sigma_yy[k]               = sigma[1][1];
        results.sigma_zz[k]               = sigma[2][2];
      }
    results.n_dofs = plate.n_dofs();
  }



  void
  StaticAnalysis::write_pressure_csv(const std::string &file_name) const
  {
    record_output_file(file_name);
    std::ofstream out(file_name);
    out << "r_mm,pressure_MPa\n";
    char line[64];
    for (unsigned int j = 0; j < results.node_radius.size(); ++j)
      {
        std::snprintf(line,
                      sizeof(line),
                      "%.6f,%.6f\n",
                      results.node_radius[j] * 1e3,
                      results.node_pressure[j] * 1e-6);
        out << line;
      }
    AssertThrow(out.good(),
                ExcOutputFailure("cannot write " + file_name +
                                 " (disk full or I/O error)."));
  }



  SummaryWriter
  StaticAnalysis::summary() const
  {
    SummaryWriter     out;
    const std::string where[3] = {"bottom", "mid", "top"};
    out.add_text("status", "completed");
    for (unsigned int k = 0; k < 3; ++k)
      out.add("static_deflection_" + where[k] + "_um",
              results.deflection[k] * 1e6,
              6);
    for (unsigned int k = 0; k < 3; ++k)
      {
        out.add("sigma_xx_" + where[k] + "_MPa", results.sigma_xx[k] * 1e-6, 6);
        out.add("sigma_yy_" + where[k] + "_MPa", results.sigma_yy[k] * 1e-6, 6);
        out.add("sigma_zz_" + where[k] + "_MPa", results.sigma_zz[k] * 1e-6, 6);
      }
    if (parameters.load == Load::sphere)
      {
        out.add("static_indentation_um", parameters.indentation * 1e6, 6);
        out.add("static_contact_force_N", results.contact_force, 6);
        out.add("contact_radius_mm", results.contact_radius * 1e3, 6);
        out.add("max_contact_pressure_MPa", results.max_pressure * 1e-6, 6);
        out.add("n_contact_nodes", results.n_contact_nodes, 0);
        const auto &p = results.plastic;
        if (p.modelled)
          {
            out.add("mean_contact_pressure_MPa",
                    results.contact_force / p.contact_area * 1e-6,
                    6);
            out.add("plastic_dissipation_J", p.dissipation, 9);
            out.add("permanent_indentation_um",
                    p.permanent_indentation * 1e6,
                    5);
            out.add("max_equivalent_plastic_strain", p.max_plastic_strain, 6);
            out.add("first_yield_contact_force_N", p.first_yield_force, 4);
            out.add("first_yield_hertz_force_N", p.first_yield_hertz_force, 4);
            out.add("first_yield_contact_radius_node_spacings",
                    p.first_yield_resolution,
                    2);
            out.add_text("warnings", p.warning.empty() ? "none" : p.warning);
            out.add("plate_iterations", p.iterations, 0);
          }
      }
    out.add("n_dofs", results.n_dofs, 0);
    return out;
  }



  void
  StaticAnalysis::write_output(
    const std::string                                &directory,
    const DataOutBase::VtkFlags::ZlibCompressionLevel vtu_compression,
    const VtuFields                                  &fields) const
  {
    // Rank 0 writes, every rank learns the outcome before the collective
    // VTU output (a failure on rank 0 alone must not leave rank 1 waiting).
    run_on_root(plate.get_mpi_communicator(), [&]() {
      if (parameters.load == Load::sphere)
        {
          write_pressure_csv(directory + "/contact_pressure.csv");
          if (results.plastic.modelled)
            write_load_curve(directory + "/load_curve.csv");
        }
    });
    TrilinosWrappers::MPI::Vector zero;
    plate.initialize_vector(zero);
    VtuWriter vtu(plate, directory, vtu_compression, fields);
    if (plastic)
      vtu.set_plasticity(*plastic);
    if (initial)
      vtu.set_prestress(*initial);
    vtu.write(0, 0., u, zero);
    vtu.finish();
  }
} // namespace fgimpact
