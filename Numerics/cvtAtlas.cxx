#include "cvtAtlas.h"

#include "cvtEdgeTable.h"

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <queue>
#include <sstream>
#include <unordered_map>

namespace cvt
{

namespace
{
using Eigen::Vector2d;
using Eigen::Vector3d;

constexpr int Free = -2; // a triangle waiting for a chart

Vector3d PointOf(const SurfaceMesh& mesh, int v)
{
  return Vector3d::Map(mesh.Point(v));
}

/// Triangle abc in its own plane: a at the origin, b on the x axis, c above it.
std::array<Vector2d, 3> InPlane(const Vector3d& a, const Vector3d& b, const Vector3d& c)
{
  const Vector3d x = (b - a).normalized();
  const Vector3d y = (b - a).cross(c - a).normalized().cross(x);
  return { Vector2d(0, 0), Vector2d((b - a).dot(x), 0), Vector2d((c - a).dot(x), (c - a).dot(y)) };
}

double Cross2(const Vector2d& a, const Vector2d& b)
{
  return a.x() * b.y() - a.y() * b.x();
}

/// Per triangle: unit normal, area, centroid, and the triangle across each edge (points e and
/// e + 1), -1 on a border or a non-manifold edge.
struct Faces
{
  std::vector<Vector3d> Normal;
  std::vector<double> Area;
  std::vector<Vector3d> Centroid;
  std::vector<std::array<int, 3>> Across;

  explicit Faces(const SurfaceMesh& mesh)
  {
    const int count = mesh.NumberOfTriangles();
    this->Normal.resize(count);
    this->Area.resize(count);
    this->Centroid.resize(count);
    this->Across.assign(count, { -1, -1, -1 });
    for (int t = 0; t < count; ++t)
    {
      const auto& tri = mesh.Triangles[t];
      const Vector3d a = PointOf(mesh, tri[0]), b = PointOf(mesh, tri[1]),
                     c = PointOf(mesh, tri[2]);
      const Vector3d n = (b - a).cross(c - a);
      this->Area[t] = 0.5 * n.norm();
      this->Normal[t] = n.norm() > 0.0 ? Vector3d(n.normalized()) : Vector3d(0, 0, 0);
      this->Centroid[t] = (a + b + c) / 3.0;
    }
    const EdgeTable edges(mesh.Triangles);
    for (int t = 0; t < count; ++t)
    {
      for (int e = 0; e < 3; ++e)
      {
        const EdgeTable::Range uses = edges.At(t, e);
        if (uses.size() == 2)
        {
          this->Across[t][e] =
            uses.First->Triangle == t ? (uses.First + 1)->Triangle : uses.First->Triangle;
        }
      }
    }
  }
};

/// One chart: its triangles, the mesh points they use (each once: a chart is a disk) and their
/// plane coordinates, and where the chart lies in the image.
struct Chart
{
  std::vector<int> Triangles;
  double Cone = 0.0; // the largest normal angle it was grown with, in degrees
  std::vector<int> Points;
  std::vector<std::array<int, 3>> Corners; // per triangle: indices into Points
  std::vector<Vector2d> UV;                // per point, in surface units
  bool Mapped = false;                     // UV holds a flip-free map, normalised
  Vector2d Lo{ 0, 0 }, Hi{ 0, 0 };         // the box round UV
  int X = 0, Y = 0;                        // the box's pixel origin in the image

  Vector2d Pixel(int k, double scale, int margin) const
  {
    return (this->UV[k] - this->Lo) * scale + Vector2d(this->X + margin, this->Y + margin);
  }
};

/// Grows disk-shaped charts over the free triangles of `pool`: from each free triangle in
/// turn, triangles are added nearest first (by centroid) while their normal lies within `cone`
/// degrees of the seed's and the chart stays a disk: a triangle joins along one edge only if
/// its third point is new to the chart, or along two edges.
void GrowCharts(const SurfaceMesh& mesh, const Faces& faces, const std::vector<int>& pool,
  double cone, std::vector<int>& chartOf, std::vector<int>& pointStamp, std::vector<Chart>& charts)
{
  const double minimumDot = std::cos(cone * 3.14159265358979323846 / 180.0);
  for (int seed : pool)
  {
    if (chartOf[seed] != Free)
    {
      continue;
    }
    const int id = static_cast<int>(charts.size());
    Chart chart;
    chart.Cone = cone;
    using Entry = std::pair<double, int>;
    std::priority_queue<Entry, std::vector<Entry>, std::greater<Entry>> front;
    front.push({ 0.0, seed });
    while (!front.empty())
    {
      const int t = front.top().second;
      front.pop();
      if (chartOf[t] != Free)
      {
        continue;
      }
      const auto& tri = mesh.Triangles[t];
      if (t != seed)
      {
        if (faces.Normal[t].dot(faces.Normal[seed]) < minimumDot)
        {
          continue;
        }
        int shared = 0, sharedEdge = -1;
        for (int e = 0; e < 3; ++e)
        {
          const int n = faces.Across[t][e];
          if (n >= 0 && chartOf[n] == id)
          {
            ++shared;
            sharedEdge = e;
          }
        }
        // Joining along one edge with the third point already in the chart would pinch it.
        if (shared == 0 || (shared == 1 && pointStamp[tri[(sharedEdge + 2) % 3]] == id))
        {
          continue;
        }
      }
      chartOf[t] = id;
      chart.Triangles.push_back(t);
      for (int v : tri)
      {
        pointStamp[v] = id;
      }
      for (int e = 0; e < 3; ++e)
      {
        const int n = faces.Across[t][e];
        if (n >= 0 && chartOf[n] == Free)
        {
          front.push({ (faces.Centroid[n] - faces.Centroid[seed]).squaredNorm(), n });
        }
      }
    }
    charts.push_back(std::move(chart));
  }
}

/// The chart's points, and its triangles as corners into them.
void IndexPoints(const SurfaceMesh& mesh, Chart& chart)
{
  std::unordered_map<int, int> local;
  chart.Points.clear();
  chart.Corners.clear();
  for (int t : chart.Triangles)
  {
    std::array<int, 3> corners;
    for (int k = 0; k < 3; ++k)
    {
      const int v = mesh.Triangles[t][k];
      const auto inserted = local.emplace(v, static_cast<int>(chart.Points.size()));
      if (inserted.second)
      {
        chart.Points.push_back(v);
      }
      corners[k] = inserted.first->second;
    }
    chart.Corners.push_back(corners);
  }
}

/// Least squares conformal map (Levy et al. 2002): per triangle, the Cauchy-Riemann residuals
/// of the map from the triangle's own plane, weighted by the square root of its area, with two
/// far-apart points pinned. Returns false when the solve fails.
bool ConformalMap(const SurfaceMesh& mesh, Chart& chart)
{
  const int points = static_cast<int>(chart.Points.size());
  chart.UV.assign(points, Vector2d(0, 0));
  const auto farthestFrom = [&](int k)
  {
    const Vector3d p = PointOf(mesh, chart.Points[k]);
    int best = k;
    double distance = -1.0;
    for (int j = 0; j < points; ++j)
    {
      const double d = (PointOf(mesh, chart.Points[j]) - p).squaredNorm();
      if (d > distance)
      {
        distance = d;
        best = j;
      }
    }
    return best;
  };
  const int pin0 = farthestFrom(0);
  const int pin1 = farthestFrom(pin0);
  if (pin0 == pin1)
  {
    return false;
  }
  chart.UV[pin1] =
    Vector2d((PointOf(mesh, chart.Points[pin1]) - PointOf(mesh, chart.Points[pin0])).norm(), 0.0);
  std::vector<int> column(points, -1);
  int unknowns = 0;
  for (int k = 0; k < points; ++k)
  {
    if (k != pin0 && k != pin1)
    {
      column[k] = unknowns++;
    }
  }
  if (unknowns == 0)
  {
    return true;
  }
  std::vector<Eigen::Triplet<double>> entries;
  const int rows = 2 * static_cast<int>(chart.Corners.size());
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(rows);
  for (size_t f = 0; f < chart.Corners.size(); ++f)
  {
    const auto& c = chart.Corners[f];
    const Vector3d a = PointOf(mesh, chart.Points[c[0]]), b = PointOf(mesh, chart.Points[c[1]]),
                   d = PointOf(mesh, chart.Points[c[2]]);
    const Vector3d normal = (b - a).cross(d - a);
    const double area = 0.5 * normal.norm();
    if (area <= 0.0)
    {
      continue;
    }
    const std::array<Vector2d, 3> p = InPlane(a, b, d);
    const double scale = 1.0 / (2.0 * std::sqrt(area));
    const int r1 = static_cast<int>(2 * f), r2 = r1 + 1;
    for (int j = 0; j < 3; ++j)
    {
      // The gradient of a linear function is sum_j f_j R90(e_j) / (2 area), e_j the edge
      // opposite corner j: residuals u_x - v_y and u_y + v_x.
      const Vector2d e = p[(j + 2) % 3] - p[(j + 1) % 3];
      const double coefficients[2][2] = { { -e.y() * scale, -e.x() * scale },
        { e.x() * scale, -e.y() * scale } };
      const int k = c[j];
      for (int r = 0; r < 2; ++r)
      {
        const int row = r == 0 ? r1 : r2;
        for (int uv = 0; uv < 2; ++uv)
        {
          if (column[k] >= 0)
          {
            entries.emplace_back(row, 2 * column[k] + uv, coefficients[r][uv]);
          }
          else
          {
            rhs[row] -= coefficients[r][uv] * chart.UV[k][uv];
          }
        }
      }
    }
  }
  Eigen::SparseMatrix<double> system(rows, 2 * unknowns);
  system.setFromTriplets(entries.begin(), entries.end());
  const Eigen::SparseMatrix<double> normal = system.transpose() * system;
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver(normal);
  if (solver.info() != Eigen::Success)
  {
    return false;
  }
  const Eigen::VectorXd solution = solver.solve(system.transpose() * rhs);
  if (solver.info() != Eigen::Success || !solution.allFinite())
  {
    return false;
  }
  for (int k = 0; k < points; ++k)
  {
    if (column[k] >= 0)
    {
      chart.UV[k] = Vector2d(solution[2 * column[k]], solution[2 * column[k] + 1]);
    }
  }
  return true;
}

/// Orthogonal projection along the chart's mean normal: flip-free when every normal is within
/// 90 degrees of it (the fallback when the conformal map flips a triangle).
bool ProjectChart(const SurfaceMesh& mesh, const Faces& faces, Chart& chart)
{
  Vector3d axis(0, 0, 0);
  for (int t : chart.Triangles)
  {
    axis += faces.Area[t] * faces.Normal[t];
  }
  if (axis.norm() == 0.0)
  {
    return false;
  }
  axis.normalize();
  for (int t : chart.Triangles)
  {
    if (faces.Normal[t].dot(axis) < 0.05)
    {
      return false;
    }
  }
  const Vector3d x = axis.unitOrthogonal();
  const Vector3d y = axis.cross(x);
  chart.UV.resize(chart.Points.size());
  for (size_t k = 0; k < chart.Points.size(); ++k)
  {
    const Vector3d p = PointOf(mesh, chart.Points[k]);
    chart.UV[k] = Vector2d(p.dot(x), p.dot(y));
  }
  return true;
}

double SignedArea(const Chart& chart, size_t f)
{
  const auto& c = chart.Corners[f];
  return 0.5 * Cross2(chart.UV[c[1]] - chart.UV[c[0]], chart.UV[c[2]] - chart.UV[c[0]]);
}

bool HasFlips(const Chart& chart)
{
  for (size_t f = 0; f < chart.Corners.size(); ++f)
  {
    if (!(SignedArea(chart, f) > 0.0))
    {
      return true;
    }
  }
  return false;
}

/// Scales the chart's plane coordinates to its surface area, turns its principal axis along u
/// (smaller boxes to pack) and sets its box.
void NormalizeChart(const Faces& faces, Chart& chart)
{
  double surface = 0.0, plane = 0.0;
  for (size_t f = 0; f < chart.Triangles.size(); ++f)
  {
    surface += faces.Area[chart.Triangles[f]];
    plane += SignedArea(chart, f);
  }
  const double scale = plane > 0.0 ? std::sqrt(surface / plane) : 1.0;
  Vector2d mean(0, 0);
  for (const Vector2d& uv : chart.UV)
  {
    mean += uv;
  }
  mean /= static_cast<double>(chart.UV.size());
  Eigen::Matrix2d covariance = Eigen::Matrix2d::Zero();
  for (const Vector2d& uv : chart.UV)
  {
    covariance += (uv - mean) * (uv - mean).transpose();
  }
  const Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> principal(covariance);
  Eigen::Matrix2d rotation = principal.eigenvectors().rowwise().reverse().transpose();
  if (rotation.determinant() < 0.0)
  {
    rotation.row(1) *= -1.0;
  }
  chart.Lo = Vector2d(1e300, 1e300);
  chart.Hi = Vector2d(-1e300, -1e300);
  for (Vector2d& uv : chart.UV)
  {
    uv = rotation * (uv - mean) * scale;
    chart.Lo = chart.Lo.cwiseMin(uv);
    chart.Hi = chart.Hi.cwiseMax(uv);
  }
}

/// Shelf packing of the charts' boxes at `scale` pixels per unit: tallest first, in rows of at
/// most `rowWidth` pixels. Returns the height they take.
long long Pack(std::vector<Chart>& charts, double scale, int margin, long long rowWidth)
{
  std::vector<std::array<long long, 2>> sizes(charts.size());
  for (size_t c = 0; c < charts.size(); ++c)
  {
    const Vector2d extent = (charts[c].Hi - charts[c].Lo) * scale;
    sizes[c] = { static_cast<long long>(std::ceil(extent.x())) + 1 + 2 * margin,
      static_cast<long long>(std::ceil(extent.y())) + 1 + 2 * margin };
    if (sizes[c][0] > rowWidth)
    {
      return 1LL << 40; // does not fit: a smaller scale is needed
    }
  }
  std::vector<size_t> order(charts.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(
    order.begin(), order.end(), [&](size_t a, size_t b) { return sizes[a][1] > sizes[b][1]; });
  long long x = 0, y = 0, rowHeight = 0;
  for (size_t c : order)
  {
    if (x + sizes[c][0] > rowWidth)
    {
      y += rowHeight;
      x = 0;
      rowHeight = 0;
    }
    charts[c].X = static_cast<int>(x);
    charts[c].Y = static_cast<int>(y);
    x += sizes[c][0];
    rowHeight = std::max(rowHeight, sizes[c][1]);
  }
  return y + rowHeight;
}

/// Barycentric coordinates of q in triangle abc.
std::array<double, 3> Barycentric(
  const Vector2d& q, const Vector2d& a, const Vector2d& b, const Vector2d& c)
{
  const double area = Cross2(b - a, c - a);
  const double beta = Cross2(q - a, c - a) / area;
  const double gamma = Cross2(b - a, q - a) / area;
  return { 1.0 - beta - gamma, beta, gamma };
}

/// Draws every chart's triangles into the image (pixel centres inside a triangle take its
/// point, normal and area per pixel). Returns the charts whose triangles overlap in the plane.
std::vector<int> Rasterize(const SurfaceMesh& mesh, const Faces& faces,
  const std::vector<Chart>& charts, double scale, int margin, Atlas& atlas)
{
  GeometryImage& image = atlas.Image;
  const size_t pixels = static_cast<size_t>(image.NumberOfPixels());
  image.Position.assign(3 * pixels, 0.0f);
  image.Normal.assign(3 * pixels, 0.0f);
  image.AreaWeight.assign(pixels, 0.0f);
  image.Mask.assign(pixels, 0);
  atlas.Chart.assign(pixels, -1);
  atlas.Sources.Triangle.assign(pixels, -1);
  atlas.Sources.Barycentric.assign(3 * pixels, 0.0f);
  std::vector<int> overlapping;
  for (int id = 0; id < static_cast<int>(charts.size()); ++id)
  {
    const Chart& chart = charts[id];
    bool overlaps = false;
    double weightSum = 0.0, surface = 0.0;
    std::vector<size_t> drawn;
    for (size_t f = 0; f < chart.Triangles.size(); ++f)
    {
      const int t = chart.Triangles[f];
      surface += faces.Area[t];
      const auto& c = chart.Corners[f];
      const Vector2d a = chart.Pixel(c[0], scale, margin), b = chart.Pixel(c[1], scale, margin),
                     d = chart.Pixel(c[2], scale, margin);
      const double pixelArea = 0.5 * Cross2(b - a, d - a);
      if (!(pixelArea > 0.0))
      {
        continue;
      }
      const double weight = faces.Area[t] / pixelArea;
      const Vector2d lo = a.cwiseMin(b).cwiseMin(d), hi = a.cwiseMax(b).cwiseMax(d);
      for (int j = std::max(0, static_cast<int>(std::floor(lo.y() - 0.5)));
           j <= std::min(image.Height - 1, static_cast<int>(std::ceil(hi.y() - 0.5))); ++j)
      {
        for (int i = std::max(0, static_cast<int>(std::floor(lo.x() - 0.5)));
             i <= std::min(image.Width - 1, static_cast<int>(std::ceil(hi.x() - 0.5))); ++i)
        {
          const auto w = Barycentric(Vector2d(i + 0.5, j + 0.5), a, b, d);
          if (w[0] < -1e-9 || w[1] < -1e-9 || w[2] < -1e-9)
          {
            continue;
          }
          const size_t p = static_cast<size_t>(j) * image.Width + i;
          if (atlas.Chart[p] >= 0)
          {
            // A centre on a shared edge lies in both triangles; strictly inside two is a fold.
            overlaps = overlaps ||
              (atlas.Chart[p] == id && w[0] > 1e-6 && w[1] > 1e-6 && w[2] > 1e-6 &&
                atlas.Sources.Barycentric[3 * p] > 1e-6 &&
                atlas.Sources.Barycentric[3 * p + 1] > 1e-6 &&
                atlas.Sources.Barycentric[3 * p + 2] > 1e-6);
            continue;
          }
          const auto& tri = mesh.Triangles[t];
          const Vector3d point = w[0] * PointOf(mesh, tri[0]) + w[1] * PointOf(mesh, tri[1]) +
            w[2] * PointOf(mesh, tri[2]);
          for (int k = 0; k < 3; ++k)
          {
            image.Position[3 * p + k] = static_cast<float>(point[k]);
            image.Normal[3 * p + k] = static_cast<float>(faces.Normal[t][k]);
            atlas.Sources.Barycentric[3 * p + k] = static_cast<float>(w[k]);
          }
          image.AreaWeight[p] = static_cast<float>(weight);
          image.Mask[p] = 1;
          atlas.Chart[p] = id;
          atlas.Sources.Triangle[p] = t;
          weightSum += weight;
          drawn.push_back(p);
        }
      }
    }
    if (overlaps)
    {
      overlapping.push_back(id);
    }
    // Each chart's pixels carry its whole area (pixel centres miss bits along its border).
    const double correction = weightSum > 0.0 ? surface / weightSum : 1.0;
    for (size_t p : drawn)
    {
      image.AreaWeight[p] = static_cast<float>(image.AreaWeight[p] * correction);
    }
  }
  return overlapping;
}

/// Seam partners: every pixel within two pixels of a chart edge that another chart shares is
/// mirrored across that edge into the other chart (the point as far past the edge as the pixel
/// is before it), and the valid pixel of that chart nearest there is its partner. The pixels
/// within a pixel and a half of a chart edge that no other triangle shares (the surface's own
/// border) are marked as such (Border).
/// Marks (1 in `marks`) the pixels of chart `id` whose centres lie within `reach` pixels of the
/// segment from `a` to `b` (in pixels).
void MarkNear(const std::vector<int>& chartOf, int width, int height, int id, const Vector2d& a,
  const Vector2d& b, double reach, std::vector<unsigned char>& marks)
{
  const Vector2d lo = a.cwiseMin(b), hi = a.cwiseMax(b), edge = b - a;
  for (int j = std::max(0, static_cast<int>(std::floor(lo.y() - reach)));
       j <= std::min(height - 1, static_cast<int>(std::ceil(hi.y() + reach))); ++j)
  {
    for (int i = std::max(0, static_cast<int>(std::floor(lo.x() - reach)));
         i <= std::min(width - 1, static_cast<int>(std::ceil(hi.x() + reach))); ++i)
    {
      const size_t p = static_cast<size_t>(j) * width + i;
      const Vector2d centre(i + 0.5, j + 0.5);
      const double lambda = std::clamp(
        edge.squaredNorm() > 0.0 ? (centre - a).dot(edge) / edge.squaredNorm() : 0.0, 0.0, 1.0);
      if (chartOf[p] == id && (centre - (a + lambda * edge)).norm() < reach)
      {
        marks[p] = 1;
      }
    }
  }
}

void FindSeams(const SurfaceMesh& mesh, const Faces& faces, const std::vector<Chart>& charts,
  double scale, int margin, Atlas& atlas)
{
  GeometryImage& image = atlas.Image;
  const size_t pixels = static_cast<size_t>(image.NumberOfPixels());
  image.SeamPartner.assign(pixels, -1);
  image.Border.assign(pixels, 0);
  struct Cut
  {
    Vector2d A, B;                // the edge in this chart's pixels
    Vector2d OtherA, OtherB, Far; // the edge, and the other triangle's third point, over there
    int OtherChart;
  };
  std::vector<Cut> cuts;
  std::vector<float> nearest(pixels, 2.0f); // distance to the nearest cut, in pixels
  std::vector<float> along(pixels, 0.0f);   // where along that cut (0 at A, 1 at B)
  std::vector<int> cutOf(pixels, -1);
  // Where each chart keeps each triangle's corners.
  std::vector<std::pair<int, int>> placed(mesh.Triangles.size(), { -1, -1 });
  for (int id = 0; id < static_cast<int>(charts.size()); ++id)
  {
    for (size_t f = 0; f < charts[id].Triangles.size(); ++f)
    {
      placed[charts[id].Triangles[f]] = { id, static_cast<int>(f) };
    }
  }
  atlas.SeamLength = 0.0;
  for (int t = 0; t < static_cast<int>(mesh.Triangles.size()); ++t)
  {
    const int id = placed[t].first;
    for (int e = 0; e < 3 && id >= 0; ++e)
    {
      const int n = faces.Across[t][e];
      if (n < 0)
      {
        const auto& corners = charts[id].Corners[placed[t].second];
        MarkNear(atlas.Chart, image.Width, image.Height, id,
          charts[id].Pixel(corners[e], scale, margin),
          charts[id].Pixel(corners[(e + 1) % 3], scale, margin), 1.5, image.Border);
        continue;
      }
      if (placed[n].first == id || placed[n].first < 0)
      {
        continue;
      }
      const Chart& here = charts[id];
      const Chart& there = charts[placed[n].first];
      const auto& corners = here.Corners[placed[t].second];
      const auto& otherCorners = there.Corners[placed[n].second];
      const int a = mesh.Triangles[t][e], b = mesh.Triangles[t][(e + 1) % 3];
      Cut cut;
      cut.A = here.Pixel(corners[e], scale, margin);
      cut.B = here.Pixel(corners[(e + 1) % 3], scale, margin);
      cut.OtherChart = placed[n].first;
      for (int k = 0; k < 3; ++k)
      {
        const int v = mesh.Triangles[n][k];
        const Vector2d q = there.Pixel(otherCorners[k], scale, margin);
        if (v == a)
        {
          cut.OtherA = q;
        }
        else if (v == b)
        {
          cut.OtherB = q;
        }
        else
        {
          cut.Far = q;
        }
      }
      if (t < n)
      {
        atlas.SeamLength += (PointOf(mesh, a) - PointOf(mesh, b)).norm();
      }
      const int index = static_cast<int>(cuts.size());
      cuts.push_back(cut);
      const Vector2d lo = cut.A.cwiseMin(cut.B), hi = cut.A.cwiseMax(cut.B);
      const Vector2d edge = cut.B - cut.A;
      for (int j = std::max(0, static_cast<int>(std::floor(lo.y() - 2.5)));
           j <= std::min(image.Height - 1, static_cast<int>(std::ceil(hi.y() + 1.5))); ++j)
      {
        for (int i = std::max(0, static_cast<int>(std::floor(lo.x() - 2.5)));
             i <= std::min(image.Width - 1, static_cast<int>(std::ceil(hi.x() + 1.5))); ++i)
        {
          const size_t p = static_cast<size_t>(j) * image.Width + i;
          if (atlas.Chart[p] != id)
          {
            continue;
          }
          const Vector2d centre(i + 0.5, j + 0.5);
          const double lambda = std::clamp(
            edge.squaredNorm() > 0.0 ? (centre - cut.A).dot(edge) / edge.squaredNorm() : 0.0, 0.0,
            1.0);
          const double distance = (centre - (cut.A + lambda * edge)).norm();
          if (distance < nearest[p])
          {
            nearest[p] = static_cast<float>(distance);
            along[p] = static_cast<float>(lambda);
            cutOf[p] = index;
          }
        }
      }
    }
  }
  atlas.SeamPixels = 0;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (cutOf[p] < 0)
    {
      continue;
    }
    const Cut& cut = cuts[cutOf[p]];
    const Vector2d otherAlong = cut.OtherB - cut.OtherA;
    Vector2d inward(-otherAlong.y(), otherAlong.x());
    inward = inward.norm() > 0.0 ? Vector2d(inward.normalized()) : Vector2d(0, 0);
    if (inward.dot(cut.Far - cut.OtherA) < 0.0)
    {
      inward = -inward;
    }
    const Vector2d target =
      cut.OtherA + along[p] * otherAlong + std::max(0.5, static_cast<double>(nearest[p])) * inward;
    const int ti = static_cast<int>(std::floor(target.x())),
              tj = static_cast<int>(std::floor(target.y()));
    double best = 1e300;
    for (int j = std::max(0, tj - 2); j <= std::min(image.Height - 1, tj + 2); ++j)
    {
      for (int i = std::max(0, ti - 2); i <= std::min(image.Width - 1, ti + 2); ++i)
      {
        const size_t q = static_cast<size_t>(j) * image.Width + i;
        const double d = (Vector2d(i + 0.5, j + 0.5) - target).squaredNorm();
        if (atlas.Chart[q] == cut.OtherChart && d < best)
        {
          best = d;
          image.SeamPartner[p] = static_cast<int>(q);
        }
      }
    }
    atlas.SeamPixels += image.SeamPartner[p] >= 0 ? 1 : 0;
  }
}

/// Area and angle stretch per triangle, over all charts.
void MeasureDistortion(
  const SurfaceMesh& mesh, const Faces& faces, const std::vector<Chart>& charts, Atlas& atlas)
{
  atlas.MinimumAreaStretch = 1e300;
  atlas.MaximumAreaStretch = 0.0;
  atlas.MaximumAngleStretch = 1.0;
  for (const Chart& chart : charts)
  {
    for (size_t f = 0; f < chart.Triangles.size(); ++f)
    {
      const int t = chart.Triangles[f];
      if (faces.Area[t] <= 0.0)
      {
        continue;
      }
      const auto& tri = mesh.Triangles[t];
      const std::array<Vector2d, 3> p =
        InPlane(PointOf(mesh, tri[0]), PointOf(mesh, tri[1]), PointOf(mesh, tri[2]));
      Eigen::Matrix2d plane, uv;
      plane.col(0) = p[1] - p[0];
      plane.col(1) = p[2] - p[0];
      const auto& k = chart.Corners[f];
      uv.col(0) = chart.UV[k[1]] - chart.UV[k[0]];
      uv.col(1) = chart.UV[k[2]] - chart.UV[k[0]];
      const Eigen::Matrix2d map = uv * plane.inverse();
      const Eigen::JacobiSVD<Eigen::Matrix2d> svd(map);
      const Vector2d sigma = svd.singularValues();
      const double area = sigma[0] * sigma[1];
      atlas.MinimumAreaStretch = std::min(atlas.MinimumAreaStretch, area);
      atlas.MaximumAreaStretch = std::max(atlas.MaximumAreaStretch, area);
      if (sigma[1] > 0.0)
      {
        atlas.MaximumAngleStretch = std::max(atlas.MaximumAngleStretch, sigma[0] / sigma[1]);
      }
    }
  }
}

} // namespace

std::string BuildAtlas(const SurfaceMesh& mesh, const AtlasOptions& options, Atlas& atlas)
{
  atlas = Atlas();
  if (mesh.NumberOfTriangles() == 0)
  {
    return "the mesh has no triangles";
  }
  const Faces faces(mesh);
  std::vector<int> chartOf(mesh.Triangles.size(), Free);
  std::vector<int> pointStamp(mesh.NumberOfPoints(), -1);
  std::vector<Chart> charts;
  std::vector<int> all;
  for (int t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    if (faces.Area[t] > 0.0)
    {
      all.push_back(t);
    }
    else
    {
      chartOf[t] = -1; // no area: nothing to sample
    }
  }
  GrowCharts(mesh, faces, all, options.MaximumNormalAngle, chartOf, pointStamp, charts);
  const int margin = std::max(1, options.Gutter);
  double totalArea = 0.0;
  for (int t : all)
  {
    totalArea += faces.Area[t];
  }
  // Charts whose map flips or folds are grown again with half the cone, until projection along
  // their mean normal is enough.
  for (int round = 0;; ++round)
  {
    if (round > 30)
    {
      return "the mesh could not be cut into charts without folds";
    }
    std::vector<int> regrow;
    for (size_t c = 0; c < charts.size(); ++c)
    {
      Chart& chart = charts[c];
      if (chart.Mapped)
      {
        continue;
      }
      IndexPoints(mesh, chart);
      bool ok = ConformalMap(mesh, chart) && !HasFlips(chart);
      if (!ok)
      {
        ok = ProjectChart(mesh, faces, chart) && !HasFlips(chart);
      }
      if (ok)
      {
        NormalizeChart(faces, chart);
        chart.Mapped = true;
      }
      else
      {
        regrow.push_back(static_cast<int>(c));
      }
    }
    // The largest scale whose packing fits (bisection on the scale, from the area's bound).
    const double pixels = static_cast<double>(options.Width) * options.Height;
    double high = std::sqrt(pixels / totalArea), low = 0.0, scale = 0.0;
    for (int attempt = 0; regrow.empty() && attempt < 30; ++attempt)
    {
      const double trial = 0.5 * (low + high);
      if (Pack(charts, trial, margin, options.Width) <= options.Height)
      {
        low = scale = trial;
      }
      else
      {
        high = trial;
      }
    }
    if (regrow.empty())
    {
      if (scale <= 0.0 || options.Width < 2 || options.Height < 2)
      {
        std::ostringstream message;
        message << "a " << options.Width << " x " << options.Height << " image cannot hold the "
                << charts.size() << " charts of this mesh; give a larger resolution";
        return message.str();
      }
      Pack(charts, scale, margin, options.Width);
      atlas.Image = GeometryImage();
      atlas.Image.Width = options.Width;
      atlas.Image.Height = options.Height;
      const std::vector<int> folded = Rasterize(mesh, faces, charts, scale, margin, atlas);
      if (folded.empty() || round >= 6)
      {
        FindSeams(mesh, faces, charts, scale, margin, atlas);
        MeasureDistortion(mesh, faces, charts, atlas);
        atlas.TriangleChart = chartOf;
        atlas.NumberOfCharts = static_cast<int>(charts.size());
        return "";
      }
      regrow = folded;
    }
    // Free the failed charts' triangles and grow them again with a narrower cone; the charts
    // are renumbered, the good ones keeping their maps.
    std::vector<char> failed(charts.size(), 0);
    std::vector<int> pool;
    double cone = options.MaximumNormalAngle;
    for (int c : regrow)
    {
      failed[c] = 1;
      cone = std::min(cone, 0.5 * charts[c].Cone);
      pool.insert(pool.end(), charts[c].Triangles.begin(), charts[c].Triangles.end());
    }
    std::vector<Chart> kept;
    for (size_t c = 0; c < charts.size(); ++c)
    {
      if (!failed[c])
      {
        for (int t : charts[c].Triangles)
        {
          chartOf[t] = static_cast<int>(kept.size());
        }
        kept.push_back(std::move(charts[c]));
      }
    }
    for (int t : pool)
    {
      chartOf[t] = Free;
    }
    std::fill(pointStamp.begin(), pointStamp.end(), -1);
    charts = std::move(kept);
    std::sort(pool.begin(), pool.end());
    GrowCharts(mesh, faces, pool, cone, chartOf, pointStamp, charts);
  }
}

} // namespace cvt
