// The optimiser skeleton on its own, through a toy problem whose answers are known: every site
// i is pulled to its own target c_i with energy |x_i - c_i|^2 (unit mass, moment c_i - x_i), so
// Lloyd reaches the minimum in one step and the energy of any state is exact.
#include "cvtExactEngine.h"
#include "cvtOptimizer.h"
#include "cvtProblems.h"
#include "cvtSampling.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
class PullProblem : public cvt::Problem
{
public:
  explicit PullProblem(std::vector<double> targets)
    : Targets(std::move(targets))
  {
  }
  int Dimension() const override { return 2; }
  bool SetState(const cvt::SiteState& state) override
  {
    this->Sites = state.Sites;
    return true;
  }
  bool GetState(cvt::SiteState& state) override
  {
    state.Sites = this->Sites;
    return true;
  }
  bool ComputeCellSums(cvt::CellSums& sums) override
  {
    if (++this->Evaluations == this->FailAt)
    {
      return this->Fail("the toy engine broke");
    }
    sums.Resize(this->Sites.size() / 2);
    for (size_t i = 0; i < sums.Size(); ++i)
    {
      sums.Mass[i] = 1.0;
      sums.MomentX[i] = this->Targets[2 * i] - this->Sites[2 * i];
      sums.MomentY[i] = this->Targets[2 * i + 1] - this->Sites[2 * i + 1];
      sums.Energy[i] = sums.MomentX[i] * sums.MomentX[i] + sums.MomentY[i] * sums.MomentY[i];
      if (this->Evaluations == this->LieAt) // the gradient points the wrong way, once
      {
        sums.MomentX[i] = -sums.MomentX[i];
        sums.MomentY[i] = -sums.MomentY[i];
      }
    }
    return true;
  }
  /// Half-way to the targets, then (from `WanderFrom` on) away from them.
  bool MoveSitesToCentroids(const cvt::CellSums& sums) override
  {
    ++this->Steps;
    const double factor = this->Steps >= this->WanderFrom ? -1.0 : 0.5;
    for (size_t i = 0; i < sums.Size(); ++i)
    {
      this->Sites[2 * i] += factor * sums.MomentX[i];
      this->Sites[2 * i + 1] += factor * sums.MomentY[i];
    }
    return true;
  }

  std::vector<double> Targets, Sites;
  int Evaluations = 0, Steps = 0;
  int FailAt = -1, WanderFrom = 1000, LieAt = -1;
};

const std::vector<double> Targets = { 0.2, 0.3, -0.5, 0.7, 0.9, -0.1 };
const cvt::SiteState Start{ { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }, {} }; // all in one place

/// Options for L-BFGS runs of the toy problem to convergence, after `warmUp` Lloyd iterations.
cvt::OptimizerOptions ConvergingOptions(int warmUp)
{
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 50;
  options.GradientTolerance = 1e-6;
  options.LloydWarmUpIterations = warmUp;
  return options;
}
}

TEST(Optimizer, LloydRecordsEveryIterationAndStopsOnTolerance)
{
  PullProblem problem(Targets);
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 5;
  options.Tolerance = 0.6; // each half-step divides the energy by 4: a decrease of 0.75
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLloyd(problem, Start, options, nullptr, result, error)) << error;
  EXPECT_EQ(result.StopReason, "iteration limit");
  ASSERT_EQ(result.History.size(), 6u);
  for (size_t k = 1; k < result.History.size(); ++k)
  {
    EXPECT_NEAR(result.History[k].Energy, 0.25 * result.History[k - 1].Energy, 1e-12);
    EXPECT_NEAR(result.History[k].GradientNorm, 0.5 * result.History[k - 1].GradientNorm, 1e-12);
    EXPECT_EQ(result.History[k].Evaluations, static_cast<int>(k) + 1);
  }
  options.Tolerance = 0.8;
  ASSERT_TRUE(cvt::RunLloyd(problem, Start, options, nullptr, result, error)) << error;
  EXPECT_EQ(result.StopReason, "relative energy decrease below tolerance");
  EXPECT_EQ(result.Iterations, 1);
}

TEST(Optimizer, ReturnsTheBestStateAndLeavesTheProblemOnIt)
{
  PullProblem problem(Targets);
  problem.WanderFrom = 3; // two good steps, then away
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 6;
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLloyd(problem, Start, options, nullptr, result, error)) << error;
  EXPECT_EQ(result.StopReason, "iteration limit");
  EXPECT_GT(result.History.back().Energy, result.History[2].Energy);
  EXPECT_DOUBLE_EQ(result.Sums.TotalEnergy(), result.History[2].Energy);
  for (size_t k = 0; k < Targets.size(); ++k)
  {
    EXPECT_NEAR(result.Sites[k], 0.75 * Targets[k], 1e-12); // two half-steps from 0
  }
  EXPECT_EQ(problem.Sites, result.Sites);
  EXPECT_EQ(problem.Evaluations, 8); // 7 iterates and the best one again
}

TEST(Optimizer, AFailureEndsTheRunWithTheProblemsMessage)
{
  PullProblem problem(Targets);
  problem.FailAt = 3;
  cvt::OptimizerResult result;
  std::string error;
  EXPECT_FALSE(cvt::RunLloyd(problem, Start, cvt::OptimizerOptions(), nullptr, result, error));
  EXPECT_EQ(error, "the toy engine broke");
  problem.FailAt = problem.Evaluations + 2;
  EXPECT_FALSE(cvt::RunLBFGS(problem, Start, cvt::OptimizerOptions(), nullptr, result, error));
  EXPECT_EQ(error, "the toy engine broke");
}

TEST(Optimizer, LBFGSWarmsUpWithLloydThenConverges)
{
  PullProblem problem(Targets);
  const cvt::OptimizerOptions options = ConvergingOptions(2);
  cvt::OptimizerResult result;
  std::string error;
  int calls = 0;
  ASSERT_TRUE(cvt::RunLBFGS(
    problem, Start, options, [&calls](double) { return ++calls > 0; }, result, error))
    << error;
  EXPECT_EQ(result.StopReason, "gradient tolerance reached");
  EXPECT_EQ(problem.Steps, 2);
  // Two Lloyd rows, the start of L-BFGS at iteration 2, then one row per accepted step.
  ASSERT_GE(result.History.size(), 4u);
  EXPECT_EQ(result.History[2].Iteration, 2);
  EXPECT_NEAR(result.History[2].Energy, result.History[0].Energy / 16.0, 1e-12);
  EXPECT_EQ(calls, static_cast<int>(result.History.size()));
  for (size_t k = 0; k < Targets.size(); ++k)
  {
    EXPECT_NEAR(result.Sites[k], Targets[k], 1e-6);
  }
}

TEST(Optimizer, LBFGSStartsAgainWhereItStallsFarFromConvergence)
{
  // One evaluation's gradient points uphill: L-BFGS's next direction climbs and its line search
  // fails with the gradient far from converged (a stall, as where cells jump across thin walls).
  // It starts again from the best sites with its memory cleared, and converges.
  PullProblem problem(Targets);
  problem.LieAt = 2;
  const cvt::OptimizerOptions options = ConvergingOptions(0);
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLBFGS(problem, Start, options, nullptr, result, error)) << error;
  EXPECT_EQ(result.StopReason, "gradient tolerance reached");
  for (size_t k = 0; k < Targets.size(); ++k)
  {
    EXPECT_NEAR(result.Sites[k], Targets[k], 1e-6);
  }
}

TEST(Optimizer, LBFGSIsNotBoxedInByWhereTheSitesStart)
{
  // Sites that start within 0.05 of each other converge onto targets up to 0.9 away: problems
  // without a domain give the solver no bounds (a box ten times the starting sites' extent, as
  // before, held them within 0.5 of where they started).
  PullProblem problem(Targets);
  const cvt::SiteState start{ { 0.0, 0.0, 0.05, 0.0, 0.0, 0.05 }, {} };
  std::vector<double> lower, upper;
  const double center[3] = { 0.0, 0.0, 0.0 };
  problem.SolverBounds(center, 0.05, lower, upper, start.Sites.size());
  ASSERT_EQ(lower.size(), start.Sites.size());
  EXPECT_TRUE(std::isinf(lower[0]) && lower[0] < 0.0);
  EXPECT_TRUE(std::isinf(upper[5]) && upper[5] > 0.0);
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLBFGS(problem, start, ConvergingOptions(0), nullptr, result, error)) << error;
  EXPECT_EQ(result.StopReason, "gradient tolerance reached");
  for (size_t k = 0; k < Targets.size(); ++k)
  {
    EXPECT_NEAR(result.Sites[k], Targets[k], 1e-6);
  }
}

TEST(Optimizer, PlaneProblemKeepsLBFGSSitesInTheDomain)
{
  // Sites pulled towards a corner of a uniform square converge inside it: L-BFGS-B may step
  // 1% outside, and the result is clamped back and re-evaluated.
  const cvt::Grid grid = cvt::Grid::Square(32, 0.0, 1.0);
  cvt::ExactEngine engine;
  ASSERT_TRUE(engine.SetDomain(grid, std::vector<float>(32 * 32, 1.0f)));
  cvt::PlaneProblem problem(engine, grid);
  std::vector<double> sites = cvt::SampleSites(grid, {}, 12, 7);
  double center[3], scale;
  problem.SolverFrame(sites, center, scale);
  EXPECT_DOUBLE_EQ(center[0], 0.5);
  EXPECT_DOUBLE_EQ(scale, 1.0);
  std::vector<double> outside = { -0.01, 0.5, 1.005, 1.0 };
  EXPECT_TRUE(problem.Conform(outside));
  EXPECT_EQ(outside, (std::vector<double>{ 0.0, 0.5, 1.0, 1.0 }));
  EXPECT_FALSE(problem.Conform(outside));
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 30;
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLBFGS(problem, { sites, {} }, options, nullptr, result, error)) << error;
  EXPECT_EQ(cvt::CheckSites(grid, result.Sites), "");
  cvt::CellSums sums;
  ASSERT_TRUE(engine.ComputeCellSums(sums));
  EXPECT_DOUBLE_EQ(sums.TotalEnergy(), result.Sums.TotalEnergy());
}
