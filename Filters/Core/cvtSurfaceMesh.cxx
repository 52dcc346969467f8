#include "cvtSurfaceMesh.h"

#include "cvtSampling.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <sstream>
#include <unordered_map>

namespace cvt
{

namespace
{
std::uint64_t EdgeKey(int a, int b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
    static_cast<std::uint32_t>(std::max(a, b));
}

double TriangleArea(const SurfaceMesh& mesh, const std::array<int, 3>& t)
{
  const double* a = mesh.Point(t[0]);
  const double* b = mesh.Point(t[1]);
  const double* c = mesh.Point(t[2]);
  const double u[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double v[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double n[3] = { u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2],
    u[0] * v[1] - u[1] * v[0] };
  return 0.5 * std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
}

struct UnionFind
{
  explicit UnionFind(size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  int Find(int i)
  {
    while (this->Parent[i] != i)
    {
      i = this->Parent[i] = this->Parent[this->Parent[i]];
    }
    return i;
  }
  void Join(int a, int b) { this->Parent[this->Find(a)] = this->Find(b); }
  std::vector<int> Parent;
};

/// The triangles on each undirected edge, as (triangle, local edge) pairs.
using EdgeMap = std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>>;

EdgeMap MapEdges(const std::vector<std::array<int, 3>>& triangles)
{
  EdgeMap edges;
  edges.reserve(triangles.size() * 2);
  for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
  {
    for (int e = 0; e < 3; ++e)
    {
      edges[EdgeKey(triangles[t][e], triangles[t][(e + 1) % 3])].emplace_back(t, e);
    }
  }
  return edges;
}

std::string Where(const SurfaceMesh& mesh, int point)
{
  std::ostringstream text;
  const double* p = mesh.Point(point);
  text << "(" << p[0] << ", " << p[1] << ", " << p[2] << ")";
  return text.str();
}

/// Splits every point whose triangles form several fans (joined through edges at the point).
int SplitNonManifoldPoints(SurfaceMesh& mesh)
{
  const int n = mesh.NumberOfPoints();
  std::vector<std::vector<int>> around(n);
  for (int t = 0; t < mesh.NumberOfTriangles(); ++t)
  {
    for (int k = 0; k < 3; ++k)
    {
      around[mesh.Triangles[t][k]].push_back(t);
    }
  }
  int split = 0;
  for (int p = 0; p < n; ++p)
  {
    const std::vector<int>& fan = around[p];
    if (fan.size() < 2)
    {
      continue;
    }
    // Triangles at p are joined when they share an edge (p, q).
    UnionFind groups(fan.size());
    std::unordered_map<int, int> firstWithOther;
    for (size_t f = 0; f < fan.size(); ++f)
    {
      for (int q : mesh.Triangles[fan[f]])
      {
        if (q == p)
        {
          continue;
        }
        auto found = firstWithOther.emplace(q, static_cast<int>(f));
        if (!found.second)
        {
          groups.Join(static_cast<int>(f), found.first->second);
        }
      }
    }
    std::unordered_map<int, int> copyOfGroup;
    for (size_t f = 0; f < fan.size(); ++f)
    {
      const int root = groups.Find(static_cast<int>(f));
      auto found = copyOfGroup.emplace(root, copyOfGroup.empty() ? p : -1);
      if (found.second && found.first->second < 0)
      {
        found.first->second = mesh.NumberOfPoints();
        mesh.Points.insert(mesh.Points.end(), mesh.Point(p), mesh.Point(p) + 3);
        if (!mesh.Density.empty())
        {
          mesh.Density.push_back(mesh.Density[p]);
        }
        mesh.SourceIds.push_back(mesh.SourceIds[p]);
        ++split;
      }
      for (int& q : mesh.Triangles[fan[f]])
      {
        if (q == p)
        {
          q = found.first->second;
        }
      }
    }
  }
  return split;
}

double SignedVolume(const SurfaceMesh& mesh, const std::vector<int>& triangles)
{
  double volume = 0.0;
  for (int t : triangles)
  {
    const double* a = mesh.Point(mesh.Triangles[t][0]);
    const double* b = mesh.Point(mesh.Triangles[t][1]);
    const double* c = mesh.Point(mesh.Triangles[t][2]);
    volume += a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
      a[2] * (b[0] * c[1] - b[1] * c[0]);
  }
  return volume / 6.0;
}
}

bool MeshRepairReport::Changed() const
{
  return this->DegenerateTriangles + this->DuplicateTriangles + this->SplitPoints +
    this->FlippedTriangles + this->UnusedPoints >
    0;
}

std::string MeshRepairReport::Summary() const
{
  std::ostringstream text;
  const char* separator = "";
  const auto item = [&](int count, const char* what)
  {
    if (count > 0)
    {
      text << separator << what << " " << count;
      separator = ", ";
    }
  };
  item(this->DegenerateTriangles, "dropped degenerate triangles:");
  item(this->DuplicateTriangles, "dropped duplicate triangles:");
  item(this->SplitPoints, "split non-manifold points:");
  item(this->FlippedTriangles, "reoriented triangles:");
  item(this->UnusedPoints, "dropped unused points:");
  return text.str();
}

std::string CheckSurfaceMesh(const SurfaceMesh& mesh)
{
  for (double c : mesh.Points)
  {
    if (!std::isfinite(c))
    {
      return "the mesh has NaN or infinite point coordinates";
    }
  }
  if (mesh.Density.empty())
  {
    return std::string();
  }
  if (static_cast<int>(mesh.Density.size()) != mesh.NumberOfPoints())
  {
    return "the density array has " + std::to_string(mesh.Density.size()) + " values for " +
      std::to_string(mesh.NumberOfPoints()) + " points";
  }
  double largest = 0.0;
  for (double d : mesh.Density)
  {
    if (!std::isfinite(d))
    {
      return "the density array has NaN or infinite values";
    }
    if (d < 0.0)
    {
      return "the density array has negative values";
    }
    largest = std::max(largest, d);
  }
  return largest > 0.0 ? std::string() : "the density array is zero everywhere";
}

std::string RepairSurfaceMesh(SurfaceMesh& mesh, MeshRepairReport& report)
{
  report = MeshRepairReport();
  if (mesh.SourceIds.empty())
  {
    mesh.SourceIds.resize(mesh.NumberOfPoints());
    std::iota(mesh.SourceIds.begin(), mesh.SourceIds.end(), 0);
  }
  // Degenerate and duplicate triangles.
  {
    std::vector<std::array<int, 3>> kept;
    kept.reserve(mesh.Triangles.size());
    std::unordered_map<std::uint64_t, std::vector<std::array<int, 3>>> seen;
    for (const auto& t : mesh.Triangles)
    {
      if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0] || !(TriangleArea(mesh, t) > 0.0))
      {
        ++report.DegenerateTriangles;
        continue;
      }
      std::array<int, 3> sorted = t;
      std::sort(sorted.begin(), sorted.end());
      auto& bucket = seen[EdgeKey(sorted[0], sorted[1])];
      if (std::find(bucket.begin(), bucket.end(), sorted) != bucket.end())
      {
        ++report.DuplicateTriangles;
        continue;
      }
      bucket.push_back(sorted);
      kept.push_back(t);
    }
    mesh.Triangles.swap(kept);
  }
  if (mesh.Triangles.empty())
  {
    return "the mesh has no triangle of positive area";
  }
  // Non-manifold edges cannot be repaired without guessing which sheets belong together.
  EdgeMap edges = MapEdges(mesh.Triangles);
  {
    int nonManifold = 0;
    std::uint64_t example = 0;
    for (const auto& edge : edges)
    {
      if (edge.second.size() > 2)
      {
        if (nonManifold++ == 0)
        {
          example = edge.first;
        }
      }
    }
    if (nonManifold > 0)
    {
      const int a = static_cast<int>(example >> 32), b = static_cast<int>(example & 0xffffffffu);
      return std::to_string(nonManifold) +
        " non-manifold edges (shared by more than two triangles), e.g. between points " +
        Where(mesh, a) + " and " + Where(mesh, b) +
        "; remove the extra sheets or split the mesh into manifold parts";
    }
  }
  // Consistent orientation, component by component (breadth-first over edges).
  const int triangleCount = mesh.NumberOfTriangles();
  std::vector<int> component(triangleCount, -1);
  std::vector<char> flip(triangleCount, 0);
  std::vector<std::vector<int>> components;
  for (int seed = 0; seed < triangleCount; ++seed)
  {
    if (component[seed] >= 0)
    {
      continue;
    }
    const int id = static_cast<int>(components.size());
    components.emplace_back(1, seed);
    component[seed] = id;
    for (size_t next = 0; next < components[id].size(); ++next)
    {
      const int t = components[id][next];
      for (int e = 0; e < 3; ++e)
      {
        const int a = mesh.Triangles[t][e], b = mesh.Triangles[t][(e + 1) % 3];
        for (const auto& other : edges[EdgeKey(a, b)])
        {
          const int u = other.first;
          if (u == t)
          {
            continue;
          }
          // Agreeing orientations traverse the shared edge in opposite directions.
          const bool sameDirection = mesh.Triangles[u][other.second] == a;
          const char needed = static_cast<char>(flip[t] ^ (sameDirection ? 1 : 0));
          if (component[u] < 0)
          {
            component[u] = id;
            flip[u] = needed;
            components[id].push_back(u);
          }
          else if (flip[u] != needed)
          {
            return "the mesh is not orientable (a Moebius-like component near point " +
              Where(mesh, a) + "); the remesher needs an orientable surface";
          }
        }
      }
    }
  }
  for (const auto& triangles : components)
  {
    int flipped = 0;
    for (int t : triangles)
    {
      if (flip[t])
      {
        std::swap(mesh.Triangles[t][1], mesh.Triangles[t][2]);
        ++flipped;
      }
    }
    // Closed components face outwards; open ones keep the orientation most triangles had.
    bool closed = true;
    for (int t : triangles)
    {
      for (int e = 0; e < 3 && closed; ++e)
      {
        closed = edges[EdgeKey(mesh.Triangles[t][e], mesh.Triangles[t][(e + 1) % 3])].size() == 2;
      }
    }
    const bool reverse = closed ? SignedVolume(mesh, triangles) < 0.0
                                : 2 * flipped > static_cast<int>(triangles.size());
    if (reverse)
    {
      for (int t : triangles)
      {
        std::swap(mesh.Triangles[t][1], mesh.Triangles[t][2]);
      }
      flipped = static_cast<int>(triangles.size()) - flipped;
    }
    report.FlippedTriangles += flipped;
  }
  report.SplitPoints = SplitNonManifoldPoints(mesh);
  // Unused points.
  std::vector<int> renumber(mesh.NumberOfPoints(), -1);
  int used = 0;
  for (const auto& t : mesh.Triangles)
  {
    for (int p : t)
    {
      if (renumber[p] < 0)
      {
        renumber[p] = used++;
      }
    }
  }
  report.UnusedPoints = mesh.NumberOfPoints() - used;
  if (report.UnusedPoints > 0 || used != mesh.NumberOfPoints())
  {
    std::vector<double> points(3 * static_cast<size_t>(used));
    std::vector<double> density(mesh.Density.empty() ? 0 : used);
    std::vector<int> sources(used);
    for (int p = 0; p < mesh.NumberOfPoints(); ++p)
    {
      if (renumber[p] >= 0)
      {
        std::copy(mesh.Point(p), mesh.Point(p) + 3, &points[3 * static_cast<size_t>(renumber[p])]);
        if (!density.empty())
        {
          density[renumber[p]] = mesh.Density[p];
        }
        sources[renumber[p]] = mesh.SourceIds[p];
      }
    }
    for (auto& t : mesh.Triangles)
    {
      for (int& p : t)
      {
        p = renumber[p];
      }
    }
    mesh.Points.swap(points);
    mesh.Density.swap(density);
    mesh.SourceIds.swap(sources);
  }
  return std::string();
}

MeshTopology ComputeMeshTopology(
  int numberOfPoints, const std::vector<std::array<int, 3>>& triangles)
{
  MeshTopology topology;
  EdgeMap edges = MapEdges(triangles);
  UnionFind parts(static_cast<size_t>(numberOfPoints));
  std::vector<char> used(numberOfPoints, 0);
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      used[t[k]] = 1;
      parts.Join(t[k], t[(k + 1) % 3]);
    }
  }
  // Boundary edges, directed as in their triangle; each boundary point starts one of them.
  std::unordered_map<int, int> nextOnBoundary;
  for (const auto& edge : edges)
  {
    if (edge.second.size() == 1)
    {
      const auto& [t, e] = edge.second[0];
      nextOnBoundary[triangles[t][e]] = triangles[t][(e + 1) % 3];
    }
  }
  std::unordered_map<int, int> verticesOf, edgesOf, facesOf, loopsOf;
  for (int p = 0; p < numberOfPoints; ++p)
  {
    if (used[p])
    {
      ++verticesOf[parts.Find(p)];
    }
  }
  for (const auto& edge : edges)
  {
    ++edgesOf[parts.Find(static_cast<int>(edge.first >> 32))];
  }
  for (const auto& t : triangles)
  {
    ++facesOf[parts.Find(t[0])];
  }
  std::unordered_map<int, char> visited;
  std::vector<int> starts;
  for (const auto& link : nextOnBoundary)
  {
    starts.push_back(link.first);
  }
  std::sort(starts.begin(), starts.end());
  for (int start : starts)
  {
    if (visited[start])
    {
      continue;
    }
    std::vector<int> loop;
    for (int p = start; !visited[p];)
    {
      visited[p] = 1;
      loop.push_back(p);
      auto next = nextOnBoundary.find(p);
      if (next == nextOnBoundary.end())
      {
        break;
      }
      p = next->second;
    }
    ++loopsOf[parts.Find(start)];
    topology.Loops.push_back(std::move(loop));
  }
  topology.BoundaryLoops = static_cast<int>(topology.Loops.size());
  for (const auto& part : verticesOf)
  {
    const int chi = part.second - edgesOf[part.first] + facesOf[part.first];
    topology.EulerCharacteristic += chi;
    topology.Genus += std::max(0, (2 - chi - loopsOf[part.first]) / 2);
    ++topology.Components;
  }
  return topology;
}

double SurfaceArea(const SurfaceMesh& mesh)
{
  double area = 0.0;
  for (const auto& t : mesh.Triangles)
  {
    area += TriangleArea(mesh, t);
  }
  return area;
}

std::vector<double> SampleMeshSites(const SurfaceMesh& mesh, int count, std::uint64_t seed)
{
  std::vector<double> cumulative(mesh.Triangles.size());
  double total = 0.0;
  for (size_t t = 0; t < mesh.Triangles.size(); ++t)
  {
    const auto& tri = mesh.Triangles[t];
    double weight = TriangleArea(mesh, tri);
    if (!mesh.Density.empty())
    {
      weight *= (mesh.Density[tri[0]] + mesh.Density[tri[1]] + mesh.Density[tri[2]]) / 3.0;
    }
    total += weight;
    cumulative[t] = total;
  }
  std::mt19937_64 rng(seed);
  std::vector<double> sites;
  sites.reserve(3 * static_cast<size_t>(count));
  for (int i = 0; i < count && total > 0.0; ++i)
  {
    const size_t t = std::min(cumulative.size() - 1,
      static_cast<size_t>(
        std::upper_bound(cumulative.begin(), cumulative.end(), Uniform01(rng) * total) -
        cumulative.begin()));
    double u = Uniform01(rng), v = Uniform01(rng);
    if (u + v > 1.0)
    {
      u = 1.0 - u;
      v = 1.0 - v;
    }
    const double* a = mesh.Point(mesh.Triangles[t][0]);
    const double* b = mesh.Point(mesh.Triangles[t][1]);
    const double* c = mesh.Point(mesh.Triangles[t][2]);
    for (int k = 0; k < 3; ++k)
    {
      sites.push_back(a[k] + u * (b[k] - a[k]) + v * (c[k] - a[k]));
    }
  }
  return sites;
}

} // namespace cvt
