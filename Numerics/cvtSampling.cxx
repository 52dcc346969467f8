#include "cvtSampling.h"

#include <algorithm>
#include <cmath>
#include <random>
#include <set>
#include <sstream>
#include <utility>

namespace cvt
{

std::vector<double> SampleSites(
  const Grid& grid, const std::vector<float>& density, int count, std::uint64_t seed)
{
  std::mt19937_64 rng(seed);
  const long long pixels = grid.NumberOfPixels();
  std::vector<double> cumulative;
  if (!density.empty())
  {
    cumulative.resize(static_cast<size_t>(pixels));
    double total = 0.0;
    for (long long p = 0; p < pixels; ++p)
    {
      total += density[p];
      cumulative[p] = total;
    }
  }
  std::vector<double> sites;
  sites.reserve(2 * static_cast<size_t>(std::max(count, 0)));
  for (int s = 0; s < count; ++s)
  {
    long long pixel;
    if (cumulative.empty())
    {
      pixel = std::min(pixels - 1, static_cast<long long>(Uniform01(rng) * pixels));
    }
    else
    {
      const double target = Uniform01(rng) * cumulative.back();
      pixel = std::upper_bound(cumulative.begin(), cumulative.end(), target) - cumulative.begin();
      pixel = std::min(pixel, pixels - 1);
    }
    const double i = static_cast<double>(pixel % grid.Width) + Uniform01(rng);
    const double j = static_cast<double>(pixel / grid.Width) + Uniform01(rng);
    sites.push_back(grid.Origin[0] + i * grid.Spacing[0]);
    sites.push_back(grid.Origin[1] + j * grid.Spacing[1]);
  }
  return sites;
}

std::string CheckDensity(const Grid& grid, const std::vector<float>& density)
{
  if (static_cast<long long>(density.size()) != grid.NumberOfPixels())
  {
    return "the density has a different number of values than the image has pixels";
  }
  bool anyPositive = false;
  for (size_t p = 0; p < density.size(); ++p)
  {
    const float v = density[p];
    if (!std::isfinite(v))
    {
      std::ostringstream msg;
      msg << "the density is not finite (NaN or infinite) at pixel " << p
          << "; give a density with finite values";
      return msg.str();
    }
    if (v < 0.0f)
    {
      std::ostringstream msg;
      msg << "the density is negative (" << v << ") at pixel " << p << "; densities must be >= 0";
      return msg.str();
    }
    anyPositive = anyPositive || v > 0.0f;
  }
  if (!anyPositive)
  {
    return "the density is zero everywhere; give at least one pixel a positive density";
  }
  return std::string();
}

std::string CheckSites(const Grid& grid, const std::vector<double>& sites)
{
  const size_t n = sites.size() / 2;
  if (n == 0)
  {
    return "there are no sites; ask for at least one";
  }
  if (static_cast<long long>(n) > grid.NumberOfPixels())
  {
    std::ostringstream msg;
    msg << n << " sites are more than the " << grid.NumberOfPixels()
        << " pixels of the domain; use fewer sites or a finer image";
    return msg.str();
  }
  std::set<std::pair<double, double>> seen;
  for (size_t i = 0; i < n; ++i)
  {
    const double x = sites[2 * i], y = sites[2 * i + 1];
    if (!std::isfinite(x) || !std::isfinite(y))
    {
      std::ostringstream msg;
      msg << "site " << i << " has a coordinate that is not finite";
      return msg.str();
    }
    if (!grid.Contains(x, y))
    {
      std::ostringstream msg;
      msg << "site " << i << " (" << x << ", " << y << ") lies outside the domain [" << grid.XMin()
          << ", " << grid.XMax() << "] x [" << grid.YMin() << ", " << grid.YMax()
          << "]; move it inside";
      return msg.str();
    }
    if (!seen.insert({ x, y }).second)
    {
      std::ostringstream msg;
      msg << "site " << i << " (" << x << ", " << y
          << ") duplicates an earlier site; remove duplicated sites";
      return msg.str();
    }
  }
  return std::string();
}

} // namespace cvt
