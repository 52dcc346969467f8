#include "cvtMemory.h"
#include "cvtSampling.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

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
