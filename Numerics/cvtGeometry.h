// Private to CVT::Numerics: small 3D vector helpers on plain double[3] arrays, shared by the
// restricted Voronoi diagram, the geometry-image code and the remesh.
#ifndef cvtGeometry_h
#define cvtGeometry_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

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

} // namespace cvt

#endif
