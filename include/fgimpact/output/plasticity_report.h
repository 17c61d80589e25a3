#ifndef fgimpact_plasticity_report_h
#define fgimpact_plasticity_report_h

#include <fgimpact/output/postprocessor.h>
#include <fgimpact/output/results.h>
#include <fgimpact/plate/plastic_plate.h>
#include <fgimpact/plate/plate_model.h>

#include <utility>
#include <vector>

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
   * bending does not thin it), the crater's diameter (where the top
   * face's thinning W(r) - W_mid along a line from the impact point
   * changes sign at the rim), the plastic zone's depth and radius, and
   * the coefficient of restitution (departure over impact velocity).
   */
  class PlasticityReport : public Postprocessor
  {
  public:
    /// whole: 1 / the part's share; V0: the impact velocity (m/s);
    /// impact_point: on the top face (m); radius: how far from it along
    /// the top face's line y = y_c, x <= x_c the crater's rim is sought (m).
    PlasticityReport(const PlasticPlate &plasticity,
                     const PlateModel   &plate,
                     ImpactResults      &results,
                     const double        whole,
                     const double        V0,
                     const Point<3>     &impact_point,
                     const double        radius);

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

    /// The crater's diameter and the plastic zone (collective).
    void
    close_output() override;

    void
    finish(const ImpactorState &ball) override;

  private:
    /// After the run: Hertz's first yield, and the computed one given as
    /// none (with a warning) where the mesh cannot resolve it.
    void
    judge_first_yield();

    /// The locally owned z DoFs of the top face's vertices on the line
    /// y = y_c, x <= x_c within the radius, with their distance (m).
    std::vector<std::pair<types::global_dof_index, double>> line;
    /// Their last deflections W = -u_z (m).
    std::vector<double>               line_deflection;
    const Point<3>                    impact_point;
    const double                      top;
    const MPI_Comm                    mpi_communicator;
    double                            W_mid = 0; // m, the last step's
    const PlasticPlate               &plasticity;
    ImpactResults                    &results;
    const double                      whole, V0;
    const double                      R; // m, the ball's radius
    const FunctionallyGradedMaterial &material;
    const unsigned int                degree; // of the plate's elements
    /// The pointwise Q1 brick, which locks under plastic flow (a warning
    /// at the end when anything yielded).
    const bool locking;
    /// The last step's trial ratio, time (s) and whole contact force (N).
    double last_ratio = 0, last_time = 0, last_force = 0;
    double indentation = 0; // m, W_top - W_mid of the last step
  };
} // namespace fgimpact

#endif
