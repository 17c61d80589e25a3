#include <fgimpact/base/memory.h>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>
#include <sys/resource.h>

namespace fgimpact
{
  namespace
  {
    /// A "Key:   value kB" line of a /proc file, in bytes (-1: absent).
    double
    proc_kilobytes(const char *file, const std::string &key)
    {
      std::ifstream in(file);
      std::string   line;
      while (std::getline(in, line))
        if (line.compare(0, key.size() + 1, key + ":") == 0)
          return 1024. * std::atof(line.c_str() + key.size() + 1);
      return -1;
    }
  } // namespace



  /// bytes as "1.23 GB" (three significant digits).
  std::string
  gigabytes(const double bytes)
  {
    char text[32];
    std::snprintf(text, sizeof(text), "%.3g GB", bytes * 1e-9);
    return text;
  }



  namespace
  {
    bool blas_buffer_mapped = false;
  }



  void
  note_blas_buffer_mapped()
  {
    blas_buffer_mapped = true;
  }



  AvailableMemory
  available_memory()
  {
    AvailableMemory available;
    available.bytes  = proc_kilobytes("/proc/meminfo", "MemAvailable");
    available.source = "MemAvailable in /proc/meminfo";
    if (available.bytes < 0)
      {
        available.bytes  = 1e30;
        available.source = "no MemAvailable in /proc/meminfo";
      }
    struct rlimit limit;
    if (getrlimit(RLIMIT_AS, &limit) == 0 && limit.rlim_cur != RLIM_INFINITY)
      {
        // OpenBLAS maps a 128 MB work buffer (134238208 bytes, measured in
        // its blas_memory_alloc) at the first dense factorization call,
        // and when that mmap fails under ulimit -v it retries forever
        // (seen with 0.3.21: 100 % CPU, no return to our code, so no stop
        // signal is ever acted on).  Counted as used: the run is refused
        // in one line instead.
        const double blas_buffer = blas_buffer_mapped ? 0. : 134238208.;
        const double used =
          std::max(0., proc_kilobytes("/proc/self/status", "VmSize"));
        const double left =
          static_cast<double>(limit.rlim_cur) - used - blas_buffer;
        if (left < available.bytes)
          {
            available.bytes = std::max(0., left);
            available.source =
              "address-space limit RLIMIT_AS (ulimit -v) " +
              gigabytes(static_cast<double>(limit.rlim_cur)) + " minus " +
              gigabytes(used) + " mapped" +
              (blas_buffer > 0 ?
                 " and OpenBLAS's " + gigabytes(blas_buffer) + " work buffer" :
                 std::string());
          }
      }
    return available;
  }



  double
  resident_memory()
  {
    return std::max(0., proc_kilobytes("/proc/self/status", "VmRSS"));
  }
} // namespace fgimpact
