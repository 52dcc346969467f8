#include "cvtMeshOptimizer.h"

#include "cvtOptimizerSupport.h"

#include <Eigen/Core>
#include <LBFGSB.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cvt
{

namespace
{
using Clock = std::chrono::steady_clock;
using Vector = Eigen::VectorXd;

/// Lloyd's step: every site with a non-empty cell to the cell's centroid.
void MoveToCentroids(const CellSums& sums, std::vector<double>& sites)
{
  for (size_t i = 0; i < sums.Size(); ++i)
  {
    if (sums.Mass[i] > 0.0)
    {
      sites[3 * i] += sums.MomentX[i] / sums.Mass[i];
      sites[3 * i + 1] += sums.MomentY[i] / sums.Mass[i];
      sites[3 * i + 2] += sums.MomentZ[i] / sums.Mass[i];
    }
  }
}

/// Evaluation, best state, history and stop conditions of both drivers.
class MeshRun
{
public:
  MeshRun(RestrictedVoronoi& engine, const OptimizerOptions& options,
    const ProgressCallback& progress, OptimizerResult& result)
    : Engine(engine)
    , Options(options)
    , Progress(progress)
    , Result(result)
    , Start(Clock::now())
  {
  }

  double Evaluate(const std::vector<double>& sites)
  {
    if (!this->Engine.SetSites(sites) || !this->Engine.ComputeCellSums(this->Sums))
    {
      throw StopOptimizer{ this->Engine.GetLastError(), true };
    }
    ++this->Result.Evaluations;
    const double energy = this->Sums.TotalEnergy();
    if (energy < this->BestEnergy)
    {
      this->BestEnergy = energy;
      this->Result.Sites = sites;
      this->Result.Sums = this->Sums;
    }
    return energy;
  }

  void Record(int iteration, double energy)
  {
    HistoryEntry entry;
    entry.Iteration = iteration;
    entry.Evaluations = this->Result.Evaluations;
    entry.Energy = energy;
    entry.GradientNorm = this->Sums.GradientNorm();
    entry.Seconds = std::chrono::duration<double>(Clock::now() - this->Start).count();
    RecordAndCheck(this->Options, this->Progress, this->Result, entry);
  }

  bool Finish(const StopOptimizer* stop, std::string& error)
  {
    if (stop && stop->EngineFailed)
    {
      error = stop->Reason;
      return false;
    }
    if (this->Result.Sites.empty())
    {
      error = "no sites were evaluated";
      return false;
    }
    // Leave the engine on the best sites, for the dual that follows.
    if (!this->Engine.SetSites(this->Result.Sites))
    {
      error = this->Engine.GetLastError();
      return false;
    }
    return true;
  }

  RestrictedVoronoi& Engine;
  const OptimizerOptions& Options;
  const ProgressCallback& Progress;
  OptimizerResult& Result;
  Clock::time_point Start;
  CellSums Sums;
  double BestEnergy = std::numeric_limits<double>::infinity();
};

/// The energy in coordinates centred on the sites' box and scaled by its size, so the solver's
/// unit first step fits a surface of any size and place.
class MeshObjective
{
public:
  MeshObjective(MeshRun& run, const double center[3], double scale)
    : Run(run)
    , Scale(scale)
  {
    std::copy(center, center + 3, this->Center);
  }

  std::vector<double> Sites(const Vector& x) const
  {
    std::vector<double> sites(x.size());
    for (Eigen::Index k = 0; k < x.size(); ++k)
    {
      sites[k] = this->Center[k % 3] + x[k] * this->Scale;
    }
    return sites;
  }

  double operator()(const Vector& x, Vector& gradient)
  {
    const double energy = this->Run.Evaluate(this->Sites(x));
    const CellSums& sums = this->Run.Sums;
    gradient.resize(x.size());
    for (size_t i = 0; i < sums.Size(); ++i)
    {
      gradient[3 * i] = -2.0 * sums.MomentX[i] * this->Scale;
      gradient[3 * i + 1] = -2.0 * sums.MomentY[i] * this->Scale;
      gradient[3 * i + 2] = -2.0 * sums.MomentZ[i] * this->Scale;
    }
    return energy;
  }

  void AcceptIterate(double energy, const Vector&)
  {
    this->Run.Record(this->Run.Result.Iterations + 1, energy);
  }

private:
  MeshRun& Run;
  double Center[3];
  double Scale;
};
}

bool RunMeshLloyd(RestrictedVoronoi& engine, const std::vector<double>& sites,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error)
{
  result = OptimizerResult();
  MeshRun run(engine, options, progress, result);
  std::vector<double> current = sites;
  try
  {
    for (int iteration = 0;; ++iteration)
    {
      run.Record(iteration, run.Evaluate(current));
      MoveToCentroids(run.Sums, current);
    }
  }
  catch (const StopOptimizer& stop)
  {
    result.StopReason = stop.Reason;
    return run.Finish(&stop, error);
  }
}

bool RunMeshLBFGS(RestrictedVoronoi& engine, const std::vector<double>& sites,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error)
{
  result = OptimizerResult();
  MeshRun run(engine, options, progress, result);
  double lo[3] = { std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    std::numeric_limits<double>::infinity() };
  double hi[3] = { -lo[0], -lo[1], -lo[2] };
  for (size_t k = 0; k < sites.size(); ++k)
  {
    lo[k % 3] = std::min(lo[k % 3], sites[k]);
    hi[k % 3] = std::max(hi[k % 3], sites[k]);
  }
  const double center[3] = { 0.5 * (lo[0] + hi[0]), 0.5 * (lo[1] + hi[1]), 0.5 * (lo[2] + hi[2]) };
  const double scale = std::max({ hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2], 1e-300 });
  std::vector<double> start = sites;
  try
  {
    for (int iteration = 0; iteration < options.LloydWarmUpIterations; ++iteration)
    {
      run.Record(iteration, run.Evaluate(start));
      MoveToCentroids(run.Sums, start);
    }
    MeshObjective objective(run, center, scale);
    const LBFGSpp::LBFGSBParam<double> parameters = SolverParameters(options);
    LBFGSpp::LBFGSBSolver<double, ReportingLineSearch> solver(parameters);
    Vector x(sites.size());
    for (size_t k = 0; k < sites.size(); ++k)
    {
      x[k] = (start[k] - center[k % 3]) / scale;
    }
    Vector gradient;
    run.Record(options.LloydWarmUpIterations, objective(x, gradient));
    // The box (ten times the sites' extent) only keeps the solver finite.
    const Vector lower = Vector::Constant(x.size(), -10.0),
                 upper = Vector::Constant(x.size(), 10.0);
    double energy = 0.0;
    solver.minimize(objective, x, energy, lower, upper);
    result.StopReason = "the solver reported convergence";
  }
  catch (const StopOptimizer& stop)
  {
    result.StopReason = stop.Reason;
    return run.Finish(&stop, error);
  }
  catch (const std::exception& failure)
  {
    result.StopReason = NoSufficientDecrease(failure);
  }
  return run.Finish(nullptr, error);
}

} // namespace cvt
