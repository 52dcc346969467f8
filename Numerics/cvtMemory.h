// Memory limits checked before the engines allocate: a domain too large for this machine gets
// a sentence saying how much it needs and how much there is, not an out-of-memory kill.
#ifndef cvtMemory_h
#define cvtMemory_h

#include "cvtNumericsModule.h" // for export macro

#include <cstddef>
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

/// Zeroed memory for a large table touched at scattered places, on the system's huge pages where
/// it has them (Linux's transparent huge pages, asked for by madvise): the first touch of each
/// page costs a page fault, and on these virtual machines one costs 9 to 23 microseconds (a
/// 64 MiB write, one byte per page: 16,384 faults, 0.14 s): the surface projector's 21 MB answer
/// table on 4 KiB pages took 0.14 s more to fill with 8,520 answers spread over most of its 5,120
/// pages (bunny00 at 1000 sites), on 2 MiB pages (10 of them) a few milliseconds. Elsewhere it
/// is plain calloc'ed memory.
class CVTNUMERICS_EXPORT ZeroedPages
{
public:
  explicit ZeroedPages(size_t bytes);
  ~ZeroedPages();
  ZeroedPages(const ZeroedPages&) = delete;
  ZeroedPages& operator=(const ZeroedPages&) = delete;

  /// The memory (aligned to at least 16 bytes); null when it could not be had.
  void* Data() const { return this->Aligned; }

private:
  void* Mapped = nullptr; // what the system gave
  size_t MappedBytes = 0; // 0: calloc'ed
  void* Aligned = nullptr;
};

} // namespace cvt

#endif
