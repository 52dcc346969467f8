// Memory limits checked before the engines allocate: a domain too large for this machine gets
// a sentence saying how much it needs and how much there is, not an out-of-memory kill.
#ifndef cvtMemory_h
#define cvtMemory_h

#include "cvtNumericsModule.h" // for export macro

#include <string>

namespace cvt
{

/// Bytes the system can give without swapping (MemAvailable of /proc/meminfo; else the free
/// physical pages); 0 when unknown.
CVTNUMERICS_EXPORT double AvailableSystemMemory();

/// Resident memory of this process in bytes (Linux: /proc/self/statm); 0 when unknown.
CVTNUMERICS_EXPORT double ResidentMemory();

/// "" when `bytes` fit in 90% of `available` (or `available` is unknown, 0), else a sentence:
/// "<what> needs about N GB of <where>; M GB are available: <advice>".
CVTNUMERICS_EXPORT std::string CheckMemory(double bytes, double available, const std::string& what,
  const std::string& where, const std::string& advice);

} // namespace cvt

#endif
