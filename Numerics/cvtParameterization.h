// Geometry images of triangle meshes of disk topology: a mean-value (Floater) parameterisation
// onto the unit square, boundary on the square's perimeter by arc length (a sparse solve with
// Eigen), then resampling on a W x H grid.
#ifndef cvtParameterization_h
#define cvtParameterization_h

#include "cvtNumericsModule.h" // for export macro
#include "cvtSurface.h"

#include <array>
#include <string>
#include <vector>

namespace cvt
{

struct TriangleMesh
{
  std::vector<double> Points; // 3 per vertex
  std::vector<std::array<int, 3>> Triangles;
};

/// Checks that the mesh is one manifold surface that can be parameterised: finite coordinates,
/// no zero-area triangle, every edge on at most two triangles, one connected component, and
/// either a disk (one boundary loop, Euler characteristic 1) or a closed genus-0 surface (no
/// boundary, Euler characteristic 2; `closed` is then set). Empty string when fine, else what
/// is wrong and what the parameterisation needs. `manifold`, when given, tells whether the
/// mesh passed every check but those of topology (components, genus, boundary loops).
CVTNUMERICS_EXPORT std::string CheckMesh(
  const TriangleMesh& mesh, bool& closed, bool* manifold = nullptr);

/// (u, v) in [0, 1]^2 per vertex: mean-value coordinates, boundary on the square. The mesh
/// must pass CheckMesh as a disk. Returns false with a message when the solve fails.
CVTNUMERICS_EXPORT bool ParameterizeDisk(
  const TriangleMesh& mesh, std::vector<double>& uv, std::string& error);

/// Samples the parameterised mesh at the pixel centres of a W x H grid: positions by
/// barycentric interpolation, normals, area weights, mask (pixels no triangle covers);
/// `sources`, when given, receives each pixel's triangle and weights.
CVTNUMERICS_EXPORT GeometryImage ResampleMesh(const TriangleMesh& mesh,
  const std::vector<double>& uv, int width, int height, PixelSources* sources = nullptr);

/// Unit normals of a geometry image from central differences of its positions (wrap-aware).
CVTNUMERICS_EXPORT std::vector<float> NormalsFromPositions(const GeometryImage& image);

} // namespace cvt

#endif
