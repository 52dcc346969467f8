#include "cvtRemesh.h"

#include "cvtSurfaceMesh.h" // for ComputeMeshTopology

#include <algorithm>
#include <cstdint>
#include <unordered_map>

namespace cvt
{

namespace
{
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
  // Vertices: the used sites, at their surface (or border) points.
  std::unordered_map<int, int> vertexOf;
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
        remesh.SiteIds.push_back(site);
      }
      site = found.first->second;
    }
  }
  remesh.Triangles = std::move(kept);
  return remesh;
}

} // namespace cvt
