/**
 * @class   vtkCVTRemeshFilter
 * @brief   Isotropic remeshing of any manifold triangle mesh by a restricted CVT.
 *
 * Input: a vtkPolyData surface (triangles, polygons or strips; any genus, boundaries and
 * number of parts). It is cleaned first, as users expect: coincident points merged, polygons
 * triangulated, degenerate and duplicate triangles dropped, non-manifold points split and
 * triangles oriented consistently (a warning says what was done). Non-manifold edges and
 * non-orientable surfaces are refused with a message saying where.
 *
 * NumberOfSites sites are drawn on the surface by area (times the optional DensityArray, a
 * point array: denser where larger; RandomSeed) and optimised by L-BFGS (default) or Lloyd on
 * the restricted centroidal Voronoi energy, computed exactly on the CPU (cvt::RestrictedVoronoi:
 * each triangle clipped by the sites' bisector planes, multi-threaded with vtkSMPTools).
 *
 * Outputs:
 * 0. sites: the final sites (vtkPolyData vertices: the centroids of their restricted cells, so
 *    slightly inside curved surfaces), SiteId, Mass, Energy; field
 *    data Energy, GradientNorm, Iterations, Evaluations, StopReason, SurfaceArea, Engine and
 *    EngineReason, the input's topology, and the seconds spent per stage (PrepareSeconds:
 *    cleaning, repairs, topology and engine set-up; OptimizeSeconds; RemeshSeconds: the dual,
 *    the remesh and the outputs);
 * 1. labels: the cleaned input with an int point array SiteId (the nearest site);
 * 2. remesh: the restricted Delaunay triangulation of the sites: vertices on the surface
 *    (sites whose cell meets the border are pinned to it), oriented like the input, the input's
 *    point arrays interpolated onto it (but its normals); field data with valence and angle
 * measures and topology;
 * 3. history: vtkTable (iteration, evaluations, energy, gradient_norm, seconds).
 * Bad input gives a clear error, empty outputs and RequestData returning 0.
 */
#ifndef vtkCVTRemeshFilter_h
#define vtkCVTRemeshFilter_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkTimeStamp.h" // for LastFailure

#include <string> // for std::string

class vtkTable;

class CVTFILTERS_EXPORT vtkCVTRemeshFilter : public vtkPolyDataAlgorithm
{
public:
  static vtkCVTRemeshFilter* New();
  vtkTypeMacro(vtkCVTRemeshFilter, vtkPolyDataAlgorithm);
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
  /** A point array of the input used as density (denser where larger); empty: uniform. */
  vtkSetStdStringFromCharMacro(DensityArray);
  vtkGetCharFromStdStringMacro(DensityArray);

  vtkPolyData* GetSitesOutput();
  vtkPolyData* GetLabelsOutput();
  vtkPolyData* GetRemeshOutput();
  vtkTable* GetHistoryOutput();

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
  vtkCVTRemeshFilter();
  ~vtkCVTRemeshFilter() override = default;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
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
  double Tolerance = 1e-7;
  double GradientTolerance = 0.0;
  int NumberOfCorrections = 7;
  std::string DensityArray;

private:
  vtkCVTRemeshFilter(const vtkCVTRemeshFilter&) = delete;
  void operator=(const vtkCVTRemeshFilter&) = delete;
};

#endif
