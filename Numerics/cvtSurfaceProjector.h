// The nearest point of a triangle mesh to any point in space, exactly: what the remesh's moves,
// flips and distance measures project onto the input surface with.
#ifndef cvtSurfaceProjector_h
#define cvtSurfaceProjector_h

#include "cvtNumericsModule.h" // for export macro
#include "cvtSurfaceMesh.h"

#include <array>
#include <memory>
#include <vector>

namespace cvt
{

/// Exact nearest points on `surface` (which must outlive the projector). The triangles, large
/// ones cut into pieces about the median's size, are grouped by size (bounding radius about the
/// centroid, classes a factor 4 apart) in one k-d tree of centroids per class; a query walks
/// each tree while "centroid distance minus the class's largest radius" is below the best
/// distance so far, so large CAD faces are found however far their centroids lie (the 16 nearest
/// centroids alone missed them: a remesh 0.7% of the diagonal from anchor measured 9%). Queries
/// are const and may run in parallel.
/// Tried and not taken (`cvtBenchmark shape`, instructions counted by callgrind in Nearest over
/// 11 shapings and measures at 1000 sites): a bounding-volume hierarchy of whole triangles
/// (median splits, 4 per leaf, the nearer child first): rotor 4.08 -> 4.29 billion, armadillo
/// 4.17 -> 3.21, but 2.4 times the build (0.29 -> 0.69 billion on armadillo) and the shaping's
/// time the same within the machine's noise; and looking up only pieces, not whole triangles, in
/// the list of those tested: 4.08 -> 4.10 and 4.17 -> 4.05 billion.
class CVTNUMERICS_EXPORT SurfaceProjector
{
public:
  explicit SurfaceProjector(const SurfaceMesh& surface);
  ~SurfaceProjector();
  SurfaceProjector(const SurfaceProjector&) = delete;
  SurfaceProjector& operator=(const SurfaceProjector&) = delete;

  /// The nearest point `q` of the surface to `p` and its barycentric weights `w` in the returned
  /// triangle (-1 and `q`, `w` untouched when the surface has no triangle). A `guess` of the
  /// triangle (the nearest to a point close by) makes the search quicker.
  int Nearest(const double* p, double q[3], double w[3], int guess = -1) const;

  /// As Nearest, among the triangles nearer to `p` than `within` alone (-1 when none is): far
  /// quicker where none is, as the search then ends at the trees' roots.
  int NearestWithin(const double* p, double within, double q[3], double w[3]) const;

  /// How far `p` is from the surface (0 when it has no triangle). With `guess`: a guess of the
  /// nearest triangle as for Nearest, replaced by the nearest (for the next point along).
  double DistanceTo(const double p[3], int* guess = nullptr) const;

  /// How far the farthest centroid of `triangles` (three points each) is from the surface: a
  /// change of a remesh must not cut across a crease (the input would then lie far from it).
  double FarthestCentroid(const std::vector<std::array<const double*, 3>>& triangles) const;

  /// From now on, a query asked before (the same point and guess) is answered from memory (a
  /// table of 262,144 answers, 21 MB at most, the newest query of a slot kept), or no longer
  /// with false; not while queries run. For a surface asked the same points again and again, as
  /// the input is by the remeshes of fidelity candidates, each a whole new remesh whose vertices,
  /// edges and sample points are mostly those of the one before (mpi at 1000 sites: 814,579
  /// queries, 64,172 different); elsewhere the lookups only cost (torus_quad at 1000 sites:
  /// 0.22 -> 0.24 s end to end).
  void SetRememberAnswers(bool remember);

  const SurfaceMesh& Surface() const { return this->Mesh; }

private:
  struct Internals;
  const SurfaceMesh& Mesh;
  std::unique_ptr<Internals> Internal;
};

} // namespace cvt

#endif
