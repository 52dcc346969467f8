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
 * The energy is minimised on the GPU (vtkCVTOpenGLEngine: 1+JFA labelling and a regional
 * reduction per evaluation) by L-BFGS (default; Liu et al. 2009, NumberOfCorrections kept) or
 * by Lloyd's method (sites move to their centroids on the GPU), until
 * MaximumNumberOfIterations, until |grad F| falls below GradientTolerance times its initial
 * value, or until the relative energy decrease falls below Tolerance (Lloyd also stops when no
 * pixel changes site; 0 runs every iteration). L-BFGS also stops, with a warning naming the
 * reason, when no sufficient decrease is possible; its best sites are the output.
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
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for OpenGLEngine
#include "vtkTimeStamp.h"    // for LastFailure

#include <string> // for std::string

class vtkCVTOpenGLEngine;
class vtkImageData;
class vtkPolyData;
class vtkRenderWindow;
class vtkTable;

class CVTFILTERS_EXPORT vtkCVTImageFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkCVTImageFilter* New();
  vtkTypeMacro(vtkCVTImageFilter, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    LLOYD = 0,
    LBFGS = 1
  };

  enum OutputPorts
  {
    SitesPort = 0,
    LabelsPort = 1,
    DualPort = 2,
    HistoryPort = 3
  };

  ///@{
  /** Number of sites drawn when no initial sites are connected (default 1000). */
  vtkSetClampMacro(NumberOfSites, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfSites, int);
  ///@}

  ///@{
  /** Seed of the initial site sampling (default 1): the same seed gives the same output. */
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

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
  /** Iteration cap (default 100). */
  vtkSetClampMacro(MaximumNumberOfIterations, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /**
   * Stop when no pixel changes site or the relative energy decrease of an iteration falls
   * below this (default 1e-6); 0 runs every iteration.
   */
  vtkSetClampMacro(Tolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /** The optimiser: LBFGS (default) or LLOYD. */
  vtkSetClampMacro(Method, int, LLOYD, LBFGS);
  vtkGetMacro(Method, int);
  void SetMethodToLloyd() { this->SetMethod(LLOYD); }
  void SetMethodToLBFGS() { this->SetMethod(LBFGS); }
  ///@}

  ///@{
  /** L-BFGS: number of corrections kept for the inverse Hessian (default 7). */
  vtkSetClampMacro(NumberOfCorrections, int, 1, 100);
  vtkGetMacro(NumberOfCorrections, int);
  ///@}

  ///@{
  /** Stop when |grad F| falls below this fraction of its initial value (default 0: never). */
  vtkSetClampMacro(GradientTolerance, double, 0.0, 1.0);
  vtkGetMacro(GradientTolerance, double);
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
  /**
   * The engine: AUTO (default: OpenGL on a hardware GPU; the exact CPU engine, multi-threaded,
   * when the only OpenGL is a software renderer such as llvmpipe, or there is none), OPENGL
   * (the GPU engine; an error without an OpenGL context) or CPU. The choice and its reason are
   * in the sites' field data (Engine, EngineReason).
   */
  enum Engines
  {
    AUTO = 0,
    OPENGL = 1,
    CPU = 2
  };
  vtkSetClampMacro(Engine, int, AUTO, CPU);
  vtkGetMacro(Engine, int);
  void SetEngineToAuto() { this->SetEngine(AUTO); }
  void SetEngineToOpenGL() { this->SetEngine(OPENGL); }
  void SetEngineToCPU() { this->SetEngine(CPU); }
  ///@}

  ///@{
  /** OpenGL engine options, see vtkCVTOpenGLEngine (both on by default). */
  vtkSetMacro(AdaptiveJumpFlooding, bool);
  vtkGetMacro(AdaptiveJumpFlooding, bool);
  vtkBooleanMacro(AdaptiveJumpFlooding, bool);
  vtkSetMacro(SplitBoundaryPixels, bool);
  vtkGetMacro(SplitBoundaryPixels, bool);
  vtkBooleanMacro(SplitBoundaryPixels, bool);
  ///@}

  /**
   * The array name that means "no density array, uniform density": what the ParaView plugin's
   * density menu offers besides the image's arrays. Any other name must be a point array.
   */
  static const char* UniformDensityName() { return "Uniform density"; }

  /** Initial sites (optional input 1). */
  void SetInitialSitesConnection(vtkAlgorithmOutput* output);
  void SetInitialSitesData(vtkDataObject* sites);

  ///@{
  /** Typed access to the outputs. */
  vtkPolyData* GetSitesOutput();
  vtkImageData* GetLabelsOutput();
  vtkPolyData* GetDualOutput();
  vtkTable* GetHistoryOutput();
  ///@}

  /** Description of the OpenGL context the last run used (empty before a run or on the CPU). */
  const std::string& GetContextDescription() const { return this->ContextDescription; }

  ///@{
  /**
   * The OpenGL engine (its context, compiled shaders and textures) lives as long as the filter,
   * so an update after a changed property pays only for what changed. SetRenderWindow runs it
   * on that window's context instead of one of its own (nullptr, the default, finds one);
   * ReleaseGraphicsResources frees the engine, its GL objects and context now (the next update
   * makes them again).
   */
  void SetRenderWindow(vtkRenderWindow* window);
  vtkRenderWindow* GetRenderWindow() const;
  void ReleaseGraphicsResources();
  ///@}

  ///@{
  /**
   * What RequestData returns after bad input or a failed run (the error is reported and the
   * outputs are empty either way): 0 when on (default, VTK's convention: Update() fails), 1
   * when off, so that ParaView shows the empty outputs (clears the view) and prints the error
   * once instead of on every view's update. The ParaView plugin turns it off.
   */
  vtkSetMacro(FailPipelineOnError, bool);
  vtkGetMacro(FailPipelineOnError, bool);
  vtkBooleanMacro(FailPipelineOnError, bool);
  ///@}

protected:
  vtkCVTImageFilter();
  ~vtkCVTImageFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** RequestData's work: false after an error (reported with vtkErrorMacro). */
  bool Compute(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  int Method = LBFGS;
  bool FailPipelineOnError = true;
  vtkTimeStamp LastFailure; // when the last failed run ended (see FailPipelineOnError)
  bool LastRunFailed = false;
  int NumberOfCorrections = 7;
  double GradientTolerance = 0.0;
  bool ComputeExactEnergy = false;
  int NumberOfSites = 1000;
  int RandomSeed = 1;
  int MaximumNumberOfIterations = 100;
  bool InvertDensity = false;
  double Tolerance = 1e-6;
  bool AdaptiveJumpFlooding = true;
  bool SplitBoundaryPixels = true;
  int Engine = AUTO;
  std::string ContextDescription;
  vtkSmartPointer<vtkRenderWindow> RenderWindow;
  vtkSmartPointer<vtkCVTOpenGLEngine> OpenGLEngine; // made on first use, kept across updates

private:
  vtkCVTImageFilter(const vtkCVTImageFilter&) = delete;
  void operator=(const vtkCVTImageFilter&) = delete;
};

#endif
