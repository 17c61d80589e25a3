#ifndef fgimpact_plasticity_report_h
#define fgimpact_plasticity_report_h

#include <fgimpact/output/postprocessor.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/plastic_plate.h>

namespace fgimpact
{
  /**
   * What a plastic plate (Material/Plasticity = J2) leaves, for
   * summary.txt: the plastic work, the largest equivalent plastic strain,
   * first yield (the time and contact force at which the largest elastic
   * trial stress reached the yield stress, interpolated linearly between
   * the last elastic step and the first plastic one), the permanent
   * indentation (the plate's thinning under the impact point at the end,
   * W_top - W_mid: the top face's dent once the ball has left; its
   * bending does not thin it) and the coefficient of restitution
   * (departure over impact velocity).
   */
  class PlasticityReport : public Postprocessor
  {
  public:
    /// whole: 1 / the part's share; V0: the impact velocity (m/s).
    PlasticityReport(const PlasticPlate &plasticity,
                     ImpactResults      &results,
                     const double        whole,
                     const double        V0);

    std::string
    name() const override
    {
      return "plasticity";
    }

    void
    execute(const StepRecord &record) override;

    void
    save(CheckpointWriter &out, const unsigned int step) override;

    void
    load(CheckpointReader &in) override;

    void
    finish(const ImpactorState &ball) override;

  private:
    const PlasticPlate &plasticity;
    ImpactResults      &results;
    const double        whole, V0;
    /// The last step's trial ratio, time (s) and whole contact force (N).
    double last_ratio = 0, last_time = 0, last_force = 0;
    double indentation = 0; // m, W_top - W_mid of the last step
  };
} // namespace fgimpact

#endif
