#include "cvtLBFGS.h"

#include "cvtOptimizerSupport.h"

#include <Eigen/Core>
#include <LBFGSB.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace cvt
{

namespace
{
using Clock = std::chrono::steady_clock;
using Vector = Eigen::VectorXd;

/// The CVT energy seen by the solver, in coordinates scaled to the unit box so that the
/// solver's unit first step means the same for any physical extent of the domain.
class Objective
{
public:
  Objective(Engine& engine, const Grid& grid, const OptimizerOptions& options,
    const ProgressCallback& progress, OptimizerResult& result)
    : Engine_(engine)
    , Options(options)
    , Progress(progress)
    , Result(result)
    , Start(Clock::now())
  {
    this->Scale = std::max(grid.XMax() - grid.XMin(), grid.YMax() - grid.YMin());
    this->Origin[0] = grid.XMin();
    this->Origin[1] = grid.YMin();
  }

  Vector ToSolver(const std::vector<double>& sites) const
  {
    Vector x(sites.size());
    for (size_t k = 0; k < sites.size(); ++k)
    {
      x[k] = (sites[k] - this->Origin[k % 2]) / this->Scale;
    }
    return x;
  }
  /// The domain grown by `margin` on every side, in solver coordinates.
  void Bounds(
    const Grid& grid, double margin, Eigen::Index size, Vector& lower, Vector& upper) const
  {
    lower.resize(size);
    upper.resize(size);
    for (Eigen::Index k = 0; k < size; k += 2)
    {
      lower[k] = (grid.XMin() - margin - this->Origin[0]) / this->Scale;
      upper[k] = (grid.XMax() + margin - this->Origin[0]) / this->Scale;
      lower[k + 1] = (grid.YMin() - margin - this->Origin[1]) / this->Scale;
      upper[k + 1] = (grid.YMax() + margin - this->Origin[1]) / this->Scale;
    }
  }
  std::vector<double> FromSolver(const Vector& x) const
  {
    std::vector<double> sites(x.size());
    for (Eigen::Index k = 0; k < x.size(); ++k)
    {
      sites[k] = this->Origin[k % 2] + x[k] * this->Scale;
    }
    return sites;
  }

  /// Energy and gradient at x: one labelling and one reduction on the engine.
  double operator()(const Vector& x, Vector& gradient)
  {
    this->LastSites = this->FromSolver(x);
    CellSums sums;
    if (!this->Engine_.SetSites(this->LastSites) || !this->Engine_.ComputeCellSums(sums))
    {
      throw StopOptimizer{ this->Engine_.GetLastError(), true };
    }
    ++this->Result.Evaluations;
    gradient.resize(x.size());
    for (size_t i = 0; i < sums.Size(); ++i)
    {
      gradient[2 * i] = -2.0 * sums.MomentX[i] * this->Scale;
      gradient[2 * i + 1] = -2.0 * sums.MomentY[i] * this->Scale;
    }
    const double energy = sums.TotalEnergy();
    if (energy < this->BestEnergy)
    {
      this->BestEnergy = energy;
      this->Result.Sites = this->LastSites;
      this->Result.Sums = sums;
    }
    if (this->Result.History.empty())
    {
      this->Record(0, energy, sums.GradientNorm());
    }
    return energy;
  }

  /// Called after every line search, at the accepted iterate.
  void AcceptIterate(double energy, const Vector& gradient)
  {
    this->Record(this->Result.Iterations + 1, energy, gradient.norm() / this->Scale);
  }

  const std::vector<double>& GetLastSites() const { return this->LastSites; }

private:
  void Record(int iteration, double energy, double gradientNorm)
  {
    HistoryEntry entry;
    entry.Iteration = iteration;
    entry.Evaluations = this->Result.Evaluations;
    entry.Energy = energy;
    entry.GradientNorm = gradientNorm;
    entry.Seconds = std::chrono::duration<double>(Clock::now() - this->Start).count();
    RecordAndCheck(this->Options, this->Progress, this->Result, entry);
  }

  Engine& Engine_;
  const OptimizerOptions& Options;
  const ProgressCallback& Progress;
  OptimizerResult& Result;
  Clock::time_point Start;
  double Scale = 1.0;
  double Origin[2] = { 0.0, 0.0 };
  double BestEnergy = std::numeric_limits<double>::infinity();
  std::vector<double> LastSites;
};

}

bool RunLBFGS(Engine& engine, const Grid& grid, const std::vector<double>& sites,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error)
{
  result = OptimizerResult();
  Objective objective(engine, grid, options, progress, result);
  const LBFGSpp::LBFGSBParam<double> parameters = SolverParameters(options);
  LBFGSpp::LBFGSBSolver<double, ReportingLineSearch> solver(parameters);
  Vector x = objective.ToSolver(sites);
  // Bounds: the domain grown by 1% on every side. With bounds exactly at the domain's edge,
  // LBFGS++ 0.1's bounded line search stalls as soon as a site touches one. The energy is
  // smooth for sites just outside (their cells still cover the border), and the result is
  // projected back into the domain at the end.
  const double margin = 0.01 * std::max(grid.XMax() - grid.XMin(), grid.YMax() - grid.YMin());
  Vector lower, upper;
  objective.Bounds(grid, margin, x.size(), lower, upper);
  double energy = 0.0;
  try
  {
    solver.minimize(objective, x, energy, lower, upper);
    result.StopReason = "the solver reported convergence";
  }
  catch (const StopOptimizer& stop)
  {
    if (stop.EngineFailed)
    {
      error = stop.Reason;
      return false;
    }
    result.StopReason = stop.Reason;
  }
  catch (const std::exception& failure)
  {
    // The line search found no point of sufficient decrease: energy and gradient are as
    // accurate as float sums allow, so this is where the method ends.
    result.StopReason = NoSufficientDecrease(failure);
  }
  if (result.Sites.empty())
  {
    error = "the L-BFGS method evaluated no sites";
    return false;
  }
  bool moved = false;
  for (size_t k = 0; k < result.Sites.size(); ++k)
  {
    const double low = k % 2 == 0 ? grid.XMin() : grid.YMin();
    const double high = k % 2 == 0 ? grid.XMax() : grid.YMax();
    const double inside = std::clamp(result.Sites[k], low, high);
    moved = moved || inside != result.Sites[k];
    result.Sites[k] = inside;
  }
  // Leave the engine labelled for the returned sites, and the sums theirs.
  if (moved || objective.GetLastSites() != result.Sites)
  {
    CellSums sums;
    if (!engine.SetSites(result.Sites) || !engine.ComputeCellSums(sums))
    {
      error = engine.GetLastError();
      return false;
    }
    if (moved)
    {
      result.Sums = sums;
    }
  }
  return true;
}

} // namespace cvt
