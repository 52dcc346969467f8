// One optimiser skeleton for every CVT in the project: Lloyd's method and L-BFGS (Liu et al.
// 2009) over a small problem interface. A problem owns the sites and an engine that labels and
// integrates; the drivers own the clock, the history, the best state, the stop rules and the
// progress. The plane (cvt::Engine), geometry images (cvt::SurfaceEngine) and restricted
// Voronoi diagrams on meshes are three problems (cvtProblems.h).
#ifndef cvtOptimizer_h
#define cvtOptimizer_h

#include "cvtEngine.h"         // for CellSums, EngineErrors
#include "cvtNumericsModule.h" // for export macro

#include <functional>
#include <string>
#include <vector>

namespace cvt
{

/// One row of the convergence history: the state after `Iteration` site updates.
struct HistoryEntry
{
  int Iteration = 0;
  int Evaluations = 0; // energy evaluations (label + reduction passes) so far
  double Energy = 0.0;
  double GradientNorm = 0.0;
  double Seconds = 0.0; // wall time since the optimiser started
};

struct OptimizerOptions
{
  int MaximumNumberOfIterations = 100;
  /// Stop when the relative energy decrease of an iteration falls below this (an increase
  /// counts as below). 0 runs every iteration.
  double Tolerance = 0.0;
  /// Stop when |grad F| falls below this fraction of its initial value (0: never).
  double GradientTolerance = 0.0;
  /// L-BFGS: number of corrections kept for the inverse Hessian (Liu et al. use 7).
  int NumberOfCorrections = 7;
  /// L-BFGS: Lloyd iterations before the first quasi-Newton step. On meshes they bring random
  /// sites close to their cells' centroids, so no first step can throw a site off the surface
  /// where its cell would be empty and stay so.
  int LloydWarmUpIterations = 0;
};

/// Where the sites are: flat coordinates (Dimension() per site) and, on geometry images, the
/// pixel holding each site (empty elsewhere).
struct SiteState
{
  std::vector<double> Sites;
  std::vector<long long> Pixels;
};

struct OptimizerResult : SiteState // the sites of lowest energy seen
{
  CellSums Sums; // integrals for those sites
  std::vector<HistoryEntry> History;
  int Iterations = 0;
  int Evaluations = 0;
  bool Aborted = false;
  std::string StopReason;
};

/// Called after every iteration with the fraction done; return false to abort.
using ProgressCallback = std::function<bool(double fraction)>;

/// What the drivers need of a CVT problem. Every method that can fail returns false and leaves a
/// message in GetLastError().
class CVTNUMERICS_EXPORT Problem : public EngineErrors
{
public:
  virtual ~Problem() = default;

  /// Coordinates per site: 2 in the plane, 3 in space.
  virtual int Dimension() const = 0;
  /// Place the sites exactly there (they are on the domain).
  virtual bool SetState(const SiteState& state) = 0;
  virtual bool GetState(SiteState& state) = 0;
  /// Label the domain for the current sites and integrate over every cell.
  virtual bool ComputeCellSums(CellSums& sums) = 0;
  /// Lloyd's step from the sums of the current sites: every site with a non-empty cell to its
  /// (constrained) centroid.
  virtual bool MoveSitesToCentroids(const CellSums& sums) = 0;
  /// The sites where an L-BFGS step puts them: at the targets, or (on a geometry image) at the
  /// nearest points of their cells.
  virtual bool MoveSitesTo(const std::vector<double>& targets);
  /// dF/d(site coordinates) for the current sites: -2 Moment, without the normal part on surfaces.
  virtual void Gradient(const CellSums& sums, std::vector<double>& gradient) const;
  double GradientNorm(const CellSums& sums) const;
  /// The solver works in (x - center) / scale so its unit first step fits any domain. Default:
  /// the box of the sites.
  virtual void SolverFrame(const std::vector<double>& sites, double center[3], double& scale) const;
  /// Bounds of the L-BFGS-B box, in physical coordinates. Default: none (infinite), for sites
  /// free in space or moved onto a surface after each step.
  virtual void SolverBounds(const double center[3], double scale, std::vector<double>& lower,
    std::vector<double>& upper, size_t size) const;
  /// Moves final sites back into the domain where a step left it; true when any moved.
  virtual bool Conform(std::vector<double>&) const { return false; }

protected:
  /// `ok`, taking the engine's message when it failed.
  bool Relay(bool ok, const EngineErrors& engine)
  {
    return ok || this->Fail(engine.GetLastError());
  }
};

/// Lloyd's method from `initial`. Returns false (message in `error`) only when the problem
/// fails. The result holds the sites of lowest energy seen, and the problem is left labelled
/// for them.
CVTNUMERICS_EXPORT bool RunLloyd(Problem& problem, const SiteState& initial,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error);

/// L-BFGS-B (LBFGS++, More-Thuente line search) on energy and gradient from the problem (Rong
/// et al. 3.4, 4.4). Each energy evaluation is one labelling and one reduction. Stops at the
/// iteration cap, at options.GradientTolerance, when the relative energy decrease falls below
/// options.Tolerance, on abort, or when no sufficient decrease is possible (the reason is in
/// StopReason). Result and return value as RunLloyd.
CVTNUMERICS_EXPORT bool RunLBFGS(Problem& problem, const SiteState& initial,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error);

} // namespace cvt

#endif
