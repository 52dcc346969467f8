/**
 * @class   vtkCVTAlgorithm
 * @brief   What every CVT filter shares: the optimiser's properties, the run, the outputs.
 *
 * A CVT filter draws NumberOfSites sites (RandomSeed), minimises the CVT energy by L-BFGS
 * (default; Liu et al. 2009, NumberOfCorrections kept) or Lloyd's method until
 * MaximumNumberOfIterations, until |grad F| falls below GradientTolerance times its initial
 * value, or until the relative energy decrease of an iteration falls below Tolerance (0 runs
 * every iteration). L-BFGS also stops, with a warning naming the reason, when no sufficient
 * decrease is possible; its best sites are the output.
 *
 * Its four outputs: 0 the sites (vtkPolyData), 1 the labels (the input with a SiteId array),
 * 2 a mesh (the dual triangulation or the remesh), 3 the convergence history (vtkTable:
 * iteration, evaluations, energy, gradient_norm, seconds).
 *
 * Bad input is reported with vtkErrorMacro; all outputs are then empty and RequestData returns
 * 0 (see FailPipelineOnError). Progress is reported every iteration and AbortExecute stops the
 * iterations (the outputs then hold the best sites so far).
 *
 * Subclasses implement Compute(): a short sequence of named steps that read the input, call
 * Optimize() on their problem, and fill the outputs (AddRunFields, FillHistory).
 */
#ifndef vtkCVTAlgorithm_h
#define vtkCVTAlgorithm_h

#include "cvtFiltersModule.h" // for export macro
#include "vtkPolyDataAlgorithm.h"
#include "vtkTimeStamp.h" // for LastFailure

#include <string> // for std::string

class vtkFieldData;
class vtkTable;
namespace cvt
{
class Problem;
class SharedCellSums;
struct OptimizerOptions;
struct OptimizerResult;
struct SiteState;
}

class CVTFILTERS_EXPORT vtkCVTAlgorithm : public vtkPolyDataAlgorithm
{
public:
  vtkTypeMacro(vtkCVTAlgorithm, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum Methods
  {
    LLOYD = 0,
    LBFGS = 1
  };

  /** The output ports; subclasses name port 2 (DualPort, RemeshPort). */
  enum OutputPorts
  {
    SitesPort = 0,
    LabelsPort = 1,
    MeshPort = 2,
    HistoryPort = 3
  };

  ///@{
  /** Number of sites drawn when no initial sites are given (default 1000). */
  vtkSetClampMacro(NumberOfSites, int, 0, VTK_INT_MAX);
  vtkGetMacro(NumberOfSites, int);
  ///@}

  ///@{
  /** Seed of the initial site sampling (default 1): the same seed gives the same output. */
  vtkSetMacro(RandomSeed, int);
  vtkGetMacro(RandomSeed, int);
  ///@}

  ///@{
  /** The optimiser: LBFGS (default) or LLOYD. */
  vtkSetClampMacro(Method, int, LLOYD, LBFGS);
  vtkGetMacro(Method, int);
  void SetMethodToLloyd() { this->SetMethod(LLOYD); }
  void SetMethodToLBFGS() { this->SetMethod(LBFGS); }
  ///@}

  ///@{
  /** Iteration cap (default 100). */
  vtkSetClampMacro(MaximumNumberOfIterations, int, 0, VTK_INT_MAX);
  vtkGetMacro(MaximumNumberOfIterations, int);
  ///@}

  ///@{
  /** Stop when the relative energy decrease of an iteration falls below this (0: never). */
  vtkSetClampMacro(Tolerance, double, 0.0, VTK_DOUBLE_MAX);
  vtkGetMacro(Tolerance, double);
  ///@}

  ///@{
  /** Stop when |grad F| falls below this fraction of its initial value (default 0: never). */
  vtkSetClampMacro(GradientTolerance, double, 0.0, 1.0);
  vtkGetMacro(GradientTolerance, double);
  ///@}

  ///@{
  /** L-BFGS: number of corrections kept for the inverse Hessian (default 7). */
  vtkSetClampMacro(NumberOfCorrections, int, 1, 100);
  vtkGetMacro(NumberOfCorrections, int);
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

  /**
   * The density array name that means "no density array, uniform density": what the ParaView
   * plugin's density menus offer besides the input's arrays.
   */
  static const char* UniformDensityName() { return "Uniform density"; }

  /** Takes the optimiser properties (sites, seed, method, stop rules) of another CVT filter. */
  void CopyOptimizerSettings(vtkCVTAlgorithm* other);

  /**
   * For a filter that runs this one inside its own request under MPI: share the cell sums
   * across the ranks as if this filter's request asked for the piece that `outerRequest` (the
   * outer filter's output information) asks for (see ShareCellSumsAcrossRanks), while its own
   * outputs stay whole (the outer filter keeps its share of its own).
   */
  void ShareRanksLike(vtkInformation* outerRequest);

  ///@{
  /** Typed access to the outputs every CVT filter has. */
  vtkPolyData* GetSitesOutput();
  vtkTable* GetHistoryOutput();
  ///@}

protected:
  vtkCVTAlgorithm();
  ~vtkCVTAlgorithm() override;

  /** The labels output's type: the input's (vtkImageData or vtkPolyData). */
  virtual const char* GetLabelsDataType() const = 0;
  /** The work of RequestData, on emptied outputs: false after an error (vtkErrorMacro). */
  virtual bool Compute(vtkInformationVector** inputVector, vtkInformationVector* outputVector) = 0;

  int FillOutputPortInformation(int port, vtkInformation* info) override;
  /** Every input in full (every pixel or triangle takes part in every cell); see MPI pieces. */
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** The optimiser options the properties ask for. */
  cvt::OptimizerOptions GetOptimizerOptions() const;
  /**
   * Runs the chosen method on `problem` from `initial` with UpdateProgress (the run's fraction
   * times `progressShare`) and AbortExecute; on failure `error` says why. Warns when L-BFGS
   * stopped short of the tolerances.
   */
  bool Optimize(cvt::Problem& problem, const cvt::SiteState& initial,
    const cvt::OptimizerOptions& options, cvt::OptimizerResult& result, std::string& error,
    double progressShare = 1.0);
  /**
   * Under MPI, when the executive asks this rank for its piece of as many pieces as there are
   * ranks (every rank then runs the same request), makes the ranks share `engine`'s cell sums:
   * each computes its share of the work and the sums are added across ranks
   * (vtkMultiProcessController::AllReduce) before every optimiser step. Every rank of such a
   * request must call it, with a null `engine` if its engine cannot share and `ready` false if
   * its engine failed to set up: the ranks share only when all of them can and their engines
   * split the work the same way (cvt::SharedCellSums::Split; not a CPU rank with an OpenGL
   * one), and otherwise each computes alone. While they share, they stop together: each reduction
   * carries the ranks' AbortExecute, and an abort asked on one rank stops all of them at the same
   * step (a rank that stopped alone would leave the others waiting in the next reduction). A filter
   * updated on one rank alone (piece 0 of 1) shares nothing. Returns the number of ranks sharing. A
   * filter run inside another shares as the outer request's piece (ShareRanksLike).
   */
  int ShareCellSumsAcrossRanks(
    cvt::SharedCellSums* engine, bool ready, vtkInformationVector* outputVector);
  /** Whether to stop: AbortExecute, or while ranks share the sums, an abort on any rank. */
  bool StopRequested() const;
  /** The run's field data: Energy, GradientNorm, Iterations, Evaluations, StopReason. */
  static void AddRunFields(
    vtkFieldData* fields, const cvt::OptimizerResult& result, double gradientNorm);

  int NumberOfSites = 1000;
  int RandomSeed = 1;
  int Method = LBFGS;
  // 50 would save 18% end to end on surfaces, but their remeshes lose regularity (46 CGAL meshes
  // at 1000 sites: valence 6 down 0.014 on average, energy up 0.2-0.5%, two more over 1% of the
  // diagonal from the input).
  int MaximumNumberOfIterations = 100;
  double Tolerance = 1e-6;
  double GradientTolerance = 0.0;
  int NumberOfCorrections = 7;
  bool FailPipelineOnError = true;
  vtkTimeStamp LastFailure; // when the last failed run ended (see FailPipelineOnError)
  bool LastRunFailed = false;
  bool RanksStopTogether = false; // see ShareCellSumsAcrossRanks
  int OuterPiece = 0;             // see ShareRanksLike; OuterPieces 0: none
  int OuterPieces = 0;
  bool AnyRankAborted = false;

private:
  vtkCVTAlgorithm(const vtkCVTAlgorithm&) = delete;
  void operator=(const vtkCVTAlgorithm&) = delete;
};

#endif
