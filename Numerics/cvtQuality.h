// Quality measures of a site set (Rong et al., Table 6), from the exact clipped Voronoi cells.
#ifndef cvtQuality_h
#define cvtQuality_h

#include "cvtEngine.h"
#include "cvtNumericsModule.h" // for export macro

#include <array>
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

CVTNUMERICS_EXPORT QualityMeasures MeasureQuality(
  const Grid& grid, const std::vector<double>& sites);

/// Quality of a triangle mesh (a remesh): vertex valences and triangle angles.
struct MeshQuality
{
  std::vector<int> ValenceHistogram; // [v] = number of vertices with v edges
  std::vector<int> AngleHistogram;   // 18 bins of 10 degrees
  double MinimumAngle = 0.0;         // degrees
  double MaximumAngle = 0.0;
  double Valence6Fraction = 0.0;         // of all vertices
  double InteriorValence6Fraction = 0.0; // of the vertices in triangles and off the border
};

/// `points` flat (x, y, z, ...); triangles index them.
CVTNUMERICS_EXPORT MeshQuality MeasureMesh(
  const std::vector<double>& points, const std::vector<std::array<int, 3>>& triangles);

} // namespace cvt

#endif
