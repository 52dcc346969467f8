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
 * Outputs:
 * 0. sites: 3D vtkPolyData, SiteId, Mass, Energy; field data Energy, GradientNorm (tangential),
 *    Iterations, Evaluations, StopReason;
 * 1. labels: the geometry image with an int SiteId array;
 * 2. remesh: the dual triangulation of the constrained CVT (vertices = sites), oriented like
 *    the geometry image;
 * 3. history: vtkTable (iteration, evaluations, energy, gradient_norm, seconds).
 * Bad input gives a clear error, empty outputs and RequestData returning 0.
 */
#ifndef vtkCVTSurfaceFilter_h
#define vtkCVTSurfaceFilter_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // for OpenGLEngine
#include "vtkTimeStamp.h"    // for LastFailure

#include <string> // for std::string

namespace cvt
{
struct GeometryImage;
}
class vtkCVTSurfaceEngine;
class vtkImageData;
class vtkPolyData;
class vtkRenderWindow;
class vtkTable;

class CVTFILTERS_EXPORT vtkCVTSurfaceFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkCVTSurfaceFilter* New();
  vtkTypeMacro(vtkCVTSurfaceFilter, vtkPolyDataAlgorithm);
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
    RemeshPort = 2,
    HistoryPort = 3
  };

  vtkSetClampMacro(NumberOfSites, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfSites, int);
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  vtkSetClampMacro(Method, int, LLOYD, LBFGS);
  vtkGetMacro(Method, int);
  void SetMethodToLloyd() { this->SetMethod(LLOYD); }
  void SetMethodToLBFGS() { this->SetMethod(LBFGS); }
  vtkSetClampMacro(MaximumNumberOfIterations, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfIterations, int);
  /** Stop when the relative energy decrease of an iteration falls below this (0: never). */
  vtkSetClampMacro(Tolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Tolerance, double);
  /** Stop when |grad F| falls below this fraction of its initial value (0: never). */
  vtkSetClampMacro(GradientTolerance, double, 0.0, 1.0);
  vtkGetMacro(GradientTolerance, double);
  vtkSetClampMacro(NumberOfCorrections, int, 1, 100);
  vtkGetMacro(NumberOfCorrections, int);

  /**
   * The engine: AUTO (default: OpenGL on a hardware GPU, else the CPU), OPENGL (the geometry
   * image on the GPU, as above) or CPU: the geometry image triangulated (at most about 60
   * triangles per site) and remeshed by vtkCVTRemeshFilter's exact restricted Voronoi engine;
   * the labels are then each pixel's nearest site. Choice and reason: field data Engine and
   * EngineReason of the sites.
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

  vtkPolyData* GetSitesOutput();
  vtkImageData* GetLabelsOutput();
  vtkPolyData* GetRemeshOutput();
  vtkTable* GetHistoryOutput();

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

  /**
   * Reads a geometry image (Position required; Normal and AreaWeight computed when missing;
   * Mask optional; WrapU/WrapV field data) into the numerical core's form. Returns false with
   * a message saying what to fix.
   */
  static bool ReadGeometryImage(vtkImageData* input, cvt::GeometryImage& image, std::string& error);

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
  vtkCVTSurfaceFilter();
  ~vtkCVTSurfaceFilter() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  /** RequestData's work: false after an error (reported with vtkErrorMacro). */
  bool Compute(vtkInformationVector** inputVector, vtkInformationVector* outputVector);

  int NumberOfSites = 1000;
  int RandomSeed = 1;
  int Method = LBFGS;
  bool FailPipelineOnError = true;
  vtkTimeStamp LastFailure; // when the last failed run ended (see FailPipelineOnError)
  bool LastRunFailed = false;
  int MaximumNumberOfIterations = 100;
  double Tolerance = 1e-6;
  double GradientTolerance = 0.0;
  int NumberOfCorrections = 7;
  int Engine = AUTO;
  std::string ContextDescription;
  vtkSmartPointer<vtkRenderWindow> RenderWindow;
  vtkSmartPointer<vtkCVTSurfaceEngine> OpenGLEngine; // made on first use, kept across updates

  /**
   * The CPU engine's run: the geometry image (with `valid` pixels in its mask) as a mesh through
   * vtkCVTRemeshFilter.
   */
  int RunOnCPU(vtkImageData* input, const cvt::GeometryImage& image, long long valid,
    const std::string& reason, vtkInformationVector* outputVector);

private:
  vtkCVTSurfaceFilter(const vtkCVTSurfaceFilter&) = delete;
  void operator=(const vtkCVTSurfaceFilter&) = delete;
};

#endif
