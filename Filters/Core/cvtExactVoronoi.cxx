#include "cvtExactVoronoi.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace cvt
{

PolygonIntegrals IntegratePolygon(const Polygon& polygon, double cx, double cy)
{
  PolygonIntegrals r;
  const size_t n = polygon.Size();
  double ixx = 0.0, iyy = 0.0;
  for (size_t k = 0; k < n; ++k)
  {
    const double x0 = polygon.X[k] - cx, y0 = polygon.Y[k] - cy;
    const double x1 = polygon.X[(k + 1) % n] - cx, y1 = polygon.Y[(k + 1) % n] - cy;
    const double cross = x0 * y1 - x1 * y0;
    r.Area += cross;
    r.MomentX += (x0 + x1) * cross;
    r.MomentY += (y0 + y1) * cross;
    ixx += (x0 * x0 + x0 * x1 + x1 * x1) * cross;
    iyy += (y0 * y0 + y0 * y1 + y1 * y1) * cross;
  }
  r.Area /= 2.0;
  r.MomentX /= 6.0;
  r.MomentY /= 6.0;
  r.SecondMoment = (ixx + iyy) / 12.0;
  return r;
}

Polygon ClipPolygon(const Polygon& polygon, double a, double b, double c)
{
  Polygon out;
  const size_t n = polygon.Size();
  for (size_t k = 0; k < n; ++k)
  {
    const double x0 = polygon.X[k], y0 = polygon.Y[k];
    const double x1 = polygon.X[(k + 1) % n], y1 = polygon.Y[(k + 1) % n];
    const double d0 = a * x0 + b * y0 - c, d1 = a * x1 + b * y1 - c;
    if (d0 <= 0.0)
    {
      out.X.push_back(x0);
      out.Y.push_back(y0);
    }
    if ((d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0))
    {
      const double t = d0 / (d0 - d1);
      out.X.push_back(x0 + t * (x1 - x0));
      out.Y.push_back(y0 + t * (y1 - y0));
    }
  }
  return out;
}

namespace
{
Polygon Rectangle(double x0, double x1, double y0, double y1)
{
  Polygon p;
  p.X = { x0, x1, x1, x0 };
  p.Y = { y0, y0, y1, y1 };
  return p;
}

double SquaredRadius(const Polygon& cell, double sx, double sy)
{
  double radius2 = 0.0;
  for (size_t k = 0; k < cell.Size(); ++k)
  {
    const double vx = cell.X[k] - sx, vy = cell.Y[k] - sy;
    radius2 = std::max(radius2, vx * vx + vy * vy);
  }
  return radius2;
}

/// Sites binned on a uniform grid of buckets over the domain, about two per bucket, so that
/// a cell is clipped only by the sites of the bucket rings that can reach it.
class Buckets
{
public:
  Buckets(const Grid& grid, const std::vector<double>& sites)
    : Grid_(grid)
  {
    const size_t n = sites.size() / 2;
    this->Count = std::max(1, static_cast<int>(std::ceil(std::sqrt(n / 2.0))));
    this->Width = (grid.XMax() - grid.XMin()) / this->Count;
    this->Height = (grid.YMax() - grid.YMin()) / this->Count;
    this->Bins.resize(static_cast<size_t>(this->Count) * this->Count);
    for (size_t i = 0; i < n; ++i)
    {
      this->Bins[this->Index(this->Column(sites[2 * i]), this->Row(sites[2 * i + 1]))].push_back(i);
    }
  }
  int Column(double x) const
  {
    return std::clamp(static_cast<int>((x - this->Grid_.XMin()) / this->Width), 0, this->Count - 1);
  }
  int Row(double y) const
  {
    return std::clamp(
      static_cast<int>((y - this->Grid_.YMin()) / this->Height), 0, this->Count - 1);
  }
  size_t Index(int column, int row) const
  {
    return static_cast<size_t>(row) * this->Count + column;
  }

  /// Sites in the buckets at Chebyshev distance `ring` from (column, row).
  void Ring(int column, int row, int ring, std::vector<size_t>& out) const
  {
    out.clear();
    for (int r = row - ring; r <= row + ring; ++r)
    {
      for (int c = column - ring; c <= column + ring; ++c)
      {
        const bool onRing = std::abs(r - row) == ring || std::abs(c - column) == ring;
        if (onRing && r >= 0 && c >= 0 && r < this->Count && c < this->Count)
        {
          const auto& bin = this->Bins[this->Index(c, r)];
          out.insert(out.end(), bin.begin(), bin.end());
        }
      }
    }
  }

  const Grid& Grid_;
  int Count = 1;
  double Width = 1.0, Height = 1.0;
  std::vector<std::vector<size_t>> Bins;
};
}

std::vector<Polygon> ClippedVoronoiCells(const Grid& grid, const std::vector<double>& sites)
{
  const size_t n = sites.size() / 2;
  const Polygon domain = Rectangle(grid.XMin(), grid.XMax(), grid.YMin(), grid.YMax());
  const Buckets buckets(grid, sites);
  const double bucketSide = std::min(buckets.Width, buckets.Height);
  std::vector<Polygon> cells(n);
  std::vector<size_t> ring;
  for (size_t i = 0; i < n; ++i)
  {
    const double sx = sites[2 * i], sy = sites[2 * i + 1];
    const int column = buckets.Column(sx), row = buckets.Row(sy);
    Polygon cell = domain;
    for (int r = 0; r < buckets.Count && cell.Size() > 0; ++r)
    {
      // Sites in ring r are at least (r - 1) bucket sides away; their bisectors miss the cell
      // once that is more than twice the cell's radius.
      const double nearest = std::max(0, r - 1) * bucketSide;
      if (nearest * nearest > 4.0 * SquaredRadius(cell, sx, sy))
      {
        break;
      }
      buckets.Ring(column, row, r, ring);
      for (size_t j : ring)
      {
        if (j == i)
        {
          continue;
        }
        const double dx = sites[2 * j] - sx, dy = sites[2 * j + 1] - sy;
        // Keep x with (x - s_i) . d <= |d|^2 / 2.
        cell = ClipPolygon(cell, dx, dy, dx * sx + dy * sy + 0.5 * (dx * dx + dy * dy));
        if (cell.Size() == 0)
        {
          break;
        }
      }
    }
    cells[i] = std::move(cell);
  }
  return cells;
}

CellSums ExactCellSums(
  const Grid& grid, const std::vector<double>& sites, const std::vector<float>& density)
{
  const size_t n = sites.size() / 2;
  const std::vector<Polygon> cells = ClippedVoronoiCells(grid, sites);
  CellSums sums;
  sums.Resize(n);
  for (size_t i = 0; i < n; ++i)
  {
    const double sx = sites[2 * i], sy = sites[2 * i + 1];
    const Polygon& cell = cells[i];
    if (cell.Size() < 3)
    {
      continue;
    }
    if (density.empty())
    {
      const PolygonIntegrals r = IntegratePolygon(cell, sx, sy);
      sums.Mass[i] = r.Area;
      sums.MomentX[i] = r.MomentX;
      sums.MomentY[i] = r.MomentY;
      sums.Energy[i] = r.SecondMoment;
      continue;
    }
    // Pixelwise constant density: integrate the cell piece inside every pixel it overlaps.
    double xmin = cell.X[0], xmax = cell.X[0], ymin = cell.Y[0], ymax = cell.Y[0];
    for (size_t k = 1; k < cell.Size(); ++k)
    {
      xmin = std::min(xmin, cell.X[k]);
      xmax = std::max(xmax, cell.X[k]);
      ymin = std::min(ymin, cell.Y[k]);
      ymax = std::max(ymax, cell.Y[k]);
    }
    const auto column = [&grid](double x)
    {
      return std::clamp(
        static_cast<int>(std::floor((x - grid.Origin[0]) / grid.Spacing[0])), 0, grid.Width - 1);
    };
    const auto row = [&grid](double y)
    {
      return std::clamp(
        static_cast<int>(std::floor((y - grid.Origin[1]) / grid.Spacing[1])), 0, grid.Height - 1);
    };
    for (int py = row(ymin); py <= row(ymax); ++py)
    {
      const double y0 = grid.Origin[1] + py * grid.Spacing[1], y1 = y0 + grid.Spacing[1];
      Polygon band = ClipPolygon(ClipPolygon(cell, 0.0, 1.0, y1), 0.0, -1.0, -y0);
      for (int px = column(xmin); px <= column(xmax) && band.Size() >= 3; ++px)
      {
        const double rho = density[static_cast<size_t>(py) * grid.Width + px];
        if (rho == 0.0)
        {
          continue;
        }
        const double x0 = grid.Origin[0] + px * grid.Spacing[0], x1 = x0 + grid.Spacing[0];
        const Polygon piece = ClipPolygon(ClipPolygon(band, 1.0, 0.0, x1), -1.0, 0.0, -x0);
        if (piece.Size() < 3)
        {
          continue;
        }
        const PolygonIntegrals r = IntegratePolygon(piece, sx, sy);
        sums.Mass[i] += rho * r.Area;
        sums.MomentX[i] += rho * r.MomentX;
        sums.MomentY[i] += rho * r.MomentY;
        sums.Energy[i] += rho * r.SecondMoment;
      }
    }
  }
  return sums;
}

std::vector<int> BruteForceLabels(const Grid& grid, const std::vector<double>& sites)
{
  const size_t n = sites.size() / 2;
  std::vector<int> labels(static_cast<size_t>(grid.NumberOfPixels()), -1);
  for (int j = 0; j < grid.Height; ++j)
  {
    const double y = grid.Origin[1] + (j + 0.5) * grid.Spacing[1];
    for (int i = 0; i < grid.Width; ++i)
    {
      const double x = grid.Origin[0] + (i + 0.5) * grid.Spacing[0];
      double best = std::numeric_limits<double>::infinity();
      int bestSite = -1;
      for (size_t s = 0; s < n; ++s)
      {
        const double dx = sites[2 * s] - x, dy = sites[2 * s + 1] - y;
        const double d2 = dx * dx + dy * dy;
        if (d2 < best)
        {
          best = d2;
          bestSite = static_cast<int>(s);
        }
      }
      labels[static_cast<size_t>(j) * grid.Width + i] = bestSite;
    }
  }
  return labels;
}

} // namespace cvt
