// The restricted Voronoi diagram of 3D sites on a triangle mesh, computed exactly on the CPU:
// every triangle is clipped by the bisector planes of the sites whose cells reach it (the
// triangle-first algorithm with a security radius, Levy and Bonneel 2012), in parallel over
// fixed blocks of triangles with vtkSMPTools, so the sums do not depend on the thread count.
// It is the surface engine for any manifold mesh (any genus, boundaries, several parts), and
// its dual, the restricted Delaunay triangulation, is the remesh.
#ifndef cvtRestrictedVoronoi_h
#define cvtRestrictedVoronoi_h

#include "cvtEngine.h"         // for CellSums, EngineErrors
#include "cvtNumericsModule.h" // for export macro
#include "cvtSurfaceMesh.h"

#include <array>
#include <memory>
#include <string>
#include <vector>

namespace cvt
{

/// The dual of the restricted Voronoi diagram and where each site meets the surface. Its
/// vertices are the connected parts of the restricted cells (one per site, except where a cell
/// reaches two sheets of the surface, as across a thin plate: then one per part).
struct RestrictedDual
{
  std::vector<int> Sites; // the site of each vertex
  /// Vertices whose cell parts meet at a point, oriented like the mesh.
  std::vector<std::array<int, 3>> Triangles;
  /// Per vertex (3 values each): the point of its cell part nearest to the site, the
  /// triangle holding it (-1: the cell is empty) and its barycentric coordinates there.
  std::vector<double> SurfacePoints;
  std::vector<int> SurfaceTriangles;
  std::vector<double> SurfaceBarycentric;
  /// Per vertex: the connected part of the mesh holding its cell part (a representative
  /// triangle's index; -1: none). Empty: the mesh is taken as one part.
  std::vector<int> Parts;
  /// Per vertex: whether its cell part meets the mesh's border; whether it meets the border or a
  /// sharp feature line (edges whose triangles meet at more than 60 degrees, in lines spanning
  /// 15% of the bounding-box diagonal with few junctions), and then the point of those lines it
  /// is pinned to in the remesh (a corner of its cell, else the point nearest to the centroid of
  /// its part of the lines), with triangle and barycentric coordinates as above.
  std::vector<char> OnBoundary;
  std::vector<char> Pinned;
  std::vector<double> BoundaryPoints;
  std::vector<int> BoundaryTriangles;
  std::vector<double> BoundaryBarycentric;
  /// Per vertex: the Euler characteristic of its cell part, 1 for a topological disk. A part
  /// that is not a disk (a ring around a tube thinner than the cells, a cell around a small
  /// hole or handle) has no dual triangles to show what it wraps, so the remesh would lose it.
  std::vector<int> EulerCharacteristic;
  /// Surface points (x, y, z) where added sites would cut the non-disk parts into disks, and
  /// split pairs of parts that meet along several curves (round a thin part: their dual edge
  /// has more than two triangles). A part that is a disk but for holes of the mesh far smaller
  /// than itself (boundary loops it holds whole, shorter than half the distance from its site to
  /// the nearest other) is not cut: no site could keep such holes, and the remesh opens them
  /// (OpenCoveredHoles).
  std::vector<double> SplitPoints;
  /// How many parts SplitPoints cuts (parts that are not disks or that wrap round a thin
  /// part): the remesh loses what they cover.
  int ThinParts = 0;
};

/// Under MPI (ShareWork) each part clips its share of the blocks of triangles for the cell
/// sums; the dual is computed whole by every part.
class CVTNUMERICS_EXPORT RestrictedVoronoi
  : public EngineErrors
  , public SharedCellSums
{
public:
  RestrictedVoronoi();
  ~RestrictedVoronoi();
  RestrictedVoronoi(const RestrictedVoronoi&) = delete;
  RestrictedVoronoi& operator=(const RestrictedVoronoi&) = delete;

  /// The surface (edge-manifold and consistently oriented: see RepairSurfaceMesh).
  bool SetMesh(const SurfaceMesh& mesh);
  /// Replaces the mesh's density (CheckDensity: a finite value >= 0 per point, not zero
  /// everywhere; empty: uniform) and keeps the rest of what SetMesh found (edges, borders,
  /// feature lines): far quicker than SetMesh again.
  bool SetDensity(const std::vector<double>& density);
  /// Sites as flat x, y, z; any number from 1 on, anywhere in space.
  bool SetSites(const std::vector<double>& sites);
  /// Mass, moments about the site (x, y, z) and energy of every restricted cell, with the
  /// mesh's density interpolated linearly over each triangle (exact integrals).
  bool ComputeCellSums(CellSums& sums);
  /// The same sums over the listed triangles alone (the rest of the mesh is not clipped): exact
  /// for the cells that lie within them whole, partial for those they cut short. For Lloyd steps
  /// of a few sites among others that stay, at a fraction of the cost of the whole mesh. In
  /// `reachBeyond`, per site: whether its cell reaches a listed triangle next to one not listed
  /// (it may go on beyond the list). The point labels are then those of the listed triangles'
  /// points alone.
  bool ComputeCellSums(
    const std::vector<int>& triangles, CellSums& sums, std::vector<char>& reachBeyond);
  /// The restricted Delaunay triangles and surface points of the current sites.
  bool ComputeDual(RestrictedDual& dual);
  /// The nearest site of every mesh point, from the last ComputeCellSums or ComputeDual.
  const std::vector<int>& GetPointLabels() const;

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
};

/// Moves the sites from `first` on, and those within `radius` of them, to their cells'
/// centroids, `iterations` times; the other sites stay. Only the triangles within reach of the
/// moving sites are clipped (1.25 site spacings, `spacing` each: LocalSettlingReach); where a
/// moving cell reaches the edge of them, those within twice as many, up to 5
/// (LocalSettlingFarthestReach), and then the whole mesh: the moving cells' sums are those of the
/// whole mesh. The engine is left with the sites as they were before the last move. False, and
/// `error`, when the engine fails, `first` is beyond the sites or `spacing` is not positive.
CVTNUMERICS_EXPORT bool SettleSitesLocally(RestrictedVoronoi& engine, const SurfaceMesh& mesh,
  size_t first, double radius, double spacing, int iterations, std::vector<double>& sites,
  std::string& error);

} // namespace cvt

#endif
