#ifndef fgimpact_postprocessor_h
#define fgimpact_postprocessor_h

#include <deal.II/base/exceptions.h>
#include <deal.II/base/symmetric_tensor.h>

#include <fgimpact/base/checkpoint.h>
#include <fgimpact/contact/contact_model.h>
#include <fgimpact/time/contact_coupler.h>
#include <fgimpact/time/plate_fields.h>

#include <cstdint>
#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// Everything history.csv shows at one time, in SI units (the whole
  /// plate's values when a symmetric part is modelled).
  struct HistorySample
  {
    double                t       = 0; // s
    const ImpactorState  *ball    = nullptr;
    const ContactState   *contact = nullptr;
    double                W_mid = 0, W_top = 0; // m, positive down
    SymmetricTensor<2, 3> sigma_mid;            // Pa
    double E_impactor = 0, E_kinetic = 0, E_strain = 0, E_contact = 0; // J
    double E_total = 0;                                                // J
    /// A plastic plate: the plastic work (J, in E_total) and the largest
    /// equivalent plastic strain.
    double E_plastic = 0, max_plastic_strain = 0;
  };

  /// One column of history.csv: name (with unit), decimals, and the value
  /// in the file's unit.
  struct HistoryColumn
  {
    const char *name;
    int         decimals;
    double (*value)(const HistorySample &);
  };

  /// The columns of history.csv, declared once (the CSV header, the rows
  /// and the docs follow this list).
  const std::vector<HistoryColumn> &
  history_columns();

  /// The columns a resolved contact adds after history_columns():
  /// contact_radius_mm, max_contact_pressure_MPa, n_contact_nodes.
  const std::vector<HistoryColumn> &
  contact_area_columns();

  /// The columns a plastic plate adds (Material/Plasticity = J2):
  /// energy_plastic_J, max_plastic_strain.
  const std::vector<HistoryColumn> &
  plasticity_columns();



  /// What every postprocessor sees at one recorded time step.
  struct StepRecord
  {
    unsigned int step = 0;
    double       t    = 0; // s
    /// The whole plate's values (history.csv's).
    const HistorySample *sample = nullptr;
    /// The contact as the model computed it for the part modelled.
    const ContactState *part_contact = nullptr;
    /// The fields with the constraints distributed (nullptr without
    /// fields: the convolution engine of a study).
    const PlateFields *fields = nullptr;
    /// Iterations of the plate's linear solver in this step.
    unsigned int linear_iterations = 0;
    /// |E_total - E0| / E0, the relative energy drift (E0 = m V0^2 / 2).
    double energy_drift = 0;
  };



  /**
   * One job of watching an impact run (deal.II's DataPostprocessor and
   * ASPECT's postprocessors in spirit): it sees every recorded step, may
   * keep state for a checkpoint in its own named, versioned section, may
   * write files, and adds its part to the results at the end.  The
   * ImpactMonitor builds the step's record once and calls its list in
   * order.
   *
   * A failed file write must not throw on one rank alone (the others
   * would wait in the next collective call): it is kept in
   * output_failure(), which the driver combines over the ranks at the end
   * of the step.
   */
  class Postprocessor
  {
  public:
    virtual ~Postprocessor() = default;

    /// The name of its checkpoint section ("": it keeps no state).
    virtual std::string
    name() const
    {
      return "";
    }

    /// The layout of its checkpoint section.
    virtual std::uint32_t
    checkpoint_version() const
    {
      return 1;
    }

    /// Whether execute() at `step` reads the velocity and acceleration
    /// fields (decided from the parameters alone: the same on every rank,
    /// as PlateFields::update() is collective).
    virtual bool
    needs_rates(const unsigned int /*step*/) const
    {
      return false;
    }

    /// Open the output files, new or continued after load() (rank 0 alone
    /// for the CSV files).
    virtual void
    start()
    {}

    virtual void
    execute(const StepRecord &record) = 0;

    /// A resumed run: whether the snapshot of the checkpoint's step has
    /// to be written again (collective).
    virtual bool
    needs_rewrite() const
    {
      return false;
    }

    /// Write the snapshot of `step` (time t, s) again from fields.
    virtual void
    rewrite(const unsigned int /*step*/,
            const double /*t*/,
            const PlateFields & /*fields*/)
    {}

    virtual void
    save(CheckpointWriter & /*out*/, const unsigned int /*step*/)
    {}

    virtual void
    load(CheckpointReader & /*in*/)
    {}

    /// Finish the files (collective: peak fields).
    virtual void
    close_output()
    {}

    /// The run has ended with the ball in state `ball`: add the results
    /// that depend on the whole history.
    virtual void
    finish(const ImpactorState & /*ball*/)
    {}

    /// Wall time spent writing (s).
    virtual double
    output_time() const
    {
      return 0.;
    }

    /// The message of a failed output write on this rank ("" if none).
    const std::string &
    output_failure() const
    {
      return output_failure_message;
    }

  protected:
    /// Keep the message of a failed write (one line).
    void
    keep_failure(const ExceptionBase &e);

    std::string output_failure_message;
  };
} // namespace fgimpact

#endif
