#include "cvtOptimizer.h"

#include <Eigen/Core>
#include <LBFGSB.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <exception>
#include <limits>

namespace cvt
{

bool Problem::MoveSitesTo(const std::vector<double>& targets)
{
  return this->SetState(SiteState{ targets, {} });
}

void Problem::Gradient(const CellSums& sums, std::vector<double>& gradient) const
{
  const int d = this->Dimension();
  gradient.assign(d * sums.Size(), 0.0);
  for (size_t i = 0; i < sums.Size(); ++i)
  {
    gradient[d * i] = -2.0 * sums.MomentX[i];
    gradient[d * i + 1] = -2.0 * sums.MomentY[i];
    if (d == 3)
    {
      gradient[d * i + 2] = -2.0 * sums.MomentZ[i];
    }
  }
}

double Problem::GradientNorm(const CellSums& sums) const
{
  std::vector<double> gradient;
  this->Gradient(sums, gradient);
  double total = 0.0;
  for (double g : gradient)
  {
    total += g * g;
  }
  return std::sqrt(total);
}

void Problem::SolverFrame(const std::vector<double>& sites, double center[3], double& scale) const
{
  const int d = this->Dimension();
  double lo[3], hi[3];
  std::fill(lo, lo + 3, std::numeric_limits<double>::infinity());
  std::fill(hi, hi + 3, -std::numeric_limits<double>::infinity());
  for (size_t k = 0; k < sites.size(); ++k)
  {
    lo[k % d] = std::min(lo[k % d], sites[k]);
    hi[k % d] = std::max(hi[k % d], sites[k]);
  }
  scale = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    center[c] = c < d && !sites.empty() ? 0.5 * (lo[c] + hi[c]) : 0.0;
    scale = c < d && !sites.empty() ? std::max(scale, hi[c] - lo[c]) : scale;
  }
  if (!(scale > 0.0)) // one site, or all in one place: any unit lets them move
  {
    scale = 1.0;
  }
}

void Problem::SolverBounds(const double[3], double, std::vector<double>& lower,
  std::vector<double>& upper, size_t size) const
{
  // No box: every coordinate is free, so LBFGS++'s Cauchy point has no break points to sort (a
  // box ten times the sites' extent, never reached, cost a sort of every coordinate per
  // iteration: about 10% of the optimisation's samples at 5000 sites).
  lower.assign(size, -std::numeric_limits<double>::infinity());
  upper.assign(size, std::numeric_limits<double>::infinity());
}

namespace
{
using Clock = std::chrono::steady_clock;
using Vector = Eigen::VectorXd;

/// Thrown from inside a driver (or the solver) to end the run: a stop rule, or a failure; or,
/// with Restart, to start L-BFGS afresh (Run::Stalled).
struct Stop
{
  std::string Reason;
  bool Failed;
  bool Restart = false;
};

/// L-BFGS stalled (an iteration without any decrease, or a failed line search) while the
/// gradient is still above this share of its first norm starts again from steepest descent, its
/// memory cleared, at most MaximumRestarts times. The memory, not convergence, is then to blame:
/// on a building of 59 parts (assimp's regr01.obj, 1000 sites) it stopped after 6 iterations at
/// 11% of the first gradient, and the remesh had a 13.5 degree corner; the 138 CGAL meshes at
/// 1000 sites all end their runs below 0.7% (12 before the iteration cap).
constexpr double StalledGradientShare = 0.05;
constexpr int MaximumRestarts = 3;

/// What both drivers share: evaluation, the best state, history, stop rules and progress.
class Run
{
public:
  Run(Problem& problem, const OptimizerOptions& options, const ProgressCallback& progress,
    OptimizerResult& result)
    : Problem_(problem)
    , Options(options)
    , Progress(progress)
    , Result(result)
    , Start(Clock::now())
  {
    this->Result = OptimizerResult();
  }

  /// Labels and integrates the current sites into Sums; keeps them if they are the best yet.
  double Evaluate()
  {
    if (!this->Problem_.ComputeCellSums(this->Sums))
    {
      this->Fail();
    }
    ++this->Result.Evaluations;
    const double energy = this->Sums.TotalEnergy();
    this->LastIsBest = energy < this->BestEnergy;
    if (this->LastIsBest)
    {
      this->BestEnergy = energy;
      this->Result.Sums = this->Sums;
      if (!this->Problem_.GetState(this->Result))
      {
        this->Fail();
      }
    }
    return energy;
  }

  /// Appends an iterate to the history, reports progress and applies the stop rules: abort,
  /// iteration cap, gradient tolerance and relative energy decrease (the last two from the
  /// first iteration on).
  void Record(int iteration, double energy, double gradientNorm)
  {
    std::vector<HistoryEntry>& history = this->Result.History;
    const double before = history.empty() ? energy : history.back().Energy;
    HistoryEntry entry;
    entry.Iteration = iteration;
    entry.Evaluations = this->Result.Evaluations;
    entry.Energy = energy;
    entry.GradientNorm = gradientNorm;
    entry.Seconds = std::chrono::duration<double>(Clock::now() - this->Start).count();
    history.push_back(entry);
    this->Result.Iterations = iteration;
    const int cap = this->Options.MaximumNumberOfIterations;
    if (this->Progress && !this->Progress(static_cast<double>(iteration) / std::max(1, cap)))
    {
      this->Result.Aborted = true;
      throw Stop{ "aborted", false };
    }
    if (iteration >= cap)
    {
      throw Stop{ "iteration limit", false };
    }
    if (iteration > 0 &&
      gradientNorm <= this->Options.GradientTolerance * history.front().GradientNorm)
    {
      throw Stop{ "gradient tolerance reached", false };
    }
    const double decrease = (before - energy) / std::max(std::abs(before), 1e-300);
    if (iteration > 0 && !(decrease > 0.0) && this->Stalled())
    {
      throw Stop{ "stalled", false, true };
    }
    if (iteration > 0 && this->Options.Tolerance > 0.0 && decrease < this->Options.Tolerance)
    {
      throw Stop{ "relative energy decrease below tolerance", false };
    }
  }

  /// Whether L-BFGS may start again after a stall: restarts left, and the last gradient still
  /// above StalledGradientShare of the first.
  bool Stalled() const
  {
    const std::vector<HistoryEntry>& history = this->Result.History;
    return this->RestartsLeft > 0 && history.size() > 1 &&
      history.back().GradientNorm > StalledGradientShare * history.front().GradientNorm;
  }

  /// One Lloyd iteration: evaluate, record, move to the centroids.
  void LloydIteration(int iteration)
  {
    const double energy = this->Evaluate();
    this->Record(iteration, energy, this->Problem_.GradientNorm(this->Sums));
    if (!this->Problem_.MoveSitesToCentroids(this->Sums))
    {
      this->Fail();
    }
  }

  /// Ends the run on the best sites, moved into the domain, with the problem labelled for them.
  bool Finish(const std::string& reason, bool failed, std::string& error)
  {
    this->Result.StopReason = reason;
    if (failed)
    {
      error = reason;
      return false;
    }
    if (this->Result.Sites.empty())
    {
      error = "no sites were evaluated";
      return false;
    }
    const bool moved = this->Problem_.Conform(this->Result.Sites);
    if (moved || !this->LastIsBest)
    {
      CellSums sums;
      if (!this->Problem_.SetState(this->Result) || !this->Problem_.ComputeCellSums(sums))
      {
        error = this->Problem_.GetLastError();
        return false;
      }
      if (moved)
      {
        this->Result.Sums = sums;
      }
    }
    return true;
  }

  [[noreturn]] void Fail() { throw Stop{ this->Problem_.GetLastError(), true }; }

  Problem& Problem_;
  const OptimizerOptions& Options;
  const ProgressCallback& Progress;
  OptimizerResult& Result;
  Clock::time_point Start;
  CellSums Sums; // of the last evaluation
  double BestEnergy = std::numeric_limits<double>::infinity();
  bool LastIsBest = false;
  int RestartsLeft = 0; // of L-BFGS after a stall (none for Lloyd)
};

/// The energy seen by LBFGS++, in solver coordinates (x - center) / scale and in units of
/// `energyUnit`. LBFGS++ has absolute thresholds (a correction pair is kept where s'y > 1e-16
/// y'y), so it sees an energy of about 1 whatever the input's size; the unit is a power of two,
/// so the solver's steps are, to the bit, those it would take in the energy's own units.
class Objective
{
public:
  Objective(Run& run, const double center[3], double scale, double energyUnit)
    : Run_(run)
    , Dimension(run.Problem_.Dimension())
    , Scale(scale)
    , EnergyUnit(energyUnit)
  {
    std::copy(center, center + 3, this->Center);
  }

  Vector ToSolver(const std::vector<double>& sites) const
  {
    Vector x(sites.size());
    for (size_t k = 0; k < sites.size(); ++k)
    {
      x[k] = (sites[k] - this->Center[k % this->Dimension]) / this->Scale;
    }
    return x;
  }

  /// Energy and gradient at x: the sites moved there, one labelling and one reduction. The
  /// solver's first call is at the sites evaluated before it started, and reuses their sums.
  double operator()(const Vector& x, Vector& gradient)
  {
    Problem& problem = this->Run_.Problem_;
    double energy = this->Run_.Result.History.back().Energy;
    if (!this->FirstCall)
    {
      std::vector<double> targets(x.size());
      for (Eigen::Index k = 0; k < x.size(); ++k)
      {
        targets[k] = this->Center[k % this->Dimension] + x[k] * this->Scale;
      }
      if (!problem.MoveSitesTo(targets))
      {
        this->Run_.Fail();
      }
      energy = this->Run_.Evaluate();
    }
    this->FirstCall = false;
    std::vector<double> g;
    problem.Gradient(this->Run_.Sums, g);
    gradient.resize(x.size());
    for (Eigen::Index k = 0; k < x.size(); ++k)
    {
      gradient[k] = g[k] * this->Scale / this->EnergyUnit;
    }
    return energy / this->EnergyUnit;
  }

  /// Called after every line search, at the accepted iterate.
  void AcceptIterate(double energy, const Vector& gradient)
  {
    this->Run_.Record(this->Run_.Result.Iterations + 1, energy * this->EnergyUnit,
      gradient.norm() * this->EnergyUnit / this->Scale);
  }

private:
  Run& Run_;
  int Dimension;
  double Center[3];
  double Scale;
  double EnergyUnit;
  bool FirstCall = true;
};

/// LBFGS++'s More-Thuente line search, reporting every accepted iterate to the objective.
template<typename Scalar>
class ReportingLineSearch
{
public:
  using SolverVector = Eigen::Matrix<Scalar, Eigen::Dynamic, 1>;
  template<typename Function>
  static void LineSearch(Function& f, Scalar& fx, SolverVector& x, SolverVector& grad, Scalar& step,
    const Scalar& stepMax, const SolverVector& direction, const SolverVector& previous,
    const LBFGSpp::LBFGSBParam<Scalar>& param)
  {
    LBFGSpp::LineSearchMoreThuente<Scalar>::LineSearch(
      f, fx, x, grad, step, stepMax, direction, previous, param);
    f.AcceptIterate(fx, grad);
  }
};
}

bool RunLloyd(Problem& problem, const SiteState& initial, const OptimizerOptions& options,
  const ProgressCallback& progress, OptimizerResult& result, std::string& error)
{
  Run run(problem, options, progress, result);
  try
  {
    if (!problem.SetState(initial))
    {
      run.Fail();
    }
    for (int iteration = 0;; ++iteration)
    {
      run.LloydIteration(iteration);
    }
  }
  catch (const Stop& stop)
  {
    return run.Finish(stop.Reason, stop.Failed, error);
  }
}

bool RunLBFGS(Problem& problem, const SiteState& initial, const OptimizerOptions& options,
  const ProgressCallback& progress, OptimizerResult& result, std::string& error)
{
  Run run(problem, options, progress, result);
  std::string reason = "the solver reported convergence";
  try
  {
    if (!problem.SetState(initial))
    {
      run.Fail();
    }
    const int warmUp = std::min(options.LloydWarmUpIterations, options.MaximumNumberOfIterations);
    for (int iteration = 0; iteration < warmUp; ++iteration)
    {
      run.LloydIteration(iteration);
    }
    SiteState start;
    if (!problem.GetState(start))
    {
      run.Fail();
    }
    // The frame of the initial sites (before any warm-up), as the mesh driver had it.
    double center[3], scale;
    problem.SolverFrame(initial.Sites, center, scale);
    std::vector<double> lower, upper;
    problem.SolverBounds(center, scale, lower, upper, start.Sites.size());
    const double energy = run.Evaluate();
    run.Record(warmUp, energy, problem.GradientNorm(run.Sums));
    // The power of two nearest to the energy there: the solver's energies are then about 1.
    const double energyUnit =
      std::isfinite(energy) && energy > 0.0 ? std::exp2(std::round(std::log2(energy))) : 1.0;
    Objective objective(run, center, scale, energyUnit);
    Vector x = objective.ToSolver(start.Sites);

    LBFGSpp::LBFGSBParam<double> parameters;
    parameters.m = std::max(1, options.NumberOfCorrections);
    // No stop rule of the solver's own: Run::Record applies them all (LBFGS++'s default energy
    // test, a change under 1e-10 in one iteration, is absolute below an energy of 1: it ended a
    // CVT on a mesh 14 mm across, in metres, after 5 of 100 iterations).
    parameters.epsilon = 0.0;
    parameters.epsilon_rel = 0.0;
    parameters.past = 0;
    parameters.max_iterations = 0;
    parameters.max_linesearch = 20;
    const Vector xLower = objective.ToSolver(lower), xUpper = objective.ToSolver(upper);
    run.RestartsLeft = MaximumRestarts; // after the Lloyd warm-up, which has no memory to clear
    for (;;)
    {
      try
      {
        LBFGSpp::LBFGSBSolver<double, ReportingLineSearch> solver(parameters);
        double solverEnergy = 0.0;
        solver.minimize(objective, x, solverEnergy, xLower, xUpper);
        break;
      }
      catch (const Stop& stop)
      {
        if (!stop.Restart)
        {
          throw;
        }
      }
      catch (const std::exception& failure)
      {
        if (!run.Stalled())
        {
          // The line search found no point of sufficient decrease: energy and gradient are as
          // accurate as float sums allow, so this is where the method ends.
          reason = std::string("no sufficient decrease possible (") + failure.what() + ")";
          break;
        }
      }
      --run.RestartsLeft; // from the best sites yet, with a fresh memory
      x = objective.ToSolver(result.Sites);
    }
  }
  catch (const Stop& stop)
  {
    return run.Finish(stop.Reason, stop.Failed, error);
  }
  return run.Finish(reason, false, error);
}

} // namespace cvt
