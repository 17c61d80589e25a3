#ifndef fgimpact_base_memory_h
#define fgimpact_base_memory_h

#include <string>

namespace fgimpact
{
  /**
   * Memory this process may still use: the smaller of the node's
   * MemAvailable (/proc/meminfo) and, if an address-space limit is set
   * (RLIMIT_AS, `ulimit -v`), what is left of it (limit minus VmSize).
   */
  struct AvailableMemory
  {
    double      bytes = 0;
    std::string source; ///< "MemAvailable" or "RLIMIT_AS (ulimit -v)"
  };

  /// The memory this process may still allocate (bytes): MemAvailable,
  /// or, under an address-space limit, what the limit leaves, less
  /// OpenBLAS's work buffer until note_blas_buffer_mapped() was called.
  AvailableMemory
  available_memory();

  /// After the first dense factorization of the process: OpenBLAS's work
  /// buffer is mapped (and counted in VmSize), not to be counted again.
  void
  note_blas_buffer_mapped();

  /// Resident set size of this process now, bytes (/proc/self/statm).
  double
  resident_memory();

  /// bytes as "1.23 GB" (three significant digits).
  std::string
  gigabytes(const double bytes);
} // namespace fgimpact

#endif
