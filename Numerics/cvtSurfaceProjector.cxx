#include "cvtSurfaceProjector.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <limits>
#include <map>
#include <mutex>

#include "cvtGeometry.h"
#include "cvtMemory.h"
#include "cvtPointCloud.h"

namespace cvt
{

namespace
{
/// The most pieces one large triangle is cut into.
constexpr int MaximumPieces = 4096;

/// Covers triangle abc with balls about `radius` across (`piece(centre, radius)` for each): the
/// triangle is laid on its longest edge and cut into columns across that edge, each column into
/// rows up to the triangle's height there, and each ball holds one such rectangle. A sliver (a CAD
/// cylinder's or a fan's triangle) becomes a row of balls along its length; the sub-triangles of
/// a barycentric grid were (length / radius)^2 slivers themselves (PrusaSlicer's cylinder.stl:
/// 3.6 million pieces for 1,440 triangles, the most of a remesh's time in their trees).
template<typename Piece>
void CoverWithPieces(const double* a, const double* b, const double* c, double radius, Piece piece)
{
  const double* corners[3] = { a, b, c };
  int longest = 0; // the edge from corner `longest` to the next
  for (int k = 1; k < 3; ++k)
  {
    if (Distance2(corners[k], corners[(k + 1) % 3]) >
      Distance2(corners[longest], corners[(longest + 1) % 3]))
    {
      longest = k;
    }
  }
  const double* p0 = corners[longest];
  const double* p1 = corners[(longest + 1) % 3];
  const double* apex = corners[(longest + 2) % 3];
  const double length = std::sqrt(Distance2(p0, p1));
  double along[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
  for (double& x : along)
  {
    x = length > 0.0 ? x / length : 0.0;
  }
  const double toApex[3] = { apex[0] - p0[0], apex[1] - p0[1], apex[2] - p0[2] };
  // The apex lies over the longest edge: its foot is within it.
  const double foot = std::min(length, std::max(0.0, Dot(toApex, along)));
  double across[3] = { toApex[0] - foot * along[0], toApex[1] - foot * along[1],
    toApex[2] - foot * along[2] };
  const double height = std::sqrt(Dot(across, across));
  for (double& x : across)
  {
    x = height > 0.0 ? x / height : 0.0;
  }
  // Squares of side sqrt(2) radius (their balls are `radius` across), larger where there would
  // be more than MaximumPieces (counted in doubles: a radius of 0 would make them infinite).
  double side = std::sqrt(2.0) * radius;
  if (!(side > 0.0))
  {
    side = std::max(length, height); // one piece
  }
  if (!(side > 0.0))
  {
    piece(p0, 0.0); // all corners at one point
    return;
  }
  double columnCount = 1.0, rowCount = 1.0;
  for (;; side *= 1.25)
  {
    columnCount = std::max(1.0, std::ceil(length / side));
    rowCount = std::max(1.0, std::ceil(height / side));
    if (columnCount * rowCount <= MaximumPieces)
    {
      break;
    }
  }
  const int columns = static_cast<int>(columnCount), rows = static_cast<int>(rowCount);
  const double width = length / columns, rowHeight = height / rows;
  for (int i = 0; i < columns; ++i)
  {
    const double u0 = i * width, u1 = i + 1 == columns ? length : (i + 1) * width;
    // The triangle's height over [u0, u1]: at the apex's foot, or at the end nearer to it.
    double reach = height;
    if (u1 < foot)
    {
      reach = height * u1 / foot;
    }
    else if (u0 > foot)
    {
      reach = height * (length - u0) / (length - foot);
    }
    const int columnRows = rowHeight > 0.0
      ? std::max(1, std::min(rows, static_cast<int>(std::ceil(reach / rowHeight))))
      : 1;
    for (int j = 0; j < columnRows; ++j)
    {
      const double v0 = j * rowHeight, v1 = j + 1 == columnRows ? reach : (j + 1) * rowHeight;
      const double u = 0.5 * (u0 + u1), v = 0.5 * (v0 + v1);
      const double centre[3] = { p0[0] + u * along[0] + v * across[0],
        p0[1] + u * along[1] + v * across[1], p0[2] + u * along[2] + v * across[2] };
      // The rectangle's half diagonal, and a margin for rounding.
      piece(centre,
        0.5 * std::sqrt((u1 - u0) * (u1 - u0) + (v1 - v0) * (v1 - v0)) * (1.0 + 1e-9) +
          1e-12 * length);
    }
  }
}

/// Triangles (or pieces of triangles) of about one size: their centroids in a k-d tree, and how
/// far each reaches.
struct SizeClass
{
  std::vector<int> Triangles;    // of the mesh, per entry
  std::vector<double> Centroids; // 3 per entry
  std::vector<double> Radii;     // the farthest corner from the centroid, per entry
  double Radius = 0.0;           // the largest of them
  PointCloud<3> Cloud{ &Centroids };
  std::unique_ptr<PointTree<3>> Tree;
};

/// A nanoflann result set that is the exact search itself: each centroid the walk offers is
/// tested against the best distance so far (its triangle cannot be nearer than the centroid's
/// distance minus the triangle's radius), and the walk's bound shrinks with the best distance.
class NearestTriangleSearch
{
public:
  /// Only triangles nearer than the square root of `bound2` can be found.
  NearestTriangleSearch(const SurfaceMesh& mesh, const double* p,
    double bound2 = std::numeric_limits<double>::infinity())
    : Best2(bound2)
    , Mesh(mesh)
    , P(p)
  {
  }

  /// Starts from triangle t (a guess: the search then only looks for nearer ones).
  void Start(int t)
  {
    this->Tested[this->TestedCount++] = t;
    this->Test(t);
  }

  void Walk(const SizeClass& sizeClass)
  {
    this->Class = &sizeClass;
    this->UpdateBound();
    sizeClass.Tree->findNeighbors(*this, this->P, nanoflann::SearchParams());
  }

  // nanoflann's result-set interface.
  size_t size() const { return 1; }
  bool full() const { return true; }
  double worstDist() const { return this->Bound2; }
  bool addPoint(double centroidDistance2, std::uint32_t index)
  {
    const double reach = std::sqrt(centroidDistance2) - this->Class->Radii[index];
    if (reach > 0.0 && reach * reach >= this->Best2)
    {
      return true;
    }
    const int t = this->Class->Triangles[index];
    // Pieces of one large triangle: it is tested once.
    if (std::find(this->Tested, this->Tested + this->TestedCount, t) !=
      this->Tested + this->TestedCount)
    {
      return true;
    }
    if (this->TestedCount < MaximumTested)
    {
      this->Tested[this->TestedCount++] = t;
    }
    if (this->Test(t))
    {
      this->UpdateBound();
    }
    return true;
  }

  int Best = -1;
  double Best2 = std::numeric_limits<double>::infinity();
  double Q[3] = { 0.0, 0.0, 0.0 };
  double W[3] = { 0.0, 0.0, 0.0 };

private:
  /// Triangle t becomes the best if it is nearer than the best so far; whether it did.
  bool Test(int t)
  {
    const auto& tri = this->Mesh.Triangles[static_cast<size_t>(t)];
    double q[3], w[3];
    ClosestPointOnTriangle(
      this->P, this->Mesh.Point(tri[0]), this->Mesh.Point(tri[1]), this->Mesh.Point(tri[2]), q, w);
    const double d2 = Distance2(q, this->P);
    if (!(d2 < this->Best2))
    {
      return false;
    }
    this->Best2 = d2;
    this->Best = t;
    std::copy(q, q + 3, this->Q);
    std::copy(w, w + 3, this->W);
    return true;
  }

  void UpdateBound()
  {
    const double bound = std::sqrt(this->Best2) + this->Class->Radius;
    this->Bound2 = bound * bound;
  }

  static constexpr int MaximumTested = 32;
  const SurfaceMesh& Mesh;
  const double* P;
  const SizeClass* Class = nullptr;
  int Tested[MaximumTested];
  int TestedCount = 0;
  double Bound2 = std::numeric_limits<double>::infinity();
};

/// Answers of earlier queries (SurfaceProjector::SetRememberAnswers): a direct-mapped table, each
/// query's slot chosen by its hash and overwritten by the next query of that slot, so nothing is
/// allocated per answer and a lookup is one memory access; a lock per group of slots for
/// queries in parallel. The table is zeroed by the system as it is touched, on huge pages
/// (ZeroedPages: a remesh's answers touch most of its 4 KiB pages, bunny00 at 1000 sites 8,520
/// slots), and a slot holds its query's guess plus 2, so a zero slot is empty.
class AnswerCache
{
public:
  AnswerCache()
    : Memory(SlotCount * sizeof(Slot))
    , Slots(static_cast<Slot*>(Memory.Data()))
  {
  }
  AnswerCache(const AnswerCache&) = delete;
  AnswerCache& operator=(const AnswerCache&) = delete;

  /// Whether `p` with `guess` was asked and its answer is still here; the answer if so.
  bool Find(const double* p, int guess, int& triangle, double q[3], double w[3])
  {
    if (!this->Slots)
    {
      return false;
    }
    const size_t index = Index(p, guess);
    std::lock_guard<std::mutex> lock(this->Locks[index % LockCount]);
    const Slot& slot = this->Slots[index];
    if (slot.Guess != guess + 2 || std::memcmp(slot.P, p, sizeof(slot.P)) != 0)
    {
      return false;
    }
    triangle = slot.Triangle;
    std::copy(slot.Q, slot.Q + 3, q);
    std::copy(slot.W, slot.W + 3, w);
    return true;
  }

  void Add(const double* p, int guess, int triangle, const double q[3], const double w[3])
  {
    if (!this->Slots)
    {
      return;
    }
    const size_t index = Index(p, guess);
    std::lock_guard<std::mutex> lock(this->Locks[index % LockCount]);
    Slot& slot = this->Slots[index];
    std::copy(p, p + 3, slot.P);
    slot.Guess = guess + 2;
    slot.Triangle = triangle;
    std::copy(q, q + 3, slot.Q);
    std::copy(w, w + 3, slot.W);
  }

private:
  static constexpr size_t SlotCount = size_t(1) << 18; // 80 bytes each: 20 MiB
  static constexpr size_t LockCount = 64;
  struct Slot
  {
    double P[3];
    int Guess; // + 2: 0 when empty
    int Triangle;
    double Q[3];
    double W[3];
  };

  static size_t Index(const double* p, int guess)
  {
    std::uint64_t bits[3];
    std::memcpy(bits, p, sizeof(bits));
    const std::uint64_t h =
      HashBits(bits, 3, static_cast<std::uint64_t>(guess + 2) * 0x9E3779B97F4A7C15ull);
    return static_cast<size_t>(h & (SlotCount - 1));
  }

  ZeroedPages Memory;
  Slot* Slots;
  std::mutex Locks[LockCount];
};
} // namespace

struct SurfaceProjector::Internals
{
  std::vector<std::unique_ptr<SizeClass>> Classes; // the most triangles first
  std::unique_ptr<AnswerCache> Cache;              // while remembering answers

  /// The search of Nearest and NearestWithin, its answer in `q` and `w` as theirs.
  int Search(const SurfaceMesh& mesh, const double* p, double bound2, int guess, double q[3],
    double w[3]) const
  {
    NearestTriangleSearch search(mesh, p, bound2);
    if (guess >= 0)
    {
      search.Start(guess);
    }
    for (const auto& sizeClass : this->Classes)
    {
      search.Walk(*sizeClass);
    }
    if (this->Cache && std::isinf(bound2)) // a bounded search is no answer to remember
    {
      this->Cache->Add(p, guess, search.Best, search.Q, search.W);
    }
    if (search.Best >= 0)
    {
      std::copy(search.Q, search.Q + 3, q);
      std::copy(search.W, search.W + 3, w);
    }
    return search.Best;
  }
};

SurfaceProjector::SurfaceProjector(const SurfaceMesh& surface)
  : Mesh(surface)
  , Internal(new Internals)
{
  const int triangles = surface.NumberOfTriangles();
  std::vector<double> centroids(3 * static_cast<size_t>(triangles));
  std::vector<double> radii(static_cast<size_t>(triangles));
  for (int t = 0; t < triangles; ++t)
  {
    const auto& tri = surface.Triangles[static_cast<size_t>(t)];
    radii[static_cast<size_t>(t)] = BoundingBall(surface.Point(tri[0]), surface.Point(tri[1]),
      surface.Point(tri[2]), &centroids[3 * static_cast<size_t>(t)]);
  }
  // Triangles far larger than most (CAD faces, long slivers) enter the trees as pieces no larger
  // than twice the median triangle nor than 1% of the diagonal (about the distances the remesh is
  // measured at): a search then visits the few pieces near the point, not every large triangle
  // whose centroid lies within its radius (cheese: 130 centroids a query).
  double pieceRadius = 0.01 * BoundingBoxDiagonal(surface);
  if (triangles > 0)
  {
    std::vector<double> sorted = radii;
    std::nth_element(sorted.begin(), sorted.begin() + triangles / 2, sorted.end());
    pieceRadius = std::min(pieceRadius, 2.0 * sorted[static_cast<size_t>(triangles / 2)]);
  }
  std::map<int, std::unique_ptr<SizeClass>> bySize; // radii a factor 4 apart
  const auto add = [&bySize](int t, const double* centroid, double radius)
  {
    std::unique_ptr<SizeClass>& sizeClass = bySize[radius > 0.0 ? std::ilogb(radius) / 2 : 0];
    if (!sizeClass)
    {
      sizeClass.reset(new SizeClass);
    }
    sizeClass->Triangles.push_back(t);
    sizeClass->Centroids.insert(sizeClass->Centroids.end(), centroid, centroid + 3);
    sizeClass->Radii.push_back(radius);
    sizeClass->Radius = std::max(sizeClass->Radius, radius);
  };
  for (int t = 0; t < triangles; ++t)
  {
    const auto& tri = surface.Triangles[static_cast<size_t>(t)];
    const double* a = surface.Point(tri[0]);
    const double* b = surface.Point(tri[1]);
    const double* c = surface.Point(tri[2]);
    const double radius = radii[static_cast<size_t>(t)];
    if (!(radius > pieceRadius))
    {
      add(t, &centroids[3 * static_cast<size_t>(t)], radius);
      continue;
    }
    CoverWithPieces(
      a, b, c, pieceRadius, [&](const double* centroid, double reach) { add(t, centroid, reach); });
  }
  for (auto& entry : bySize)
  {
    SizeClass& sizeClass = *entry.second;
    sizeClass.Tree.reset(
      new PointTree<3>(3, sizeClass.Cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)));
    this->Internal->Classes.push_back(std::move(entry.second));
  }
  // The class of most triangles most likely holds the nearest one: walked first, it sets a tight
  // bound for the others.
  std::stable_sort(this->Internal->Classes.begin(), this->Internal->Classes.end(),
    [](const std::unique_ptr<SizeClass>& a, const std::unique_ptr<SizeClass>& b)
    { return a->Triangles.size() > b->Triangles.size(); });
}

SurfaceProjector::~SurfaceProjector() = default;

void SurfaceProjector::SetRememberAnswers(bool remember)
{
  this->Internal->Cache.reset(remember ? new AnswerCache : nullptr);
}

int SurfaceProjector::NearestWithin(const double* p, double within, double q[3], double w[3]) const
{
  return this->Internal->Search(this->Mesh, p, within * within, -1, q, w);
}

int SurfaceProjector::Nearest(const double* p, double q[3], double w[3], int guess) const
{
  if (guess < 0 || guess >= this->Mesh.NumberOfTriangles())
  {
    guess = -1;
  }
  AnswerCache* cache = this->Internal->Cache.get();
  int triangle = -1;
  double remembered[6];
  if (cache && cache->Find(p, guess, triangle, remembered, remembered + 3))
  {
    if (triangle >= 0)
    {
      std::copy(remembered, remembered + 3, q);
      std::copy(remembered + 3, remembered + 6, w);
    }
    return triangle;
  }
  return this->Internal->Search(
    this->Mesh, p, std::numeric_limits<double>::infinity(), guess, q, w);
}

double SurfaceProjector::DistanceTo(const double p[3], int* guess) const
{
  double q[3], w[3];
  const int nearest = this->Nearest(p, q, w, guess ? *guess : -1);
  if (guess)
  {
    *guess = nearest;
  }
  return nearest >= 0 ? std::sqrt(Distance2(q, p)) : 0.0;
}

double SurfaceProjector::FarthestCentroid(
  const std::vector<std::array<const double*, 3>>& triangles) const
{
  double farthest = 0.0;
  int guess = -1; // the triangles are mostly neighbours (round a vertex, across an edge)
  for (const auto& t : triangles)
  {
    double c[3];
    for (int k = 0; k < 3; ++k)
    {
      c[k] = (t[0][k] + t[1][k] + t[2][k]) / 3.0;
    }
    farthest = std::max(farthest, this->DistanceTo(c, &guess));
  }
  return farthest;
}

} // namespace cvt
