#include "cvtRestrictedVoronoi.h"

#include "cvtEdgeTable.h"
#include "cvtGeometry.h"
#include "cvtPointCloud.h"
#include "cvtThreads.h"
#include "cvtUnionFind.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <unordered_map>

namespace cvt
{

namespace
{
/// A vertex of a clipped triangle. Label names the edge to the next vertex: -1 - e for edge e
/// of the mesh triangle (from local vertex e to e + 1), j >= 0 for the bisector with site j.
/// Origin is the local mesh vertex it is (0..2), or -1 for a computed point.
struct PolygonVertex
{
  double P[3];
  int Label;
  int Origin;
};

constexpr int MaximumPolygonSize = 64;
struct Polygon
{
  PolygonVertex V[MaximumPolygonSize];
  int Size = 0;
};

/// One restricted cell's part in one triangle, integrated.
struct Piece
{
  int Site;
  double Mass, Moment[3], Energy;
};

/// What the dual pass learns about a site from one triangle (one per cell and triangle: a
/// million for a large mesh, hence small).
struct SiteContact
{
  int Site;
  int Triangle;
  double Distance2; // from the site to the nearest point of its part of the triangle
  double Point[3];
  double BoundaryDistance2; // corners: from the site to BoundaryPoint
  double BoundaryPoint[3];
  double Area;        // of this piece of the cell
  double Centroid[3]; // of this piece of the cell
  // The parts of the mesh border in this piece of the cell (at most one per triangle edge):
  // SegmentCount segments from FirstSegment in the list's Segments.
  int FirstSegment;
  std::uint8_t SegmentCount;
  std::uint8_t BoundaryRank; // 0: none, 1: boundary edge point, 2: boundary corner
  std::uint8_t EdgeMask;     // bit e: the piece runs along edge e of its triangle (length > 0)
  std::uint8_t CornerMask;   // bit k: the piece holds corner k of its triangle
  bool TouchesBorder;        // one of the segments is on the mesh's border (not a feature line)
};

/// The contacts of a block of triangles, and the border segments they hold (x0 y0 z0 x1 y1 z1).
struct ContactList
{
  std::vector<SiteContact> Contacts;
  std::vector<std::array<double, 6>> Segments;
};

/// Nearest sites kept per site for clipping (more are asked of the k-d tree when a cell needs
/// them, rarely). 12 is quicker than 20 (fewer found per site and iteration) and than 8 (more
/// fallbacks to the tree): turbine, bunny, armadillo and spider at 1000 sites.
constexpr int NeighborCount = 12;
/// Nearest sites searched per site: the NeighborCount nearest clip, and all of them stay the
/// candidates of the next evaluations while it is certain that the NeighborCount nearest are
/// still among them (SetSites). 24 reach the hexagonal ring beyond the 12 (2.65 spacings
/// against 1.73), a margin of a spacing for the sites' moves. 32 and 40 (the same outputs) took
/// as long or longer (homer, armadillo, man and bunny at 1000 and 5000 sites, medians of 3).
constexpr int CandidateCount = 24;
constexpr double CornerAngleDegrees = 60.0;
/// Edges whose triangles' normals differ by more are sharp (CAD models' creases) ...
constexpr double FeatureAngleDegrees = 60.0;
/// ... when the lines they form span at least this fraction of the bounding-box diagonal and
/// meet at few junctions (scanner noise and sliver triangles make small webs of sharp edges).
constexpr double MinimumFeatureExtent = 0.15;
/// Lloyd iterations of a few sites among others that stay clip only the triangles within this
/// many site spacings of the moving sites (SettleSitesLocally): a cell reaches about 0.6 of one
/// from its site, and a settling site moves a fraction of one. Where a moving cell still reaches
/// the edge of them (cells stretched round holes), the reach doubles for the iterations left, up
/// to the farthest reach, and beyond that the whole mesh is clipped. The moving cells' sums are
/// exact either way, so the reach trades clipping against such retries, not accuracy: against a
/// fixed reach of 2.5 with the whole mesh beyond, remeshes are byte-identical on 65 CGAL meshes
/// at 1000 and 5000 sites and 25 with borders. Armadillo subdivided to 832k triangles settles its
/// added sites in 0.72 s instead of 1.03. A fixed 1.25 had every iteration of elephant-with-holes
/// and b9_mesh clip the whole mesh; doubling, they reach 2.5 or 5 and none does.
constexpr double LocalSettlingReach = 1.25;
constexpr double LocalSettlingFarthestReach = 5.0;

/// The dual pass's pieces (one per cell and triangle) in triangle order: those of triangle t
/// are [First[t], First[t + 1]), a few at most. What the joins and Euler characteristics read of
/// them side by side (a neighbour's mask read from its SiteContact, 120 bytes and out of cache,
/// took 60% of FindNonDiskParts).
struct PieceIndex
{
  std::vector<int> First;
  std::vector<int> Triangle;
  std::vector<int> Site;
  std::vector<std::uint8_t> EdgeMask;   // SiteContact::EdgeMask
  std::vector<std::uint8_t> CornerMask; // SiteContact::CornerMask
  /// The piece of `site`'s cell in `triangle`, or -1.
  int Of(int site, int triangle) const
  {
    for (int p = this->First[triangle]; p < this->First[triangle + 1]; ++p)
    {
      if (this->Site[p] == site)
      {
        return p;
      }
    }
    return -1;
  }
};
}

namespace
{
/// Adds a cell's piece of a triangle to its cell's sums.
void AddPiece(const Piece& piece, CellSums& sums)
{
  sums.Mass[piece.Site] += piece.Mass;
  sums.MomentX[piece.Site] += piece.Moment[0];
  sums.MomentY[piece.Site] += piece.Moment[1];
  sums.MomentZ[piece.Site] += piece.Moment[2];
  sums.Energy[piece.Site] += piece.Energy;
}
}

struct RestrictedVoronoi::Internals
{
  SurfaceMesh Mesh;
  std::vector<double> Normals; // unit normal per triangle
  /// Per triangle edge: 0 inside, 1 on the mesh's border, 2 on a sharp feature line. Cells that
  /// meet a border or feature line are pinned to it in the remesh.
  std::vector<std::array<char, 3>> OnMeshBoundary;
  std::vector<char> Corner; // per point: where a border or feature line turns, ends or meets
  void FindBordersAndFeatures(const EdgeTable& edges);

  std::vector<double> Sites;
  PointCloud<3> Cloud;
  std::unique_ptr<PointTree<3>> Tree;
  int K = 0;                            // neighbours stored per site
  std::vector<std::uint32_t> Neighbors; // K per site, nearest first
  std::vector<double> NeighborDistance2;
  int C = 0;                             // candidates stored per site
  std::vector<std::uint32_t> Candidates; // C per site, nearest first
  std::vector<double> CandidateReach;    // per site: every other site lies at least this far
  std::vector<double> PreviousSites;     // where the sites were when the candidates were found
  /// Finds the neighbours of sites [begin, end), which moved by at most `largestMove` since
  /// their candidates were found (infinity: not found).
  void FindNeighbors(int begin, int end, double largestMove);

  /// Per triangle: density-weighted mass, centroid and integral of rho |x - centroid|^2, so a
  /// triangle inside one cell costs a few operations: E = J + m |g - s|^2.
  std::vector<Piece> TriangleMoments;
  void ComputeTriangleMoments();

  std::vector<int> PointLabels;
  int BlockCount = 1;
  std::vector<std::vector<Piece>> BlockPieces;
  std::vector<std::vector<std::array<int, 4>>> BlockTriples; // sites i, j, k and the triangle
  std::vector<std::array<int, 3>> Adjacent; // per triangle edge: the triangle across it, or -1
  std::vector<int> TriangleParts;           // per triangle: its connected part of the mesh
  /// The mesh's boundary loops (points joined by border edges): per point, its loop or -1; per
  /// loop, its number of border edges and its length.
  std::vector<int> LoopOfPoint;
  std::vector<int> LoopEdges;
  std::vector<double> LoopLength;
  std::vector<ContactList> BlockContacts;

  /// Labels the mesh's points (those listed, if given) with their nearest sites.
  void LabelPoints(const std::vector<int>* points = nullptr);
  /// Clips the triangles of blocks [firstBlock, lastBlock) (all of them for the dual): into the
  /// pieces' integrals (BlockPieces), or for the dual into their contacts and the triples of
  /// cells meeting at points (BlockContacts, BlockTriples).
  void Sweep(bool dual, int firstBlock, int lastBlock);
  /// Nearest sites of one site beyond the stored ones, nearest first.
  struct NeighborList
  {
    std::vector<std::uint32_t> Ids;
    std::vector<double> D2;
  };
  /// Per thread: more neighbours when the stored ones do not suffice, and the cells queued for
  /// one triangle (a large triangle, as in CAD models, can meet thousands of cells).
  struct Scratch
  {
    /// Per site: the longest list asked of the tree in these blocks, for the site's other
    /// triangles, where the stored neighbours do not suffice (thin plates: the nearest 12 are
    /// the rings of both faces). Asking again per triangle took 3% more time on Cura's 91
    /// printer models at 1000 sites (median), for the same cells.
    std::unordered_map<int, NeighborList> More;
    std::vector<int> Queue;
    std::vector<int> Stamp; // per site: the mark of the last triangle that queued it
    int Mark = 0;
  };
  void ProcessTriangle(int t, bool dual, std::vector<Piece>& pieces,
    std::vector<std::array<int, 4>>& triples, ContactList& contacts, Scratch& scratch) const;
  const Polygon* ClipToCell(
    int t, int site, Polygon& polygon, Polygon& spare, Scratch& scratch) const;
  void Integrate(int t, const double* s, const Polygon& polygon, Piece& piece) const;
  void WholeTriangle(int t, Polygon& polygon) const;
  void Barycentric(int t, const double* p, double* lambda) const;
  /// Appends the contact of `site`'s piece `polygon` of triangle t to `list`.
  void Contact(int t, int site, const Polygon& polygon, ContactList& list) const;
  /// ComputeDual's arrays per piece, kept from one call to the next: made afresh, their pages
  /// were faulted in again on some calls (1654 faults a dual on armadillo at 5000 sites, about
  /// 10 us each here).
  struct DualWork
  {
    std::vector<const SiteContact*> Pieces;               // in triangle order (Index)
    std::vector<const std::array<double, 6>*> SegmentsOf; // per piece: its border segments
    PieceIndex Index;
    std::vector<std::array<int, 3>> SameCellAcross; // per piece and edge: the joins of Parts
    UnionFind Parts{ 0 };                           // the pieces joined into cell parts
    std::vector<int> HolderOfPoint;                 // per mesh point: the first piece holding it
    std::vector<std::uint8_t> FirstHolder;          // bit k: the first of its cell to hold corner k
    std::vector<int> VertexOfRoot;                  // per union-find root: its dual vertex
    std::vector<int> VertexOfPiece;                 // the dual vertex (cell part) of each piece
    std::vector<int> PieceEuler;                    // FindNonDiskParts: what each piece adds
    std::vector<std::uint8_t> Unpaired;             // bit k: edge k has no triangle across
  };
  DualWork Work;
  /// The Euler characteristic of each cell part, and where sites would cut the parts that are
  /// not disks, from the pieces in `work`.
  void FindNonDiskParts(DualWork& work, RestrictedDual& dual) const;
};

//------------------------------------------------------------------------------
void RestrictedVoronoi::Internals::Barycentric(int t, const double* p, double* lambda) const
{
  const auto& tri = this->Mesh.Triangles[t];
  const double* a = this->Mesh.Point(tri[0]);
  const double* b = this->Mesh.Point(tri[1]);
  const double* c = this->Mesh.Point(tri[2]);
  const double e1[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
  const double e2[3] = { c[0] - a[0], c[1] - a[1], c[2] - a[2] };
  const double w[3] = { p[0] - a[0], p[1] - a[1], p[2] - a[2] };
  const double g11 = Dot(e1, e1), g12 = Dot(e1, e2), g22 = Dot(e2, e2);
  const double r1 = Dot(w, e1), r2 = Dot(w, e2);
  const double det = g11 * g22 - g12 * g12;
  const double u = det > 0.0 ? (g22 * r1 - g12 * r2) / det : 0.0;
  const double v = det > 0.0 ? (g11 * r2 - g12 * r1) / det : 0.0;
  lambda[0] = 1.0 - u - v;
  lambda[1] = u;
  lambda[2] = v;
}

//------------------------------------------------------------------------------
void RestrictedVoronoi::Internals::WholeTriangle(int t, Polygon& polygon) const
{
  const auto& tri = this->Mesh.Triangles[t];
  polygon.Size = 3;
  for (int k = 0; k < 3; ++k)
  {
    // Element by element: std::copy of three doubles was a call to memmove (4% of a remesh).
    const double* corner = this->Mesh.Point(tri[k]);
    polygon.V[k].P[0] = corner[0];
    polygon.V[k].P[1] = corner[1];
    polygon.V[k].P[2] = corner[2];
    polygon.V[k].Label = -1 - k;
    polygon.V[k].Origin = k;
  }
}

//------------------------------------------------------------------------------
// Clips triangle t to the Voronoi cell of `site`: by the bisectors of its neighbours, nearest
// first, until no further neighbour can reach the polygon (security radius). Mesh-edge points
// are computed from the edge's end points in a fixed order, so the two triangles of an edge
// agree on them exactly. Clipping alternates between `polygon` and `spare` (no copies); returns
// the one that holds the result, or nullptr when it is empty.
// Tried and not taken (cvtBenchmark dual, armadillo at 1000 sites; same results): keeping each
// vertex less the site, which saves three subtractions per vertex and bisector, and clipping by
// the triangle's other corner sites first, to shrink the polygon sooner (8.80 million bisector
// tests against 8.76): no gain beyond the machine's noise. The bisector tests are about 5 per
// call, most of them the nearest neighbours, which clip.
const Polygon* RestrictedVoronoi::Internals::ClipToCell(
  int t, int site, Polygon& polygon, Polygon& spare, Scratch& scratch) const
{
  const auto& tri = this->Mesh.Triangles[t];
  this->WholeTriangle(t, polygon);
  const double* s = &this->Sites[3 * static_cast<size_t>(site)];
  const size_t siteCount = this->Sites.size() / 3;
  const std::uint32_t* ids = &this->Neighbors[static_cast<size_t>(site) * this->K];
  const double* d2 = &this->NeighborDistance2[static_cast<size_t>(site) * this->K];
  size_t available = static_cast<size_t>(this->K);
  Polygon* current = &polygon;
  Polygon* clipped = &spare;
  double dist[MaximumPolygonSize];
  double radius2 = -1.0; // of the polygon about the site; < 0: to be computed
  for (size_t n = 0;; ++n)
  {
    if (n == available)
    {
      if (available >= siteCount - 1)
      {
        break; // every other site has clipped
      }
      // Rare: more neighbours are needed than are stored. Those this site needed for another
      // triangle come first, then twice as many from the tree. The same clipping: a shorter
      // exact k-nearest list of nanoflann is the start of a longer one (ties in visit order).
      NeighborList& more = scratch.More[site];
      if (more.Ids.size() <= available)
      {
        const size_t want = std::min(siteCount, 2 * (available + 1));
        more.Ids.resize(want);
        more.D2.resize(want);
        const size_t found = this->Tree->knnSearch(s, want, more.Ids.data(), more.D2.data());
        // The first result is the site itself (or a site at the same place).
        size_t keep = 0;
        for (size_t f = 0; f < found; ++f)
        {
          if (more.Ids[f] != static_cast<std::uint32_t>(site))
          {
            more.Ids[keep] = more.Ids[f];
            more.D2[keep] = more.D2[f];
            ++keep;
          }
        }
        more.Ids.resize(keep);
        more.D2.resize(keep);
      }
      if (more.Ids.size() <= available)
      {
        break;
      }
      ids = more.Ids.data();
      d2 = more.D2.data();
      available = more.Ids.size();
    }
    if (radius2 < 0.0)
    {
      radius2 = 0.0;
      for (int v = 0; v < current->Size; ++v)
      {
        radius2 = std::max(radius2, Distance2(current->V[v].P, s));
      }
    }
    if (4.0 * radius2 < d2[n])
    {
      break; // this neighbour and all further ones are beyond the polygon
    }
    const int j = static_cast<int>(ids[n]);
    const double* q = &this->Sites[3 * static_cast<size_t>(j)];
    const double normal[3] = { q[0] - s[0], q[1] - s[1], q[2] - s[2] };
    const double offset = 0.5 * Dot(normal, normal);
    if (offset == 0.0)
    {
      // Coincident sites: the lower index takes the cell, the other gets nothing.
      if (j < site)
      {
        return nullptr;
      }
      continue;
    }
    const auto side = [&](const double* p)
    {
      const double w[3] = { p[0] - s[0], p[1] - s[1], p[2] - s[2] };
      return Dot(w, normal) - offset;
    };
    bool anyOut = false, anyIn = false;
    for (int v = 0; v < current->Size; ++v)
    {
      dist[v] = side(current->V[v].P);
      (dist[v] > 0.0 ? anyOut : anyIn) = true;
    }
    if (!anyOut)
    {
      continue;
    }
    if (!anyIn)
    {
      return nullptr;
    }
    clipped->Size = 0;
    for (int v = 0; v < current->Size && clipped->Size < MaximumPolygonSize - 1; ++v)
    {
      const PolygonVertex& a = current->V[v];
      const PolygonVertex& b = current->V[(v + 1) % current->Size];
      const double da = dist[v], db = dist[(v + 1) % current->Size];
      if (da <= 0.0)
      {
        clipped->V[clipped->Size++] = a;
      }
      if ((da <= 0.0) == (db <= 0.0))
      {
        continue;
      }
      PolygonVertex& p = clipped->V[clipped->Size++];
      p.Origin = -1;
      p.Label = da <= 0.0 ? j : a.Label;
      if (a.Label < 0)
      {
        const int e = -1 - a.Label;
        int from = tri[e], to = tri[(e + 1) % 3];
        if (from > to)
        {
          std::swap(from, to);
        }
        const double* A = this->Mesh.Point(from);
        const double* B = this->Mesh.Point(to);
        const double dA = side(A), dB = side(B);
        const double u = dA / (dA - dB);
        for (int k = 0; k < 3; ++k)
        {
          p.P[k] = A[k] + u * (B[k] - A[k]);
        }
      }
      else
      {
        const double u = da / (da - db);
        for (int k = 0; k < 3; ++k)
        {
          p.P[k] = a.P[k] + u * (b.P[k] - a.P[k]);
        }
      }
    }
    std::swap(current, clipped);
    radius2 = -1.0;
    if (current->Size < 3)
    {
      return nullptr;
    }
  }
  return current->Size >= 3 ? current : nullptr;
}

//------------------------------------------------------------------------------
// Exact integrals over the polygon (a fan of triangles) of rho, rho (x - s) and rho |x - s|^2
// with rho linear over the mesh triangle: integral of l_a l_b l_c over a triangle of area A is
// A/10, A/30 or A/60 for three, two or no equal indices.
void RestrictedVoronoi::Internals::Integrate(
  int t, const double* s, const Polygon& polygon, Piece& piece) const
{
  piece.Mass = piece.Energy = 0.0;
  piece.Moment[0] = piece.Moment[1] = piece.Moment[2] = 0.0;
  const bool uniform = this->Mesh.Density.empty();
  double rho[MaximumPolygonSize];
  if (!uniform)
  {
    const auto& tri = this->Mesh.Triangles[t];
    for (int v = 0; v < polygon.Size; ++v)
    {
      double lambda[3];
      this->Barycentric(t, polygon.V[v].P, lambda);
      rho[v] = lambda[0] * this->Mesh.Density[tri[0]] + lambda[1] * this->Mesh.Density[tri[1]] +
        lambda[2] * this->Mesh.Density[tri[2]];
    }
  }
  const double* p0 = polygon.V[0].P;
  const double u0[3] = { p0[0] - s[0], p0[1] - s[1], p0[2] - s[2] };
  for (int v = 1; v + 1 < polygon.Size; ++v)
  {
    const double* p1 = polygon.V[v].P;
    const double* p2 = polygon.V[v + 1].P;
    const double u1[3] = { p1[0] - s[0], p1[1] - s[1], p1[2] - s[2] };
    const double u2[3] = { p2[0] - s[0], p2[1] - s[1], p2[2] - s[2] };
    const double e1[3] = { p1[0] - p0[0], p1[1] - p0[1], p1[2] - p0[2] };
    const double e2[3] = { p2[0] - p0[0], p2[1] - p0[1], p2[2] - p0[2] };
    double n[3];
    Cross(e1, e2, n);
    const double area = 0.5 * std::sqrt(Dot(n, n));
    const double* u[3] = { u0, u1, u2 };
    if (uniform)
    {
      piece.Mass += area;
      for (int k = 0; k < 3; ++k)
      {
        piece.Moment[k] += area * (u0[k] + u1[k] + u2[k]) / 3.0;
      }
      piece.Energy += area / 6.0 *
        (Dot(u0, u0) + Dot(u1, u1) + Dot(u2, u2) + Dot(u0, u1) + Dot(u1, u2) + Dot(u2, u0));
      continue;
    }
    const double r[3] = { rho[0], rho[v], rho[v + 1] };
    const double sum = r[0] + r[1] + r[2];
    piece.Mass += area * sum / 3.0;
    for (int k = 0; k < 3; ++k)
    {
      piece.Moment[k] +=
        area / 12.0 * ((r[0] + sum) * u0[k] + (r[1] + sum) * u1[k] + (r[2] + sum) * u2[k]);
    }
    double energy = 0.0;
    for (int a = 0; a < 3; ++a)
    {
      for (int b = 0; b < 3; ++b)
      {
        const double ub = Dot(u[a], u[b]);
        for (int c = 0; c < 3; ++c)
        {
          const int equal = (a == b) + (b == c) + (a == c);
          energy += r[c] * ub * (equal == 3 ? 1.0 / 10.0 : (equal == 1 ? 1.0 / 30.0 : 1.0 / 60.0));
        }
      }
    }
    piece.Energy += area * energy;
  }
}

//------------------------------------------------------------------------------
// The nearest point of the polygon to its site, and its boundary part (edges on the mesh
// boundary, corners first).
void RestrictedVoronoi::Internals::Contact(
  int t, int site, const Polygon& polygon, ContactList& list) const
{
  SiteContact& contact = list.Contacts.emplace_back();
  const double* s = &this->Sites[3 * static_cast<size_t>(site)];
  const double* n = &this->Normals[3 * static_cast<size_t>(t)];
  contact.Site = site;
  contact.Triangle = t;
  contact.BoundaryRank = 0;
  contact.BoundaryDistance2 = std::numeric_limits<double>::infinity();
  contact.FirstSegment = static_cast<int>(list.Segments.size());
  contact.SegmentCount = 0;
  contact.TouchesBorder = false;
  contact.EdgeMask = 0;
  contact.CornerMask = 0;
  // Summed in locals: the contact is new memory the polygon might alias, so sums kept in it
  // were stored and read back on every step.
  double pieceArea = 0.0, centroid[3] = { 0.0, 0.0, 0.0 };
  for (int v = 1; v + 1 < polygon.Size; ++v)
  {
    const double* p0 = polygon.V[0].P;
    const double e1[3] = { polygon.V[v].P[0] - p0[0], polygon.V[v].P[1] - p0[1],
      polygon.V[v].P[2] - p0[2] };
    const double e2[3] = { polygon.V[v + 1].P[0] - p0[0], polygon.V[v + 1].P[1] - p0[1],
      polygon.V[v + 1].P[2] - p0[2] };
    double cross[3];
    Cross(e1, e2, cross);
    const double area = 0.5 * std::sqrt(Dot(cross, cross));
    pieceArea += area;
    for (int k = 0; k < 3; ++k)
    {
      centroid[k] += area * (p0[k] + polygon.V[v].P[k] + polygon.V[v + 1].P[k]) / 3.0;
    }
  }
  contact.Area = pieceArea;
  for (int k = 0; k < 3; ++k)
  {
    contact.Centroid[k] = pieceArea > 0.0 ? centroid[k] / pieceArea : polygon.V[0].P[k];
  }
  // The projection onto the plane, when it falls inside the (convex) polygon.
  const double height = (s[0] - polygon.V[0].P[0]) * n[0] + (s[1] - polygon.V[0].P[1]) * n[1] +
    (s[2] - polygon.V[0].P[2]) * n[2];
  const double q[3] = { s[0] - height * n[0], s[1] - height * n[1], s[2] - height * n[2] };
  bool inside = true;
  for (int v = 0; v < polygon.Size && inside; ++v)
  {
    const double* a = polygon.V[v].P;
    const double* b = polygon.V[(v + 1) % polygon.Size].P;
    const double e[3] = { b[0] - a[0], b[1] - a[1], b[2] - a[2] };
    const double w[3] = { q[0] - a[0], q[1] - a[1], q[2] - a[2] };
    double c[3];
    Cross(e, w, c);
    inside = Dot(c, n) >= 0.0;
  }
  if (inside)
  {
    contact.Distance2 = height * height;
    std::copy(q, q + 3, contact.Point);
  }
  else
  {
    contact.Distance2 = std::numeric_limits<double>::infinity();
  }
  const auto& tri = this->Mesh.Triangles[t];
  for (int v = 0; v < polygon.Size; ++v)
  {
    const PolygonVertex& a = polygon.V[v];
    const PolygonVertex& b = polygon.V[(v + 1) % polygon.Size];
    const double e[3] = { b.P[0] - a.P[0], b.P[1] - a.P[1], b.P[2] - a.P[2] };
    const double length2 = Dot(e, e);
    const double w[3] = { s[0] - a.P[0], s[1] - a.P[1], s[2] - a.P[2] };
    const double u = length2 > 0.0 ? std::clamp(Dot(w, e) / length2, 0.0, 1.0) : 0.0;
    const double p[3] = { a.P[0] + u * e[0], a.P[1] + u * e[1], a.P[2] + u * e[2] };
    const double d2 = Distance2(p, s);
    if (!inside && d2 < contact.Distance2)
    {
      contact.Distance2 = d2;
      std::copy(p, p + 3, contact.Point);
    }
    if (a.Origin >= 0 && this->Corner[tri[a.Origin]])
    {
      const double dc = Distance2(a.P, s);
      if (contact.BoundaryRank < 2 || dc < contact.BoundaryDistance2)
      {
        contact.BoundaryRank = 2;
        contact.BoundaryDistance2 = dc;
        std::copy(a.P, a.P + 3, contact.BoundaryPoint);
      }
    }
    if (a.Label < 0 && length2 > 0.0)
    {
      contact.EdgeMask |= static_cast<std::uint8_t>(1u << (-1 - a.Label));
    }
    if (a.Origin >= 0)
    {
      contact.CornerMask |= static_cast<std::uint8_t>(1u << a.Origin);
    }
    if (a.Label < 0 && this->OnMeshBoundary[t][-1 - a.Label] && contact.SegmentCount < 3)
    {
      contact.TouchesBorder |= this->OnMeshBoundary[t][-1 - a.Label] == 1;
      contact.BoundaryRank = std::max<std::uint8_t>(contact.BoundaryRank, 1);
      std::array<double, 6>& segment = list.Segments.emplace_back();
      std::copy(a.P, a.P + 3, segment.begin());
      std::copy(b.P, b.P + 3, segment.begin() + 3);
      ++contact.SegmentCount;
    }
  }
}

//------------------------------------------------------------------------------
// The Euler characteristic of a cell part, from its pieces alone: the part is the disjoint
// union of its parts inside triangles, inside mesh edges and at mesh points, and the Euler
// characteristic (with compact support) adds up over such a union. A convex piece without its
// triangle's border counts 1 - (its edge segments without their ends) - (its corners); an edge
// segment counts 1 - (the edge's end points it holds); a point counts 1.
void RestrictedVoronoi::Internals::FindNonDiskParts(DualWork& work, RestrictedDual& dual) const
{
  const std::vector<const SiteContact*>& pieces = work.Pieces;
  const PieceIndex& index = work.Index;
  const std::vector<int>& vertexOfPiece = work.VertexOfPiece;
  const std::vector<std::uint8_t>& firstHolder = work.FirstHolder;
  const size_t vertexCount = dual.Sites.size();
  dual.EulerCharacteristic.assign(vertexCount, 0);
  dual.SplitPoints.clear();
  dual.ThinParts = 0;
  // What the mesh edges and points the pieces hold add, each once per part. A point is counted
  // by its first holder (firstHolder); an edge between two triangles by the piece in the first
  // of them when the other triangle's piece of the cell holds it too and with the same ends.
  // Edges of one triangle or of more than two are keys (first point, second point, what it adds
  // + 1) sorted by part: few.
  std::vector<int>& pieceEuler = work.PieceEuler;
  std::vector<std::uint8_t>& unpaired = work.Unpaired;
  pieceEuler.resize(pieces.size());
  unpaired.assign(pieces.size(), 0);
  cvt::For(0, static_cast<vtkIdType>(pieces.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        const int triangle = index.Triangle[p];
        const std::uint8_t cornerMask = index.CornerMask[p], edgeMask = index.EdgeMask[p];
        const auto& tri = this->Mesh.Triangles[triangle];
        int euler = 1;
        for (int k = 0; k < 3; ++k)
        {
          const int next = (k + 1) % 3;
          const int corner = (cornerMask >> k) & 1;
          if (corner)
          {
            euler -= 1 - ((firstHolder[p] >> k) & 1);
          }
          if (!((edgeMask >> k) & 1))
          {
            continue;
          }
          const int ends = corner + ((cornerMask >> next) & 1);
          euler -= 1 - ends;
          const int across = this->Adjacent[triangle][k];
          if (across < 0)
          {
            unpaired[p] |= static_cast<std::uint8_t>(1u << k);
            continue;
          }
          // The other piece holds the edge alike and comes first (only a triangle before this
          // one can), as the joining of the pieces found it.
          bool sharedFirst = false;
          const int q = across < triangle ? work.SameCellAcross[p][k] : -1;
          const auto& other = this->Mesh.Triangles[across];
          for (int j = 0; j < 3 && q >= 0; ++j)
          {
            const int after = (j + 1) % 3;
            const bool sameEdge = std::minmax(other[j], other[after]) ==
              std::minmax(tri[k], tri[next]); // either way round
            if (sameEdge && ((index.EdgeMask[q] >> j) & 1))
            {
              const int otherEnds =
                ((index.CornerMask[q] >> j) & 1) + ((index.CornerMask[q] >> after) & 1);
              sharedFirst = otherEnds == ends;
            }
          }
          if (!sharedFirst)
          {
            euler += 1 - ends;
          }
        }
        pieceEuler[p] = euler;
      }
    });
  std::vector<std::pair<int, std::uint64_t>> otherEdges;
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    const int part = vertexOfPiece[p];
    dual.EulerCharacteristic[part] += pieceEuler[p];
    for (int k = 0; k < 3 && unpaired[p]; ++k)
    {
      if ((unpaired[p] >> k) & 1)
      {
        const auto& tri = this->Mesh.Triangles[index.Triangle[p]];
        const int next = (k + 1) % 3;
        const int ends = ((index.CornerMask[p] >> k) & 1) + ((index.CornerMask[p] >> next) & 1);
        otherEdges.emplace_back(part,
          (static_cast<std::uint64_t>(std::min(tri[k], tri[next])) << 33) |
            (static_cast<std::uint64_t>(std::max(tri[k], tri[next])) << 2) |
            static_cast<std::uint64_t>(2 - ends));
      }
    }
  }
  std::sort(otherEdges.begin(), otherEdges.end());
  otherEdges.erase(std::unique(otherEdges.begin(), otherEdges.end()), otherEdges.end());
  for (const auto& [part, key] : otherEdges)
  {
    dual.EulerCharacteristic[part] += static_cast<int>(key & 3u) - 1;
  }
  // Per part, the mesh's holes it covers: boundary loops whose border edges all lie in it alone,
  // far smaller than its cell (shorter than half the distance from its site to the nearest
  // other). No site can keep such a hole (three cells round it would meet in slivers); the
  // remesh opens it instead (OpenCoveredHoles). A part that is a disk but for them is no thin
  // part: the rounds of added sites had chased such holes in vain (a scan's missing triangles).
  std::vector<int> coveredHoles(vertexCount, 0);
  if (!this->LoopEdges.empty() && this->K > 0)
  {
    constexpr int several = -2;
    std::vector<int> holder(this->LoopEdges.size(), -1), held(this->LoopEdges.size(), 0);
    std::uint64_t previousEdge = ~std::uint64_t(0);
    int previousPart = -1;
    for (const auto& [part, key] : otherEdges)
    {
      const std::uint64_t edge = key >> 2; // its two points
      const int loop = this->LoopOfPoint[static_cast<size_t>(key >> 33)];
      if (loop < 0 || (part == previousPart && edge == previousEdge))
      {
        continue; // an edge of more than two triangles, or one held by two pieces of the part
      }
      previousPart = part;
      previousEdge = edge;
      holder[loop] = holder[loop] == -1 || holder[loop] == part ? part : several;
      ++held[loop];
    }
    for (size_t loop = 0; loop < holder.size(); ++loop)
    {
      const int part = holder[loop];
      if (part < 0 || held[loop] != this->LoopEdges[loop])
      {
        continue;
      }
      const size_t site = static_cast<size_t>(dual.Sites[part]);
      const double spacing = std::sqrt(this->NeighborDistance2[site * this->K]);
      if (this->LoopLength[loop] < 0.5 * spacing)
      {
        ++coveredHoles[part];
      }
    }
  }
  // Parts that are not disks, and parts whose shared border has several pieces (they wrap
  // round a thin part and meet on both sides: their edge has more than two triangles).
  std::vector<char> wrapping(vertexCount, 0);
  const EdgeTable edges(dual.Triangles);
  for (size_t e = 0; e < edges.NumberOfEdges(); ++e)
  {
    const EdgeTable::Range uses = edges.Edge(e);
    if (uses.size() > 2)
    {
      wrapping[uses.Key() >> 32] = wrapping[uses.Key() & 0xffffffffu] = 1;
    }
  }
  const auto notDisk = [&dual, &coveredHoles](size_t v)
  {
    const int euler = dual.EulerCharacteristic[v];
    return euler != 1 && euler + coveredHoles[v] != 1;
  };
  // Where sites would cut those parts: centroids of their pieces, 3 (1 - chi) for a part that
  // is not a disk (at least 3: a ring needs three cells round it to make triangles), 2 for
  // the others, each farthest from the part's nearest point and from those already taken.
  std::vector<std::vector<int>> piecesOfPart(vertexCount);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    if (notDisk(vertexOfPiece[p]) || wrapping[vertexOfPiece[p]])
    {
      piecesOfPart[vertexOfPiece[p]].push_back(static_cast<int>(p));
    }
  }
  for (size_t v = 0; v < vertexCount; ++v)
  {
    const std::vector<int>& own = piecesOfPart[v];
    if (own.empty())
    {
      continue;
    }
    ++dual.ThinParts;
    const int wanted = notDisk(v) ? 3 * std::max(1, 1 - dual.EulerCharacteristic[v]) : 2;
    std::vector<double> gap(own.size());
    for (size_t k = 0; k < own.size(); ++k)
    {
      gap[k] = Distance2(pieces[own[k]]->Centroid, &dual.SurfacePoints[3 * v]);
    }
    for (int n = 0; n < wanted; ++n)
    {
      const size_t far = std::max_element(gap.begin(), gap.end()) - gap.begin();
      if (!(gap[far] > 0.0))
      {
        break;
      }
      const double* point = pieces[own[far]]->Centroid;
      dual.SplitPoints.insert(dual.SplitPoints.end(), point, point + 3);
      for (size_t k = 0; k < own.size(); ++k)
      {
        gap[k] = std::min(gap[k], Distance2(pieces[own[k]]->Centroid, point));
      }
    }
  }
}

//------------------------------------------------------------------------------
void RestrictedVoronoi::Internals::ProcessTriangle(int t, bool dual, std::vector<Piece>& pieces,
  std::vector<std::array<int, 4>>& triples, ContactList& contacts, Scratch& scratch) const
{
  const auto& tri = this->Mesh.Triangles[t];
  const int l0 = this->PointLabels[tri[0]], l1 = this->PointLabels[tri[1]],
            l2 = this->PointLabels[tri[2]];
  Polygon polygon;
  Piece piece;
  if (l0 == l1 && l1 == l2)
  {
    // Voronoi cells are convex: a triangle whose corners share a site lies in its cell.
    if (dual)
    {
      this->WholeTriangle(t, polygon);
      this->Contact(t, l0, polygon, contacts);
      return;
    }
    const Piece& whole = this->TriangleMoments[t];
    const double* s = &this->Sites[3 * static_cast<size_t>(l0)];
    const double d[3] = { whole.Moment[0] - s[0], whole.Moment[1] - s[1], whole.Moment[2] - s[2] };
    piece.Site = l0;
    piece.Mass = whole.Mass;
    for (int k = 0; k < 3; ++k)
    {
      piece.Moment[k] = whole.Mass * d[k];
    }
    piece.Energy = whole.Energy + whole.Mass * Dot(d, d);
    pieces.push_back(piece);
    return;
  }
  // Breadth-first over the cells that reach the triangle, from its corners' sites.
  Polygon spare;
  const size_t siteCount = this->Sites.size() / 3;
  if (scratch.Stamp.size() != siteCount)
  {
    scratch.Stamp.assign(siteCount, 0);
    scratch.Mark = 0;
  }
  ++scratch.Mark;
  std::vector<int>& queue = scratch.Queue;
  queue.clear();
  const auto enqueue = [&scratch, &queue](int site)
  {
    if (scratch.Stamp[site] != scratch.Mark)
    {
      scratch.Stamp[site] = scratch.Mark;
      queue.push_back(site);
    }
  };
  for (int label : { l0, l1, l2 })
  {
    enqueue(label);
  }
  for (size_t next = 0; next < queue.size(); ++next)
  {
    const int site = queue[next];
    const Polygon* clipped = this->ClipToCell(t, site, polygon, spare, scratch);
    if (!clipped)
    {
      continue;
    }
    if (!dual) // the dual needs the contacts alone, not the integrals
    {
      this->Integrate(t, &this->Sites[3 * static_cast<size_t>(site)], *clipped, piece);
      piece.Site = site;
      pieces.push_back(piece);
    }
    for (int v = 0; v < clipped->Size; ++v)
    {
      const int label = clipped->V[v].Label;
      if (label >= 0)
      {
        enqueue(label);
      }
      const int before = clipped->V[(v + clipped->Size - 1) % clipped->Size].Label;
      if (dual && label >= 0 && before >= 0)
      {
        // Around this point the cells come in the order site, before, label (counter-
        // clockwise seen along the triangle's normal): the dual triangle's orientation.
        std::array<int, 3> triple = { site, before, label };
        std::rotate(triple.begin(), std::min_element(triple.begin(), triple.end()), triple.end());
        triples.push_back({ triple[0], triple[1], triple[2], t });
      }
    }
    if (dual)
    {
      this->Contact(t, site, *clipped, contacts);
    }
  }
}

//------------------------------------------------------------------------------
// Tried and not taken: keeping per point how far its site was nearer than any other, and
// skipping the points whose sites cannot have been overtaken since (the sites' largest moves
// summed): 47% of the points skipped on armadillo at 1000 sites, the same labels, no gain in
// the optimisation's time (0.592 -> 0.590 s, median of 4).
void RestrictedVoronoi::Internals::LabelPoints(const std::vector<int>* points)
{
  const int pointCount = this->Mesh.NumberOfPoints();
  const int siteCount = static_cast<int>(this->Sites.size() / 3);
  if (static_cast<int>(this->PointLabels.size()) != pointCount)
  {
    this->PointLabels.assign(pointCount, -1);
  }
  const int count = points ? static_cast<int>(points->size()) : pointCount;
  cvt::For(0, count, 1024,
    [this, siteCount, points](int begin, int end)
    {
      for (int i = begin; i < end; ++i)
      {
        const int p = points ? (*points)[static_cast<size_t>(i)] : i;
        const double* x = this->Mesh.Point(p);
        const int previous = this->PointLabels[p];
        if (previous >= 0 && previous<siteCount&& this->K> 0)
        {
          // The previous site and its neighbours; the nearest of them is the nearest of all
          // when no site beyond the neighbours can be closer (triangle inequality).
          const double* s = &this->Sites[3 * static_cast<size_t>(previous)];
          int best = previous;
          double best2 = Distance2(x, s);
          const std::uint32_t* ids = &this->Neighbors[static_cast<size_t>(previous) * this->K];
          for (int n = 0; n < this->K; ++n)
          {
            const double d2 = Distance2(x, &this->Sites[3 * static_cast<size_t>(ids[n])]);
            if (d2 < best2)
            {
              best2 = d2;
              best = static_cast<int>(ids[n]);
            }
          }
          const double reach =
            std::sqrt(
              this->NeighborDistance2[static_cast<size_t>(previous) * this->K + this->K - 1]) -
            std::sqrt(Distance2(x, s));
          if (reach > 0.0 && best2 < reach * reach)
          {
            this->PointLabels[p] = best;
            continue;
          }
        }
        std::uint32_t id = 0;
        double d2 = 0.0;
        this->Tree->knnSearch(x, 1, &id, &d2);
        this->PointLabels[p] = static_cast<int>(id);
      }
    });
}

//------------------------------------------------------------------------------
void RestrictedVoronoi::Internals::Sweep(bool dual, int firstBlock, int lastBlock)
{
  this->LabelPoints();
  const int triangleCount = this->Mesh.NumberOfTriangles();
  const int blockSize = (triangleCount + this->BlockCount - 1) / this->BlockCount;
  cvt::For(firstBlock, lastBlock, 1,
    [&](int first, int last)
    {
      Scratch scratch;
      for (int block = first; block < last; ++block)
      {
        // The block's lists are filled in this thread's own vectors (their storage swapped in
        // and back): the lists of neighbouring blocks, which other threads fill meanwhile, share
        // cache lines, and each append wrote to them (16% of ProcessTriangle's own samples fell
        // on the load of the list's end before each append).
        std::vector<Piece> pieces;
        std::vector<std::array<int, 4>> triples;
        ContactList contacts;
        pieces.swap(this->BlockPieces[block]);
        triples.swap(this->BlockTriples[block]);
        std::swap(contacts, this->BlockContacts[block]);
        pieces.clear();
        triples.clear();
        contacts.Contacts.clear();
        contacts.Segments.clear();
        const int end = std::min(triangleCount, (block + 1) * blockSize);
        for (int t = block * blockSize; t < end; ++t)
        {
          this->ProcessTriangle(t, dual, pieces, triples, contacts, scratch);
        }
        pieces.swap(this->BlockPieces[block]);
        triples.swap(this->BlockTriples[block]);
        std::swap(contacts, this->BlockContacts[block]);
      }
    });
}

//------------------------------------------------------------------------------
RestrictedVoronoi::RestrictedVoronoi()
  : SharedCellSums(Split::TriangleBlocks)
  , Impl(new Internals)
{
  UseThreads();
}

RestrictedVoronoi::~RestrictedVoronoi() = default;

const std::vector<int>& RestrictedVoronoi::GetPointLabels() const
{
  return this->Impl->PointLabels;
}

//------------------------------------------------------------------------------
// Borders (edges of one triangle) and sharp feature lines (edges of two triangles whose normals
// differ by more than FeatureAngleDegrees, in lines spanning MinimumFeatureExtent), and the
// corners of both: where a line turns by more than CornerAngleDegrees, ends or meets others.
void RestrictedVoronoi::Internals::FindBordersAndFeatures(const EdgeTable& edges)
{
  const SurfaceMesh& mesh = this->Mesh;
  const int pointCount = mesh.NumberOfPoints();
  struct Line
  {
    int A, B; // directed as in its (first) triangle
    char Kind;
    size_t Edge; // in the edge table
  };
  std::vector<Line> lines;
  const double diagonal = BoundingBoxDiagonal(mesh);
  const double sharp = std::cos(FeatureAngleDegrees * 3.14159265358979323846 / 180.0);
  for (size_t edge = 0; edge < edges.NumberOfEdges(); ++edge)
  {
    const EdgeTable::Range uses = edges.Edge(edge);
    const int t = uses.begin()->Triangle, e = uses.begin()->Local;
    const int a = mesh.Triangles[t][e], b = mesh.Triangles[t][(e + 1) % 3];
    if (uses.size() == 1)
    {
      lines.push_back({ a, b, 1, edge });
    }
    else if (uses.size() == 2 &&
      Dot(&this->Normals[3 * static_cast<size_t>(t)],
        &this->Normals[3 * static_cast<size_t>((uses.begin() + 1)->Triangle)]) < sharp)
    {
      lines.push_back({ a, b, 2, edge });
    }
  }
  // Feature lines shorter than the threshold are dropped (joined through shared points).
  UnionFind chains(static_cast<size_t>(pointCount));
  for (const Line& line : lines)
  {
    if (line.Kind == 2)
    {
      chains.Join(line.A, line.B);
    }
  }
  // The extent of each line: the diagonal of the box of its points.
  std::vector<std::array<double, 6>> box(pointCount);
  for (const Line& line : lines)
  {
    if (line.Kind != 2)
    {
      continue;
    }
    std::array<double, 6>& b = box[chains.Find(line.A)];
    if (b[0] == 0.0 && b[1] == 0.0 && b[3] == 0.0 && b[4] == 0.0 && b[2] == 0.0 && b[5] == 0.0)
    {
      b = { 1e300, 1e300, 1e300, -1e300, -1e300, -1e300 };
    }
    for (const int p : { line.A, line.B })
    {
      for (int k = 0; k < 3; ++k)
      {
        b[k] = std::min(b[k], mesh.Point(p)[k]);
        b[3 + k] = std::max(b[3 + k], mesh.Point(p)[k]);
      }
    }
  }
  // Junctions (points of three or more sharp edges) per line network, and its points: creases
  // meet at a few corners, noise makes a web of sharp edges.
  std::vector<int> sharpDegree(pointCount, 0), junctions(pointCount, 0), members(pointCount, 0);
  for (const Line& line : lines)
  {
    if (line.Kind == 2)
    {
      ++sharpDegree[line.A];
      ++sharpDegree[line.B];
    }
  }
  for (int p = 0; p < pointCount; ++p)
  {
    if (sharpDegree[p] > 0)
    {
      ++members[chains.Find(p)];
      junctions[chains.Find(p)] += sharpDegree[p] >= 3 ? 1 : 0;
    }
  }
  const auto webLike = [&](int root) { return junctions[root] > std::max(8, members[root] / 10); };
  const auto extent = [&box](int root)
  {
    const std::array<double, 6>& b = box[root];
    return std::sqrt((b[3] - b[0]) * (b[3] - b[0]) + (b[4] - b[1]) * (b[4] - b[1]) +
      (b[5] - b[2]) * (b[5] - b[2]));
  };
  std::vector<int> degree(pointCount, 0);
  std::vector<int> neighbor1(pointCount, -1), neighbor2(pointCount, -1);
  for (const Line& line : lines)
  {
    if (line.Kind == 2 &&
      (extent(chains.Find(line.A)) < MinimumFeatureExtent * diagonal ||
        webLike(chains.Find(line.A))))
    {
      continue;
    }
    for (const EdgeUse& use : edges.Edge(line.Edge))
    {
      this->OnMeshBoundary[use.Triangle][use.Local] = line.Kind; // the edge pins
    }
    for (int end = 0; end < 2; ++end)
    {
      const int p = end ? line.B : line.A, q = end ? line.A : line.B;
      (neighbor1[p] < 0 ? neighbor1[p] : neighbor2[p]) = q;
      ++degree[p];
    }
  }
  const double cosine = std::cos(CornerAngleDegrees * 3.14159265358979323846 / 180.0);
  this->Corner.assign(pointCount, 0);
  for (int p = 0; p < pointCount; ++p)
  {
    if (degree[p] == 0)
    {
      continue;
    }
    if (degree[p] != 2)
    {
      this->Corner[p] = 1; // a line ends here, or lines meet
      continue;
    }
    const double* x = mesh.Point(p);
    const double* a = mesh.Point(neighbor1[p]);
    const double* b = mesh.Point(neighbor2[p]);
    const double in[3] = { x[0] - a[0], x[1] - a[1], x[2] - a[2] };
    const double out[3] = { b[0] - x[0], b[1] - x[1], b[2] - x[2] };
    const double lengths = std::sqrt(Dot(in, in) * Dot(out, out));
    this->Corner[p] = lengths > 0.0 && Dot(in, out) < cosine * lengths;
  }
}

//------------------------------------------------------------------------------
bool RestrictedVoronoi::SetMesh(const SurfaceMesh& mesh)
{
  Internals& d = *this->Impl;
  if (mesh.Triangles.empty())
  {
    return this->Fail("the mesh has no triangles");
  }
  d.Mesh = mesh;
  const int triangleCount = mesh.NumberOfTriangles();
  d.Normals.assign(3 * static_cast<size_t>(triangleCount), 0.0);
  d.OnMeshBoundary.assign(triangleCount, { 0, 0, 0 });
  for (int t = 0; t < triangleCount; ++t)
  {
    const auto& tri = mesh.Triangles[t];
    UnitNormal(mesh.Point(tri[0]), mesh.Point(tri[1]), mesh.Point(tri[2]),
      &d.Normals[3 * static_cast<size_t>(t)]);
  }
  const EdgeTable edges(mesh.Triangles);
  d.FindBordersAndFeatures(edges);
  // The triangle across each edge (edges of exactly two triangles), for the dual's components.
  d.Adjacent.assign(triangleCount, { -1, -1, -1 });
  for (int t = 0; t < triangleCount; ++t)
  {
    for (int e = 0; e < 3; ++e)
    {
      const EdgeTable::Range uses = edges.At(t, e);
      if (uses.size() == 2)
      {
        const EdgeUse& first = *uses.begin();
        d.Adjacent[t][e] = first.Triangle != t ? first.Triangle : (uses.begin() + 1)->Triangle;
      }
    }
  }
  // The boundary loops: border edges joined through their points.
  UnionFind loops(static_cast<size_t>(mesh.NumberOfPoints()));
  for (int t = 0; t < triangleCount; ++t)
  {
    for (int e = 0; e < 3; ++e)
    {
      if (d.OnMeshBoundary[t][e] == 1)
      {
        loops.Join(mesh.Triangles[t][e], mesh.Triangles[t][(e + 1) % 3]);
      }
    }
  }
  d.LoopOfPoint.assign(mesh.NumberOfPoints(), -1);
  d.LoopEdges.clear();
  d.LoopLength.clear();
  std::vector<int> loopOfRoot(mesh.NumberOfPoints(), -1);
  for (int t = 0; t < triangleCount; ++t)
  {
    for (int e = 0; e < 3; ++e)
    {
      if (d.OnMeshBoundary[t][e] != 1)
      {
        continue;
      }
      const int a = mesh.Triangles[t][e], b = mesh.Triangles[t][(e + 1) % 3];
      int& loop = loopOfRoot[loops.Find(a)];
      if (loop < 0)
      {
        loop = static_cast<int>(d.LoopEdges.size());
        d.LoopEdges.push_back(0);
        d.LoopLength.push_back(0.0);
      }
      d.LoopOfPoint[a] = d.LoopOfPoint[b] = loop;
      ++d.LoopEdges[loop];
      d.LoopLength[loop] += std::sqrt(Distance2(mesh.Point(a), mesh.Point(b)));
    }
  }
  UnionFind parts(static_cast<size_t>(triangleCount));
  for (int t = 0; t < triangleCount; ++t)
  {
    for (int across : d.Adjacent[t])
    {
      if (across >= 0)
      {
        parts.Join(t, across);
      }
    }
  }
  d.TriangleParts.resize(triangleCount);
  for (int t = 0; t < triangleCount; ++t)
  {
    d.TriangleParts[t] = parts.Find(t);
  }
  // Fixed blocks of triangles: the sums are added in the same order for any thread count.
  d.BlockCount = std::max(1, std::min(256, triangleCount / 256));
  d.BlockPieces.assign(d.BlockCount, {});
  d.BlockTriples.assign(d.BlockCount, {});
  d.BlockContacts.assign(d.BlockCount, {});
  d.PointLabels.assign(mesh.NumberOfPoints(), -1);
  d.ComputeTriangleMoments();
  return true;
}

void RestrictedVoronoi::Internals::ComputeTriangleMoments()
{
  const int triangleCount = this->Mesh.NumberOfTriangles();
  this->TriangleMoments.resize(triangleCount);
  cvt::For(0, triangleCount, 4096,
    [this](int begin, int end)
    {
      Polygon polygon;
      for (int t = begin; t < end; ++t)
      {
        this->WholeTriangle(t, polygon);
        Piece about;
        this->Integrate(t, polygon.V[0].P, polygon, about);
        Piece& whole = this->TriangleMoments[t];
        whole.Mass = about.Mass;
        for (int k = 0; k < 3; ++k)
        {
          // Stored in Moment: the centroid.
          whole.Moment[k] =
            polygon.V[0].P[k] + (about.Mass > 0.0 ? about.Moment[k] / about.Mass : 0.0);
        }
        this->Integrate(t, whole.Moment, polygon, about);
        whole.Energy = about.Energy;
      }
    });
}

//------------------------------------------------------------------------------
bool RestrictedVoronoi::SetDensity(const std::vector<double>& density)
{
  Internals& d = *this->Impl;
  if (d.Mesh.Triangles.empty())
  {
    return this->Fail("set a mesh before its density");
  }
  const std::string problem = CheckDensity(density, d.Mesh.NumberOfPoints());
  if (!problem.empty())
  {
    return this->Fail(problem);
  }
  d.Mesh.Density = density;
  d.ComputeTriangleMoments();
  return true;
}

//------------------------------------------------------------------------------
// The k-d tree's searches were a quarter of an optimisation on small meshes. Late in it the
// sites move by a small part of their spacing per evaluation: a site that moved by m, while
// none moved by more than M, is still nearer to its candidates than to any other site when its
// K-th nearest candidate is nearer than its reach less m + M (triangle inequality: the others
// lay beyond the reach and came at most m + M closer). Then the candidates, sorted again, give
// the same K nearest as the tree, and the reach shrinks by m + M; else the tree is asked.
// Tried and not taken: M as the largest move round each site alone (per cell of a grid as wide
// as the reaches), which a line search's leap of a few sites elsewhere leaves small. The same
// outputs and 8 to 12% fewer searches (homer and man at 1000 and 5000 sites): L-BFGS moves
// most sites alike, and no time was saved beyond the machine's noise.
void RestrictedVoronoi::Internals::FindNeighbors(int begin, int end, double largestMove)
{
  std::uint32_t ids[CandidateCount + 1];
  double d2[CandidateCount + 1];
  const size_t k = static_cast<size_t>(this->K), c = static_cast<size_t>(this->C);
  for (int i = begin; i < end; ++i)
  {
    const double* site = &this->Sites[3 * static_cast<size_t>(i)];
    std::uint32_t* candidates = &this->Candidates[static_cast<size_t>(i) * c];
    double& reach = this->CandidateReach[static_cast<size_t>(i)];
    bool found = false;
    if (std::isfinite(largestMove))
    {
      const double nearer = reach -
        std::sqrt(Distance2(site, &this->PreviousSites[3 * static_cast<size_t>(i)])) - largestMove;
      if (nearer > 0.0)
      {
        // Insertion sort by the distances now (the order changes little).
        for (size_t n = 0; n < c; ++n)
        {
          const std::uint32_t id = candidates[n];
          const double dn = Distance2(site, &this->Sites[3 * static_cast<size_t>(id)]);
          size_t at = n;
          for (; at > 0 && d2[at - 1] > dn; --at)
          {
            ids[at] = ids[at - 1];
            d2[at] = d2[at - 1];
          }
          ids[at] = id;
          d2[at] = dn;
        }
        // Coincident sites take the tree's order (the cell goes to the lower index).
        found = d2[0] > 0.0 && d2[k - 1] < nearer * nearer * (1.0 - 1e-12);
        if (found)
        {
          reach = nearer;
        }
      }
    }
    if (!found)
    {
      const size_t results = this->Tree->knnSearch(site, c + 1, ids, d2);
      // The first result is the site itself (or a site at the same place): skipped. Were it not
      // among them, the last is dropped, no nearer than the others.
      size_t kept = 0;
      for (size_t f = 0; f < results && kept < c; ++f)
      {
        if (ids[f] != static_cast<std::uint32_t>(i))
        {
          ids[kept] = ids[f];
          d2[kept] = d2[f];
          ++kept;
        }
      }
      reach = std::sqrt(d2[c - 1]);
    }
    std::copy(ids, ids + c, candidates);
    std::copy(ids, ids + k, &this->Neighbors[static_cast<size_t>(i) * k]);
    std::copy(d2, d2 + k, &this->NeighborDistance2[static_cast<size_t>(i) * k]);
  }
}

//------------------------------------------------------------------------------
bool RestrictedVoronoi::SetSites(const std::vector<double>& sites)
{
  Internals& d = *this->Impl;
  if (sites.empty() || sites.size() % 3 != 0)
  {
    return this->Fail("the sites must be a non-empty list of x, y, z triples");
  }
  for (double c : sites)
  {
    if (!std::isfinite(c))
    {
      return this->Fail("a site has a NaN or infinite coordinate");
    }
  }
  const bool sameCount = d.Sites.size() == sites.size();
  d.PreviousSites.swap(d.Sites);
  d.Sites = sites;
  if (!sameCount)
  {
    d.PointLabels.assign(d.Mesh.NumberOfPoints(), -1);
  }
  d.Cloud.Points = &d.Sites;
  d.Tree.reset(new PointTree<3>(3, d.Cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10)));
  const int siteCount = static_cast<int>(sites.size() / 3);
  double largestMove = std::numeric_limits<double>::infinity();
  if (sameCount && d.C == std::min(CandidateCount, siteCount - 1))
  {
    largestMove = 0.0;
    for (size_t c = 0; c < d.Sites.size(); c += 3)
    {
      largestMove = std::max(largestMove, Distance2(&d.Sites[c], &d.PreviousSites[c]));
    }
    largestMove = std::sqrt(largestMove);
  }
  d.K = std::min(NeighborCount, siteCount - 1);
  d.C = std::min(CandidateCount, siteCount - 1);
  d.Neighbors.resize(static_cast<size_t>(siteCount) * d.K);
  d.NeighborDistance2.resize(static_cast<size_t>(siteCount) * d.K);
  d.Candidates.resize(static_cast<size_t>(siteCount) * d.C);
  d.CandidateReach.resize(static_cast<size_t>(siteCount));
  if (d.K == 0)
  {
    return true;
  }
  cvt::For(0, siteCount, 256,
    [&d, largestMove](int begin, int end) { d.FindNeighbors(begin, end, largestMove); });
  return true;
}

//------------------------------------------------------------------------------
bool RestrictedVoronoi::ComputeCellSums(CellSums& sums)
{
  Internals& d = *this->Impl;
  if (d.Mesh.Triangles.empty() || d.Sites.empty())
  {
    return this->Fail("set a mesh and sites before computing cell sums");
  }
  // Under MPI this part clips its share of the blocks of triangles (each cell's pieces are
  // summed over all parts by SumAcrossParts).
  int firstBlock = 0, lastBlock = 0;
  this->PartRange(d.BlockCount, firstBlock, lastBlock);
  d.Sweep(false, firstBlock, lastBlock);
  sums.Resize(d.Sites.size() / 3, true);
  for (int block = firstBlock; block < lastBlock; ++block)
  {
    for (const Piece& piece : d.BlockPieces[block])
    {
      AddPiece(piece, sums);
    }
  }
  if (!this->SumAcrossParts(sums))
  {
    return this->Fail("the cell sums of the other processes sharing the work did not arrive");
  }
  return true;
}

//------------------------------------------------------------------------------
bool RestrictedVoronoi::ComputeCellSums(
  const std::vector<int>& triangles, CellSums& sums, std::vector<char>& reachBeyond)
{
  Internals& d = *this->Impl;
  if (d.Mesh.Triangles.empty() || d.Sites.empty())
  {
    return this->Fail("set a mesh and sites before computing cell sums");
  }
  const int triangleCount = d.Mesh.NumberOfTriangles();
  std::vector<char> listed(static_cast<size_t>(triangleCount), 0);
  std::vector<char> listedPoint(static_cast<size_t>(d.Mesh.NumberOfPoints()), 0);
  for (int t : triangles)
  {
    if (t < 0 || t >= triangleCount)
    {
      return this->Fail("a listed triangle is not one of the mesh's");
    }
    listed[static_cast<size_t>(t)] = 1;
    for (int p : d.Mesh.Triangles[static_cast<size_t>(t)])
    {
      listedPoint[static_cast<size_t>(p)] = 1;
    }
  }
  const std::vector<int> points = Flagged(listedPoint);
  d.LabelPoints(&points);
  // Fixed chunks of the list, summed in their order: the sums do not depend on the threads. Per
  // piece, whether its triangle is on the list's edge (next to a triangle not listed).
  const size_t chunkSize = 256;
  const size_t chunks = (triangles.size() + chunkSize - 1) / chunkSize;
  std::vector<std::vector<Piece>> chunkPieces(chunks);
  std::vector<std::vector<char>> chunkOnEdge(chunks);
  cvt::For(0, static_cast<vtkIdType>(chunks), 1,
    [&](vtkIdType first, vtkIdType last)
    {
      Internals::Scratch scratch;
      std::vector<std::array<int, 4>> triples; // of the dual: none here
      ContactList contacts;
      for (vtkIdType chunk = first; chunk < last; ++chunk)
      {
        const size_t begin = static_cast<size_t>(chunk) * chunkSize;
        const size_t end = std::min(triangles.size(), begin + chunkSize);
        std::vector<Piece>& pieces = chunkPieces[static_cast<size_t>(chunk)];
        std::vector<char>& onEdge = chunkOnEdge[static_cast<size_t>(chunk)];
        for (size_t i = begin; i < end; ++i)
        {
          const int t = triangles[i];
          d.ProcessTriangle(t, false, pieces, triples, contacts, scratch);
          const std::array<int, 3>& across = d.Adjacent[static_cast<size_t>(t)];
          onEdge.resize(pieces.size(),
            std::any_of(across.begin(), across.end(),
              [&listed](int u) { return u >= 0 && !listed[static_cast<size_t>(u)]; }));
        }
      }
    });
  sums.Resize(d.Sites.size() / 3, true);
  reachBeyond.assign(d.Sites.size() / 3, 0);
  for (size_t chunk = 0; chunk < chunks; ++chunk)
  {
    for (size_t i = 0; i < chunkPieces[chunk].size(); ++i)
    {
      const Piece& piece = chunkPieces[chunk][i];
      if (chunkOnEdge[chunk][i])
      {
        reachBeyond[static_cast<size_t>(piece.Site)] = 1;
      }
      AddPiece(piece, sums);
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool RestrictedVoronoi::ComputeDual(RestrictedDual& dual)
{
  Internals& d = *this->Impl;
  if (d.Mesh.Triangles.empty() || d.Sites.empty())
  {
    return this->Fail("set a mesh and sites before computing the dual");
  }
  d.Sweep(true, 0, d.BlockCount);
  dual = RestrictedDual();
  // The pieces (one per cell and triangle), in block order, hence in triangle order (a block
  // is a range of triangles, swept in order; indexed below by triangle and cell: PieceIndex).
  // Listed block by block in parallel: each contact is read (for its segments), out of cache.
  Internals::DualWork& work = d.Work;
  std::vector<const SiteContact*>& pieces = work.Pieces;
  std::vector<const std::array<double, 6>*>& segmentsOf = work.SegmentsOf;
  const size_t blockCount = d.BlockContacts.size();
  std::vector<size_t> blockStart(blockCount + 1, 0);
  for (size_t block = 0; block < blockCount; ++block)
  {
    blockStart[block + 1] = blockStart[block] + d.BlockContacts[block].Contacts.size();
  }
  pieces.resize(blockStart.back());
  segmentsOf.resize(blockStart.back());
  cvt::For(0, static_cast<vtkIdType>(blockCount), 1,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType block = begin; block < end; ++block)
      {
        const ContactList& list = d.BlockContacts[block];
        for (size_t i = 0; i < list.Contacts.size(); ++i)
        {
          pieces[blockStart[block] + i] = &list.Contacts[i];
          segmentsOf[blockStart[block] + i] = list.Segments.data() + list.Contacts[i].FirstSegment;
        }
      }
    });
  const int triangleCount = d.Mesh.NumberOfTriangles();
  PieceIndex& index = work.Index;
  index.Triangle.resize(pieces.size());
  index.Site.resize(pieces.size());
  index.EdgeMask.resize(pieces.size());
  index.CornerMask.resize(pieces.size());
  cvt::For(0, static_cast<vtkIdType>(pieces.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        index.Triangle[p] = pieces[p]->Triangle;
        index.Site[p] = pieces[p]->Site;
        index.EdgeMask[p] = pieces[p]->EdgeMask;
        index.CornerMask[p] = pieces[p]->CornerMask;
      }
    });
  index.First.assign(triangleCount + 1, 0);
  for (int triangle : index.Triangle)
  {
    ++index.First[triangle + 1];
  }
  std::partial_sum(index.First.begin(), index.First.end(), index.First.begin());
  // A restricted cell can have several connected parts (a thin plate: one on each side). Its
  // pieces are joined across the mesh edges they share; each part is a vertex of the dual
  // (the "multinerve"), so the remesh keeps the plate's two sides apart.
  UnionFind& parts = work.Parts;
  parts.Reset(pieces.size());
  // The piece of the same cell across each edge a piece holds: looked up in parallel, joined in
  // order, and read again by FindNonDiskParts.
  std::vector<std::array<int, 3>>& sameCellAcross = work.SameCellAcross;
  sameCellAcross.resize(pieces.size());
  cvt::For(0, static_cast<vtkIdType>(pieces.size()),
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType p = begin; p < end; ++p)
      {
        for (int e = 0; e < 3; ++e)
        {
          const int across = (index.EdgeMask[p] >> e) & 1 ? d.Adjacent[index.Triangle[p]][e] : -1;
          sameCellAcross[p][e] = across < 0 ? -1 : index.Of(index.Site[p], across);
        }
      }
    });
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    for (const int found : sameCellAcross[p])
    {
      if (found >= 0)
      {
        parts.Join(static_cast<int>(p), found);
      }
    }
  }
  // Pieces of a cell that hold the same mesh point touch there: one part (a jagged border's
  // teeth, a cell around a vertex).
  // The first piece holding each point; a point held by several cells (a tie) is rare and
  // looked up by cell.
  std::vector<int>& holderOfPoint = work.HolderOfPoint;
  holderOfPoint.assign(d.Mesh.NumberOfPoints(), -1);
  std::unordered_map<std::uint64_t, int> otherHolders;
  std::vector<std::uint8_t>& firstHolder = work.FirstHolder;
  firstHolder.assign(pieces.size(), 0);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    for (int k = 0; k < 3; ++k)
    {
      if ((index.CornerMask[p] >> k) & 1)
      {
        const int point = d.Mesh.Triangles[index.Triangle[p]][k];
        int& holder = holderOfPoint[point];
        int other = -1;
        if (holder < 0)
        {
          holder = static_cast<int>(p);
        }
        else if (index.Site[holder] == index.Site[p])
        {
          other = holder;
        }
        else
        {
          const auto found =
            otherHolders.emplace(DirectedKey(index.Site[p], point), static_cast<int>(p));
          other = found.second ? -1 : found.first->second;
        }
        if (other >= 0)
        {
          parts.Join(static_cast<int>(p), other);
        }
        else
        {
          firstHolder[p] |= static_cast<std::uint8_t>(1u << k);
        }
      }
    }
  }
  std::vector<int>& vertexOfRoot = work.VertexOfRoot;
  std::vector<int>& vertexOfPiece = work.VertexOfPiece;
  vertexOfRoot.assign(pieces.size(), -1);
  vertexOfPiece.resize(pieces.size());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    int& vertex = vertexOfRoot[parts.Find(static_cast<int>(p))];
    if (vertex < 0)
    {
      vertex = static_cast<int>(dual.Sites.size());
      dual.Sites.push_back(index.Site[p]);
    }
    vertexOfPiece[p] = vertex;
  }
  const size_t vertexCount = dual.Sites.size();
  std::vector<std::array<int, 3>> triples;
  size_t tripleCount = 0;
  for (const auto& block : d.BlockTriples)
  {
    tripleCount += block.size();
  }
  triples.reserve(tripleCount); // no copies as they are listed
  for (const auto& block : d.BlockTriples)
  {
    for (const auto& t : block)
    {
      std::array<int, 3> triangle;
      bool found = true;
      for (int k = 0; k < 3 && found; ++k)
      {
        const int piece = index.Of(t[k], t[3]);
        found = piece >= 0;
        triangle[k] = found ? vertexOfPiece[piece] : -1;
      }
      if (found && triangle[0] != triangle[1] && triangle[1] != triangle[2] &&
        triangle[2] != triangle[0])
      {
        std::rotate(
          triangle.begin(), std::min_element(triangle.begin(), triangle.end()), triangle.end());
        triples.push_back(triangle);
      }
    }
  }
  std::sort(triples.begin(), triples.end());
  triples.erase(std::unique(triples.begin(), triples.end()), triples.end());
  dual.Triangles = std::move(triples);

  const size_t siteCount = vertexCount; // below, per vertex of the dual
  dual.SurfacePoints.assign(3 * siteCount, 0.0);
  dual.SurfaceTriangles.assign(siteCount, -1);
  dual.SurfaceBarycentric.assign(3 * siteCount, 0.0);
  dual.OnBoundary.assign(siteCount, 0);
  dual.Pinned.assign(siteCount, 0);
  dual.BoundaryPoints.assign(3 * siteCount, 0.0);
  dual.BoundaryTriangles.assign(siteCount, -1);
  dual.BoundaryBarycentric.assign(3 * siteCount, 0.0);
  std::vector<double> nearest2(siteCount, std::numeric_limits<double>::infinity());
  std::vector<int> boundaryRank(siteCount, 0);
  std::vector<double> boundary2(siteCount, std::numeric_limits<double>::infinity());
  std::vector<double> borderLength(siteCount, 0.0), borderMoment(3 * siteCount, 0.0);
  std::vector<double> cellArea(siteCount, 0.0);
  std::vector<char> severalCorners(siteCount, 0);
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    {
      const SiteContact& c = *pieces[p];
      const size_t i = static_cast<size_t>(vertexOfPiece[p]);
      if (c.Distance2 < nearest2[i])
      {
        nearest2[i] = c.Distance2;
        std::copy(c.Point, c.Point + 3, &dual.SurfacePoints[3 * i]);
        dual.SurfaceTriangles[i] = c.Triangle;
      }
      if (c.BoundaryRank == 2 && boundaryRank[i] == 2 &&
        Distance2(c.BoundaryPoint, &dual.BoundaryPoints[3 * i]) > 0.0)
      {
        severalCorners[i] = 1;
      }
      if (c.BoundaryRank == 2 && (boundaryRank[i] < 2 || c.BoundaryDistance2 < boundary2[i]))
      {
        boundary2[i] = c.BoundaryDistance2;
        std::copy(c.BoundaryPoint, c.BoundaryPoint + 3, &dual.BoundaryPoints[3 * i]);
        dual.BoundaryTriangles[i] = c.Triangle;
      }
      boundaryRank[i] = std::max(boundaryRank[i], static_cast<int>(c.BoundaryRank));
      dual.OnBoundary[i] |= c.TouchesBorder ? 1 : 0;
      cellArea[i] += c.Area;
      for (int s = 0; s < c.SegmentCount; ++s)
      {
        const double* segment = segmentsOf[p][s].data();
        const double length = std::sqrt(Distance2(segment, segment + 3));
        borderLength[i] += length;
        for (int k = 0; k < 3; ++k)
        {
          borderMoment[3 * i + k] += 0.5 * length * (segment[k] + segment[3 + k]);
        }
      }
    }
  }
  // A cell that only grazes feature lines (its part of them is short for its size) is not
  // pinned, not even to a corner: moving its vertex there would make needle triangles, and
  // jagged creases (marching cubes) have many small turns.
  for (size_t i = 0; i < siteCount; ++i)
  {
    if (boundaryRank[i] > 0 && !dual.OnBoundary[i] &&
      borderLength[i] < 0.8 * std::sqrt(cellArea[i]))
    {
      boundaryRank[i] = 0;
    }
    else if (boundaryRank[i] == 2 && severalCorners[i])
    {
      boundaryRank[i] = 1; // a jagged border: its centroid, not one of its teeth
    }
  }
  // Cells on the border without a corner: pinned to the border point nearest to the centroid
  // of their part of the border (the 1D centroid), which spaces the remesh's border evenly.
  std::fill(boundary2.begin(), boundary2.end(), std::numeric_limits<double>::infinity());
  for (size_t p = 0; p < pieces.size(); ++p)
  {
    {
      const SiteContact& c = *pieces[p];
      const size_t i = static_cast<size_t>(vertexOfPiece[p]);
      if (boundaryRank[i] != 1 || !(borderLength[i] > 0.0))
      {
        continue;
      }
      const double target[3] = { borderMoment[3 * i] / borderLength[i],
        borderMoment[3 * i + 1] / borderLength[i], borderMoment[3 * i + 2] / borderLength[i] };
      for (int s = 0; s < c.SegmentCount; ++s)
      {
        const double* a = segmentsOf[p][s].data();
        const double e[3] = { a[3] - a[0], a[4] - a[1], a[5] - a[2] };
        const double w[3] = { target[0] - a[0], target[1] - a[1], target[2] - a[2] };
        const double length2 = Dot(e, e);
        const double u = length2 > 0.0 ? std::clamp(Dot(w, e) / length2, 0.0, 1.0) : 0.0;
        const double q[3] = { a[0] + u * e[0], a[1] + u * e[1], a[2] + u * e[2] };
        const double d2 = Distance2(q, target);
        if (d2 < boundary2[i])
        {
          boundary2[i] = d2;
          std::copy(q, q + 3, &dual.BoundaryPoints[3 * i]);
          dual.BoundaryTriangles[i] = c.Triangle;
        }
      }
    }
  }
  dual.Parts.assign(siteCount, -1);
  for (size_t i = 0; i < siteCount; ++i)
  {
    if (dual.SurfaceTriangles[i] >= 0)
    {
      d.Barycentric(
        dual.SurfaceTriangles[i], &dual.SurfacePoints[3 * i], &dual.SurfaceBarycentric[3 * i]);
      dual.Parts[i] = d.TriangleParts[dual.SurfaceTriangles[i]];
    }
    // A cell whose part of the border has no length (a sliver's edge, a point) has no border
    // point to be pinned to.
    dual.Pinned[i] = boundaryRank[i] > 0 && dual.BoundaryTriangles[i] >= 0;
    if (dual.Pinned[i])
    {
      d.Barycentric(
        dual.BoundaryTriangles[i], &dual.BoundaryPoints[3 * i], &dual.BoundaryBarycentric[3 * i]);
    }
  }
  d.FindNonDiskParts(work, dual);
  return true;
}

//------------------------------------------------------------------------------
bool SettleSitesLocally(RestrictedVoronoi& engine, const SurfaceMesh& mesh, size_t first,
  double radius, double spacing, int iterations, std::vector<double>& sites, std::string& error)
{
  if (sites.size() % 3 != 0 || first > sites.size() / 3 || !(spacing > 0.0) ||
    !std::isfinite(spacing))
  {
    error = "local settling needs x, y, z sites, the first moving one among them and a "
            "positive site spacing";
    return false;
  }
  const std::vector<double> added(
    sites.begin() + 3 * static_cast<std::ptrdiff_t>(first), sites.end());
  const std::vector<int> moving = PointsNear(sites, added, radius);
  std::vector<double> movingSites;
  for (int i : moving)
  {
    movingSites.insert(movingSites.end(), &sites[3 * i], &sites[3 * i] + 3);
  }
  double reach = LocalSettlingReach * spacing;
  std::vector<int> near = TrianglesNear(mesh, movingSites, reach);
  const auto beyond = [&moving](const std::vector<char>& reachBeyond)
  { return std::any_of(moving.begin(), moving.end(), [&](int i) { return reachBeyond[i]; }); };
  for (int iteration = 0; iteration < iterations; ++iteration)
  {
    CellSums sums;
    std::vector<char> reachBeyond;
    bool summed = engine.SetSites(sites) && engine.ComputeCellSums(near, sums, reachBeyond);
    while (summed && beyond(reachBeyond))
    {
      if (reach >= LocalSettlingFarthestReach * spacing)
      {
        summed = engine.ComputeCellSums(sums);
        break;
      }
      reach *= 2.0; // and so for the iterations left
      near = TrianglesNear(mesh, movingSites, reach);
      summed = engine.ComputeCellSums(near, sums, reachBeyond);
    }
    if (!summed)
    {
      error = engine.GetLastError();
      return false;
    }
    for (int i : moving)
    {
      if (sums.Mass[i] > 0.0) // moments are about the site
      {
        sites[3 * i] += sums.MomentX[i] / sums.Mass[i];
        sites[3 * i + 1] += sums.MomentY[i] / sums.Mass[i];
        sites[3 * i + 2] += sums.MomentZ[i] / sums.Mass[i];
      }
    }
  }
  return true;
}

} // namespace cvt
