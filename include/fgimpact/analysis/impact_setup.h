#ifndef fgimpact_analysis_impact_setup_h
#define fgimpact_analysis_impact_setup_h

#include <fgimpact/contact/contact_model.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/plate_model.h>
#include <fgimpact/problem/parameters.h>
#include <fgimpact/problem/scene.h>

namespace fgimpact
{
  /**
   * What the run models: the parameters' choices as resolved (the
   * symmetric part, the contact refinement levels of the mesh) and the
   * in-plane element size at the impact point (m, measured on the mesh).
   * Collective.
   */
  ModelDescription
  describe_model(const Parameters &parameters,
                 const Scene      &scene,
                 const PlateModel &plate,
                 const double      time_step);

  /**
   * An impact run's results before the time loop, shared by a run and a
   * study case: DoFs, MPI ranks, the impactor's and the whole plate's
   * masses (kg; the part's mass over its share), the contact model's
   * constants, and setup_time (s).  Collective.
   */
  ImpactResults
  setup_results(const PlateModel   &plate,
                const Scene        &scene,
                const ContactModel &contact,
                const double        setup_time);
} // namespace fgimpact

#endif
