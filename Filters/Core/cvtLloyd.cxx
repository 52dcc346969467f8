#include "cvtLloyd.h"

#include <chrono>
#include <cmath>

namespace cvt
{

bool RunLloyd(Engine& engine, const OptimizerOptions& options, const ProgressCallback& progress,
  OptimizerResult& result, std::string& error)
{
  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  result = OptimizerResult();
  const bool checkLabels = options.Tolerance > 0.0;
  std::vector<int> labels, previousLabels;

  for (int iteration = 0;; ++iteration)
  {
    if (!engine.ComputeCellSums(result.Sums))
    {
      error = engine.GetLastError();
      return false;
    }
    ++result.Evaluations;
    HistoryEntry entry;
    entry.Iteration = iteration;
    entry.Evaluations = result.Evaluations;
    entry.Energy = result.Sums.TotalEnergy();
    entry.GradientNorm = result.Sums.GradientNorm();
    entry.Seconds = std::chrono::duration<double>(Clock::now() - start).count();
    result.History.push_back(entry);
    result.Iterations = iteration;

    if (progress &&
      !progress(options.MaximumNumberOfIterations > 0
          ? static_cast<double>(iteration) / options.MaximumNumberOfIterations
          : 1.0))
    {
      result.Aborted = true;
      result.StopReason = "aborted";
      break;
    }
    if (iteration >= options.MaximumNumberOfIterations)
    {
      result.StopReason = "iteration limit";
      break;
    }
    if (entry.GradientNorm <= options.GradientTolerance * result.History.front().GradientNorm)
    {
      result.StopReason = "gradient tolerance reached";
      break;
    }
    if (checkLabels && iteration > 0)
    {
      const double before = result.History[iteration - 1].Energy;
      const double decrease = (before - entry.Energy) / std::max(std::abs(before), 1e-300);
      if (decrease >= 0.0 && decrease < options.Tolerance)
      {
        result.StopReason = "relative energy decrease below tolerance";
        break;
      }
    }
    if (checkLabels)
    {
      if (!engine.GetLabels(labels))
      {
        error = engine.GetLastError();
        return false;
      }
      if (labels == previousLabels)
      {
        result.StopReason = "no pixel changed site";
        break;
      }
      previousLabels.swap(labels);
    }
    if (!engine.MoveSitesToCentroids())
    {
      error = engine.GetLastError();
      return false;
    }
  }
  if (!engine.GetSites(result.Sites))
  {
    error = engine.GetLastError();
    return false;
  }
  return true;
}

} // namespace cvt
