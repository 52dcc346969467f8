// Private to CVT::Numerics: the edges of a triangle list and the triangles on each, found by
// sorting (triangle, edge) uses by their end points, which is much faster to build than a hash
// map of vectors. Mesh repairs, topology and the restricted Voronoi engine read it.
#ifndef cvtEdgeTable_h
#define cvtEdgeTable_h

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace cvt
{

/// An ordered pair (a directed edge, a cell and a point, ...) as one number: a, then b.
inline std::uint64_t DirectedKey(int a, int b)
{
  return (static_cast<std::uint64_t>(a) << 32) | static_cast<std::uint32_t>(b);
}

/// An undirected edge as one number: its smaller point, then its larger.
inline std::uint64_t EdgeKey(int a, int b)
{
  return (static_cast<std::uint64_t>(std::min(a, b)) << 32) |
    static_cast<std::uint32_t>(std::max(a, b));
}

/// The triangles on each undirected edge: (key, triangle, local edge) sorted by key, so one
/// edge's uses are adjacent (much faster to build than a hash map of vectors).
struct EdgeUse
{
  std::uint64_t Key;
  int Triangle;
  int Local;
  bool operator<(const EdgeUse& other) const
  {
    return this->Key != other.Key ? this->Key < other.Key : this->Triangle < other.Triangle;
  }
};

class EdgeTable
{
public:
  struct Range
  {
    const EdgeUse* First;
    const EdgeUse* Last;
    const EdgeUse* begin() const { return this->First; }
    const EdgeUse* end() const { return this->Last; }
    size_t size() const { return static_cast<size_t>(this->Last - this->First); }
    std::uint64_t Key() const { return this->First->Key; }
  };

  explicit EdgeTable(const std::vector<std::array<int, 3>>& triangles)
  {
    // The uses sorted by (key, triangle) in linear time: counted into buckets by the edge's
    // smaller point (a key's high half), then each bucket, a few uses, sorted in place. On a
    // mesh of a million triangles this is several times quicker than sorting all the uses.
    // Indices into the uses are 32-bit (a mesh of over a billion triangles does not fit in
    // memory anyway): the table is rebuilt several times per run, and each fresh page of it
    // costs its first touch.
    int points = 0;
    for (const auto& triangle : triangles)
    {
      points = std::max({ points, triangle[0] + 1, triangle[1] + 1, triangle[2] + 1 });
    }
    std::vector<std::uint32_t> bucketStart(static_cast<size_t>(points) + 1, 0);
    for (const auto& triangle : triangles)
    {
      for (int e = 0; e < 3; ++e)
      {
        ++bucketStart[static_cast<size_t>(std::min(triangle[e], triangle[(e + 1) % 3])) + 1];
      }
    }
    for (size_t p = 1; p < bucketStart.size(); ++p)
    {
      bucketStart[p] += bucketStart[p - 1];
    }
    this->Uses.resize(3 * triangles.size());
    std::vector<std::uint32_t> next(bucketStart.begin(), bucketStart.end() - 1);
    for (int t = 0; t < static_cast<int>(triangles.size()); ++t)
    {
      for (int e = 0; e < 3; ++e)
      {
        const int a = triangles[t][e], b = triangles[t][(e + 1) % 3];
        this->Uses[next[static_cast<size_t>(std::min(a, b))]++] = { EdgeKey(a, b), t, e };
      }
    }
    for (size_t p = 0; p + 1 < bucketStart.size(); ++p)
    {
      std::sort(this->Uses.begin() + bucketStart[p], this->Uses.begin() + bucketStart[p + 1]);
    }
    this->GroupOf.resize(this->Uses.size());
    // Room for one edge per use: only the pages written are touched, and nothing is copied as
    // the list grows.
    this->Starts.reserve(this->Uses.size() + 1);
    for (size_t u = 0; u < this->Uses.size(); ++u)
    {
      if (u == 0 || this->Uses[u].Key != this->Uses[u - 1].Key)
      {
        this->Starts.push_back(static_cast<std::uint32_t>(u));
      }
      this->GroupOf[3 * static_cast<size_t>(this->Uses[u].Triangle) + this->Uses[u].Local] =
        static_cast<std::uint32_t>(this->Starts.size() - 1);
    }
    this->Starts.push_back(static_cast<std::uint32_t>(this->Uses.size()));
  }
  /// The uses of edge `local` of triangle `t` (its own included).
  Range At(int t, int local) const
  {
    return this->Edge(this->GroupOf[3 * static_cast<size_t>(t) + local]);
  }
  size_t NumberOfEdges() const { return this->Starts.size() - 1; }
  Range Edge(size_t e) const
  {
    return { this->Uses.data() + this->Starts[e], this->Uses.data() + this->Starts[e + 1] };
  }
  Range Find(std::uint64_t key) const
  {
    const auto range = std::equal_range(this->Uses.begin(), this->Uses.end(), EdgeUse{ key, -1, 0 },
      [](const EdgeUse& a, const EdgeUse& b) { return a.Key < b.Key; });
    return { this->Uses.data() + (range.first - this->Uses.begin()),
      this->Uses.data() + (range.second - this->Uses.begin()) };
  }

private:
  std::vector<EdgeUse> Uses;
  std::vector<std::uint32_t> Starts;
  std::vector<std::uint32_t> GroupOf; // per (triangle, local edge)
};

} // namespace cvt

#endif
