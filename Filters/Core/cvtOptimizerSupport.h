// Private to CVT::Core: what the L-BFGS drivers share. LBFGS++'s More-Thuente line search,
// reporting every accepted iterate to the objective (f.AcceptIterate), so that the optimisers
// keep a history per iteration and can stop the solver from there by throwing StopOptimizer.
#ifndef cvtOptimizerSupport_h
#define cvtOptimizerSupport_h

#include "cvtLloyd.h" // for OptimizerOptions, OptimizerResult, HistoryEntry

#include <Eigen/Core>
#include <LBFGSB.h>

#include <algorithm>
#include <cmath>
#include <exception>
#include <string>

namespace cvt
{

/// Thrown from inside the solver to end it: a stop condition, or an engine failure.
struct StopOptimizer
{
  std::string Reason;
  bool EngineFailed;
};

/// Appends `entry` to the history and applies the stop conditions of the L-BFGS drivers:
/// abort, iteration cap, gradient tolerance, relative energy decrease (the last two from the
/// first iteration on). Throws StopOptimizer to stop.
inline void RecordAndCheck(const OptimizerOptions& options, const ProgressCallback& progress,
  OptimizerResult& result, const HistoryEntry& entry)
{
  const double before = result.History.empty() ? entry.Energy : result.History.back().Energy;
  result.History.push_back(entry);
  result.Iterations = entry.Iteration;
  if (progress &&
    !progress(
      static_cast<double>(entry.Iteration) / std::max(1, options.MaximumNumberOfIterations)))
  {
    result.Aborted = true;
    throw StopOptimizer{ "aborted", false };
  }
  if (entry.Iteration >= options.MaximumNumberOfIterations)
  {
    throw StopOptimizer{ "iteration limit", false };
  }
  if (entry.Iteration > 0 &&
    entry.GradientNorm <= options.GradientTolerance * result.History.front().GradientNorm)
  {
    throw StopOptimizer{ "gradient tolerance reached", false };
  }
  const double decrease = (before - entry.Energy) / std::max(std::abs(before), 1e-300);
  if (entry.Iteration > 0 && options.Tolerance > 0.0 && decrease < options.Tolerance)
  {
    throw StopOptimizer{ "relative energy decrease below tolerance", false };
  }
}

/// The solver's parameters: M corrections; no stop test of its own (RecordAndCheck applies
/// them all); at most 20 line-search steps.
inline LBFGSpp::LBFGSBParam<double> SolverParameters(const OptimizerOptions& options)
{
  LBFGSpp::LBFGSBParam<double> parameters;
  parameters.m = std::max(1, options.NumberOfCorrections);
  parameters.epsilon = 0.0;
  parameters.epsilon_rel = 0.0;
  parameters.max_iterations = 0;
  parameters.max_linesearch = 20;
  return parameters;
}

/// The stop reason when the solver gives up: no step of sufficient decrease was found.
inline std::string NoSufficientDecrease(const std::exception& failure)
{
  return std::string("no sufficient decrease possible (") + failure.what() + ")";
}

/// LBFGS++'s More-Thuente line search, reporting every accepted iterate to the objective.
template<typename Scalar>
class ReportingLineSearch
{
public:
  using Vector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  template<typename Function>
  static void LineSearch(Function& f, Scalar& fx, Vector& x, Vector& grad, Scalar& step,
    const Scalar& stepMax, const Vector& direction, const Vector& previous,
    const LBFGSpp::LBFGSBParam<Scalar>& param)
  {
    LBFGSpp::LineSearchMoreThuente<Scalar>::LineSearch(
      f, fx, x, grad, step, stepMax, direction, previous, param);
    f.AcceptIterate(fx, grad);
  }
};

} // namespace cvt

#endif
