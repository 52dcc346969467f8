/**
 * @class   vtkCVTGeometryImageSource
 * @brief   A geometry image of a parametric surface (any vtkParametricFunction).
 *
 * Samples the function on a W x H grid of its (u, v) domain and produces a vtkImageData
 * whose point arrays are what the surface CVT needs (Rong et al. 2011, 4.1):
 * - Position (3 components): the surface point of each pixel;
 * - Normal (3): the unit normal, Pu x Pv normalised;
 * - AreaWeight (1): the distortion factor, a third of the areas of the triangles of the
 *   regular triangulation incident to the pixel;
 * - Mask (unsigned char): 1 where the pixel is on the surface.
 * Field data WrapU and WrapV (0/1) say which borders are identified: a direction the function
 * joins (JoinU/JoinV, e.g. both for a torus) is sampled periodically at pixel centres and
 * wraps; otherwise the samples include both ends. Field data MinimumAreaWeight and
 * MaximumAreaWeight report the parameterisation's distortion, and TotalArea the area.
 */
#ifndef vtkCVTGeometryImageSource_h
#define vtkCVTGeometryImageSource_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class vtkParametricFunction;

class CVTFILTERS_EXPORT vtkCVTGeometryImageSource : public vtkImageAlgorithm
{
public:
  static vtkCVTGeometryImageSource* New();
  vtkTypeMacro(vtkCVTGeometryImageSource, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The surface (default: a torus with ring radius 1 and cross-section radius 0.4). */
  void SetParametricFunction(vtkParametricFunction* function);
  vtkGetObjectMacro(ParametricFunction, vtkParametricFunction);
  ///@}

  ///@{
  /** Geometry image size in pixels along u and v (default 512 x 256). */
  vtkSetVector2Macro(Resolution, int);
  vtkGetVector2Macro(Resolution, int);
  ///@}

  vtkMTimeType GetMTime() override;

protected:
  vtkCVTGeometryImageSource();
  ~vtkCVTGeometryImageSource() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  vtkParametricFunction* ParametricFunction = nullptr;
  int Resolution[2] = { 512, 256 };

private:
  vtkCVTGeometryImageSource(const vtkCVTGeometryImageSource&) = delete;
  void operator=(const vtkCVTGeometryImageSource&) = delete;
};

#endif
