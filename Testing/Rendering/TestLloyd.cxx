// Lloyd's method on the GPU engine: monotone energy, and GPU site updates equal to the
// centroids of the reduced sums.
#include "cvtExactVoronoi.h"
#include "cvtProblems.h"
#include "cvtSampling.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

TEST(Lloyd, EnergyDecreasesEveryIteration)
{
  const cvt::Grid grid = cvt::Grid::Square(128, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  vtkNew<vtkCVTOpenGLEngine> engine;
  ASSERT_TRUE(engine->SetDomain(grid, density));
  cvt::PlaneProblem problem(*engine, grid);
  const cvt::SiteState initial{ cvt::SampleSites(grid, {}, 100, 2), {} };
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 30;
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLloyd(problem, initial, options, nullptr, result, error)) << error;
  ASSERT_EQ(result.History.size(), 31u);
  for (size_t k = 1; k < result.History.size(); ++k)
  {
    EXPECT_LE(result.History[k].Energy, result.History[k - 1].Energy * (1.0 + 1e-6))
      << "iteration " << k;
  }
  EXPECT_LT(result.History.back().Energy, 0.8 * result.History.front().Energy);
  EXPECT_LT(result.History.back().GradientNorm, 0.2 * result.History.front().GradientNorm);
  // The reported energy is that of the returned sites.
  EXPECT_NEAR(result.Sums.TotalEnergy(), cvt::ExactCellSums(grid, result.Sites, {}).TotalEnergy(),
    1e-3 * result.Sums.TotalEnergy());
}

TEST(Lloyd, GpuUpdateMovesSitesToCentroids)
{
  const cvt::Grid grid = cvt::Grid::Square(64, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  const auto sites = cvt::SampleSites(grid, {}, 20, 6);
  vtkNew<vtkCVTOpenGLEngine> engine;
  ASSERT_TRUE(engine->SetDomain(grid, density));
  ASSERT_TRUE(engine->SetSites(sites));
  cvt::CellSums sums;
  ASSERT_TRUE(engine->ComputeCellSums(sums));
  ASSERT_TRUE(engine->MoveSitesToCentroids());
  std::vector<double> moved;
  ASSERT_TRUE(engine->GetSites(moved));
  const cvt::CellSums exact = cvt::ExactCellSums(grid, sites, {});
  for (size_t i = 0; i < sites.size() / 2; ++i)
  {
    EXPECT_NEAR(moved[2 * i], sites[2 * i] + exact.MomentX[i] / exact.Mass[i], 1e-4);
    EXPECT_NEAR(moved[2 * i + 1], sites[2 * i + 1] + exact.MomentY[i] / exact.Mass[i], 1e-4);
  }
}

TEST(Lloyd, ToleranceStopsEarly)
{
  const cvt::Grid grid = cvt::Grid::Square(64, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  vtkNew<vtkCVTOpenGLEngine> engine;
  ASSERT_TRUE(engine->SetDomain(grid, density));
  cvt::PlaneProblem problem(*engine, grid);
  const cvt::SiteState initial{ cvt::SampleSites(grid, {}, 10, 1), {} };
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 500;
  options.Tolerance = 1e-4;
  cvt::OptimizerResult result;
  std::string error;
  ASSERT_TRUE(cvt::RunLloyd(problem, initial, options, nullptr, result, error)) << error;
  EXPECT_LT(result.Iterations, 500);
  EXPECT_NE(result.StopReason, "iteration limit");
}

TEST(Lloyd, ProgressCallbackCanAbort)
{
  const cvt::Grid grid = cvt::Grid::Square(32, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  vtkNew<vtkCVTOpenGLEngine> engine;
  ASSERT_TRUE(engine->SetDomain(grid, density));
  cvt::PlaneProblem problem(*engine, grid);
  const cvt::SiteState initial{ cvt::SampleSites(grid, {}, 10, 1), {} };
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 100;
  cvt::OptimizerResult result;
  std::string error;
  int calls = 0;
  ASSERT_TRUE(cvt::RunLloyd(
    problem, initial, options, [&calls](double) { return ++calls < 5; }, result, error));
  EXPECT_TRUE(result.Aborted);
  EXPECT_EQ(calls, 5);
  EXPECT_EQ(result.Sites.size(), 20u);
}
