#include <deal.II/base/timer.h>

#include <fgimpact/analysis/thermal_step.h>
#include <fgimpact/base/parameter_table.h>
#include <fgimpact/plate/rigid_modes.h>
#include <fgimpact/plate/thermal_load.h>

#include <iomanip>
#include <limits>
#include <sstream>

namespace fgimpact
{
  ThermalStep::ThermalStep(const ThermalParameters                 &parameters,
                           const PlateModel                        &plate,
                           const EffectiveMatrixSolver::Parameters &solver)
    : plate(plate)
    , profile(parameters, plate.get_material())
    , solver_parameters(solver)
  {}



  void
  ThermalStep::run()
  {
    Timer timer;
    buckling.factor = std::numeric_limits<double>::quiet_NaN();
    // A free plate: springs as stiff as the diagonal at the pins, which
    // the self-equilibrated load (and a buckling mode) leaves unloaded.
    const std::vector<types::global_dof_index> pins = rigid_motion_pins(plate);
    n_pins                                          = pins.size();
    TrilinosWrappers::SparseMatrix pinned;
    if (n_pins > 0)
      {
        pinned.copy_from(plate.stiffness_matrix());
        for (const auto dof : pins)
          if (plate.locally_owned_dofs().is_element(dof))
            pinned.add(dof, dof, pinned.diag_element(dof));
        pinned.compress(VectorOperation::add);
      }
    const TrilinosWrappers::SparseMatrix &K =
      n_pins > 0 ? pinned : plate.stiffness_matrix();
    EffectiveMatrixSolver solver(solver_parameters);
    solver.initialize(K, &plate.get_dof_handler());
    solve_displacement(solver);
    if (profile.get_parameters().geometric_stiffness)
      solve_buckling(K, solver);
    seconds = timer.wall_time();
  }



  void
  ThermalStep::solve_displacement(EffectiveMatrixSolver &solver)
  {
    TrilinosWrappers::MPI::Vector f, x;
    assemble_thermal_load(plate, profile, f);
    plate.initialize_vector(x);
    solver.solve(x, f);
    plate.get_constraints().distribute(x);
    u.reinit(plate.locally_owned_dofs(),
             plate.locally_relevant_dofs(),
             plate.get_mpi_communicator());
    u       = x;
    initial = std::make_unique<InitialStress>(plate, profile, u);
    const PlateGeometry::Parameters &g = plate.get_geometry().get_parameters();
    top    = stress_at(Point<3>(g.length / 2, g.width / 2, g.thickness));
    bottom = stress_at(Point<3>(g.length / 2, g.width / 2, 0.));
  }



  void
  ThermalStep::solve_buckling(const TrilinosWrappers::SparseMatrix &K,
                              EffectiveMatrixSolver                &solver)
  {
    assemble_geometric_stiffness(plate, *initial, K_sigma);
    buckling = thermal_buckling_factor(K, K_sigma, solver, plate);
    const ThermalParameters &p = profile.get_parameters();
    const std::string        entry =
      p.field == TemperatureField::uniform ?
               "Thermal/Temperature change = " + prm_string(p.temperature_change) +
          " K" :
               "Thermal/Top temperature = " + prm_string(p.top_temperature) +
          " K and Bottom temperature = " + prm_string(p.bottom_temperature) +
          " K";
    std::ostringstream critical;
    critical << std::setprecision(4) << buckling.factor * largest_change();
    AssertThrow(!(buckling.factor <= 1.),
                ExcMessage(entry +
                           " buckle the plate: its thermal buckling "
                           "temperature change is " +
                           critical.str() +
                           " K (the largest |T - T_ref| at which K + "
                           "K_sigma turns singular); lower the temperatures "
                           "or set Thermal/Geometric stiffness = false."));
  }



  double
  ThermalStep::largest_change() const
  {
    const double h       = plate.get_geometry().get_parameters().thickness;
    double       largest = 0;
    for (unsigned int i = 0; i <= 1000; ++i)
      largest = std::max(largest, std::abs(profile.change(i * h / 1000)));
    return largest;
  }



  SymmetricTensor<2, 3>
  ThermalStep::stress_at(const Point<3> &p) const
  {
    return initial->stress_at(p);
  }



  SummaryWriter
  ThermalStep::summary() const
  {
    const double  h = plate.get_geometry().get_parameters().thickness;
    SummaryWriter s;
    s.add_text("temperature_field",
               temperature_field_names().name(profile.get_parameters().field));
    s.add("temperature_top_K", profile.temperature(h), 3);
    s.add("temperature_bottom_K", profile.temperature(0.), 3);
    s.add("thermal_stress_top_MPa", top[0][0] / 1e6, 3);
    s.add("thermal_stress_bottom_MPa", bottom[0][0] / 1e6, 3);
    if (profile.get_parameters().geometric_stiffness)
      {
        s.add_scientific("thermal_buckling_factor", buckling.factor);
        s.add("thermal_buckling_temperature_change_K",
              buckling.factor * largest_change(),
              3);
      }
    return s;
  }



  void
  ThermalStep::print(ConditionalOStream &out, const bool with_time) const
  {
    // The buckling solve's iterations are left out: they may vary with the
    // BLAS kernel.
    const double h = plate.get_geometry().get_parameters().thickness;
    const std::ios_base::fmtflags flags     = out.get_stream().flags();
    const std::streamsize         precision = out.get_stream().precision();
    out << std::fixed << std::setprecision(3)
        << "  thermal step: T = " << profile.temperature(0.)
        << " K (bottom) to " << profile.temperature(h) << " K (top), T_ref = "
        << profile.get_parameters().reference_temperature
        << " K; sigma_xx at the face centres " << top[0][0] / 1e6
        << " MPa (top), " << bottom[0][0] / 1e6 << " MPa (bottom)";
    if (n_pins > 0)
      out << "; " << n_pins
          << " rigid-body motion(s) free, pinned without force";
    if (with_time)
      out << "; " << std::setprecision(2) << seconds << " s";
    out << '\n';
    if (profile.get_parameters().geometric_stiffness)
      out << "  thermal buckling at " << std::setprecision(3) << buckling.factor
          << " x (T - T_ref), a change of " << std::setprecision(1)
          << buckling.factor * largest_change() << " K\n";
    out.get_stream().flags(flags);
    out.get_stream().precision(precision);
  }
} // namespace fgimpact
