/**
 * @class   vtkCVTMeshGeometryImage
 * @brief   A geometry image of a triangle mesh, for vtkCVTSurfaceFilter.
 *
 * A mesh of disk topology is parameterised onto the unit square (mean-value coordinates,
 * Floater 2003: a sparse solve with Eigen; the boundary loop on the square's perimeter by arc
 * length) and resampled on a W x H grid. A closed genus-0 mesh is cut open along a meridian
 * and at two poles: pixel (i, j) is where the ray from the mesh's centroid in the direction of
 * azimuth i and polar angle j meets the surface (columns wrap; the first and last rows are the
 * poles), which needs the mesh to be star-shaped about its centroid. The output has the same
 * arrays as vtkCVTGeometryImageSource (Position, Normal, AreaWeight, Mask, wrap flags); its
 * field data report the smallest and largest area weight: the parameterisation's distortion.
 *
 * Any other orientable manifold mesh (several parts, any genus and number of boundary loops,
 * a closed shape that is not star-shaped), or any mesh when Parameterization is ATLAS, becomes
 * an atlas (cvt::BuildAtlas): disk-shaped charts of bounded normal variation, each mapped by
 * least squares conformal maps, scaled as large as fits and packed into the Resolution[0] x
 * Resolution[1] image, with an int point array ChartId (-1
 * between charts), SeamPartner (the pixel where the surface goes on across a chart border,
 * -1 for none) and an unsigned char SurfaceBorder (1 within a pixel and a half of the mesh's own
 * border); field data NumberOfCharts, SeamLength, SeamPixels and the distortion range
 * (Minimum/MaximumAreaStretch, MaximumAngleStretch). Pinched points are split and triangles
 * oriented first (a warning says so).
 *
 * Every point array of the mesh (a density, say, for vtkCVTSurfaceFilter's DensityArray) is
 * carried onto the pixels: each pixel interpolates the triangle it samples; pixels off the
 * surface get zeros. Arrays named like the image's own (Position, Normal, AreaWeight, Mask,
 * ChartId, SeamPartner, SurfaceBorder) are left out.
 *
 * The mesh must be made of triangles with finite coordinates, no zero-area triangle and every
 * edge on at most two triangles; a non-orientable surface is refused. Each is an error saying
 * what to fix.
 */
#ifndef vtkCVTMeshGeometryImage_h
#define vtkCVTMeshGeometryImage_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <string> // for std::string

namespace cvt
{
struct GeometryImage;
struct PixelSources;
struct TriangleMesh;
}
class vtkPolyData;

class CVTFILTERS_EXPORT vtkCVTMeshGeometryImage : public vtkImageAlgorithm
{
public:
  static vtkCVTMeshGeometryImage* New();
  vtkTypeMacro(vtkCVTMeshGeometryImage, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Geometry image size in pixels (default 512 x 512). */
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  ///@}

  enum ParameterizationType
  {
    AUTOMATIC = 0, ///< one chart for disks and star-shaped genus-0 meshes, else an atlas
    ATLAS = 1      ///< always an atlas
  };
  ///@{
  /** How the mesh is mapped to the image (default AUTOMATIC). */
  vtkSetClampMacro(Parameterization, int, AUTOMATIC, ATLAS);
  vtkGetMacro(Parameterization, int);
  void SetParameterizationToAutomatic() { this->SetParameterization(AUTOMATIC); }
  void SetParameterizationToAtlas() { this->SetParameterization(ATLAS); }
  ///@}

protected:
  vtkCVTMeshGeometryImage();
  ~vtkCVTMeshGeometryImage() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution[2] = { 512, 512 };
  int Parameterization = AUTOMATIC;

private:
  bool BuildAtlas(vtkPolyData* input, const cvt::TriangleMesh& mesh, vtkImageData* output);
  bool SampleClosedMesh(
    vtkPolyData* mesh, cvt::GeometryImage& image, cvt::PixelSources& sources, std::string& error);
  vtkCVTMeshGeometryImage(const vtkCVTMeshGeometryImage&) = delete;
  void operator=(const vtkCVTMeshGeometryImage&) = delete;
};

#endif
