// Triangle meshes as the numerical core sees them: points, oriented triangles, an optional
// density per point. Here: the repairs users expect before remeshing (degenerate and duplicate
// triangles, non-manifold vertices, orientation), topology (components, genus, boundary loops)
// and area-weighted sampling of sites.
#ifndef cvtSurfaceMesh_h
#define cvtSurfaceMesh_h

#include "cvtNumericsModule.h" // for export macro

#include <array>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace cvt
{

struct SurfaceMesh
{
  std::vector<double> Points; // x, y, z per point
  std::vector<std::array<int, 3>> Triangles;
  std::vector<double> Density; // one per point, > 0; empty = uniform
  /// The input point each point came from (repairs split and drop points); empty = itself.
  std::vector<int> SourceIds;

  int NumberOfPoints() const { return static_cast<int>(this->Points.size() / 3); }
  int NumberOfTriangles() const { return static_cast<int>(this->Triangles.size()); }
  const double* Point(int i) const { return &this->Points[3 * static_cast<size_t>(i)]; }
};

/// What RepairSurfaceMesh changed.
struct MeshRepairReport
{
  int DegenerateTriangles = 0; // zero area or a repeated point: dropped
  int JoinedAtLines = 0;       // added splitting the triangles that degenerate ones joined
  int DuplicateTriangles = 0;  // same three points as another: dropped
  int SplitEdges = 0;          // edges of more than two triangles, the extra ones detached
  int SplitEdgesApart = 0;     // of those, with every triangle apart: pairs twisted the surface
  int SplitPoints = 0;         // non-manifold points made into one point per fan
  int FlippedTriangles = 0;    // reoriented to agree with their neighbours
  int UnusedPoints = 0;        // points of no triangle: dropped
  bool Changed() const;
  /// One sentence listing what was done ("" when nothing was).
  std::string Summary() const;
};

/// Prepares a mesh for remeshing: drops degenerate and duplicate triangles and unused points
/// (where zero-area triangles joined others along a line, those are split to join there),
/// splits non-manifold edges (the triangles beyond an agreeing pair get their own copies of the
/// edge's points; where the pairs would make a component non-orientable, every triangle on
/// that component's such edges)
/// and points (one copy per fan of triangles), orients every connected component
/// consistently (closed ones outwards). Returns "" or what makes the mesh unusable: a
/// non-orientable component (with where), no triangle left.
CVTNUMERICS_EXPORT std::string RepairSurfaceMesh(SurfaceMesh& mesh, MeshRepairReport& report);

/// Makes an edge-manifold triangle list vertex-manifold: a point whose triangles form several
/// fans (sheets meeting only there) gets a copy for each fan beyond its first, numbered from
/// `numberOfPoints` on. Returns, for each copy in order, the point it copies.
CVTNUMERICS_EXPORT std::vector<int> SplitPinchedPoints(
  int numberOfPoints, std::vector<std::array<int, 3>>& triangles);

/// Whether two of `points` (flat x, y, z) lie within `tolerance` of each other (coincident ones
/// included), as a cleaning filter would merge them. May also answer true, at no more cost,
/// where over 64 points crowd one grid cell a thousand tolerances wide: the caller then cleans
/// as if there were. O(n log n).
CVTNUMERICS_EXPORT bool HasPointsWithin(const std::vector<double>& points, double tolerance);

/// A triangulation of the polygon with `corners` (x, y, z each, in order): n - 2 triangles of
/// corner indices, in the polygon's orientation, whose thinnest triangle is as wide as it can be
/// among those that all face the polygon's normal (which cover a flat polygon once), else among
/// all. O(n^3): for small polygons, and those ear cutting leaves corners out of.
CVTNUMERICS_EXPORT std::vector<std::array<int, 3>> TriangulatePolygonByAngles(
  const std::vector<double>& corners);

/// Checks coordinates and density: "" or what is wrong (NaN, infinite or beyond 1e30
/// coordinates, NaN, infinite, negative or all-zero density, wrong density size).
CVTNUMERICS_EXPORT std::string CheckSurfaceMesh(const SurfaceMesh& mesh);
/// Checks a density for a mesh of `numberOfPoints` points likewise (empty: uniform, fine).
CVTNUMERICS_EXPORT std::string CheckDensity(const std::vector<double>& density, int numberOfPoints);

struct MeshTopology
{
  int Components = 0;
  int BoundaryLoops = 0;
  int EulerCharacteristic = 0;
  int Genus = 0; // summed over the components: (2 - chi_c - loops_c) / 2
  /// Each boundary loop as its points in order (the surface on the left, as the triangles).
  std::vector<std::vector<int>> Loops;
  std::vector<int> PointComponents; // the component of each point (-1: in no triangle)
  std::vector<int> ComponentGenus;  // per component
  /// A remesh's only (RemeshTopologyOf): per component, the component of the input under most
  /// of its vertices (-1: none known).
  std::vector<int> InputComponents;
};

/// Splits directed edges (a, b) that form closed chains into simple loops of points: at a point
/// where chains meet (a pinch), each loop is cut off when the path comes back to it.
CVTNUMERICS_EXPORT std::vector<std::vector<int>> TraceLoops(
  const std::vector<std::pair<int, int>>& edges);

/// The length of the closed loop of `points` (x, y, z each) indexed by `loop` up to each of its
/// points: loop.size() + 1 values, 0 first and the whole length last.
CVTNUMERICS_EXPORT std::vector<double> LoopLengths(
  const std::vector<double>& points, const std::vector<int>& loop);

/// Topology of an edge-manifold, consistently oriented mesh (after RepairSurfaceMesh).
CVTNUMERICS_EXPORT MeshTopology ComputeMeshTopology(
  int numberOfPoints, const std::vector<std::array<int, 3>>& triangles);

/// The length of the diagonal of the box round the mesh's points, or round `points` (x, y, z).
CVTNUMERICS_EXPORT double BoundingBoxDiagonal(const SurfaceMesh& mesh);
CVTNUMERICS_EXPORT double BoundingBoxDiagonal(const std::vector<double>& points);

/// Total area, and each triangle's area times its mean density (the sampling weight).
CVTNUMERICS_EXPORT double SurfaceArea(const SurfaceMesh& mesh);

/// The area of triangle `t` of `mesh`.
CVTNUMERICS_EXPORT double TriangleArea(const SurfaceMesh& mesh, const std::array<int, 3>& t);

/// Points of the surface such that every point of it lies within about `spacing` of one: its
/// points first (in order), then points along its edges longer than `spacing`, at most `spacing`
/// apart, and inside its triangles wider than `spacing`, in rows about as far apart (about
/// area / spacing^2 of them). A remesh is measured against them: a coarse input (CAD) has edges
/// longer than the cells, whose ridges a remesh cuts across far from any input point (pig), and
/// triangles wider than them.
CVTNUMERICS_EXPORT std::vector<double> CoveringPoints(const SurfaceMesh& mesh, double spacing);

/// The triangles of `mesh` that come within `distance` of one of `points` (flat x, y, z; by
/// their bounding spheres about their centroids: a few more at most), in increasing order.
CVTNUMERICS_EXPORT std::vector<int> TrianglesNear(
  const SurfaceMesh& mesh, const std::vector<double>& points, double distance);

/// The indices whose flags are set, in increasing order.
CVTNUMERICS_EXPORT std::vector<int> Flagged(const std::vector<char>& flags);

/// The indices of `points` (flat x, y, z) closer than `distance` to one of `centres` (likewise),
/// in increasing order.
CVTNUMERICS_EXPORT std::vector<int> PointsNear(
  const std::vector<double>& points, const std::vector<double>& centres, double distance);

/// The fewest sites a component of genus `genus` needs for a remesh with its topology: 4 for
/// genus 0 (a tetrahedron; three cells on a small ball meet at its two poles only, and their two
/// triangles cover each other), 8 + 16 g for genus g.
CVTNUMERICS_EXPORT int SitesForComponent(int genus);

/// `count` points on the surface, drawn with probability proportional to area times density.
/// With the mesh's topology, every component first gets the few sites its topology needs in a
/// remesh (SitesForComponent), when `count` allows, so small parts survive.
CVTNUMERICS_EXPORT std::vector<double> SampleMeshSites(
  const SurfaceMesh& mesh, int count, std::uint64_t seed, const MeshTopology* topology = nullptr);

/// A density under which the cells of sites whose nearest-site labels are `labels` (one per
/// point of `mesh`, -1: none) and whose masses are `cellMasses` (the integral of the mesh's
/// density over each cell) already have about the sizes a CVT would give them: per point,
/// (density / mass of its cell)^2, relative to the mean (a CVT's cells have areas about
/// proportional to density^-1/2), within a factor of 10^4. Lloyd iterations under it regularise
/// sites without moving them from regions of small cells to regions of large ones.
CVTNUMERICS_EXPORT std::vector<double> DensityOfCellSizes(
  const SurfaceMesh& mesh, const std::vector<int>& labels, const std::vector<double>& cellMasses);

} // namespace cvt

#endif
