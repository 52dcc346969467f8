// A multi-chart geometry image of any orientable manifold triangle mesh (any genus, boundary
// loops and parts): the surface is cut into disk-like charts of bounded normal variation,
// each chart is mapped to the plane by least squares conformal maps (Levy et al. 2002; a
// sparse solve with Eigen) without flipped or overlapping triangles, and the charts are packed
// into one image of a given size, with a mask. Every pixel near a chart border whose surface goes
// on in another chart records the pixel where it goes on (its seam partner), so that the Voronoi
// labelling and everything built on it can cross the cut.
#ifndef cvtAtlas_h
#define cvtAtlas_h

#include "cvtNumericsModule.h" // for export macro
#include "cvtSurface.h"
#include "cvtSurfaceMesh.h"

#include <string>
#include <vector>

namespace cvt
{

struct AtlasOptions
{
  int Width = 512; // the image's size: the charts are scaled to fill it
  int Height = 512;
  double MaximumNormalAngle = 60.0; // degrees between a chart's seed and any of its triangles
  int Gutter = 2;                   // empty pixels round each chart's box (at least 1)
};

struct Atlas
{
  /// Positions, normals (the triangles'), area weights (each chart's pixels sum to its area),
  /// mask and seam partners.
  GeometryImage Image;
  std::vector<int> Chart;         // per pixel: its chart, -1 outside every chart
  PixelSources Sources;           // per pixel: the mesh triangle it samples and its weights
  std::vector<int> TriangleChart; // per mesh triangle: its chart
  int NumberOfCharts = 0;
  double MinimumAreaStretch = 0.0; // per triangle: pixel area / (3D area x pixels per unit^2)
  double MaximumAreaStretch = 0.0;
  double MaximumAngleStretch = 0.0; // per triangle: largest / smallest singular value of the map
  double SeamLength = 0.0;          // 3D length of the mesh edges between charts
  long long SeamPixels = 0;         // pixels with a partner
};

/// Builds the atlas of a mesh that RepairSurfaceMesh has cleaned (edge-manifold, oriented).
/// Returns "" or what went wrong (no triangle, an image too small for the charts).
CVTNUMERICS_EXPORT std::string BuildAtlas(
  const SurfaceMesh& mesh, const AtlasOptions& options, Atlas& atlas);

} // namespace cvt

#endif
