#include <fgimpact/modal_analysis.h>
#include <fgimpact/simulator.h>
#include <fgimpact/static_analysis.h>

#include <cstdio>

namespace fgimpact
{
  namespace
  {
    /// The static and modal drivers: nothing to set up beyond the plate.
    class LinearProblemDriver : public ProblemDriver
    {
    public:
      LinearProblemDriver(const Parameters &parameters, const PlateModel &plate)
        : parameters(parameters)
        , plate(plate)
        , pcout(std::cout,
                Utilities::MPI::this_mpi_process(
                  plate.get_mpi_communicator()) == 0)
      {}

      void
      setup() override
      {}

    protected:
      const Parameters  &parameters;
      const PlateModel  &plate;
      ConditionalOStream pcout;
    };



    /// Problem type = static: K u = f, deflections and stresses.
    class StaticDriver : public LinearProblemDriver
    {
    public:
      using LinearProblemDriver::LinearProblemDriver;

      void
      run() override
      {
        const Impactor       impactor(parameters.impactor);
        const PlateGeometry &g = plate.get_geometry();
        StaticAnalysis       analysis(parameters.static_analysis,
                                parameters.linear_solver,
                                plate,
                                impactor.impact_point(g.length(), g.width()));
        analysis.solve();
        analysis.write_output(parameters.output.directory,
                              parameters.output.vtu_compression,
                              parameters.output.vtu_fields);
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
      }
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
        analysis.solve();
        analysis.write_output(parameters.output.directory,
                              parameters.output.vtu_compression,
                              parameters.output.vtu_fields);
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
  {}



  void
  Simulator::setup()
  {
    total_timer.restart();
    geometry = std::make_unique<PlateGeometry>(parameters.geometry);
    material =
      std::make_unique<FunctionallyGradedMaterial>(parameters.material,
                                                   geometry->thickness());
    plate = std::make_unique<PlateModel>(parameters.finite_element,
                                         *geometry,
                                         *material,
                                         mpi_communicator);
    plate->setup();

    const PropertyMode mode = parameters.material.property_mode;
    pcout << "fgimpact: FGM plate " << geometry->length() << " x "
          << geometry->width() << " x " << geometry->thickness() << " m, "
          << plate->n_active_cells() << " cells, " << plate->n_dofs()
          << " DoFs (Q" << plate->get_fe().degree << ", "
          << (mode == PropertyMode::graded      ? "graded" :
              mode == PropertyMode::homogeneous ? "homogeneous" :
                                                  "pointwise")
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
    if (!parameters.accuracy.log_message.empty())
      pcout << "  " << parameters.accuracy.log_message << '\n';

    switch (parameters.problem_type)
      {
        case ProblemType::impact:
          {
            auto impact =
              std::make_unique<ImpactDriver>(parameters, *plate, total_timer);
            for (const auto &observer : observers)
              impact->add_row_observer(observer);
            driver = std::move(impact);
            break;
          }
        case ProblemType::static_load:
          driver = std::make_unique<StaticDriver>(parameters, *plate);
          break;
        case ProblemType::modal:
          driver = std::make_unique<ModalDriver>(parameters, *plate);
          break;
      }
    driver->setup();
  }



  void
  Simulator::run()
  {
    if (!driver)
      setup();
    driver->run();
  }



  const ImpactResults &
  Simulator::get_results() const
  {
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
} // namespace fgimpact
