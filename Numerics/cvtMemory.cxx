#include "cvtMemory.h"

#include <fstream>
#include <sstream>
#include <unistd.h>

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

} // namespace cvt
