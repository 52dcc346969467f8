/**
 * @class   vtkCVTSurfaceFilter
 * @brief   Constrained centroidal Voronoi tessellation of a surface, on the GPU, and remeshing.
 *
 * Input 0 is a geometry image (see vtkCVTGeometryImageSource): a vtkImageData with point
 * arrays Position (3 components, required), Normal (3; computed when missing), AreaWeight
 * (computed when missing) and Mask (optional), and field data WrapU/WrapV for identified
 * borders. Sites are drawn by the area weights (RandomSeed) and optimised on the GPU engine
 * (vtkCVTSurfaceEngine: 3D-distance jump flooding and reductions) by L-BFGS with tangential
 * gradients and projection onto the surface (default) or by Lloyd's method with constrained
 * centroids (Rong et al. 2011, section 4; Liu et al. 2009, section 6).
 *
 * Engine (vtkCVTGPUAlgorithm): OPENGL runs the geometry image on the GPU, as above; CPU
 * triangulates the geometry image (at most about 60 triangles per site) and remeshes it with
 * vtkCVTRemeshFilter's exact restricted Voronoi engine, the labels then being each pixel's
 * nearest site (for an atlas, whose charts the mesh keeps apart at the seams, the sites are
 * optimised on it and the remesh is the dual across the seams, as on the GPU); AUTO (default)
 * takes the faster engine (see vtkCVTGPUAlgorithm). Optimiser properties and stop rules:
 * vtkCVTAlgorithm.
 *
 * Outputs:
 * 0. sites: 3D vtkPolyData, SiteId, Mass, Energy; field data Energy, GradientNorm (tangential),
 *    Iterations, Evaluations, StopReason;
 * 1. labels: the geometry image with an int SiteId array;
 * 2. remesh: the dual triangulation of the constrained CVT (vertices = sites), oriented like
 *    the geometry image, with the image's surface arrays (a mesh's, carried by
 *    vtkCVTMeshGeometryImage) at its vertices;
 * 3. history: vtkTable (iteration, evaluations, energy, gradient_norm, seconds).
 * Bad input gives a clear error, empty outputs and RequestData returning 0.
 */
#ifndef vtkCVTSurfaceFilter_h
#define vtkCVTSurfaceFilter_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkCVTGPUAlgorithm.h"

#include <string> // for std::string
#include <vector> // for std::vector

namespace cvt
{
struct GeometryImage;
}
class vtkImageData;
class vtkPolyData;

class CVTFILTERS_EXPORT vtkCVTSurfaceFilter : public vtkCVTGPUAlgorithm
{
public:
  static vtkCVTSurfaceFilter* New();
  vtkTypeMacro(vtkCVTSurfaceFilter, vtkCVTGPUAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum SurfaceOutputPorts
  {
    RemeshPort = MeshPort
  };

  ///@{
  /** Typed access to the outputs (GetSitesOutput and GetHistoryOutput: vtkCVTAlgorithm). */
  vtkImageData* GetLabelsOutput();
  vtkPolyData* GetRemeshOutput();
  ///@}

  /**
   * A point array of the geometry image used as density (denser where larger; one component,
   * finite, not negative, positive somewhere on the surface): it weighs each pixel's area, and
   * on the CPU engine the triangulated image's points. vtkCVTMeshGeometryImage carries a mesh's
   * point arrays onto its pixels. Empty (default): uniform.
   */
  vtkSetStdStringFromCharMacro(DensityArray);
  vtkGetCharFromStdStringMacro(DensityArray);

  ///@{
  /**
   * On the CPU engine (the remesh of the triangulated image, vtkCVTRemeshFilter): collapse
   * remesh edges where that brings valences closer to 6 (the remesh then has a vertex fewer than
   * sites per collapse). Default off: every site keeps its vertex, as on the OpenGL engine (the
   * dual of the labels).
   */
  vtkSetMacro(CollapseForValence, bool);
  vtkGetMacro(CollapseForValence, bool);
  vtkBooleanMacro(CollapseForValence, bool);
  ///@}

  /**
   * Reads a geometry image (Position required; Normal and AreaWeight computed when missing;
   * Mask optional; WrapU/WrapV field data) into the numerical core's form. Returns false with
   * a message saying what to fix.
   */
  static bool ReadGeometryImage(vtkImageData* input, cvt::GeometryImage& image, std::string& error);

protected:
  vtkCVTSurfaceFilter();
  ~vtkCVTSurfaceFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  bool Compute(vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  /** The sites drawn by the area weights (RandomSeed) and their pixels; false (an error) when
   * fewer distinct pixels than sites can hold them. */
  bool DrawSites(
    const cvt::GeometryImage& image, std::vector<double>& sites, std::vector<long long>& pixels);
  /** The OpenGL engine's run: the geometry image on the GPU. */
  bool RunOnGPU(vtkImageData* input, const cvt::GeometryImage& image, const std::string& reason,
    vtkInformationVector* outputVector);
  /**
   * The CPU engine's run: the geometry image (with `valid` pixels in its mask) as a mesh through
   * vtkCVTRemeshFilter.
   */
  bool RunOnCPU(vtkImageData* input, const cvt::GeometryImage& image, long long valid,
    bool weighted, const std::string& reason, vtkInformationVector* outputVector);
  /**
   * The CPU engine's run on an atlas: the sites optimised on the charts as a mesh (exact
   * restricted Voronoi cells, which are 3D and so cross the seams), the labels each pixel's
   * nearest site and the remesh the dual across the seams, as on the GPU.
   */
  bool RunAtlasOnCPU(vtkImageData* input, const cvt::GeometryImage& image, int stride,
    bool weighted, const std::string& reason, vtkInformationVector* outputVector);

  std::string DensityArray;
  bool CollapseForValence = false;

private:
  vtkCVTSurfaceFilter(const vtkCVTSurfaceFilter&) = delete;
  void operator=(const vtkCVTSurfaceFilter&) = delete;
};

#endif
