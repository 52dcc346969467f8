// L-BFGS through the engine seam: on the exact CPU engine and on the GPU engine.
#include "cvtExactEngine.h"
#include "cvtExactVoronoi.h"
#include "cvtProblems.h"
#include "cvtQuality.h"
#include "cvtSampling.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

namespace
{
cvt::OptimizerResult Optimize(cvt::Engine& engine, const cvt::Grid& grid,
  const std::vector<double>& sites, int iterations, bool lbfgs)
{
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = iterations;
  cvt::OptimizerResult result;
  std::string error;
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  EXPECT_TRUE(engine.SetDomain(grid, density)) << engine.GetLastError();
  cvt::PlaneProblem problem(engine, grid);
  const cvt::SiteState initial{ sites, {} };
  const bool ok = lbfgs ? cvt::RunLBFGS(problem, initial, options, nullptr, result, error)
                        : cvt::RunLloyd(problem, initial, options, nullptr, result, error);
  EXPECT_TRUE(ok) << error;
  return result;
}

}

TEST(LBFGS, ExactEngineBeatsLloydPerEvaluation)
{
  const cvt::Grid grid = cvt::Grid::Square(64, -1.0, 1.0);
  const auto sites = cvt::SampleSites(grid, {}, 60, 12);
  cvt::ExactEngine lbfgsEngine, lloydEngine;
  const auto lbfgs = Optimize(lbfgsEngine, grid, sites, 40, true);
  const auto lloyd = Optimize(lloydEngine, grid, sites, 200, false);
  ASSERT_GE(lbfgs.History.size(), 2u);
  EXPECT_LT(lbfgs.Sums.TotalEnergy(), lbfgs.History.front().Energy);
  // Energy falls at every accepted iterate (sufficient decrease of the line search).
  for (size_t k = 1; k < lbfgs.History.size(); ++k)
  {
    EXPECT_LT(lbfgs.History[k].Energy, lbfgs.History[k - 1].Energy);
  }
  // Fewer evaluations than Lloyd for Lloyd's final energy.
  const double target = lloyd.History.back().Energy;
  int needed = -1;
  for (const auto& entry : lbfgs.History)
  {
    if (entry.Energy <= target && needed < 0)
    {
      needed = entry.Evaluations;
    }
  }
  std::cout << "[ measured ] Lloyd: " << lloyd.Evaluations << " evaluations to " << target
            << "; L-BFGS: " << needed << " evaluations (final " << lbfgs.Sums.TotalEnergy() << ", "
            << lbfgs.StopReason << ")\n";
  ASSERT_GT(needed, 0);
  EXPECT_LT(needed, lloyd.Evaluations);
  EXPECT_LT(lbfgs.Sums.GradientNorm(), 0.05 * lbfgs.History.front().GradientNorm);
  EXPECT_EQ(cvt::CheckSites(grid, lbfgs.Sites), "");
}

TEST(LBFGS, GpuMatchesTheExactEngine)
{
  const cvt::Grid grid = cvt::Grid::Square(256, -1.0, 1.0);
  const auto sites = cvt::SampleSites(grid, {}, 100, 4);
  vtkNew<vtkCVTOpenGLEngine> gpu;
  cvt::ExactEngine exact;
  const auto onGpu = Optimize(*gpu, grid, sites, 60, true);
  const auto onCpu = Optimize(exact, grid, sites, 60, true);
  const double exactEnergyOfGpuSites = cvt::ExactCellSums(grid, onGpu.Sites, {}).TotalEnergy();
  std::cout << "[ measured ] L-BFGS 60 iterations: GPU " << exactEnergyOfGpuSites << " ("
            << onGpu.Evaluations << " evaluations, " << onGpu.StopReason << "), exact CPU "
            << onCpu.Sums.TotalEnergy() << " (" << onCpu.Evaluations << ")\n";
  EXPECT_NEAR(exactEnergyOfGpuSites, onCpu.Sums.TotalEnergy(), 0.003 * onCpu.Sums.TotalEnergy());
  EXPECT_NEAR(onGpu.Sums.TotalEnergy(), exactEnergyOfGpuSites, 1e-4 * exactEnergyOfGpuSites);
}

TEST(LBFGS, StopsOnGradientToleranceAndAbort)
{
  const cvt::Grid grid = cvt::Grid::Square(32, 0.0, 1.0);
  const auto sites = cvt::SampleSites(grid, {}, 20, 3);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  cvt::ExactEngine engine;
  ASSERT_TRUE(engine.SetDomain(grid, density));
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 1000;
  options.GradientTolerance = 0.01;
  cvt::OptimizerResult result;
  std::string error;
  cvt::PlaneProblem problem(engine, grid);
  const cvt::SiteState initial{ sites, {} };
  ASSERT_TRUE(cvt::RunLBFGS(problem, initial, options, nullptr, result, error)) << error;
  EXPECT_EQ(result.StopReason, "gradient tolerance reached");
  EXPECT_LE(result.History.back().GradientNorm, 0.01 * result.History.front().GradientNorm);

  int calls = 0;
  ASSERT_TRUE(cvt::RunLBFGS(
    problem, initial, options, [&calls](double) { return ++calls < 3; }, result, error));
  EXPECT_TRUE(result.Aborted);
  EXPECT_EQ(result.StopReason, "aborted");
  EXPECT_EQ(result.Sites.size(), sites.size());
}

TEST(Quality, SquareLatticeAndRelaxedSites)
{
  const cvt::Grid grid = cvt::Grid::Square(64, 0.0, 1.0);
  std::vector<double> lattice;
  for (int j = 0; j < 8; ++j)
  {
    for (int i = 0; i < 8; ++i)
    {
      lattice.push_back((i + 0.5) / 8.0);
      lattice.push_back((j + 0.5) / 8.0);
    }
  }
  const cvt::QualityMeasures square = cvt::MeasureQuality(grid, lattice);
  EXPECT_EQ(square.InteriorCells, 36);
  EXPECT_EQ(square.HexagonalFraction, 0.0); // squares, not hexagons
  EXPECT_NEAR(square.AreaStandardDeviation, 0.0, 1e-12);
  EXPECT_NEAR(square.NearestNeighborStandardDeviation, 0.0, 1e-12);
  EXPECT_NEAR(square.RadiusStandardDeviation, 0.0, 1e-12);

  const auto random = cvt::SampleSites(grid, {}, 150, 5);
  cvt::ExactEngine engine;
  const auto relaxed = Optimize(engine, grid, random, 100, true);
  const cvt::QualityMeasures before = cvt::MeasureQuality(grid, random);
  const cvt::QualityMeasures after = cvt::MeasureQuality(grid, relaxed.Sites);
  std::cout << "[ measured ] hexagons " << before.HexagonalFraction << " -> "
            << after.HexagonalFraction << ", stdev(area) " << before.AreaStandardDeviation << " -> "
            << after.AreaStandardDeviation << "\n";
  EXPECT_GT(after.HexagonalFraction, 0.6);
  EXPECT_LT(after.AreaStandardDeviation, 0.5 * before.AreaStandardDeviation);
  EXPECT_LT(after.NearestNeighborStandardDeviation, before.NearestNeighborStandardDeviation);
}
