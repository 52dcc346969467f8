/**
 * @class   vtkCVTImageFilter
 * @brief   Centroidal Voronoi tessellation of a 2D image domain, computed on the GPU.
 *
 * Input 0 is a 2D vtkImageData: each point is the centre of one pixel of the domain (any
 * origin and spacing). The density is the point scalar array chosen with
 * SetInputArrayToProcess(0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, name), uniform when
 * none is chosen; it must be finite, non-negative and not all zero. Optional input 1 gives the
 * initial sites (any vtkPointSet; z is ignored); without it NumberOfSites sites are drawn with
 * probability proportional to the density, seeded by RandomSeed.
 *
 * The energy is minimised by the optimiser vtkCVTAlgorithm describes, on the engine
 * vtkCVTGPUAlgorithm chooses: the OpenGL engine (vtkCVTOpenGLEngine: 1+JFA labelling and a
 * regional reduction per evaluation; Lloyd's sites move to their centroids on the GPU) or the
 * exact CPU engine.
 *
 * Outputs:
 * 0. sites: vtkPolyData, one vertex per site, point arrays SiteId, Mass, Energy; field data
 *    Energy, GradientNorm, Iterations, Evaluations, StopReason, and the quality measures
 *    HexagonalFraction, RadiusStandardDeviation, NearestNeighborStandardDeviation,
 *    AreaStandardDeviation (Rong et al., Table 6); with ComputeExactEnergy also ExactEnergy
 *    and EnergyRelativeDifference (GPU energy against the exact CPU one);
 * 1. labels: vtkImageData with the input's geometry, int point array SiteId;
 * 2. dual: the Delaunay triangulation of sites whose cells meet inside the domain,
 *    counter-clockwise triangles;
 * 3. history: vtkTable (iteration, evaluations, energy, gradient_norm, seconds).
 *
 * Bad input (empty or 3D image, bad density, bad sites, no OpenGL context, a grid beyond the
 * GPU's texture size) is reported with vtkErrorMacro; all outputs are then empty and
 * RequestData returns 0. Progress is reported every iteration and AbortExecute stops the
 * iterations (the outputs then hold the last iterate).
 */
#ifndef vtkCVTImageFilter_h
#define vtkCVTImageFilter_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkCVTGPUAlgorithm.h"

#include <string> // for std::string
#include <vector> // for std::vector

class vtkFieldData;
class vtkImageData;
class vtkPointSet;
class vtkPolyData;
namespace cvt
{
struct Grid;
struct OptimizerResult;
}

class CVTFILTERS_EXPORT vtkCVTImageFilter : public vtkCVTGPUAlgorithm
{
public:
  static vtkCVTImageFilter* New();
  vtkTypeMacro(vtkCVTImageFilter, vtkCVTGPUAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ImageOutputPorts
  {
    DualPort = MeshPort
  };

  ///@{
  /**
   * Use the largest value minus the density instead of the density (off by default): dark
   * pixels of a picture become dense, as stippling needs. The largest value is the array
   * type's for integer arrays (255 for 8-bit pictures), else the array's own. No effect with
   * a uniform density.
   */
  vtkSetMacro(InvertDensity, bool);
  vtkGetMacro(InvertDensity, bool);
  vtkBooleanMacro(InvertDensity, bool);
  ///@}

  ///@{
  /**
   * Also compute the exact energy of the output sites on the CPU (clipped Voronoi cells,
   * integrated exactly for the pixelwise-constant density) and report the relative difference
   * of the GPU energy to it (off by default: it costs CPU time).
   */
  vtkSetMacro(ComputeExactEnergy, bool);
  vtkGetMacro(ComputeExactEnergy, bool);
  vtkBooleanMacro(ComputeExactEnergy, bool);
  ///@}

  ///@{
  /** OpenGL engine option, see vtkCVTOpenGLEngine (on by default). */
  vtkSetMacro(SplitBoundaryPixels, bool);
  vtkGetMacro(SplitBoundaryPixels, bool);
  vtkBooleanMacro(SplitBoundaryPixels, bool);
  ///@}

  /** Initial sites (optional input 1). */
  void SetInitialSitesConnection(vtkAlgorithmOutput* output);
  void SetInitialSitesData(vtkDataObject* sites);

  ///@{
  /** Typed access to the outputs (GetSitesOutput and GetHistoryOutput: vtkCVTAlgorithm). */
  vtkImageData* GetLabelsOutput();
  vtkPolyData* GetDualOutput();
  ///@}

protected:
  vtkCVTImageFilter();
  ~vtkCVTImageFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  bool Compute(vtkInformationVector** inputVector, vtkInformationVector* outputVector) override;

  /** The chosen density array's name, or nullptr for a uniform density. */
  const char* GetDensityArrayName();
  /** The initial sites: input 1's points, or NumberOfSites drawn from `density`. */
  bool ReadInitialSites(vtkPointSet* initialSites, const cvt::Grid& grid,
    const std::vector<float>& density, std::vector<double>& sites, std::string& error);
  /** Rong et al.'s quality measures (Table 6) and, when asked, the exact energy. */
  void AddQualityFields(vtkFieldData* fields, const cvt::Grid& grid,
    const cvt::OptimizerResult& result, const std::vector<float>& density);

  bool ComputeExactEnergy = false;
  bool InvertDensity = false;
  bool SplitBoundaryPixels = true;

private:
  vtkCVTImageFilter(const vtkCVTImageFilter&) = delete;
  void operator=(const vtkCVTImageFilter&) = delete;
};

#endif
