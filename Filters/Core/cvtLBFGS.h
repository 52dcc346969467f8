// The L-BFGS method (Liu et al. 2009) on energy and gradient from the engine (Rong et al. 3.4).
#ifndef cvtLBFGS_h
#define cvtLBFGS_h

#include "cvtCoreModule.h" // for export macro
#include "cvtEngine.h"
#include "cvtLloyd.h" // for OptimizerOptions, OptimizerResult, ProgressCallback

#include <string>

namespace cvt
{

/// Minimises the CVT energy from the sites set on the engine with L-BFGS-B (LBFGS++, More-Thuente
/// line search; the domain box bounds the sites, so no step can push one out). Each energy
/// evaluation is one labelling and one reduction. Stops at the iteration cap, at
/// options.GradientTolerance, when the relative energy decrease falls below options.Tolerance,
/// on abort, or when no sufficient decrease is possible (the reason is in StopReason). The
/// result holds the sites of lowest energy seen, and the engine is left labelled for them.
/// Returns false (message in `error`) only when the engine fails.
CVTCORE_EXPORT bool RunLBFGS(Engine& engine, const Grid& grid, const std::vector<double>& sites,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error);

} // namespace cvt

#endif
