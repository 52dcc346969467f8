#include "cvtExactVoronoi.h"

#include "cvtPointCloud.h"

#include "cvtThreads.h"

#include <cstdint>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

namespace cvt
{

PolygonIntegrals IntegratePolygon(const Polygon& polygon, double cx, double cy)
{
  return IntegrateVertices(polygon.X.data(), polygon.Y.data(), polygon.Size(), cx, cy);
}

PolygonIntegrals IntegrateVertices(const double* x, const double* y, size_t n, double cx, double cy)
{
  PolygonIntegrals r;
  double ixx = 0.0, iyy = 0.0;
  for (size_t k = 0; k < n; ++k)
  {
    const double x0 = x[k] - cx, y0 = y[k] - cy;
    const double x1 = x[(k + 1) % n] - cx, y1 = y[(k + 1) % n] - cy;
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

void ClipPolygon(const Polygon& polygon, double a, double b, double c, Polygon& out)
{
  out.X.clear(); // keeps the capacity: a caller clipping in a loop allocates once
  out.Y.clear();
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
}

Polygon ClipPolygon(const Polygon& polygon, double a, double b, double c)
{
  Polygon out;
  out.X.reserve(polygon.Size() + 1); // a convex polygon gains at most one vertex
  out.Y.reserve(polygon.Size() + 1);
  ClipPolygon(polygon, a, b, c, out);
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

/// True when some vertex of the polygon has a x + b y > c (a clip would change it).
bool Outside(const Polygon& polygon, double a, double b, double c)
{
  for (size_t k = 0; k < polygon.Size(); ++k)
  {
    if (a * polygon.X[k] + b * polygon.Y[k] - c > 0.0)
    {
      return true;
    }
  }
  return false;
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
    // The sites sorted by bucket (a counting sort): two arrays, not one per bucket.
    this->Start.assign(static_cast<size_t>(this->Count) * this->Count + 1, 0);
    for (size_t i = 0; i < n; ++i)
    {
      ++this->Start[this->Index(this->Column(sites[2 * i]), this->Row(sites[2 * i + 1])) + 1];
    }
    for (size_t b = 1; b < this->Start.size(); ++b)
    {
      this->Start[b] += this->Start[b - 1];
    }
    this->Ids.resize(n);
    std::vector<size_t> next(this->Start.begin(), this->Start.end() - 1);
    for (size_t i = 0; i < n; ++i)
    {
      this->Ids[next[this->Index(this->Column(sites[2 * i]), this->Row(sites[2 * i + 1]))]++] = i;
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
          const size_t b = this->Index(c, r);
          out.insert(
            out.end(), this->Ids.begin() + this->Start[b], this->Ids.begin() + this->Start[b + 1]);
        }
      }
    }
  }

  const Grid& Grid_;
  int Count = 1;
  double Width = 1.0, Height = 1.0;
  std::vector<size_t> Start; // bucket b holds Ids[Start[b]] .. Ids[Start[b + 1] - 1]
  std::vector<size_t> Ids;
};

/// Clips the Voronoi cell of each site first..last-1 to the grid's domain, in parallel, and
/// hands it to `use(i, cell)`; the polygon is scratch, reused for the thread's next cell.
template<typename Use>
void ForEachClippedCell(
  const Grid& grid, const std::vector<double>& sites, size_t first, size_t last, Use&& use)
{
  const Polygon domain = Rectangle(grid.XMin(), grid.XMax(), grid.YMin(), grid.YMax());
  const Buckets buckets(grid, sites);
  const double bucketSide = std::min(buckets.Width, buckets.Height);
  cvt::For(static_cast<vtkIdType>(first), static_cast<vtkIdType>(std::max(first, last)), 64,
    [&](vtkIdType begin, vtkIdType end)
    {
      std::vector<size_t> ring;
      Polygon cell, clipped;
      for (vtkIdType i = begin; i < end; ++i)
      {
        const double sx = sites[2 * i], sy = sites[2 * i + 1];
        const int column = buckets.Column(sx), row = buckets.Row(sy);
        cell.X.assign(domain.X.begin(), domain.X.end());
        cell.Y.assign(domain.Y.begin(), domain.Y.end());
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
            if (j == static_cast<size_t>(i))
            {
              continue;
            }
            const double dx = sites[2 * j] - sx, dy = sites[2 * j + 1] - sy;
            // Keep x with (x - s_i) . d <= |d|^2 / 2; most bisectors of a ring miss the cell.
            const double c = dx * sx + dy * sy + 0.5 * (dx * dx + dy * dy);
            if (!Outside(cell, dx, dy, c))
            {
              continue;
            }
            ClipPolygon(cell, dx, dy, c, clipped);
            std::swap(cell, clipped);
            if (cell.Size() == 0)
            {
              break;
            }
          }
        }
        use(static_cast<size_t>(i), cell);
      }
    });
}
}

std::vector<Polygon> ClippedVoronoiCells(
  const Grid& grid, const std::vector<double>& sites, size_t first, size_t last)
{
  const size_t n = sites.size() / 2;
  std::vector<Polygon> cells(n);
  ForEachClippedCell(grid, sites, first, std::min(last, n),
    [&cells](size_t i, const Polygon& cell) { cells[i] = cell; });
  return cells;
}

DensityTables::DensityTables(const Grid& grid, const std::vector<float>& density)
{
  if (density.empty())
  {
    return;
  }
  const size_t stride = static_cast<size_t>(grid.Width) + 1;
  this->Stride = stride;
  for (auto* table : { &this->Rho, &this->RhoX, &this->RhoY, &this->RhoR2 })
  {
    table->assign(stride * grid.Height, 0.0);
  }
  for (int j = 0; j < grid.Height; ++j)
  {
    const double cy = (j + 0.5) * grid.Spacing[1];
    for (int i = 0; i < grid.Width; ++i)
    {
      const double rho = density[static_cast<size_t>(j) * grid.Width + i];
      const double cx = (i + 0.5) * grid.Spacing[0];
      const size_t k = j * stride + i;
      this->Rho[k + 1] = this->Rho[k] + rho;
      this->RhoX[k + 1] = this->RhoX[k] + rho * cx;
      this->RhoY[k + 1] = this->RhoY[k] + rho * cy;
      this->RhoR2[k + 1] = this->RhoR2[k] + rho * (cx * cx + cy * cy);
    }
  }
}

namespace
{
constexpr size_t SmallPolygonSize = 256;

/// Keeps the part of the polygon left of x = at (keepLeft) or right of it, into fixed buffers.
size_t ClipVertical(
  const double* x, const double* y, size_t n, double at, bool keepLeft, double* ox, double* oy)
{
  size_t out = 0;
  for (size_t k = 0; k < n && out + 2 <= SmallPolygonSize; ++k)
  {
    const size_t next = (k + 1) % n;
    const double d0 = keepLeft ? x[k] - at : at - x[k];
    const double d1 = keepLeft ? x[next] - at : at - x[next];
    if (d0 <= 0.0)
    {
      ox[out] = x[k];
      oy[out++] = y[k];
    }
    if ((d0 < 0.0 && d1 > 0.0) || (d0 > 0.0 && d1 < 0.0))
    {
      const double t = d0 / (d0 - d1);
      ox[out] = x[k] + t * (x[next] - x[k]);
      oy[out++] = y[k] + t * (y[next] - y[k]);
    }
  }
  return out;
}

/// The x extent of the convex polygon on the line at height y (which must meet it).
void SpanAt(const Polygon& polygon, double y, double& left, double& right)
{
  left = std::numeric_limits<double>::infinity();
  right = -left;
  const size_t n = polygon.Size();
  for (size_t k = 0; k < n; ++k)
  {
    const double xa = polygon.X[k], ya = polygon.Y[k];
    const double xb = polygon.X[(k + 1) % n], yb = polygon.Y[(k + 1) % n];
    if ((ya <= y && y <= yb) || (yb <= y && y <= ya))
    {
      const double x = ya == yb ? xa : xa + (y - ya) / (yb - ya) * (xb - xa);
      left = std::min({ left, x, ya == yb ? xb : x });
      right = std::max({ right, x, ya == yb ? xb : x });
    }
  }
}

/// The integrals of one cell with a pixelwise-constant density: pixels wholly inside the cell
/// come from the row prefix sums (a contiguous run per row, the cell being convex), the
/// pixels on its border are clipped exactly.
void DensityCellSums(const Grid& grid, const std::vector<float>& density,
  const DensityTables& tables, const Polygon& cell, double sx, double sy, double sums[4])
{
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
  const double area = grid.PixelArea();
  const double pixelInertia =
    (grid.Spacing[0] * grid.Spacing[0] + grid.Spacing[1] * grid.Spacing[1]) / 12.0;
  // The site relative to the grid's origin, as the tables' pixel centres are.
  const double rx = sx - grid.Origin[0], ry = sy - grid.Origin[1];
  const auto partial = [&](
                         const double* bandX, const double* bandY, size_t bandSize, int px, int py)
  {
    const double rho = density[static_cast<size_t>(py) * grid.Width + px];
    if (rho == 0.0)
    {
      return;
    }
    // The band's piece in this pixel's column, clipped in fixed buffers (no allocation: these
    // pieces are most of the work when cells are a few pixels wide).
    const double x0 = grid.Origin[0] + px * grid.Spacing[0], x1 = x0 + grid.Spacing[0];
    double ax[SmallPolygonSize], ay[SmallPolygonSize], bx[SmallPolygonSize], by[SmallPolygonSize];
    size_t n = ClipVertical(bandX, bandY, bandSize, x1, true, ax, ay);
    n = ClipVertical(ax, ay, n, x0, false, bx, by);
    if (n < 3)
    {
      return;
    }
    const PolygonIntegrals r = IntegrateVertices(bx, by, n, sx, sy);
    sums[0] += rho * r.Area;
    sums[1] += rho * r.MomentX;
    sums[2] += rho * r.MomentY;
    sums[3] += rho * r.SecondMoment;
  };
  double clippedX[SmallPolygonSize], clippedY[SmallPolygonSize];
  double bandX[SmallPolygonSize], bandY[SmallPolygonSize];
  for (int py = row(ymin); py <= row(ymax); ++py)
  {
    const double y0 = grid.Origin[1] + py * grid.Spacing[1], y1 = y0 + grid.Spacing[1];
    // The cell within the row's strip y0 <= y <= y1 (ClipVertical with the axes swapped).
    size_t n =
      ClipVertical(cell.Y.data(), cell.X.data(), cell.Size(), y1, true, clippedY, clippedX);
    n = ClipVertical(clippedY, clippedX, n, y0, false, bandY, bandX);
    if (n < 3)
    {
      continue;
    }
    double bandMin = bandX[0], bandMax = bandX[0];
    for (size_t k = 1; k < n; ++k)
    {
      bandMin = std::min(bandMin, bandX[k]);
      bandMax = std::max(bandMax, bandX[k]);
    }
    const int left = column(bandMin), right = column(bandMax);
    // Whole pixels: the cell is convex, so its left border is furthest right, and its right
    // border furthest left, at the strip's top or bottom.
    int first = right + 1, last = right;
    if (y0 >= ymin && y1 <= ymax)
    {
      double l0, r0, l1, r1;
      SpanAt(cell, y0, l0, r0);
      SpanAt(cell, y1, l1, r1);
      const double from = (std::max(l0, l1) - grid.Origin[0]) / grid.Spacing[0];
      const double to = (std::min(r0, r1) - grid.Origin[0]) / grid.Spacing[0];
      first = std::max(left, static_cast<int>(std::ceil(from)));
      last = std::min(right, static_cast<int>(std::floor(to)) - 1);
    }
    if (first > last)
    {
      for (int px = left; px <= right; ++px)
      {
        partial(bandX, bandY, n, px, py);
      }
      continue;
    }
    for (int px = left; px < first; ++px)
    {
      partial(bandX, bandY, n, px, py);
    }
    for (int px = last + 1; px <= right; ++px)
    {
      partial(bandX, bandY, n, px, py);
    }
    // Pixels first..last are wholly inside: rho A, rho A (c - s), rho A (|c - s|^2 + inertia).
    const size_t k0 = py * tables.Stride + first, k1 = py * tables.Stride + last + 1;
    const double rho = tables.Rho[k1] - tables.Rho[k0];
    const double rhoX = tables.RhoX[k1] - tables.RhoX[k0];
    const double rhoY = tables.RhoY[k1] - tables.RhoY[k0];
    const double rhoR2 = tables.RhoR2[k1] - tables.RhoR2[k0];
    sums[0] += area * rho;
    sums[1] += area * (rhoX - rx * rho);
    sums[2] += area * (rhoY - ry * rho);
    sums[3] += area *
      (rhoR2 - 2.0 * (rx * rhoX + ry * rhoY) + (rx * rx + ry * ry) * rho + pixelInertia * rho);
  }
}
}

CellSums ExactCellSums(
  const Grid& grid, const std::vector<double>& sites, const std::vector<float>& density)
{
  return ExactCellSums(grid, sites, density, DensityTables(grid, density));
}

CellSums ExactCellSums(const Grid& grid, const std::vector<double>& sites,
  const std::vector<float>& density, const DensityTables& tables, size_t first, size_t last)
{
  const size_t n = sites.size() / 2;
  last = std::min(last, n);
  CellSums sums;
  sums.Resize(n);
  // Each cell is integrated as soon as it is clipped: no polygon is kept or copied.
  ForEachClippedCell(grid, sites, first, last,
    [&](size_t i, const Polygon& cell)
    {
      if (cell.Size() < 3)
      {
        return;
      }
      const double sx = sites[2 * i], sy = sites[2 * i + 1];
      double cellSums[4] = { 0.0, 0.0, 0.0, 0.0 };
      if (density.empty())
      {
        const PolygonIntegrals r = IntegratePolygon(cell, sx, sy);
        cellSums[0] = r.Area;
        cellSums[1] = r.MomentX;
        cellSums[2] = r.MomentY;
        cellSums[3] = r.SecondMoment;
      }
      else
      {
        DensityCellSums(grid, density, tables, cell, sx, sy, cellSums);
      }
      sums.Mass[i] = cellSums[0];
      sums.MomentX[i] = cellSums[1];
      sums.MomentY[i] = cellSums[2];
      sums.Energy[i] = cellSums[3];
    });
  return sums;
}

std::vector<int> NearestSiteLabels(const Grid& grid, const std::vector<double>& sites)
{
  std::vector<int> labels(static_cast<size_t>(grid.NumberOfPixels()), -1);
  if (sites.size() < 2)
  {
    return labels;
  }
  PointCloud<2> cloud;
  cloud.Points = &sites;
  const PointTree<2> tree(2, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  cvt::For(0, grid.Height, 8,
    [&](int first, int last)
    {
      for (int j = first; j < last; ++j)
      {
        for (int i = 0; i < grid.Width; ++i)
        {
          const double x[2] = { grid.Origin[0] + (i + 0.5) * grid.Spacing[0],
            grid.Origin[1] + (j + 0.5) * grid.Spacing[1] };
          std::uint32_t id = 0;
          double d2 = 0.0;
          tree.knnSearch(x, 1, &id, &d2);
          labels[static_cast<size_t>(j) * grid.Width + i] = static_cast<int>(id);
        }
      }
    });
  return labels;
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
