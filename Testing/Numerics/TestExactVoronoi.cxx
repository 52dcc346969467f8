#include "cvtExactEngine.h"
#include "cvtExactVoronoi.h"
#include "cvtPointCloud.h"
#include "cvtSampling.h"
#include "cvtTwoRanks.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <random>
#include <vector>

TEST(ExactVoronoi, UnitSquareIntegrals)
{
  cvt::Polygon square;
  square.X = { 0, 1, 1, 0 };
  square.Y = { 0, 0, 1, 1 };
  const auto r = cvt::IntegratePolygon(square, 0.0, 0.0);
  EXPECT_NEAR(r.Area, 1.0, 1e-15);
  EXPECT_NEAR(r.MomentX, 0.5, 1e-15);
  EXPECT_NEAR(r.MomentY, 0.5, 1e-15);
  EXPECT_NEAR(r.SecondMoment, 2.0 / 3.0, 1e-15); // integral of x^2 + y^2
  const auto c = cvt::IntegratePolygon(square, 0.5, 0.5);
  EXPECT_NEAR(c.MomentX, 0.0, 1e-15);
  EXPECT_NEAR(c.SecondMoment, 1.0 / 6.0, 1e-15);
}

TEST(ExactVoronoi, TwoSitesSplitTheSquareInHalves)
{
  const cvt::Grid grid = cvt::Grid::Square(4, -1.0, 1.0);
  const std::vector<double> sites{ -0.5, 0.0, 0.5, 0.0 };
  const cvt::CellSums sums = cvt::ExactCellSums(grid, sites, {});
  EXPECT_NEAR(sums.Mass[0], 2.0, 1e-12);
  EXPECT_NEAR(sums.Mass[1], 2.0, 1e-12);
  // Each half [0,1] x [-1,1] about its centre: (1/12 + 4/12) * 2.
  EXPECT_NEAR(sums.Energy[0], 2.0 * (1.0 / 12.0 + 4.0 / 12.0), 1e-12);
  EXPECT_NEAR(sums.GradientNorm(), 0.0, 1e-12); // both sites are centroids already
}

TEST(ExactVoronoi, CellsTileTheDomain)
{
  const cvt::Grid grid = cvt::Grid::Square(64, -1.0, 1.0);
  const auto sites = cvt::SampleSites(grid, {}, 300, 11);
  const cvt::CellSums sums = cvt::ExactCellSums(grid, sites, {});
  double total = 0.0;
  for (double m : sums.Mass)
  {
    total += m;
  }
  EXPECT_NEAR(total, 4.0, 1e-9);
}

TEST(ExactVoronoi, PixelwiseDensityMatchesUniformWhenConstant)
{
  const cvt::Grid grid = cvt::Grid::Square(16, 0.0, 1.0);
  const auto sites = cvt::SampleSites(grid, {}, 20, 5);
  const cvt::CellSums uniform = cvt::ExactCellSums(grid, sites, {});
  const cvt::CellSums pixelwise = cvt::ExactCellSums(grid, sites, std::vector<float>(256, 2.0f));
  for (size_t i = 0; i < uniform.Size(); ++i)
  {
    EXPECT_NEAR(pixelwise.Mass[i], 2.0 * uniform.Mass[i], 1e-12);
    EXPECT_NEAR(pixelwise.Energy[i], 2.0 * uniform.Energy[i], 1e-12);
    EXPECT_NEAR(pixelwise.MomentX[i], 2.0 * uniform.MomentX[i], 1e-12);
  }
}

TEST(ExactVoronoi, BruteForceLabelsPickTheNearestSite)
{
  const cvt::Grid grid = cvt::Grid::Square(4, 0.0, 4.0);
  const auto labels = cvt::BruteForceLabels(grid, { 0.5, 0.5, 3.5, 3.5 });
  EXPECT_EQ(labels[0], 0);
  EXPECT_EQ(labels[15], 1);
  EXPECT_EQ(labels[1 * 4 + 0], 0);
}

TEST(ExactVoronoi, PrefixSumsMatchPixelByPixelClipping)
{
  // An uneven grid and density; the oracle clips every cell to every pixel it overlaps.
  cvt::Grid grid;
  grid.Width = 37;
  grid.Height = 29;
  grid.Origin[0] = -1.3;
  grid.Origin[1] = 0.4;
  grid.Spacing[0] = 0.07;
  grid.Spacing[1] = 0.05;
  std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()));
  for (size_t p = 0; p < density.size(); ++p)
  {
    density[p] = static_cast<float>((p * 7919) % 13) / 4.0f; // zeros included
  }
  const auto sites = cvt::SampleSites(grid, density, 40, 5);
  const cvt::CellSums sums = cvt::ExactCellSums(grid, sites, density);
  const std::vector<cvt::Polygon> cells = cvt::ClippedVoronoiCells(grid, sites);
  for (size_t i = 0; i < cells.size(); ++i)
  {
    double mass = 0.0, mx = 0.0, my = 0.0, energy = 0.0;
    for (int py = 0; py < grid.Height; ++py)
    {
      for (int px = 0; px < grid.Width; ++px)
      {
        const double x0 = grid.Origin[0] + px * grid.Spacing[0], x1 = x0 + grid.Spacing[0];
        const double y0 = grid.Origin[1] + py * grid.Spacing[1], y1 = y0 + grid.Spacing[1];
        cvt::Polygon piece = cvt::ClipPolygon(cells[i], 1.0, 0.0, x1);
        piece = cvt::ClipPolygon(piece, -1.0, 0.0, -x0);
        piece = cvt::ClipPolygon(piece, 0.0, 1.0, y1);
        piece = cvt::ClipPolygon(piece, 0.0, -1.0, -y0);
        if (piece.Size() < 3)
        {
          continue;
        }
        const double rho = density[static_cast<size_t>(py) * grid.Width + px];
        const auto r = cvt::IntegratePolygon(piece, sites[2 * i], sites[2 * i + 1]);
        mass += rho * r.Area;
        mx += rho * r.MomentX;
        my += rho * r.MomentY;
        energy += rho * r.SecondMoment;
      }
    }
    EXPECT_NEAR(sums.Mass[i], mass, 1e-12) << "cell " << i;
    EXPECT_NEAR(sums.MomentX[i], mx, 1e-12);
    EXPECT_NEAR(sums.MomentY[i], my, 1e-12);
    EXPECT_NEAR(sums.Energy[i], energy, 1e-12);
  }
  // The k-d tree labels agree with brute force.
  EXPECT_EQ(cvt::NearestSiteLabels(grid, sites), cvt::BruteForceLabels(grid, sites));
}

TEST(ExactEngine, SharedWorkGivesTheSumsOfOneProcessToTheBit)
{
  // Two engines play two MPI ranks: part 1 hands its sums over, part 0 adds them to its own.
  const cvt::Grid grid = cvt::Grid::Square(64, 0.0, 1.0);
  std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()));
  for (size_t p = 0; p < density.size(); ++p)
  {
    density[p] = 0.5f + static_cast<float>(p % 64) / 64.0f;
  }
  const std::vector<double> sites = cvt::SampleSites(grid, density, 101, 3);
  const size_t n = sites.size() / 2;

  cvt::ExactEngine alone;
  ASSERT_TRUE(alone.SetDomain(grid, density) && alone.SetSites(sites));
  cvt::CellSums whole;
  ASSERT_TRUE(alone.ComputeCellSums(whole));

  std::vector<double> fromPartOne;
  cvt::ExactEngine partOne, partZero;
  cvttest::PlayTwoRanks(partZero, partOne, fromPartOne);
  cvt::CellSums ownHalf, combined;
  ASSERT_TRUE(partOne.SetDomain(grid, density) && partOne.SetSites(sites));
  ASSERT_TRUE(partOne.ComputeCellSums(ownHalf));
  // Part one integrated sites n/2 .. n-1 only.
  ASSERT_EQ(fromPartOne.size(), 4 * n);
  for (size_t i = 0; i < n; ++i)
  {
    EXPECT_EQ(ownHalf.Mass[i] > 0.0, i >= n / 2) << "site " << i;
  }
  ASSERT_TRUE(partZero.SetDomain(grid, density) && partZero.SetSites(sites));
  ASSERT_TRUE(partZero.ComputeCellSums(combined));
  EXPECT_EQ(combined.Mass, whole.Mass);
  EXPECT_EQ(combined.MomentX, whole.MomentX);
  EXPECT_EQ(combined.MomentY, whole.MomentY);
  EXPECT_EQ(combined.Energy, whole.Energy);

  // A Lloyd step from the combined sums moves the sites as one process does.
  std::vector<double> movedAlone, movedShared;
  ASSERT_TRUE(alone.MoveSitesToCentroids() && alone.GetSites(movedAlone));
  ASSERT_TRUE(partZero.MoveSitesToCentroids() && partZero.GetSites(movedShared));
  EXPECT_EQ(movedShared, movedAlone);

  // A part whose exchange fails says so.
  cvt::ExactEngine cutOff;
  cutOff.ShareWork(0, 2, [](std::vector<double>&) { return false; });
  ASSERT_TRUE(cutOff.SetDomain(grid, density) && cutOff.SetSites(sites));
  cvt::CellSums none;
  EXPECT_FALSE(cutOff.ComputeCellSums(none));
  EXPECT_NE(cutOff.GetLastError().find("other processes"), std::string::npos);
}

// The nearest point from a hint (the remesh's probes search their nearest vertex from the
// previous probe's) is the brute-force nearest, whatever the hint: near, far or the answer.
TEST(PointCloud, NearestPointFromAnyHintIsTheBruteForceNearest)
{
  std::mt19937 random(3);
  std::uniform_real_distribution<double> coordinate(-1.0, 1.0);
  std::vector<double> points(3 * 500);
  for (double& x : points)
  {
    x = coordinate(random);
  }
  cvt::PointCloud<3> cloud{ &points };
  cvt::PointTree<3> tree(3, cloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  tree.buildIndex();
  const auto distance2 = [&points](const double* x, std::uint32_t i)
  {
    double d2 = 0.0;
    for (int k = 0; k < 3; ++k)
    {
      d2 += (x[k] - points[3 * i + k]) * (x[k] - points[3 * i + k]);
    }
    return d2;
  };
  std::uint32_t hint = 0;
  for (int q = 0; q < 2000; ++q)
  {
    const double x[3] = { coordinate(random), coordinate(random), coordinate(random) };
    std::uint32_t brute = 0;
    for (std::uint32_t i = 1; i < 500; ++i)
    {
      if (distance2(x, i) < distance2(x, brute))
      {
        brute = i;
      }
    }
    // The previous answer (a point anywhere), the far corner's point, and the answer itself.
    for (std::uint32_t start : { hint, static_cast<std::uint32_t>(q % 500), brute })
    {
      const std::uint32_t found = cvt::NearestPoint(tree, x, start);
      ASSERT_EQ(distance2(x, found), distance2(x, brute)) << "query " << q << " hint " << start;
    }
    hint = brute;
  }
  // Where two points are equally near, the hint is kept.
  const std::vector<double> pair{ -1.0, 0.0, 0.0, 1.0, 0.0, 0.0 };
  cvt::PointCloud<3> pairCloud{ &pair };
  cvt::PointTree<3> pairTree(3, pairCloud, nanoflann::KDTreeSingleIndexAdaptorParams(10));
  pairTree.buildIndex();
  const double middle[3] = { 0.0, 0.5, 0.0 };
  EXPECT_EQ(cvt::NearestPoint(pairTree, middle, 0), 0u);
  EXPECT_EQ(cvt::NearestPoint(pairTree, middle, 1), 1u);
}
