// Initial sites and checks of user-given sites.
#ifndef cvtSampling_h
#define cvtSampling_h

#include "cvtCoreModule.h" // for export macro
#include "cvtEngine.h"

#include <cstdint>
#include <string>
#include <vector>

namespace cvt
{

/// Draws `count` sites with probability proportional to the pixelwise density (uniform inside
/// the chosen pixel). Deterministic for a given seed. An empty density means uniform.
CVTCORE_EXPORT std::vector<double> SampleSites(
  const Grid& grid, const std::vector<float>& density, int count, std::uint64_t seed);

/// Checks a density image: one finite, non-negative value per pixel, not all zero.
/// Returns an empty string when it is fine, else what is wrong.
CVTCORE_EXPORT std::string CheckDensity(const Grid& grid, const std::vector<float>& density);

/// Checks sites (flat x, y): finite, inside the domain, no two equal, no more than pixels.
/// Returns an empty string when they are fine, else what is wrong.
CVTCORE_EXPORT std::string CheckSites(const Grid& grid, const std::vector<double>& sites);

} // namespace cvt

#endif
