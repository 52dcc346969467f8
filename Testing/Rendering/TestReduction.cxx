// Regional reduction sums against independent CPU sums: exact polygon integrals of the clipped
// Voronoi cells (split boundary pixels) and whole-pixel sums over brute-force labels.
#include "cvtExactVoronoi.h"
#include "cvtSampling.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkNew.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

namespace
{
cvt::Grid MakeGrid(int width, int height, double x0, double y0, double sx, double sy)
{
  cvt::Grid grid;
  grid.Width = width;
  grid.Height = height;
  grid.Origin[0] = x0;
  grid.Origin[1] = y0;
  grid.Spacing[0] = sx;
  grid.Spacing[1] = sy;
  return grid;
}

void ExpectClose(const cvt::CellSums& gpu, const cvt::CellSums& cpu, double relative)
{
  ASSERT_EQ(gpu.Size(), cpu.Size());
  double totalMass = 0.0, totalEnergy = 0.0;
  for (size_t i = 0; i < cpu.Size(); ++i)
  {
    totalMass += cpu.Mass[i];
    totalEnergy += cpu.Energy[i];
  }
  const double meanMass = totalMass / cpu.Size();
  const double meanEnergy = totalEnergy / cpu.Size();
  const double meanMoment = meanMass * std::sqrt(meanMass); // mass times a cell radius
  for (size_t i = 0; i < cpu.Size(); ++i)
  {
    EXPECT_NEAR(gpu.Mass[i], cpu.Mass[i], relative * meanMass) << "site " << i;
    EXPECT_NEAR(gpu.MomentX[i], cpu.MomentX[i], relative * meanMoment) << "site " << i;
    EXPECT_NEAR(gpu.MomentY[i], cpu.MomentY[i], relative * meanMoment) << "site " << i;
    EXPECT_NEAR(gpu.Energy[i], cpu.Energy[i], relative * meanEnergy) << "site " << i;
  }
  EXPECT_NEAR(gpu.TotalEnergy(), cpu.TotalEnergy(), relative * 0.1 * cpu.TotalEnergy());
}
}

TEST(Reduction, SplitPixelsGiveExactCellIntegralsUniformDensity)
{
  const cvt::Grid grid = MakeGrid(96, 64, -1.5, 0.25, 3.0 / 96, 2.0 / 64);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  const auto sites = cvt::SampleSites(grid, {}, 40, 21);
  vtkNew<vtkCVTOpenGLEngine> engine;
  ASSERT_TRUE(engine->SetDomain(grid, density)) << engine->GetLastError();
  ASSERT_TRUE(engine->SetSites(sites)) << engine->GetLastError();
  cvt::CellSums gpu;
  ASSERT_TRUE(engine->ComputeCellSums(gpu)) << engine->GetLastError();
  const cvt::CellSums exact = cvt::ExactCellSums(grid, sites, {});
  ExpectClose(gpu, exact, 2e-3);
  std::cout << "[ measured ] GPU energy " << gpu.TotalEnergy() << ", exact " << exact.TotalEnergy()
            << " (relative difference "
            << (gpu.TotalEnergy() - exact.TotalEnergy()) / exact.TotalEnergy() << ")\n";
}

TEST(Reduction, SplitPixelsGiveExactCellIntegralsPixelwiseDensity)
{
  const cvt::Grid grid = MakeGrid(64, 64, 0.0, 0.0, 1.0, 1.0);
  std::mt19937 rng(3);
  std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()));
  for (float& value : density)
  {
    value = static_cast<float>(rng() % 1000) / 100.0f; // zeros included
  }
  const auto sites = cvt::SampleSites(grid, density, 30, 4);
  vtkNew<vtkCVTOpenGLEngine> engine;
  ASSERT_TRUE(engine->SetDomain(grid, density));
  ASSERT_TRUE(engine->SetSites(sites));
  cvt::CellSums gpu;
  ASSERT_TRUE(engine->ComputeCellSums(gpu)) << engine->GetLastError();
  ExpectClose(gpu, cvt::ExactCellSums(grid, sites, density), 2e-3);
}

TEST(Reduction, WholePixelsMatchCpuSumsOverBruteForceLabels)
{
  const cvt::Grid grid = MakeGrid(80, 80, -1.0, -1.0, 2.0 / 80, 2.0 / 80);
  std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()));
  for (int j = 0; j < grid.Height; ++j)
  {
    for (int i = 0; i < grid.Width; ++i)
    {
      density[j * grid.Width + i] = 1.0f + static_cast<float>(i) / grid.Width;
    }
  }
  const auto sites = cvt::SampleSites(grid, density, 25, 8);
  vtkNew<vtkCVTOpenGLEngine> engine;
  engine->SplitBoundaryPixelsOff();
  ASSERT_TRUE(engine->SetDomain(grid, density));
  ASSERT_TRUE(engine->SetSites(sites));
  cvt::CellSums gpu;
  ASSERT_TRUE(engine->ComputeCellSums(gpu));

  const std::vector<int> labels = cvt::BruteForceLabels(grid, sites);
  cvt::CellSums cpu;
  cpu.Resize(sites.size() / 2);
  const double area = grid.PixelArea();
  for (int j = 0; j < grid.Height; ++j)
  {
    for (int i = 0; i < grid.Width; ++i)
    {
      const size_t p = static_cast<size_t>(j) * grid.Width + i;
      const int s = labels[p];
      // A pixel's own share: rho * integral over the pixel square of (x - site) and |x - site|^2.
      const double dx = grid.Origin[0] + (i + 0.5) * grid.Spacing[0] - sites[2 * s];
      const double dy = grid.Origin[1] + (j + 0.5) * grid.Spacing[1] - sites[2 * s + 1];
      const double rho = density[p];
      cpu.Mass[s] += rho * area;
      cpu.MomentX[s] += rho * area * dx;
      cpu.MomentY[s] += rho * area * dy;
      cpu.Energy[s] += rho * area *
        (dx * dx + dy * dy +
          (grid.Spacing[0] * grid.Spacing[0] + grid.Spacing[1] * grid.Spacing[1]) / 12.0);
    }
  }
  ExpectClose(gpu, cpu, 1e-4);
}
