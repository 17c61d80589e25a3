#ifndef fgimpact_raw_vtu_h
#define fgimpact_raw_vtu_h

#include <deal.II/base/data_out_base.h>

#include <ostream>
#include <string>
#include <tuple>
#include <vector>

namespace fgimpact
{
  using namespace dealii;

  /// DataOut's vector and tensor fields: (first component, last
  /// component, name, kind).
  using NonscalarRanges = std::vector<
    std::tuple<unsigned int,
               unsigned int,
               std::string,
               DataComponentInterpretation::DataComponentInterpretation>>;

  /**
   * Write patches as a VTU file with the same points, cells and data
   * arrays (Float32) as DataOutBase::write_vtu(), but as raw appended
   * binary data (`<AppendedData encoding="raw">`, 64-bit headers) instead
   * of base64-encoded zlib blocks: no compression and no encoding, so the
   * file is written at the speed of a memory copy (about 2.5 times the
   * size of deal.II's `best_speed` file).  Output/VTU compression = none
   * selects it; it is what makes the whole plate of a symmetric part
   * (MirroredDataOut, four times the part's data) as cheap to write as the
   * part itself was.  ParaView and VTK read it like any VTU file.
   *
   * time, cycle: the TIME and CYCLE field data (as deal.II writes them;
   * left out for VtkFlags' default time, the smallest double).
   */
  void
  write_raw_vtu(const std::vector<DataOutBase::Patch<3, 3>> &patches,
                const std::vector<std::string>              &names,
                const NonscalarRanges                       &nonscalar_ranges,
                const double                                 time,
                const unsigned int                           cycle,
                std::ostream                                &out);
} // namespace fgimpact

#endif
