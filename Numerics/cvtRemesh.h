// The remesh of a restricted CVT: its restricted Delaunay triangles, with vertices on the
// input surface (boundary sites pinned to the input's border), checked and repaired into a
// manifold mesh.
#ifndef cvtRemesh_h
#define cvtRemesh_h

#include "cvtNumericsModule.h" // for export macro
#include "cvtRestrictedVoronoi.h"
#include "cvtSurfaceMesh.h"
#include "cvtSurfaceProjector.h"

#include <algorithm>
#include <array>
#include <unordered_map>
#include <vector>

namespace cvt
{

struct Remesh
{
  std::vector<double> Points; // x, y, z per vertex
  std::vector<std::array<int, 3>> Triangles;
  std::vector<int> SiteIds;              // the site of each vertex
  std::vector<int> SourceTriangles;      // the input triangle holding each vertex
  std::vector<double> SourceBarycentric; // 3 per vertex, in that triangle
  int RemovedTriangles = 0;              // dropped to keep edges manifold
  int FilledHoles = 0;                   // small holes closed (cells meeting in a degenerate point)
  int DroppedFragments = 0;  // pieces of 1-2 triangles cut off from a larger one of their part
  int SplitVertices = 0;     // pinched vertices given one copy per extra fan
  int FlippedEdges = 0;      // diagonals flipped to widen thin triangles
  int ValenceFlips = 0;      // diagonals flipped to bring valences closer to 6
  int MovedVertices = 0;     // free vertices of thin triangles moved along the surface
  int CollapsedEdges = 0;    // edges of thin triangles collapsed (a vertex fewer each)
  int ValenceCollapses = 0;  // edges collapsed to bring valences closer to 6 (likewise)
  int SeparatedVertices = 0; // vertices at one place moved apart (split copies)
  int FittedVertices = 0;    // free vertices moved towards input tips and ridges the remesh cut off
  int StraddlingVertices = 0; // free vertices moved along their normals to straddle the input
  int OpenedHoles = 0;        // triangles taken out where the input has a hole the cells covered
  int BorderCorners = 0;      // vertices added on input border corners the remesh's border cut off
  int SlidBorderVertices = 0; // border vertices slid along the input's border to widen triangles
};

/// The input surface as remeshes are shaped and measured against it (BuildRemesh,
/// MeasureFidelity): its exact nearest points and its CoveringPoints 0.8% of its bounding-box
/// diagonal apart. Made once per input: on large inputs they cost as much as shaping a remesh.
struct CVTNUMERICS_EXPORT RemeshInput
{
  /// `surface` must outlive this; its `topology` is computed when not given.
  explicit RemeshInput(const SurfaceMesh& surface, const MeshTopology* topology = nullptr);
  RemeshInput(const RemeshInput&) = delete;
  RemeshInput& operator=(const RemeshInput&) = delete;

  /// Where a point of a boundary loop lies on it, and a triangle it is a corner of.
  struct LoopPoint
  {
    int Loop = -1;
    int Index = -1; // in Loops[Loop]
    int Triangle = -1;
    int Corner = -1;       // of Triangle
    int EdgeTriangle = -1; // the triangle of the border edge from it to the loop's next point
  };

  const SurfaceMesh& Surface;
  double Diagonal;
  SurfaceProjector Projector;
  std::vector<double> Probes; // CoveringPoints
  std::vector<double> Areas;  // the area each probe stands for (none for those off its points)
  std::vector<std::vector<int>> Loops;          // its boundary loops (MeshTopology::Loops)
  std::vector<std::vector<double>> LoopLengths; // of each loop (cvt::LoopLengths)
  std::unordered_map<int, LoopPoint> OnLoop;    // per point of a loop
  /// A place on a boundary loop: the loop (-1: none) and the length along it from its first point.
  struct BorderPlace
  {
    int Loop = -1;
    double Along = 0.0;
  };
  /// Where the point at barycentric weights `w` of `triangle` lies on the border: at a loop point,
  /// or on the border edge between two that follow each other on a loop; else no loop.
  BorderPlace PlaceOnBorder(int triangle, const double w[3]) const;
  /// Whether the surface's nearest point to p lies on its border (PlaceOnBorder).
  bool OnBorder(const double p[3]) const;
  /// BuildRemesh may collapse edges to bring valences closer to 6 (the remesh then has fewer
  /// vertices than the dual); false keeps a vertex per dual vertex.
  bool CollapseForValence = true;
};

/// Builds the remesh from the dual of the final sites: vertices are the sites' nearest surface
/// points (boundary points for cells on the border), triangles the restricted Delaunay ones;
/// triangles that would make an edge non-manifold are dropped, as are pairs on the same three
/// sites, and pieces of one or two triangles joined to the rest by no edge on a part of the
/// input that has a larger piece (RestrictedDual::Parts); vertices where sheets meet are split,
/// and holes of at most `maximumHole` edges are closed (by the triangulation whose thinnest
/// triangle is widest): those with a vertex off the input's border, and the shortest loops of
/// border cells beyond the input's number of boundary loops. Edges of nearly coplanar pairs are
/// then flipped where that widens thin triangles, or brings valences closer to 6 without a corner
/// under 30 degrees (given the input `surface`, also pairs bent by up to 90 degrees where the new
/// pair lies no farther from it; again after the moves and collapses). Given the input, free
/// vertices of triangles with a corner under 30 degrees are then moved along it where that widens
/// them, and where that is not enough an edge of theirs is collapsed (the remesh then has a vertex
/// fewer) if that widens the triangles around it; the vertices of thin triangles left, free or
/// pinned to a crease (not to the border), then search the surface around them for wider places.
/// Then vertices off the border (free or on creases) move towards input points (its vertices, and
/// points along its long edges) that lie farther than 0.8% of the input's bounding-box diagonal
/// from the remesh (tips and ridges thinner than the cells, the far crease of a band narrower than
/// them), where that brings them closer without a corner under 27 degrees.
/// Border edges whose input boundary between their ends lies farther than that from them get an end
/// moved along the border onto its farthest point (a corner of the input's border) where that cuts
/// less of it off, else are split there (the edge's free apex moving to widen the two triangles
/// where need be), while the triangles keep corners of 27 degrees; border vertices of triangles
/// with a corner under 30 degrees then slide along the border where that widens them. Edges
/// between free vertices are then collapsed where that brings the valences round them closer to 6
/// (two valence-5 vertices with 7s across their edge: a vertex fewer), keeping corners of 30
/// degrees and the remesh as close to the input, and the valence flips run again. Last,
/// where the remesh still lies farther than 0.8% from the input either way, free vertices off
/// creases and the border move along their normals so that it straddles the input (a least-squares
/// step), where that brings the remesh round them no farther from it.
CVTNUMERICS_EXPORT Remesh BuildRemesh(
  const RestrictedDual& dual, size_t inputBoundaryLoops, int maximumHole, const RemeshInput& input);
/// The same without the input (no shaping against it) or, given `surface`, with a RemeshInput
/// made for this remesh alone.
CVTNUMERICS_EXPORT Remesh BuildRemesh(const RestrictedDual& dual, size_t inputBoundaryLoops,
  int maximumHole = 8, const SurfaceMesh* surface = nullptr);

/// A triangle soup on `points` (a vertex each: a labelling's dual, cvt::DualTriangles) made
/// manifold as BuildRemesh makes a restricted dual, with no input to shape it against: triangles
/// that would double an edge or run one the same way twice dropped, the holes of at most
/// `maximumHole` edges they leave closed unless all their points are `onBorder` (per point; the
/// surface's own border), thin triangles flipped wider, pinched vertices split. Its SiteIds name
/// the points.
CVTNUMERICS_EXPORT Remesh ManifoldRemesh(const std::vector<double>& points,
  const std::vector<std::array<int, 3>>& triangles, const std::vector<char>& onBorder,
  int maximumHole = 8);

/// Holes of the input that the remesh covers (smaller than its cells: no border vertex of the
/// remesh within an edge length of them) are opened, one remesh triangle each, the one nearest
/// to the hole's middle whose corners are off the border and off the other opened triangles,
/// while the remesh has fewer boundary loops than the input. The remesh's hole is then a
/// triangle round the input's (its border a third of an edge off the hole, not on it), which
/// keeps the input's number of boundary loops without the slivers that vertices on a hole
/// smaller than the cells would make. `inputLoops`: the input's boundary loops, as points of
/// `surface`. Returns the number of holes opened (also in OpenedHoles).
CVTNUMERICS_EXPORT int OpenCoveredHoles(
  Remesh& remesh, const SurfaceMesh& surface, const std::vector<std::vector<int>>& inputLoops);

/// How far a remesh and its input lie from each other.
struct RemeshFidelity
{
  double InputToRemesh = 0.0;    // the farthest input point from the remesh, share of the diagonal
  double RemeshToInput = 0.0;    // the farthest remesh point from the input, likewise
  std::vector<double> FarPoints; // input points where either is beyond the share asked for
  std::vector<char> FarOnBorder; // per far point: whether it lies on the input's border
  /// Per probe of the input (RemeshInput::Probes): its distance to the remesh and a nearest
  /// remesh triangle, for measuring a remesh that differs from this one in places.
  std::vector<double> ProbeDistances;
  std::vector<int> ProbeTriangles;
  /// Input points between the probes (near those that lie almost as far as the share asked
  /// for), measured likewise.
  std::vector<double> FinerProbes;
  std::vector<double> FinerProbeDistances;
  std::vector<int> FinerProbeTriangles;
  /// The remesh's own points it was measured at (CoveringPoints, then those between them) and
  /// their distances to the input.
  std::vector<double> RemeshPoints;
  std::vector<double> RemeshPointDistances;

  /// The two-way distance: the farther of the two ways.
  double TwoWay() const { return std::max(this->InputToRemesh, this->RemeshToInput); }
};

/// Per vertex of `remesh`: whether it ends an edge with one triangle (the remesh's border).
CVTNUMERICS_EXPORT std::vector<char> BorderVertices(const Remesh& remesh);

/// How far `remesh` and `input` lie from each other (each measured at its CoveringPoints 0.8%
/// of the input's diagonal apart, against the other's triangles near them, and again at points
/// 0.2% apart within 0.8% of those beyond 70% of `share` but within it: the distance can peak
/// between them, over a crease, by up to 0.3% more), and where they lie
/// farther than `share` of the diagonal apart: the input points that far from the remesh (tips
/// and creases its triangles cut off) and the input points nearest to remesh points that far
/// from the input (triangles bridging a fold), farthest first, none within twice its distance of
/// one before it, at most `maximumPoints` of them off the input's border and
/// `maximumBorderPoints` on it (the rim of a hole a border edge cuts across). Given a remesh
/// `before` that this one differs from in places (as one with sites added differs from the remesh
/// without) and its fidelity `measuredBefore`, an input probe whose nearest triangle there is also
/// here (the same corners in the same order) is measured against the triangles that are new here
/// alone (so is an input point between the probes that was measured there, the same to the bit),
/// and a remesh point that was measured there (likewise) is not measured again: the same
/// distances from far fewer queries.
CVTNUMERICS_EXPORT RemeshFidelity MeasureFidelity(const Remesh& remesh, const RemeshInput& input,
  double share, size_t maximumPoints, size_t maximumBorderPoints, const Remesh* before = nullptr,
  const RemeshFidelity* measuredBefore = nullptr);

/// The topology of `remesh`, and given its `input` mesh and that mesh's topology, the part of
/// the input under each of its parts (MeshTopology::InputComponents, by its vertices'
/// SourceTriangles: most of them, since a vertex fitted to the input near another part may have
/// its source there).
CVTNUMERICS_EXPORT MeshTopology RemeshTopologyOf(const Remesh& remesh,
  const SurfaceMesh* input = nullptr, const MeshTopology* inputTopology = nullptr);

/// The topology of BuildRemesh's remesh of `dual` without building it whole: its triangles and
/// split vertices without the shaping (flips, moves and collapses keep the topology). For
/// choosing among many duals the one to build. With the input, as RemeshTopologyOf.
CVTNUMERICS_EXPORT MeshTopology RemeshTopology(const RestrictedDual& dual,
  size_t inputBoundaryLoops, int maximumHole = 8, const SurfaceMesh* input = nullptr,
  const MeshTopology* inputTopology = nullptr);

/// Per site of `dual` (up to the largest in it): the part of RemeshTopology's remesh that its
/// vertex lies in (-1: none).
CVTNUMERICS_EXPORT std::vector<int> RemeshSiteParts(
  const RestrictedDual& dual, size_t inputBoundaryLoops, int maximumHole = 8);

} // namespace cvt

#endif
