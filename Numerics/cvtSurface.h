// Surfaces as geometry images (Rong et al. 2011, section 4): a W x H grid of surface points
// with normals, area weights and a validity mask; borders may be identified (cylinder and torus
// topology). Here: the surface engine seam, area weights, sampling, the constrained centroid
// (nearest point of a cell to a 3D point) and the dual triangulation of a labelling.
#ifndef cvtSurface_h
#define cvtSurface_h

#include "cvtEngine.h"
#include "cvtNumericsModule.h" // for export macro

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace cvt
{

struct GeometryImage
{
  int Width = 0;
  int Height = 0;
  bool WrapU = false;              // column 0 and column W-1 are neighbours
  bool WrapV = false;              // row 0 and row H-1 are neighbours
  std::vector<float> Position;     // 3 per pixel
  std::vector<float> Normal;       // 3 per pixel, unit
  std::vector<float> AreaWeight;   // 1 per pixel (the distortion factor)
  std::vector<unsigned char> Mask; // 1 per pixel, 0 = not on the surface; empty = all
  /// Per pixel of an atlas: the pixel where the surface goes on across a chart border (its seam
  /// partner), -1 where it does not; empty = no seams.
  std::vector<int> SeamPartner;
  /// Per pixel of an atlas: 1 within a pixel and a half of the surface's own border (edges of
  /// one triangle), where a chart ends and no other goes on; empty = none known.
  std::vector<unsigned char> Border;

  long long NumberOfPixels() const { return static_cast<long long>(this->Width) * this->Height; }
  bool IsValid(long long p) const { return this->Mask.empty() || this->Mask[p] != 0; }
  /// Pixel (i + di, j + dj) honouring the wrap flags, or -1 outside the image.
  long long Neighbor(int i, int j, int di, int dj) const;
};

/// Where each pixel of a geometry image made from a mesh samples it: the mesh triangle (-1 for
/// none) and the weights of its three points, to carry the mesh's point data onto the pixels.
struct PixelSources
{
  std::vector<int> Triangle;      // per pixel
  std::vector<float> Barycentric; // 3 per pixel
};

/// One third of the areas of the triangles of the regular triangulation incident to each pixel
/// (each quad split along its (i, j)-(i+1, j+1) diagonal; masked pixels take no part).
CVTNUMERICS_EXPORT std::vector<float> ComputeAreaWeights(const GeometryImage& image);

/// Checks positions, normals, weights and mask; empty string when fine, else what is wrong.
CVTNUMERICS_EXPORT std::string CheckGeometryImage(const GeometryImage& image, int numberOfSites);

/// Sites at pixel positions, drawn with probability proportional to the area weights.
CVTNUMERICS_EXPORT std::vector<double> SampleSurfaceSites(
  const GeometryImage& image, int count, std::uint64_t seed, std::vector<long long>& pixels);

/// For every site i, the nearest point to targets[i] on the triangles of the pixels labelled i
/// (Rong 4.3: each pixel checks the two triangles of its quad; the minimum over the cell wins),
/// with the pixel nearest to it. Sites whose cell is empty keep `sites[i]` and `pixels[i]`.
CVTNUMERICS_EXPORT void NearestPointsInCells(const GeometryImage& image,
  const std::vector<int>& labels, const std::vector<double>& targets, std::vector<double>& sites,
  std::vector<long long>& pixels);

/// The dual triangulation of a labelling: one triangle per pixel corner where three cells
/// meet (two where four meet, split along the shorter diagonal), oriented like the image,
/// without duplicates. On an atlas, two neighbouring border pixels and their seam partners
/// also make a corner, whose triangles face the pixels' normal.
CVTNUMERICS_EXPORT std::vector<std::array<int, 3>> DualTriangles(
  const GeometryImage& image, const std::vector<int>& labels, const std::vector<double>& sites);

/// The geometry image as a triangle mesh, every `stride`-th pixel a point (the last row and
/// column kept where borders are not identified), each quad split along its (i, j)-(i+1, j+1)
/// diagonal as the image's own triangulation, identified borders joined, masked pixels left
/// out. Points repeated by the image (a sphere's poles) are left for the caller to merge.
/// `pixels`, when given, receives the pixel of each point.
CVTNUMERICS_EXPORT void GeometryImageMesh(const GeometryImage& image, int stride,
  std::vector<double>& points, std::vector<std::array<int, 3>>& triangles,
  std::vector<long long>* pixels = nullptr);

/// The nearest site (3D distance, k-d tree, in parallel) of every valid pixel; -1 elsewhere.
CVTNUMERICS_EXPORT std::vector<int> NearestSiteLabels(
  const GeometryImage& image, const std::vector<double>& sites);

/// What a surface engine must do: the 3D counterpart of cvt::Engine. Sites are flat
/// (x, y, z, ...) points on the surface, each with the pixel that holds it.
class CVTNUMERICS_EXPORT SurfaceEngine : public EngineErrors
{
public:
  virtual ~SurfaceEngine() = default;
  virtual bool SetGeometryImage(const GeometryImage& image) = 0;
  virtual bool SetSites(const std::vector<double>& sites, const std::vector<long long>& pixels) = 0;
  /// Label the geometry image (3D distances) and integrate every cell: mass, moments (x, y, z)
  /// about the site and energy, weighted by the area weights.
  virtual bool ComputeCellSums(CellSums& sums) = 0;
  virtual bool GetLabels(std::vector<int>& labels) = 0;
  /// For every site i, the point of its cell (last labelling) nearest to targets[i], and the
  /// pixel holding it: the constrained centroid when the target is the 3D centroid (Rong 4.3;
  /// cvt::NearestPointsInCells is the CPU reference). Sites whose cell is empty keep theirs.
  virtual bool NearestPointsInCells(const std::vector<double>& targets, std::vector<double>& sites,
    std::vector<long long>& pixels) = 0;
};

} // namespace cvt

#endif
