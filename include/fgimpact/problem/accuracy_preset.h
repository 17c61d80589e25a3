#ifndef fgimpact_accuracy_preset_h
#define fgimpact_accuracy_preset_h

#include <deal.II/base/parameter_handler.h>

#include <fgimpact/base/selection.h>

#include <string>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /**
   * Accuracy presets: one entry, `Accuracy = custom | fast | standard |
   * accurate`, that fixes the discretization of an impact run from the
   * speed/accuracy map (doc/accuracy.md). A preset other than custom sets
   * Geometry/Subdivisions x, y, z and Time integration/Time step in the
   * ParameterHandler itself, before the other subsections are read, so the
   * parameters.prm written next to the output holds the effective values.
   *
   * All presets use the same in-plane element size, 5 mm (the default
   * mesh's): under the paper's point contact force the peak force depends
   * on that size and does not converge (doc/mesh_study.md), so runs are
   * only comparable at equal in-plane size. The presets differ in the
   * elements through the thickness and the time step, which converge.
   * The subdivisions follow from the plate size: the nearest even number
   * of elements of that size (a node at the plate centre).
   */
  class AccuracyPreset
  {
  public:
    /// What a preset sets.
    struct Setting
    {
      std::string  name;
      double       element_size; // in-plane element edge, m
      unsigned int subdivisions_z;
      double       time_step; // s
    };

    /// The presets other than custom, as documented in the entry's help.
    static const std::vector<Setting> &
    settings();

    /// Accuracy.
    enum class Preset
    {
      custom,
      fast,
      standard,
      accurate,
      converged
    };

    /// The names of Accuracy.
    static const SelectionTable<Preset> &
    preset_names();

    struct Parameters
    {
      Preset preset = Preset::custom;
      /// Accuracy = converged: the relative change of the headline numbers
      /// between two contact refinement levels at which the sequence stops
      /// (ConvergedRun).
      double tolerance = 0.01;
      /// What the file had before a preset other than custom overwrote
      /// it: Geometry/Subdivisions x, y, z and Time integration/Time step
      /// (s); 0 for custom.
      unsigned int file_subdivisions_x = 0, file_subdivisions_y = 0,
                   file_subdivisions_z = 0;
      double file_time_step            = 0;

      /// One line saying what the preset set, given the subdivisions it
      /// set (empty for custom); printed by Simulator::setup().
      std::string
      applied_message(const unsigned int nx,
                      const unsigned int ny,
                      const unsigned int nz) const;

      static void
      declare_parameters(ParameterHandler &prm);
      /// Read Accuracy and, unless custom, overwrite the Geometry
      /// subdivisions and the time step in prm.  Not a component's parse:
      /// fgimpact::Parameters::parse_parameters() calls it explicitly
      /// before any component reads its subsection.  Throws ExcMessage
      /// naming the entry if the preset cannot be applied (explicit
      /// scheme, too many elements).
      void
      apply(ParameterHandler &prm);
    };

    /// Nearest even number (at least 2) of elements of size element_size
    /// on a length: the mesh then has a node at the middle.
    static unsigned int
    even_subdivisions(const double length, const double element_size);
  };
} // namespace fgimpact

#endif
