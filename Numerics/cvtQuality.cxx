#include "cvtQuality.h"

#include "cvtExactVoronoi.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace cvt
{

namespace
{
double StandardDeviation(const std::vector<double>& values)
{
  if (values.size() < 2)
  {
    return 0.0;
  }
  double mean = 0.0;
  for (double v : values)
  {
    mean += v;
  }
  mean /= values.size();
  double variance = 0.0;
  for (double v : values)
  {
    variance += (v - mean) * (v - mean);
  }
  return std::sqrt(variance / values.size());
}
}

QualityMeasures MeasureQuality(const Grid& grid, const std::vector<double>& sites)
{
  QualityMeasures q;
  const size_t n = sites.size() / 2;
  if (n == 0)
  {
    return q;
  }
  const std::vector<Polygon> cells = ClippedVoronoiCells(grid, sites);
  const double tolerance = 1e-9 * std::max(grid.XMax() - grid.XMin(), grid.YMax() - grid.YMin());
  std::vector<double> radius(n), nearest(n), area(n);
  int hexagons = 0;
  for (size_t i = 0; i < n; ++i)
  {
    const double sx = sites[2 * i], sy = sites[2 * i + 1];
    const Polygon& cell = cells[i];
    bool interior = cell.Size() >= 3;
    double r2 = 0.0;
    for (size_t k = 0; k < cell.Size(); ++k)
    {
      r2 = std::max(r2, std::pow(cell.X[k] - sx, 2) + std::pow(cell.Y[k] - sy, 2));
      interior = interior && cell.X[k] > grid.XMin() + tolerance &&
        cell.X[k] < grid.XMax() - tolerance && cell.Y[k] > grid.YMin() + tolerance &&
        cell.Y[k] < grid.YMax() - tolerance;
    }
    radius[i] = std::sqrt(r2);
    area[i] = IntegratePolygon(cell, sx, sy).Area;
    if (interior)
    {
      ++q.InteriorCells;
      hexagons += cell.Size() == 6 ? 1 : 0;
    }
    // The nearest other site j is a Voronoi neighbour: the midpoint of x_i x_j lies on the
    // cell's boundary (inside the domain), on the bisector edge at distance d_i / 2 from x_i,
    // and every other bisector edge is farther. So d_i = 2 * the distance to the nearest edge
    // that is not part of the domain's boundary.
    double best = std::numeric_limits<double>::infinity();
    for (size_t k = 0; k < cell.Size(); ++k)
    {
      const size_t l = (k + 1) % cell.Size();
      const double ex = cell.X[l] - cell.X[k], ey = cell.Y[l] - cell.Y[k];
      const double length = std::hypot(ex, ey);
      if (length == 0.0)
      {
        continue;
      }
      // Distance from the site to the edge's line.
      const double distance = std::abs((sx - cell.X[k]) * ey - (sy - cell.Y[k]) * ex) / length;
      const bool onBoundary = (std::abs(cell.X[k] - cell.X[l]) < tolerance &&
                                (std::abs(cell.X[k] - grid.XMin()) < tolerance ||
                                  std::abs(cell.X[k] - grid.XMax()) < tolerance)) ||
        (std::abs(cell.Y[k] - cell.Y[l]) < tolerance &&
          (std::abs(cell.Y[k] - grid.YMin()) < tolerance ||
            std::abs(cell.Y[k] - grid.YMax()) < tolerance));
      if (!onBoundary)
      {
        best = std::min(best, 2.0 * distance);
      }
    }
    nearest[i] = best;
  }
  std::vector<double> finiteNearest;
  for (double d : nearest)
  {
    if (std::isfinite(d))
    {
      finiteNearest.push_back(d);
    }
  }
  q.HexagonalFraction = q.InteriorCells > 0 ? static_cast<double>(hexagons) / q.InteriorCells : 0.0;
  q.RadiusStandardDeviation = StandardDeviation(radius);
  q.NearestNeighborStandardDeviation = StandardDeviation(finiteNearest);
  q.AreaStandardDeviation = StandardDeviation(area);
  return q;
}

MeshQuality MeasureMesh(
  const std::vector<double>& points, const std::vector<std::array<int, 3>>& triangles)
{
  MeshQuality q;
  q.AngleHistogram.assign(18, 0);
  q.MinimumAngle = triangles.empty() ? 0.0 : 180.0;
  std::map<std::pair<int, int>, int> edges; // and the triangles using each
  for (const auto& t : triangles)
  {
    for (int e = 0; e < 3; ++e)
    {
      const int a = t[e], b = t[(e + 1) % 3], c = t[(e + 2) % 3];
      ++edges[{ std::min(a, b), std::max(a, b) }];
      double u[3], v[3];
      for (int k = 0; k < 3; ++k)
      {
        u[k] = points[3 * b + k] - points[3 * a + k];
        v[k] = points[3 * c + k] - points[3 * a + k];
      }
      const double nu = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
      const double nv = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
      const double cosine = (u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / std::max(nu * nv, 1e-300);
      const double angle =
        std::acos(std::clamp(cosine, -1.0, 1.0)) * 180.0 / 3.14159265358979323846;
      q.MinimumAngle = std::min(q.MinimumAngle, angle);
      q.MaximumAngle = std::max(q.MaximumAngle, angle);
      ++q.AngleHistogram[std::min(17, static_cast<int>(angle / 10.0))];
    }
  }
  std::vector<int> valence(points.size() / 3, 0);
  std::vector<char> onBorder(valence.size(), 0);
  for (const auto& [edge, uses] : edges)
  {
    ++valence[edge.first];
    ++valence[edge.second];
    if (uses == 1)
    {
      onBorder[edge.first] = onBorder[edge.second] = 1;
    }
  }
  int six = 0, interior = 0, interiorSix = 0;
  for (size_t i = 0; i < valence.size(); ++i)
  {
    const int v = valence[i];
    if (static_cast<int>(q.ValenceHistogram.size()) <= v)
    {
      q.ValenceHistogram.resize(v + 1, 0);
    }
    ++q.ValenceHistogram[v];
    six += v == 6 ? 1 : 0;
    if (v > 0 && !onBorder[i])
    {
      ++interior;
      interiorSix += v == 6 ? 1 : 0;
    }
  }
  q.Valence6Fraction = valence.empty() ? 0.0 : static_cast<double>(six) / valence.size();
  q.InteriorValence6Fraction = interior > 0 ? static_cast<double>(interiorSix) / interior : 0.0;
  return q;
}

} // namespace cvt
