#include "cvtMemory.h"
#include "cvtSampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>

#ifdef __linux__
#include <sys/resource.h>
#endif

TEST(Sampling, SameSeedSameSitesOtherSeedOtherSites)
{
  const cvt::Grid grid = cvt::Grid::Square(32, -1.0, 1.0);
  const auto a = cvt::SampleSites(grid, {}, 50, 7);
  const auto b = cvt::SampleSites(grid, {}, 50, 7);
  const auto c = cvt::SampleSites(grid, {}, 50, 8);
  ASSERT_EQ(a.size(), 100u);
  EXPECT_EQ(a, b);
  EXPECT_NE(a, c);
  EXPECT_EQ(cvt::CheckSites(grid, a), "");
}

TEST(Sampling, FollowsTheDensity)
{
  // Density only in the left half: every site must land there.
  const cvt::Grid grid = cvt::Grid::Square(16, -1.0, 1.0);
  std::vector<float> density(256, 0.0f);
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      density[j * 16 + i] = 1.0f;
    }
  }
  const auto sites = cvt::SampleSites(grid, density, 200, 3);
  for (size_t s = 0; s < sites.size(); s += 2)
  {
    EXPECT_LE(sites[s], 0.0);
  }
}

TEST(Sampling, DensityChecksSayWhatIsWrong)
{
  const cvt::Grid grid = cvt::Grid::Square(2, -1.0, 1.0);
  EXPECT_EQ(cvt::CheckDensity(grid, { 1, 2, 3, 0 }), "");
  EXPECT_NE(cvt::CheckDensity(grid, { 1, -2, 3, 0 }).find("negative"), std::string::npos);
  EXPECT_NE(cvt::CheckDensity(grid, { 1, std::numeric_limits<float>::quiet_NaN(), 3, 0 })
              .find("not finite"),
    std::string::npos);
  EXPECT_NE(cvt::CheckDensity(grid, { 0, 0, 0, 0 }).find("zero everywhere"), std::string::npos);
  EXPECT_NE(cvt::CheckDensity(grid, { 1, 1 }), "");
}

TEST(Sampling, SiteChecksSayWhatIsWrong)
{
  const cvt::Grid grid = cvt::Grid::Square(2, -1.0, 1.0);
  EXPECT_EQ(cvt::CheckSites(grid, { 0.0, 0.0, 0.5, 0.5 }), "");
  EXPECT_NE(cvt::CheckSites(grid, {}).find("no sites"), std::string::npos);
  EXPECT_NE(cvt::CheckSites(grid, { 0.0, 0.0, 2.0, 0.0 }).find("outside"), std::string::npos);
  EXPECT_NE(cvt::CheckSites(grid, { 0.1, 0.1, 0.1, 0.1 }).find("duplicates"), std::string::npos);
  EXPECT_NE(cvt::CheckSites(grid, { 0, 0, 0.1, 0, 0.2, 0, 0.3, 0, 0.4, 0 }).find("more than"),
    std::string::npos);
}

TEST(Memory, CheckMemorySaysWhatItNeedsAndWhatThereIs)
{
  EXPECT_EQ(cvt::CheckMemory(8e9, 10e9, "x", "memory", "advice"), "");
  EXPECT_EQ(cvt::CheckMemory(8e9, 0.0, "x", "memory", "advice"), ""); // unknown: no check
  EXPECT_EQ(cvt::CheckMemory(9.5e9, 10e9, "an image", "memory", "use less"),
    "an image needs about 9.5 GB of memory; 10 GB are available: use less");
  EXPECT_GT(cvt::AvailableSystemMemory(), 1e6);
}

#ifdef __linux__
/// The /proc/self/smaps entry of the mapping that holds `address`: its VmFlags line, and its
/// AnonHugePages in kB; false when there is none.
bool MappingOf(const void* address, std::string& flags, long& hugeKilobytes)
{
  std::ifstream smaps("/proc/self/smaps");
  const auto at = reinterpret_cast<std::uintptr_t>(address);
  bool inside = false;
  for (std::string line; std::getline(smaps, line);)
  {
    unsigned long long start = 0, end = 0;
    char dash = 0;
    std::istringstream header(line);
    if (line.find(':') > line.find(' ') && header >> std::hex >> start >> dash >> end &&
      dash == '-')
    {
      if (inside)
      {
        return true; // the next mapping
      }
      inside = start <= at && at < end;
      continue;
    }
    if (inside && line.rfind("VmFlags:", 0) == 0)
    {
      flags = line;
    }
    if (inside && line.rfind("AnonHugePages:", 0) == 0)
    {
      hugeKilobytes = std::stol(line.substr(14));
    }
  }
  return inside;
}
#endif

TEST(Memory, ZeroedPagesAreZeroedAndFaultOncePerHugePage)
{
  constexpr size_t bytes = size_t(8) << 20; // 2048 pages of 4 KiB, 4 huge pages
  const cvt::ZeroedPages pages(bytes);
  unsigned char* data = static_cast<unsigned char*>(pages.Data());
  ASSERT_NE(data, nullptr);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(data) % 16, 0u);
#ifdef __linux__
  std::ifstream setting("/sys/kernel/mm/transparent_hugepage/enabled");
  std::string modes;
  std::getline(setting, modes);
  rusage before{}, after{};
  getrusage(RUSAGE_SELF, &before);
#endif
  // One byte per 4 KiB page, each read and then written, as the answer table's slots are.
  size_t nonZero = 0;
  for (size_t at = 0; at < bytes; at += 4096)
  {
    nonZero += data[at] != 0;
    data[at] = 1;
  }
  EXPECT_EQ(nonZero, 0u);
#ifdef __linux__
  getrusage(RUSAGE_SELF, &after);
  if (modes.empty() || modes.find("[never]") != std::string::npos)
  {
    GTEST_SKIP() << "this system has no transparent huge pages";
  }
  // The mapping asks for huge pages (madvise: "hg")...
  std::string flags;
  long hugeKilobytes = 0;
  ASSERT_TRUE(MappingOf(data, flags, hugeKilobytes));
  EXPECT_NE(flags.find(" hg"), std::string::npos) << flags;
  // ...and where the system had them to give (not under memory pressure, nor with huge pages
  // turned off for the process), a few faults fill it. On 4 KiB pages each page faults once or
  // twice (a read may map the shared zero page first): 2048 to 4096; under AddressSanitizer
  // its shadow's pages fault too, 256 of them.
  if (hugeKilobytes == 0)
  {
    GTEST_SKIP() << "the system gave no huge pages now";
  }
  EXPECT_LT(after.ru_minflt - before.ru_minflt, 512) << "huge pages: " << modes;
#endif
}
