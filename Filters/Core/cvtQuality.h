// Quality measures of a site set (Rong et al., Table 6), from the exact clipped Voronoi cells.
#ifndef cvtQuality_h
#define cvtQuality_h

#include "cvtCoreModule.h" // for export macro
#include "cvtEngine.h"

#include <vector>

namespace cvt
{

struct QualityMeasures
{
  /// Fraction of interior cells (not touching the domain boundary) that are hexagons.
  double HexagonalFraction = 0.0;
  int InteriorCells = 0;
  /// Standard deviations of the cell radius r_i = max |x - x_i| over the cell, of the distance
  /// d_i to the nearest other site and of the cell area a_i.
  double RadiusStandardDeviation = 0.0;
  double NearestNeighborStandardDeviation = 0.0;
  double AreaStandardDeviation = 0.0;
};

CVTCORE_EXPORT QualityMeasures MeasureQuality(const Grid& grid, const std::vector<double>& sites);

} // namespace cvt

#endif
