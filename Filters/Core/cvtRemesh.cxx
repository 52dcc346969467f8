#include "cvtRemesh.h"

#include "cvtSurfaceMesh.h" // for TraceLoops, SplitPinchedPoints

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>

namespace cvt
{

namespace
{
/// Below this angle (radians: 10 degrees) a triangle of pinned vertices is a sliver.
constexpr double MinimumBorderAngle = 10.0 * 3.14159265358979323846 / 180.0;

/// The angles (radians) of triangle p0 p1 p2 at its three corners.
void CornerAngles(const double* p0, const double* p1, const double* p2, double angle[3])
{
  const double* p[3] = { p0, p1, p2 };
  for (int k = 0; k < 3; ++k)
  {
    const double* a = p[k];
    const double* b = p[(k + 1) % 3];
    const double* d = p[(k + 2) % 3];
    const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double v[3] = { d[0] - a[0], d[1] - a[1], d[2] - a[2] };
    const double norms = std::sqrt(
      (u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) * (v[0] * v[0] + v[1] * v[1] + v[2] * v[2]));
    angle[k] = norms > 0.0
      ? std::acos(std::clamp((u[0] * v[0] + u[1] * v[1] + u[2] * v[2]) / norms, -1.0, 1.0))
      : 0.0;
  }
}

std::uint64_t DirectedKey(int a, int b)
{
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}
}

Remesh BuildRemesh(const RestrictedDual& dual, size_t inputBoundaryLoops, int maximumHole)
{
  Remesh remesh;
  // Keep triangles whose directed edges are all new: a second triangle on an edge in the same
  // direction, or a third on it, would make the surface non-manifold.
  std::unordered_map<std::uint64_t, int> directed;
  std::vector<std::array<int, 3>> kept;
  kept.reserve(dual.Triangles.size());
  for (const auto& t : dual.Triangles)
  {
    bool fits = true;
    for (int e = 0; e < 3 && fits; ++e)
    {
      fits = directed.count(DirectedKey(t[e], t[(e + 1) % 3])) == 0;
    }
    if (!fits)
    {
      ++remesh.RemovedTriangles;
      continue;
    }
    for (int e = 0; e < 3; ++e)
    {
      directed[DirectedKey(t[e], t[(e + 1) % 3])] = 1;
    }
    kept.push_back(t);
  }
  // Two triangles on the same three sites (the two sides of a part thinner than the cells)
  // close on each other: a pillow of no area, joined to the rest by no edge. Both go.
  {
    std::unordered_map<std::uint64_t, int> firstOn; // sorted site triple -> triangle
    std::vector<char> drop(kept.size(), 0);
    for (size_t k = 0; k < kept.size(); ++k)
    {
      std::array<int, 3> sorted = kept[k];
      std::sort(sorted.begin(), sorted.end());
      const std::uint64_t key = (static_cast<std::uint64_t>(sorted[0]) << 42) ^
        (static_cast<std::uint64_t>(sorted[1]) << 21) ^ static_cast<std::uint64_t>(sorted[2]);
      auto found = firstOn.emplace(key, static_cast<int>(k));
      if (!found.second && !drop[found.first->second])
      {
        std::array<int, 3> other = kept[found.first->second];
        std::sort(other.begin(), other.end());
        if (other == sorted)
        {
          drop[k] = drop[found.first->second] = 1;
        }
      }
    }
    size_t last = 0;
    for (size_t k = 0; k < kept.size(); ++k)
    {
      if (drop[k])
      {
        ++remesh.RemovedTriangles;
        for (int e = 0; e < 3; ++e)
        {
          directed.erase(DirectedKey(kept[k][e], kept[k][(e + 1) % 3]));
        }
      }
      else
      {
        kept[last++] = kept[k];
      }
    }
    kept.resize(last);
  }
  // Holes: loops of edges with no twin. A loop along the input's border is part of the
  // surface; a short loop elsewhere is where cells met in a degenerate point: close it.
  std::vector<std::pair<int, int>> border;
  for (const auto& t : kept)
  {
    for (int e = 0; e < 3; ++e)
    {
      if (directed.count(DirectedKey(t[(e + 1) % 3], t[e])) == 0)
      {
        border.emplace_back(t[(e + 1) % 3], t[e]); // against the triangles: the hole's way
      }
    }
  }
  std::vector<std::vector<int>> holes, borderLoops;
  for (auto& loop : TraceLoops(border))
  {
    if (loop.size() < 3)
    {
      continue;
    }
    const bool onBorder = std::all_of(
      loop.begin(), loop.end(), [&dual](int site) { return dual.OnBoundary[site] != 0; });
    (onBorder ? borderLoops : holes).push_back(std::move(loop));
  }
  // Loops of border cells beyond the input's own loops are notches where a border cell met its
  // neighbours outside the surface: the shortest ones are closed.
  std::sort(borderLoops.begin(), borderLoops.end(),
    [](const std::vector<int>& a, const std::vector<int>& b) { return a.size() < b.size(); });
  for (size_t extra = 0; extra + inputBoundaryLoops < borderLoops.size(); ++extra)
  {
    holes.push_back(borderLoops[extra]);
  }
  for (const auto& loop : holes)
  {
    if (static_cast<int>(loop.size()) > maximumHole)
    {
      continue;
    }
    for (size_t k = 1; k + 1 < loop.size(); ++k)
    {
      kept.push_back({ loop[0], loop[k], loop[k + 1] });
    }
    ++remesh.FilledHoles;
  }
  // A triangle of three cells along a straight border can be flat once they are pinned to it;
  // when its widest corner is in no other triangle, that corner is an ear of the border: drop
  // both (the border then runs straight past it).
  {
    std::unordered_map<int, int> uses;
    for (const auto& t : kept)
    {
      for (int v : t)
      {
        ++uses[v];
      }
    }
    const auto position = [&dual](int v)
    {
      const size_t i = static_cast<size_t>(v);
      return dual.Pinned[i] ? &dual.BoundaryPoints[3 * i] : &dual.SurfacePoints[3 * i];
    };
    std::vector<std::array<int, 3>> shaped;
    shaped.reserve(kept.size());
    for (const auto& t : kept)
    {
      double angle[3];
      CornerAngles(position(t[0]), position(t[1]), position(t[2]), angle);
      const int widest = static_cast<int>(std::max_element(angle, angle + 3) - angle);
      if (*std::min_element(angle, angle + 3) < MinimumBorderAngle && uses[t[widest]] == 1 &&
        dual.Pinned[t[widest]])
      {
        ++remesh.RemovedTriangles;
        continue;
      }
      shaped.push_back(t);
    }
    kept.swap(shaped);
  }
  // Vertices: the used sites, at their surface (or border) points.
  std::unordered_map<int, int> vertexOf;
  std::vector<int> dualOf; // the dual vertex of each remesh vertex
  for (auto& t : kept)
  {
    for (int& site : t)
    {
      auto found = vertexOf.emplace(site, static_cast<int>(remesh.SiteIds.size()));
      if (found.second)
      {
        const size_t i = static_cast<size_t>(site);
        const bool border = dual.Pinned[i] != 0;
        const double* p = border ? &dual.BoundaryPoints[3 * i] : &dual.SurfacePoints[3 * i];
        const double* lambda =
          border ? &dual.BoundaryBarycentric[3 * i] : &dual.SurfaceBarycentric[3 * i];
        remesh.Points.insert(remesh.Points.end(), p, p + 3);
        remesh.SourceBarycentric.insert(remesh.SourceBarycentric.end(), lambda, lambda + 3);
        remesh.SourceTriangles.push_back(
          border ? dual.BoundaryTriangles[i] : dual.SurfaceTriangles[i]);
        remesh.SiteIds.push_back(dual.Sites[i]);
        dualOf.push_back(site);
      }
      site = found.first->second;
    }
  }
  remesh.Triangles = std::move(kept);
  // Three cells along a straight stretch of the border can make a triangle whose vertices, once
  // pinned, are (nearly) in line: its widest corner goes back to its cell's surface point.
  for (const auto& t : remesh.Triangles)
  {
    double angle[3];
    CornerAngles(
      &remesh.Points[3 * t[0]], &remesh.Points[3 * t[1]], &remesh.Points[3 * t[2]], angle);
    const int widest = static_cast<int>(std::max_element(angle, angle + 3) - angle);
    const size_t i = static_cast<size_t>(dualOf[t[widest]]);
    if (*std::min_element(angle, angle + 3) < MinimumBorderAngle && dual.Pinned[i] &&
      dual.SurfaceTriangles[i] >= 0)
    {
      std::copy(
        &dual.SurfacePoints[3 * i], &dual.SurfacePoints[3 * i] + 3, &remesh.Points[3 * t[widest]]);
      std::copy(&dual.SurfaceBarycentric[3 * i], &dual.SurfaceBarycentric[3 * i] + 3,
        &remesh.SourceBarycentric[3 * t[widest]]);
      remesh.SourceTriangles[t[widest]] = dual.SurfaceTriangles[i];
    }
  }
  // Sheets that meet only at a vertex (a part thinner than the cells, a border touching
  // itself) get a vertex each, so the remesh is manifold at its vertices too.
  for (int v : SplitPinchedPoints(static_cast<int>(remesh.SiteIds.size()), remesh.Triangles))
  {
    const size_t i = static_cast<size_t>(v);
    remesh.Points.insert(remesh.Points.end(), &remesh.Points[3 * i], &remesh.Points[3 * i] + 3);
    remesh.SourceBarycentric.insert(remesh.SourceBarycentric.end(),
      &remesh.SourceBarycentric[3 * i], &remesh.SourceBarycentric[3 * i] + 3);
    remesh.SourceTriangles.push_back(remesh.SourceTriangles[i]);
    remesh.SiteIds.push_back(remesh.SiteIds[i]);
    ++remesh.SplitVertices;
  }
  return remesh;
}

} // namespace cvt
