// Lloyd's method driven through the engine seam, with convergence history.
#ifndef cvtLloyd_h
#define cvtLloyd_h

#include "cvtCoreModule.h" // for export macro
#include "cvtEngine.h"

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
  /// Stop when the relative energy decrease of an iteration falls below this (and, for
  /// Lloyd, when no pixel changes site). 0 runs every iteration.
  double Tolerance = 0.0;
  /// Stop when |grad F| falls below this fraction of its initial value (0: never).
  double GradientTolerance = 0.0;
  /// L-BFGS: number of corrections kept for the inverse Hessian (Liu et al. use 7).
  int NumberOfCorrections = 7;
  /// Restricted CVT on meshes (RunMeshLBFGS): Lloyd iterations before L-BFGS. They bring the
  /// random sites close to their cells' centroids, so no first quasi-Newton step can throw a
  /// site off the surface where its cell would be empty and stay so.
  int LloydWarmUpIterations = 0;
};

struct OptimizerResult
{
  std::vector<double> Sites; // final sites (flat x, y)
  CellSums Sums;             // integrals for the final sites
  std::vector<HistoryEntry> History;
  int Iterations = 0;
  int Evaluations = 0;
  bool Aborted = false;
  std::string StopReason;
};

/// Called after every evaluation with the fraction done; return false to abort.
using ProgressCallback = std::function<bool(double fraction)>;

/// Runs Lloyd's method from the sites already set on the engine. Returns false (with the
/// engine's message in `error`) when the engine fails; the result then holds the last good state.
CVTCORE_EXPORT bool RunLloyd(Engine& engine, const OptimizerOptions& options,
  const ProgressCallback& progress, OptimizerResult& result, std::string& error);

} // namespace cvt

#endif
