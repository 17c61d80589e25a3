#include <deal.II/lac/solver_control.h>

#include <fgimpact/analysis/modal_analysis.h>
#include <fgimpact/analysis/static_analysis.h>
#include <fgimpact/analysis/thermal_step.h>
#include <fgimpact/base/exceptions.h>
#include <fgimpact/base/stop_signals.h>
#include <fgimpact/material/constitutive_law.h>
#include <fgimpact/output/output_files.h>
#include <fgimpact/output/postprocessing.h>
#include <fgimpact/problem/symmetry.h>
#include <fgimpact/study/adaptive_run.h>
#include <fgimpact/study/converged_run.h>
#include <fgimpact/study/simulator.h>

#include <cmath>
#include <cstdio>

namespace fgimpact
{
  namespace
  {
    /// The static and modal drivers: nothing to set up beyond the plate.
    class LinearProblemDriver : public ProblemDriver
    {
    public:
      LinearProblemDriver(const Parameters &parameters,
                          const PlateModel &plate,
                          SummaryFile      &summary)
        : parameters(parameters)
        , plate(plate)
        , summary(summary)
        , pcout(std::cout,
                Utilities::MPI::this_mpi_process(
                  plate.get_mpi_communicator()) == 0)
      {}

      void
      setup() override
      {}

      /// Only the status and the problem size: the results do not exist.
      void
      write_failed_summary(const std::string &status) const override
      {
        SummaryWriter out;
        out.add_text("status", status);
        out.add("n_dofs", plate.n_dofs(), 0);
        summary.write(out);
      }

    protected:
      /// Run solve(), turning a linear solver failure into one line that
      /// names the phase and the parameter.
      template <typename Solve>
      void
      solve_in_phase(const std::string &phase, const Solve &solve) const
      {
        try
          {
            solve();
          }
        catch (const SolverControl::NoConvergence &e)
          {
            AssertThrow(false,
                        linear_solver_failure("in the " + phase, e.last_step));
          }
        catch (const ExcNumericalFailure &e)
          {
            // A factorization, or the modal iteration: name the phase.
            AssertThrow(false,
                        ExcNumericalFailure("in the " + phase + ": " +
                                            message_of(e)));
          }
        catch (const RunInterrupted &)
          {
            // A solve that looks at the stop signals (the modal iteration,
            // the static load steps): summary.txt and the line below.
            stop_if_signalled(phase);
            throw;
          }
        stop_if_signalled(phase);
      }

      /// summary.txt through the run's one writer, on rank 0 (every rank
      /// keeps the entries, for a study's study.csv); a failure on rank 0
      /// stops every rank.
      void
      write_summary(const SummaryWriter &content) const
      {
        summary.keep(content);
        run_on_root(plate.get_mpi_communicator(),
                    [&]() { summary.write(content); });
      }

      /// SIGINT/SIGTERM/SIGHUP during the solve (which cannot stop midway,
      /// and the signal only set a flag): no results, summary.txt says
      /// interrupted, RunInterrupted on every rank.
      void
      stop_if_signalled(const std::string &phase) const
      {
        const int stop = agreed_stop(plate.get_mpi_communicator(), false);
        if (stop <= 0)
          return;
        write_failed_summary("interrupted");
        throw RunInterrupted(stop,
                             std::string("interrupted by ") +
                               signal_name(stop) + " during the " + phase +
                               "; no results written, summary.txt says "
                               "status = interrupted; run it again.");
      }

      const Parameters  &parameters;
      const PlateModel  &plate;
      SummaryFile       &summary;
      ConditionalOStream pcout;
    };



    /// Problem type = static: K u = f, deflections and stresses.
    class StaticDriver : public LinearProblemDriver
    {
    public:
      /// thermal: the thermal step before (null: none), whose state the
      /// written stresses add.
      StaticDriver(const Parameters  &parameters,
                   const PlateModel  &plate,
                   const Scene       &scene,
                   SummaryFile       &summary,
                   const ThermalStep *thermal)
        : LinearProblemDriver(parameters, plate, summary)
        , scene(scene)
        , thermal(thermal)
      {}

      void
      run() override
      {
        SphereIndenter indenter;
        indenter.radius           = scene.impactor().radius();
        indenter.candidate_radius = parameters.contact_model.candidate_radius;
        indenter.paraboloid_gap   = parameters.contact_model.paraboloid_gap;
        indenter.modulus          = scene.impactor().indentation_modulus();
        StaticAnalysis analysis(parameters.static_analysis,
                                parameters.linear_solver,
                                plate,
                                scene.impact_point_in_plane(),
                                indenter);
        if (thermal)
          analysis.set_prestress(thermal->initial_stress());
        // Material/Plasticity = J2: the graded strengths and the plastic
        // state (validate() allows it with Load = sphere only).
        const GradedStrength          strength(parameters.strength,
                                      plate.get_material());
        std::unique_ptr<PlasticPlate> plasticity;
        if (parameters.strength.plasticity == GradedStrength::Plasticity::j2)
          {
            plasticity = std::make_unique<PlasticPlate>(plate, strength);
            if (thermal)
              plasticity->set_prestress(thermal->initial_stress());
            analysis.set_plasticity(
              *plasticity, parameters.time_integration.newton.tolerance);
          }
        solve_in_phase("static solve", [&]() { analysis.solve(); });
        analysis.write_output(parameters.output.directory,
                              parameters.output.vtu_compression,
                              parameters.output.vtu_fields);
        write_summary(analysis.summary());
        const auto &r = analysis.get_results();
        char        line[300];
        std::snprintf(line,
                      sizeof(line),
                      "  static deflection at the centre: bottom %.6f um, mid "
                      "%.6f um, top %.6f um\n"
                      "  sigma_xx at the centre: bottom %.4f MPa, mid %.4f "
                      "MPa, top %.4f MPa\n",
                      r.deflection[0] * 1e6,
                      r.deflection[1] * 1e6,
                      r.deflection[2] * 1e6,
                      r.sigma_xx[0] * 1e-6,
                      r.sigma_xx[1] * 1e-6,
                      r.sigma_xx[2] * 1e-6);
        pcout << line;
        if (parameters.static_analysis.load == StaticAnalysis::Load::sphere)
          {
            std::snprintf(line,
                          sizeof(line),
                          "  sphere indentation %.4f um: force %.4f N, "
                          "contact radius %.4f mm (%u nodes), max pressure "
                          "%.3f MPa\n",
                          parameters.static_analysis.indentation * 1e6,
                          r.contact_force,
                          r.contact_radius * 1e3,
                          r.n_contact_nodes,
                          r.max_pressure * 1e-6);
            pcout << line;
          }
      }

    private:
      const Scene       &scene;
      const ThermalStep *thermal;
    };



    /// Problem type = modal: the lowest natural frequencies and shapes.
    class ModalDriver : public LinearProblemDriver
    {
    public:
      using LinearProblemDriver::LinearProblemDriver;

      void
      run() override
      {
        ModalAnalysis analysis(parameters.modal,
                               parameters.linear_solver,
                               plate);
        analysis.report_costs(parameters.output.print_timing);
        solve_in_phase("modal subspace iteration", [&]() { analysis.solve(); });
        analysis.write_output(parameters.output.directory,
                              parameters.output.vtu_compression,
                              parameters.output.vtu_fields);
        write_summary(analysis.summary());
        pcout << "  " << analysis.get_modes().size() << " modes after "
              << analysis.n_iterations() << " subspace iterations:\n";
        for (unsigned int j = 0; j < analysis.get_modes().size(); ++j)
          {
            char line[120];
            std::snprintf(line,
                          sizeof(line),
                          "  mode %2u  %12.4f Hz  w-energy fraction %.3f\n",
                          j + 1,
                          analysis.get_modes()[j].frequency,
                          analysis.get_modes()[j].w_fraction);
            pcout << line;
          }
      }
    };
  } // namespace



  Simulator::Simulator(const Parameters &parameters,
                       const MPI_Comm    mpi_communicator)
    : parameters(parameters)
    , mpi_communicator(mpi_communicator)
    , pcout(std::cout, Utilities::MPI::this_mpi_process(mpi_communicator) == 0)
    , summary_file(parameters.output.directory, mpi_communicator)
  {}



  Simulator::~Simulator() = default;



  void
  Simulator::setup()
  {
    if (parameters.accuracy.preset == AccuracyPreset::Preset::converged)
      {
        converged = std::make_unique<ConvergedRun>(parameters,
                                                   mpi_communicator,
                                                   summary_file,
                                                   observers);
        converged->setup();
        return;
      }
    if (parameters.geometry.adaptive_cycles > 0)
      {
        adaptive = std::make_unique<AdaptiveRun>(parameters,
                                                 mpi_communicator,
                                                 summary_file,
                                                 observers);
        adaptive->setup();
        return;
      }
    if (plate)
      total_timer.restart(); // the plate taken over: the driver's set-up
    else
      setup_plate();
    run_thermal_step();
    switch (parameters.problem_type)
      {
        case ProblemType::impact:
          {
            auto impact = std::make_unique<ImpactDriver>(
              parameters, *scene, *plate, total_timer, summary_file);
            for (const auto &observer : observers)
              impact->add_row_observer(observer);
            if (indicator_wanted)
              {
                indicator = std::make_unique<RefinementIndicator>(*plate);
                impact->set_refinement_indicator(*indicator);
              }
            impact->set_checkpointing(checkpoint_settings);
            if (thermal)
              impact->set_thermal_state(*thermal);
            driver = std::move(impact);
            break;
          }
        case ProblemType::static_load:
          driver = std::make_unique<StaticDriver>(
            parameters, *plate, *scene, summary_file, thermal.get());
          break;
        case ProblemType::modal:
          driver =
            std::make_unique<ModalDriver>(parameters, *plate, summary_file);
          break;
      }
    driver->setup();
  }



  const PlateModel &
  Simulator::setup_plate()
  {
    total_timer.restart();
    const SymmetricPart part = resolve_symmetry(parameters);
    geometry = std::make_unique<PlateGeometry>(parameters.geometry, part.cut);
    make_material();
    scene = std::make_unique<Scene>(parameters, *material, geometry->share());
    // Refuse a run that cannot fit before the long set-up (the mesh).
    const LocalRefinement refinement =
      contact_refinement_of(parameters, *scene);
    resource_estimate = estimate_resources(parameters, refinement);
    check_memory(parameters, resource_estimate, mpi_communicator);
    plate = std::make_unique<PlateModel>(parameters.finite_element,
                                         *geometry,
                                         *material,
                                         mpi_communicator);
    plate->setup(refinement, adaptive_mesh, mesh_split);

    const PropertyMode mode = parameters.material.property_mode;
    pcout << "fgimpact: FGM plate " << geometry->length() << " x "
          << geometry->width() << " x " << geometry->thickness() << " m, "
          << plate->n_active_cells() << " cells, " << plate->n_dofs()
          << " DoFs (Q" << plate->get_fe().degree
          << (plate->element_technology() == "standard" ?
                "" :
                " with " + plate->element_technology())
          << ", " << property_mode_names().name(mode)
          << " elements), n = " << parameters.material.power_law_index << '\n';
    const unsigned int n_ranks =
      Utilities::MPI::n_mpi_processes(mpi_communicator);
    const auto owned =
      Utilities::MPI::min_max_avg(static_cast<double>(
                                    plate->locally_owned_dofs().n_elements()),
                                  mpi_communicator);
    pcout << "  " << n_ranks << " MPI rank" << (n_ranks > 1 ? "s" : "")
          << ", DoFs per rank min "
          << static_cast<types::global_dof_index>(owned.min) << " / max "
          << static_cast<types::global_dof_index>(owned.max) << '\n';
    // Machine-dependent timings: only with them.
    if (parameters.output.print_timing)
      pcout << "  " << resource_estimate.describe() << '\n';
    const auto &g = parameters.geometry;
    if (const std::string line = parameters.accuracy.applied_message(
          g.subdivisions_x, g.subdivisions_y, g.subdivisions_z);
        !line.empty())
      pcout << "  " << line << '\n';
    if (!part.note.empty())
      pcout << "  " << part.note << '\n';
    warn_sampled_boundary_layer();
    if (refinement.levels > 0)
      pcout << "  contact refinement: " << refinement.levels << " levels"
            << (parameters.geometry.contact_refinement_auto ? " (auto)" : "")
            << " within " << refinement.radius * 1e3
            << " mm of the impact point, smallest element "
            << plate->smallest_cell_size() * 1e6 << " um\n";
    return *plate;
  }



  void
  Simulator::warn_sampled_boundary_layer() const
  {
    const auto &m = parameters.material;
    if (m.property_mode != PropertyMode::graded ||
        m.graded_nodal_values != GradedNodalValues::sampled)
      return;
    const unsigned int layers = parameters.geometry.subdivisions_z;
    const auto [error, layer] = sampled_layer_error(*material,
                                                    geometry->thickness(),
                                                    layers,
                                                    plate->get_fe().degree);
    if (error <= 0.25)
      return;
    char line[400];
    std::snprintf(line,
                  sizeof(line),
                  "  WARNING: the graded elements' nodal samples of E(z) "
                  "misread its average over the element layer z = %.3g .. "
                  "%.3g mm by %.0f %% (a boundary layer thinner than an "
                  "element); set Material/Graded nodal values = layer "
                  "average (or Property mode = pointwise).\n",
                  1e3 * geometry->thickness() * layer / layers,
                  1e3 * geometry->thickness() * (layer + 1) / layers,
                  100. * error);
    pcout << line;
  }



  void
  Simulator::run()
  {
    if (!driver && !converged && !adaptive)
      setup();
    try
      {
        if (converged)
          converged->run();
        else if (adaptive)
          adaptive->run();
        else
          driver->run();
      }
    catch (const RunInterrupted &)
      {
        // Its summary.txt says interrupted already, unless a level of
        // Accuracy = converged or a pilot run of the adaptive mesh was
        // running (its own directory's does).
        if ((converged && !converged->final_run_started()) ||
            (adaptive && !adaptive->final_run_started()))
          write_failed_summary("interrupted");
        throw;
      }
    catch (...)
      {
        // The impact driver writes its own failed summary once its outputs
        // exist; otherwise summary.txt says failed here.
        write_failed_summary();
        throw;
      }
  }



  void
  Simulator::write_failed_summary(const std::string &status) const
  {
    // Best effort: the failure being reported is the one that counts.
    try
      {
        if (driver)
          driver->write_failed_summary(status);
      }
    catch (...)
      {}
    if (!driver && !(converged && converged->final_run_started()) &&
        !(adaptive && adaptive->final_run_started()))
      {
        // Only the status: nothing else is known.
        SummaryWriter out;
        out.add_text("status", status);
        summary_file.write_failed(out);
      }
  }



  const ImpactResults &
  Simulator::get_results() const
  {
    if (converged)
      return converged->results();
    if (adaptive)
      return adaptive->results();
    const auto *impact = dynamic_cast<const ImpactDriver *>(driver.get());
    AssertThrow(impact != nullptr,
                ExcMessage("Simulator::get_results(): not an impact run."));
    return impact->get_results();
  }



  void
  Simulator::add_history_observer(const ImpactMonitor::RowObserver &observer)
  {
    AssertThrow(!driver,
                ExcMessage("add_history_observer() must precede setup()."));
    observers.push_back(observer);
  }



  void
  Simulator::set_checkpointing(const CheckpointSettings &settings)
  {
    checkpoint_settings = settings;
  }
} // namespace fgimpact
