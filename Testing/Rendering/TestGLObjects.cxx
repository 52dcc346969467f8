// The OpenGL engines' GL objects: engines kept across many calls stop growing, and texture
// storage follows sizes (domain, site count), not calls.
#include "cvtRenderingTestSupport.h"
#include "cvtSurface.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkCVTSurfaceEngine.h"

#include "vtkNew.h"

#include <gtest/gtest.h>

#include <random>
#include <vector>

using cvttest::LiveGLObjects;
using cvttest::TorusGeometryImage;

// Engines kept across updates (as the filters will, issue 8) must not pile up GL objects: after
// a warm-up, 200 rounds of new site counts, evaluations, Lloyd steps, nearest points and a new
// domain every 50 rounds leave the same number of live objects.
TEST(GLObjects, EnginesStopGrowing)
{
  std::mt19937 random(5);
  vtkNew<vtkCVTOpenGLEngine> flat;
  cvt::Grid grid;
  grid.Width = grid.Height = 64;
  const std::vector<float> density(64 * 64, 1.0f);
  const cvt::GeometryImage gi = TorusGeometryImage(64, 32);
  vtkNew<vtkCVTSurfaceEngine> surface;
  int warm[2] = { 0, 0 };
  for (int round = 0; round < 250; ++round)
  {
    const int n = 20 + static_cast<int>(random() % 7);
    if (round % 50 == 0)
    {
      ASSERT_TRUE(flat->SetDomain(grid, density)) << flat->GetLastError();
      ASSERT_TRUE(surface->SetGeometryImage(gi)) << surface->GetLastError();
    }
    std::vector<double> sites(2 * static_cast<size_t>(n));
    for (double& c : sites)
    {
      c = std::uniform_real_distribution<double>(0.5, 63.5)(random);
    }
    cvt::CellSums sums;
    ASSERT_TRUE(
      flat->SetSites(sites) && flat->ComputeCellSums(sums) && flat->MoveSitesToCentroids())
      << flat->GetLastError();
    std::vector<long long> pixels;
    std::vector<double> onSurface = cvt::SampleSurfaceSites(gi, n, round, pixels);
    ASSERT_TRUE(surface->SetSites(onSurface, pixels) && surface->ComputeCellSums(sums))
      << surface->GetLastError();
    std::vector<double> nearest = onSurface;
    ASSERT_TRUE(surface->NearestPointsInCells(onSurface, nearest, pixels))
      << surface->GetLastError();
    if (round == 49)
    {
      warm[0] = LiveGLObjects(flat->GetContext());
      warm[1] = LiveGLObjects(surface->GetContext());
    }
  }
  const int after[2] = { LiveGLObjects(flat->GetContext()), LiveGLObjects(surface->GetContext()) };
  std::cout << "[ measured ] live GL objects after warm-up / after 200 more rounds: 2D engine "
            << warm[0] << " / " << after[0] << ", surface engine " << warm[1] << " / " << after[1]
            << "\n";
  EXPECT_GT(warm[0], 5);
  EXPECT_GT(warm[1], 5);
  EXPECT_EQ(after[0], warm[0]) << "the 2D engine leaks GL objects";
  EXPECT_EQ(after[1], warm[1]) << "the surface engine leaks GL objects";
  flat->ReleaseGraphicsResources();
  surface->ReleaseGraphicsResources();
  std::cout << "[ measured ] after ReleaseGraphicsResources: " << LiveGLObjects(flat->GetContext())
            << " and " << LiveGLObjects(surface->GetContext()) << "\n";
}

// Texture storage follows sizes, not calls: once a domain and a site count are set, moving the
// sites (every L-BFGS evaluation), evaluating, Lloyd steps, nearest points and setting the same
// domain again give no texture new storage; a new site count or domain size does.
TEST(GLObjects, StorageFollowsSizes)
{
  cvt::Grid grid;
  grid.Width = grid.Height = 64;
  const std::vector<float> density(64 * 64, 1.0f);
  const cvt::GeometryImage gi = TorusGeometryImage(64, 32);
  vtkNew<vtkCVTOpenGLEngine> flat;
  vtkNew<vtkCVTSurfaceEngine> surface;
  std::mt19937 random(3);
  const auto planeSites = [&random](int n)
  {
    std::vector<double> sites(2 * static_cast<size_t>(n));
    for (double& c : sites)
    {
      c = std::uniform_real_distribution<double>(0.5, 63.5)(random);
    }
    return sites;
  };
  cvt::CellSums sums;
  std::vector<long long> pixels;
  std::vector<double> onSurface = cvt::SampleSurfaceSites(gi, 30, 1, pixels);
  ASSERT_TRUE(flat->SetDomain(grid, density) && flat->SetSites(planeSites(30)) &&
    flat->ComputeCellSums(sums) && flat->MoveSitesToCentroids())
    << flat->GetLastError();
  ASSERT_TRUE(surface->SetGeometryImage(gi) && surface->SetSites(onSurface, pixels) &&
    surface->ComputeCellSums(sums) && surface->NearestPointsInCells(onSurface, onSurface, pixels))
    << surface->GetLastError();
  const long long settled = vtkCVTOpenGLContext::GetNumberOfTextureAllocations();
  for (int round = 0; round < 10; ++round)
  {
    ASSERT_TRUE(flat->SetSites(planeSites(30)) && flat->ComputeCellSums(sums) &&
      flat->MoveSitesToCentroids() && flat->ComputeCellSums(sums));
    onSurface = cvt::SampleSurfaceSites(gi, 30, 2 + round, pixels);
    std::vector<double> nearest = onSurface;
    ASSERT_TRUE(surface->SetSites(onSurface, pixels) && surface->ComputeCellSums(sums) &&
      surface->NearestPointsInCells(onSurface, nearest, pixels));
  }
  ASSERT_TRUE(flat->SetDomain(grid, density) && flat->SetSites(planeSites(30)));
  EXPECT_EQ(vtkCVTOpenGLContext::GetNumberOfTextureAllocations(), settled)
    << "moving sites or setting the same domain gave textures new storage";
  ASSERT_TRUE(flat->SetSites(planeSites(200)) && flat->ComputeCellSums(sums));
  EXPECT_GT(vtkCVTOpenGLContext::GetNumberOfTextureAllocations(), settled)
    << "a new site count kept the old slot textures";
}