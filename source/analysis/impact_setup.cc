// What an impact run modelled and its results before the time loop, for a
// run (ImpactDriver) and a study case (ImpactStudyEngine) alike.

#include <deal.II/base/mpi.h>

#include <fgimpact/analysis/impact_setup.h>
#include <fgimpact/contact/impactor.h>
#include <fgimpact/material/gradation.h>
#include <fgimpact/time/time_stepper.h>

namespace fgimpact
{
  ImpactResults
  setup_results(const PlateModel   &plate,
                const Scene        &scene,
                const ContactModel &contact,
                const double        setup_time)
  {
    ImpactResults results;
    results.n_dofs = plate.n_dofs();
    results.n_mpi_ranks =
      Utilities::MPI::n_mpi_processes(plate.get_mpi_communicator());
    results.impactor_mass = scene.impactor().mass();
    results.plate_mass    = plate.total_mass() / scene.share();
    results.set_contact_constants(contact.constants());
    results.setup_time = setup_time;
    return results;
  }



  ModelDescription
  describe_model(const Parameters &parameters,
                 const Scene      &scene,
                 const PlateModel &plate,
                 const double      time_step)
  {
    using Model        = ContactModelParameters::Model;
    const auto      &g = plate.get_geometry();
    const auto      &m = parameters.material;
    ModelDescription d;
    const Model      model = parameters.contact_model.model;
    d.contact_model        = ContactModelParameters::model_names().name(model);
    d.contact_refinement_levels = plate.contact_refinement().levels;
    d.element_size_under_ball   = plate.cell_size_at(scene.impact_point());
    d.time_step                 = time_step;
    d.scheme =
      TimeStepper::scheme_names().name(parameters.time_integration.scheme);
    d.element_degree     = plate.get_fe().degree;
    d.element_technology = plate.element_technology();
    d.symmetry           = g.part_name();
    d.property_mode      = property_mode_names().name(m.property_mode);
    d.gradation          = gradation_names().name(m.gradation);
    d.power_law_index    = m.power_law_index;
    d.impactor_radius    = parameters.impactor.radius;
    d.thickness          = g.thickness();
    d.homogenization     = homogenization_names().name(m.homogenization);
    return d;
  }
} // namespace fgimpact
