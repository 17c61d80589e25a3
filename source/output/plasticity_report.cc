// What a plastic plate leaves, for summary.txt (plasticity_report.h).

#include <fgimpact/output/plasticity_report.h>

#include <algorithm>
#include <cmath>

namespace fgimpact
{
  PlasticityReport::PlasticityReport(const PlasticPlate &plasticity,
                                     ImpactResults      &results,
                                     const double        whole,
                                     const double        V0)
    : plasticity(plasticity)
    , results(results)
    , whole(whole)
    , V0(V0)
  {
    results.plastic.modelled = true;
  }



  void
  PlasticityReport::execute(const StepRecord &record)
  {
    const HistorySample &s     = *record.sample;
    const double         ratio = plasticity.max_trial_ratio();
    const double         force = s.contact->force;
    auto                &r     = results.plastic;
    if (std::isnan(r.first_yield_time) &&
        plasticity.max_equivalent_plastic_strain() > 0.)
      {
        // The trial ratio crossed 1 in this step.
        const double theta  = yield_crossing(last_ratio, ratio);
        r.first_yield_time  = last_time + theta * (record.t - last_time);
        r.first_yield_force = last_force + theta * (force - last_force);
      }
    last_ratio  = ratio;
    last_time   = record.t;
    last_force  = force;
    indentation = s.W_top - s.W_mid;
  }



  void
  PlasticityReport::save(CheckpointWriter &out, const unsigned int)
  {
    for (const double value : {last_ratio,
                               last_time,
                               last_force,
                               indentation,
                               results.plastic.first_yield_time,
                               results.plastic.first_yield_force})
      out.put(value);
  }



  void
  PlasticityReport::load(CheckpointReader &in)
  {
    for (double *value : {&last_ratio,
                          &last_time,
                          &last_force,
                          &indentation,
                          &results.plastic.first_yield_time,
                          &results.plastic.first_yield_force})
      in.get(*value);
  }



  void
  PlasticityReport::finish(const ImpactorState &)
  {
    auto &r                 = results.plastic;
    r.dissipation           = whole * plasticity.plastic_work();
    r.max_plastic_strain    = plasticity.max_equivalent_plastic_strain();
    r.permanent_indentation = indentation;
    // The results accumulator, first in the list, has set it.
    r.restitution = results.departure_velocity / V0;
    r.mean_iterations =
      double(plasticity.n_iterations()) / std::max(results.n_time_steps, 1u);
    r.max_iterations = plasticity.max_increment_iterations();
  }
} // namespace fgimpact
