// Initial sites and checks of user-given sites.
#ifndef cvtSampling_h
#define cvtSampling_h

#include "cvtEngine.h"
#include "cvtNumericsModule.h" // for export macro

#include <cstdint>
#include <random>
#include <string>
#include <vector>

namespace cvt
{

/// A uniform draw in [0, 1) from the top 53 bits: std::uniform_real_distribution is
/// implementation-defined, this is not, so a seed gives the same sites with every library.
inline double Uniform01(std::mt19937_64& rng)
{
  return static_cast<double>(rng() >> 11) * (1.0 / 9007199254740992.0);
}

/// Draws `count` sites with probability proportional to the pixelwise density (uniform inside
/// the chosen pixel). Deterministic for a given seed. An empty density means uniform.
CVTNUMERICS_EXPORT std::vector<double> SampleSites(
  const Grid& grid, const std::vector<float>& density, int count, std::uint64_t seed);

/// Checks a density image: one finite, non-negative value per pixel, not all zero.
/// Returns an empty string when it is fine, else what is wrong.
CVTNUMERICS_EXPORT std::string CheckDensity(const Grid& grid, const std::vector<float>& density);

/// Checks sites (flat x, y): finite, inside the domain, no two equal, no more than pixels.
/// Returns an empty string when they are fine, else what is wrong.
CVTNUMERICS_EXPORT std::string CheckSites(const Grid& grid, const std::vector<double>& sites);

} // namespace cvt

#endif
