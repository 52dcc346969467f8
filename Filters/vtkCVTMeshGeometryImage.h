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
 * The mesh must be one manifold surface: triangles only, finite coordinates, no zero-area
 * triangle, every edge on at most two triangles, one component, and a disk or a closed genus-0
 * surface. Anything else is an error saying what the parameterisation needs.
 */
#ifndef vtkCVTMeshGeometryImage_h
#define vtkCVTMeshGeometryImage_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

#include <string> // for std::string

namespace cvt
{
struct GeometryImage;
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

protected:
  vtkCVTMeshGeometryImage();
  ~vtkCVTMeshGeometryImage() override = default;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Resolution[2] = { 512, 512 };

private:
  bool SampleClosedMesh(vtkPolyData* mesh, cvt::GeometryImage& image, std::string& error);
  vtkCVTMeshGeometryImage(const vtkCVTMeshGeometryImage&) = delete;
  void operator=(const vtkCVTMeshGeometryImage&) = delete;
};

#endif
