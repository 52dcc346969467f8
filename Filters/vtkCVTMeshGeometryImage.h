/**
 * @class   vtkCVTMeshGeometryImage
 * @brief   A geometry image of a triangle mesh of disk topology, for vtkCVTSurfaceFilter.
 *
 * Parameterises the mesh onto the unit square (mean-value coordinates, Floater 2003: a sparse
 * solve with Eigen; the boundary loop on the square's perimeter by arc length) and resamples
 * it on a W x H grid: the same arrays as vtkCVTGeometryImageSource (Position, Normal,
 * AreaWeight, Mask; no border identified). The field data report the smallest and largest
 * area weight: their ratio is the parameterisation's distortion.
 *
 * The mesh must be one manifold disk: triangles only, finite coordinates, no zero-area
 * triangle, every edge on at most two triangles, one component, one boundary loop. Anything
 * else (closed meshes included: cutting them open is not available yet) is an error saying
 * what the parameterisation needs.
 */
#ifndef vtkCVTMeshGeometryImage_h
#define vtkCVTMeshGeometryImage_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

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
  vtkCVTMeshGeometryImage(const vtkCVTMeshGeometryImage&) = delete;
  void operator=(const vtkCVTMeshGeometryImage&) = delete;
};

#endif
