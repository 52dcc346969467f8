// Private to CVT::Numerics: small 3D vector helpers on plain double[3] arrays, shared by the
// restricted Voronoi diagram, the geometry-image code, the input's cleaning and the remesh.
#ifndef cvtGeometry_h
#define cvtGeometry_h

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

namespace cvt
{

/// A hash of `count` 64-bit words (the bits of coordinates), mixed into `seed`: keys of points and
/// triangles asked again, equal to the bit.
inline std::uint64_t HashBits(
  const std::uint64_t* bits, size_t count, std::uint64_t seed = 0xCBF29CE484222325ull)
{
  std::uint64_t h = seed;
  for (size_t i = 0; i < count; ++i)
  {
    h = (h ^ bits[i]) * 0x100000001B3ull;
    h ^= h >> 29;
  }
  return h;
}

inline double Dot(const double* a, const double* b)
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

inline double Distance2(const double* a, const double* b)
{
  const double d[3] = { a[0] - b[0], a[1] - b[1], a[2] - b[2] };
  return Dot(d, d);
}

inline void Cross(const double* a, const double* b, double* out)
{
  out[0] = a[1] * b[2] - a[2] * b[1];
  out[1] = a[2] * b[0] - a[0] * b[2];
  out[2] = a[0] * b[1] - a[1] * b[0];
}

/// The normal of triangle abc scaled by twice its area (the cross product of two edges): summed
/// over the triangles round a vertex, their area-weighted normal.
inline void TriangleNormal(const double* a, const double* b, const double* c, double n[3])
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  Cross(u, v, n);
}

/// The unit normal of triangle abc (zero when degenerate).
inline void UnitNormal(const double* a, const double* b, const double* c, double n[3])
{
  TriangleNormal(a, b, c, n);
  const double length = std::sqrt(Dot(n, n));
  for (int k = 0; k < 3; ++k)
  {
    n[k] = length > 0.0 ? n[k] / length : 0.0;
  }
}

/// The centroid of triangle abc and the distance from it to its farthest corner: a ball that holds
/// the triangle, for skipping triangles too far to matter.
inline double BoundingBall(const double* a, const double* b, const double* c, double centroid[3])
{
  for (int k = 0; k < 3; ++k)
  {
    centroid[k] = (a[k] + b[k] + c[k]) / 3.0;
  }
  return std::sqrt(
    std::max({ Distance2(centroid, a), Distance2(centroid, b), Distance2(centroid, c) }));
}

/// The squared distance from p to the segment ab.
inline double Distance2ToSegment(const double* p, const double* a, const double* b)
{
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ap[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
  const double length2 = Dot(ab, ab);
  const double t = length2 > 0.0 ? std::min(1.0, std::max(0.0, Dot(ab, ap) / length2)) : 0.0;
  const double q[3] = { a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2] };
  return Distance2(p, q);
}

/// The point of triangle abc nearest to p, and its barycentric coordinates there (Ericson,
/// Real-Time Collision Detection, 5.1.5).
inline void ClosestPointOnTriangle(const double* p, const double* a, const double* b,
  const double* c, double point[3], double weights[3])
{
  const auto set = [&](double u, double v, double w)
  {
    weights[0] = u;
    weights[1] = v;
    weights[2] = w;
  };
  const auto at = [&](const double* q)
  {
    for (int k = 0; k < 3; ++k)
    {
      point[k] = q[k];
    }
  };
  const auto along = [&](const double* from, const double* to, double t)
  {
    for (int k = 0; k < 3; ++k)
    {
      point[k] = from[k] + t * (to[k] - from[k]);
    }
  };
  const double ab[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double ac[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double ap[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
  const double d1 = Dot(ab, ap), d2 = Dot(ac, ap);
  if (d1 <= 0.0 && d2 <= 0.0)
  {
    set(1.0, 0.0, 0.0);
    return at(a);
  }
  const double bp[3] = { p[0] - b[0], p[1] - b[1], p[2] - b[2] };
  const double d3 = Dot(ab, bp), d4 = Dot(ac, bp);
  if (d3 >= 0.0 && d4 <= d3)
  {
    set(0.0, 1.0, 0.0);
    return at(b);
  }
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0)
  {
    const double t = d1 / (d1 - d3);
    set(1.0 - t, t, 0.0);
    return along(a, b, t);
  }
  const double cp[3] = { p[0] - c[0], p[1] - c[1], p[2] - c[2] };
  const double d5 = Dot(ab, cp), d6 = Dot(ac, cp);
  if (d6 >= 0.0 && d5 <= d6)
  {
    set(0.0, 0.0, 1.0);
    return at(c);
  }
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0)
  {
    const double t = d2 / (d2 - d6);
    set(1.0 - t, 0.0, t);
    return along(a, c, t);
  }
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0)
  {
    const double t = (d4 - d3) / ((d4 - d3) + (d5 - d6));
    set(0.0, 1.0 - t, t);
    return along(b, c, t);
  }
  const double denominator = 1.0 / (va + vb + vc);
  const double v = vb * denominator, w = vc * denominator;
  set(1.0 - v - w, v, w);
  for (int k = 0; k < 3; ++k)
  {
    point[k] = a[k] + ab[k] * v + ac[k] * w;
  }
}

/// The cosine of the corner at a of triangle a b d; 1 (a corner of 0) when an edge has no length.
inline double CornerCosine(const double* a, const double* b, const double* d)
{
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
  const double norms = std::sqrt(
    (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
  return norms > 0.0 ? std::clamp((u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / norms, -1.0, 1.0)
                     : 1.0;
}

/// The angles (radians) of triangle p0 p1 p2 at its three corners.
inline void CornerAngles(const double* p0, const double* p1, const double* p2, double angle[3])
{
  angle[0] = std::acos(CornerCosine(p0, p1, p2));
  angle[1] = std::acos(CornerCosine(p1, p2, p0));
  angle[2] = std::acos(CornerCosine(p2, p0, p1));
}

/// Triangulates a loop of at most a few dozen vertices (a hole, a polygon), in the loop's
/// orientation, so that its thinnest triangle is as wide as it can be: the classic dynamic
/// programme over sub-polygons, O(n^3). `position(v)` gives vertex v's point; diagonals for
/// which `isEdge(a, b)` holds (edges the mesh has already), and triangles a b c (in the loop's
/// orientation) for which `fits(a, b, c)` does not, are taken only where nothing else fits.
template<class Position, class IsEdge, class Fits>
std::vector<std::array<int, 3>> TriangulateLoop(
  const std::vector<int>& loop, const Position& position, const IsEdge& isEdge, const Fits& fits)
{
  const int n = static_cast<int>(loop.size());
  // best[i][j]: the largest smallest angle of a triangulation of loop[i..j]; split[i][j]: its apex.
  std::vector<double> best(static_cast<size_t>(n * n), 10.0);
  std::vector<int> split(static_cast<size_t>(n * n), -1);
  const auto at = [n](int i, int j) { return static_cast<size_t>(i * n + j); };
  for (int length = 2; length < n; ++length)
  {
    for (int i = 0; i + length < n; ++i)
    {
      const int j = i + length;
      best[at(i, j)] = -1e300;
      for (int k = i + 1; k < j; ++k)
      {
        double angle[3];
        CornerAngles(position(loop[i]), position(loop[k]), position(loop[j]), angle);
        const double here = std::min(
          { *std::min_element(angle, angle + 3) - (fits(loop[i], loop[k], loop[j]) ? 0.0 : 100.0),
            k - i > 1 ? best[at(i, k)] : 10.0, j - k > 1 ? best[at(k, j)] : 10.0 });
        if (here > best[at(i, j)])
        {
          best[at(i, j)] = here;
          split[at(i, j)] = k;
        }
      }
      if (j - i < n - 1 && isEdge(loop[i], loop[j]))
      {
        best[at(i, j)] -= 20.0;
      }
    }
  }
  std::vector<std::array<int, 3>> triangles;
  std::vector<std::pair<int, int>> pending = { { 0, n - 1 } };
  while (!pending.empty())
  {
    const auto [i, j] = pending.back();
    pending.pop_back();
    const int k = split[at(i, j)];
    triangles.push_back({ loop[i], loop[k], loop[j] });
    if (k - i > 1)
    {
      pending.emplace_back(i, k);
    }
    if (j - k > 1)
    {
      pending.emplace_back(k, j);
    }
  }
  return triangles;
}

} // namespace cvt

#endif
