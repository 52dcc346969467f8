#include "cvtMemory.h"

#include <cstdint>
#include <cstdlib>
#include <fstream>
#include <limits>
#include <sstream>
#include <unistd.h>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace cvt
{

double AvailableSystemMemory()
{
  std::ifstream meminfo("/proc/meminfo");
  std::string key;
  double kilobytes = 0.0;
  std::string unit;
  while (meminfo >> key >> kilobytes >> unit)
  {
    if (key == "MemAvailable:")
    {
      return kilobytes * 1024.0;
    }
  }
  const long pages = sysconf(_SC_AVPHYS_PAGES), pageSize = sysconf(_SC_PAGESIZE);
  return pages > 0 && pageSize > 0 ? static_cast<double>(pages) * pageSize : 0.0;
}

double ResidentMemory()
{
  std::ifstream statm("/proc/self/statm");
  long pages = 0, resident = 0;
  statm >> pages >> resident;
  return static_cast<double>(resident) * static_cast<double>(sysconf(_SC_PAGESIZE));
}

std::string CheckMemory(double bytes, double available, const std::string& what,
  const std::string& where, const std::string& advice)
{
  if (available <= 0.0 || bytes <= 0.9 * available)
  {
    return std::string();
  }
  std::ostringstream text;
  text.precision(bytes < 1e10 ? 2 : 3);
  text << what << " needs about " << bytes / 1e9 << " GB of " << where << "; " << available / 1e9
       << " GB are available: " << advice;
  return text.str();
}

ZeroedPages::ZeroedPages(size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  // Anonymous mappings are zeroed; huge pages need 2 MiB-aligned 2 MiB ranges, so the memory is
  // rounded up to whole huge pages and the mapping is a huge page longer, the memory starting at
  // its first such boundary.
  constexpr size_t huge = size_t(1) << 21;
  if (bytes <= std::numeric_limits<size_t>::max() - 2 * huge)
  {
    const size_t rounded = (bytes + huge - 1) & ~(huge - 1);
    const size_t length = rounded + huge;
    void* mapped =
      mmap(nullptr, length, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS, -1, 0);
    if (mapped != MAP_FAILED)
    {
      this->Mapped = mapped;
      this->MappedBytes = length;
      const std::uintptr_t start = reinterpret_cast<std::uintptr_t>(mapped);
      this->Aligned = reinterpret_cast<void*>((start + huge - 1) & ~std::uintptr_t(huge - 1));
      madvise(this->Aligned, rounded, MADV_HUGEPAGE); // a hint: without it, 4 KiB pages
      return;
    }
  }
#endif
  this->Mapped = this->Aligned = std::calloc(bytes, 1); // null when too large
}

ZeroedPages::~ZeroedPages()
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
  if (this->MappedBytes > 0)
  {
    munmap(this->Mapped, this->MappedBytes);
    return;
  }
#endif
  std::free(this->Mapped);
}

} // namespace cvt
