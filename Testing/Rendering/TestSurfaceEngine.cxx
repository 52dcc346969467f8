// The GPU surface engine on a torus geometry image against independent CPU computations:
// brute-force nearest-site labels, sums over the GPU's labels, constrained centroids.
#include "cvtAtlas.h"
#include "cvtRenderingTestSupport.h"
#include "cvtSurface.h"
#include "cvtTestMeshes.h"
#include "vtkCVTSurfaceEngine.h"

#include "vtkNew.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>
#include <vector>

using cvttest::TorusGeometryImage;

namespace
{
/// Pixels whose label is not (within float error) a nearest site in 3D, by brute force, or
/// that are masked but labelled; with `seamsOnly`, only pixels with a seam partner count.
int CountSurfaceMislabels(const cvt::GeometryImage& gi, const std::vector<double>& sites,
  const std::vector<int>& labels, bool seamsOnly = false)
{
  const int n = static_cast<int>(sites.size() / 3);
  const auto distance2 = [&](long long p, int s)
  {
    double d2 = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      d2 += std::pow(gi.Position[3 * p + c] - sites[3 * s + c], 2);
    }
    return d2;
  };
  int wrong = 0;
  for (long long p = 0; p < gi.NumberOfPixels(); ++p)
  {
    if (seamsOnly && (gi.SeamPartner.empty() || gi.SeamPartner[p] < 0))
    {
      continue;
    }
    if (!gi.IsValid(p))
    {
      wrong += labels[p] != -1 ? 1 : 0;
      continue;
    }
    double best = std::numeric_limits<double>::infinity();
    for (int s = 0; s < n; ++s)
    {
      best = std::min(best, distance2(p, s));
    }
    wrong += labels[p] < 0 || distance2(p, labels[p]) > best * (1.0 + 1e-5) ? 1 : 0;
  }
  return wrong;
}

/// One labelling and reduction of `sites` by a new engine: the sums and every pixel's label.
::testing::AssertionResult LabelOnce(const cvt::GeometryImage& gi, const std::vector<double>& sites,
  const std::vector<long long>& pixels, cvt::CellSums& sums, std::vector<int>& labels)
{
  vtkNew<vtkCVTSurfaceEngine> engine;
  if (!engine->SetGeometryImage(gi) || !engine->SetSites(sites, pixels) ||
    !engine->ComputeCellSums(sums) || !engine->GetLabels(labels))
  {
    return ::testing::AssertionFailure() << engine->GetLastError();
  }
  return ::testing::AssertionSuccess();
}
}

TEST(SurfaceEngine, LabelsAndSumsMatchTheCpu)
{
  // Enough sites that Euclidean cells stay small against the tube radius (few large cells
  // reach across the hole: Euclidean Voronoi regions disconnected on the surface).
  const cvt::GeometryImage gi = TorusGeometryImage(128, 64);
  std::vector<long long> pixels;
  const std::vector<double> sites = cvt::SampleSurfaceSites(gi, 200, 3, pixels);
  cvt::CellSums sums;
  std::vector<int> labels;
  ASSERT_TRUE(LabelOnce(gi, sites, pixels, sums, labels));

  // Brute force: the nearest site in 3D of every pixel; and the weighted sums over the GPU's
  // labels (so that the reduction is checked on its own).
  const int wrong = CountSurfaceMislabels(gi, sites, labels);
  cvt::CellSums cpu;
  cpu.Resize(200, true);
  for (long long p = 0; p < gi.NumberOfPixels(); ++p)
  {
    const int label = labels[p];
    ASSERT_GE(label, 0);
    const double w = gi.AreaWeight[p];
    const double d[3] = { gi.Position[3 * p] - sites[3 * label],
      gi.Position[3 * p + 1] - sites[3 * label + 1],
      gi.Position[3 * p + 2] - sites[3 * label + 2] };
    cpu.Mass[label] += w;
    cpu.MomentX[label] += w * d[0];
    cpu.MomentY[label] += w * d[1];
    cpu.MomentZ[label] += w * d[2];
    cpu.Energy[label] += w * (d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
  }
  std::cout << "[ measured ] surface 1+JFA: " << wrong << " of " << gi.NumberOfPixels()
            << " pixels mislabelled\n";
  EXPECT_LE(wrong, gi.NumberOfPixels() / 200); // under 0.5%
  for (int s = 0; s < 200; ++s)
  {
    EXPECT_NEAR(sums.Mass[s], cpu.Mass[s], 1e-4 * cpu.Mass[s] + 1e-9);
    EXPECT_NEAR(sums.MomentZ[s], cpu.MomentZ[s], 1e-4 * cpu.Mass[s] + 1e-9);
    EXPECT_NEAR(sums.Energy[s], cpu.Energy[s], 1e-4 * cpu.Energy[s] + 1e-9);
  }
}

TEST(SurfaceEngine, ConstrainedCentroidsMatchTheCpu)
{
  const cvt::GeometryImage gi = TorusGeometryImage(128, 64);
  std::vector<long long> pixels;
  const std::vector<double> sites = cvt::SampleSurfaceSites(gi, 150, 8, pixels);
  vtkNew<vtkCVTSurfaceEngine> engine;
  ASSERT_TRUE(engine->SetGeometryImage(gi));
  ASSERT_TRUE(engine->SetSites(sites, pixels));
  cvt::CellSums sums;
  ASSERT_TRUE(engine->ComputeCellSums(sums));
  std::vector<int> labels;
  ASSERT_TRUE(engine->GetLabels(labels));
  // Targets: the cells' 3D centroids, off the surface.
  std::vector<double> centroids = sites;
  for (size_t i = 0; i < 150; ++i)
  {
    centroids[3 * i] += sums.MomentX[i] / sums.Mass[i];
    centroids[3 * i + 1] += sums.MomentY[i] / sums.Mass[i];
    centroids[3 * i + 2] += sums.MomentZ[i] / sums.Mass[i];
  }
  std::vector<double> gpuSites = sites, cpuSites = sites;
  std::vector<long long> gpuPixels = pixels, cpuPixels = pixels;
  ASSERT_TRUE(engine->NearestPointsInCells(centroids, gpuSites, gpuPixels))
    << engine->GetLastError();
  cvt::NearestPointsInCells(gi, labels, centroids, cpuSites, cpuPixels);
  int samePixel = 0;
  for (size_t i = 0; i < 150; ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      // float on the GPU, double on the CPU: near-ties between triangles may pick either
      EXPECT_NEAR(gpuSites[3 * i + c], cpuSites[3 * i + c], 1e-3) << "site " << i;
    }
    samePixel += gpuPixels[i] == cpuPixels[i] ? 1 : 0;
  }
  EXPECT_GE(samePixel, 145);
}

TEST(SurfaceEngine, AdaptiveStepLabelsLikeTheFullStep)
{
  // Once the sites are known to be spread, the labelling starts from a shorter step (fewer
  // passes) and labels as the full 1+JFA does.
  const cvt::GeometryImage gi = TorusGeometryImage(256, 128);
  std::vector<long long> pixels;
  const std::vector<double> sites = cvt::SampleSurfaceSites(gi, 400, 4, pixels);
  vtkNew<vtkCVTSurfaceEngine> adaptive, full;
  full->AdaptiveStepOff();
  cvt::CellSums sums, fullSums;
  std::vector<int> adaptiveLabels, fullLabels;
  for (vtkCVTSurfaceEngine* engine : { adaptive.Get(), full.Get() })
  {
    ASSERT_TRUE(engine->SetGeometryImage(gi)) << engine->GetLastError();
    ASSERT_TRUE(engine->SetSites(sites, pixels)) << engine->GetLastError();
    ASSERT_TRUE(engine->ComputeCellSums(sums)) << engine->GetLastError();
    EXPECT_EQ(engine->GetLastInitialStep(), 128); // nothing known yet: the full step
    ASSERT_TRUE(engine->ComputeCellSums(engine == full.Get() ? fullSums : sums));
  }
  ASSERT_TRUE(adaptive->GetLabels(adaptiveLabels));
  ASSERT_TRUE(full->GetLabels(fullLabels));
  int differ = 0;
  for (size_t p = 0; p < fullLabels.size(); ++p)
  {
    differ += adaptiveLabels[p] != fullLabels[p] ? 1 : 0;
  }
  const int wrong = CountSurfaceMislabels(gi, sites, adaptiveLabels);
  std::cout << "[ measured ] surface adaptive 1+JFA: initial step "
            << adaptive->GetLastInitialStep() << " (full 128), largest cell radius "
            << adaptive->GetLastMaximumCellRadius() << " pixels; " << differ
            << " pixels differ from the full 1+JFA, " << wrong << " of " << gi.NumberOfPixels()
            << " mislabelled\n";
  EXPECT_LT(adaptive->GetLastInitialStep(), 128);
  EXPECT_EQ(full->GetLastInitialStep(), 128);
  EXPECT_EQ(adaptive->GetNumberOfSafeguardFallbacks(), 0);
  EXPECT_LE(differ, gi.NumberOfPixels() / 1000);
  EXPECT_LE(wrong, gi.NumberOfPixels() / 200); // as the full step: under 0.5%
  for (int s = 0; s < 400; ++s)
  {
    EXPECT_NEAR(sums.Mass[s], fullSums.Mass[s], 1e-2 * fullSums.Mass[s] + 1e-9) << "site " << s;
  }
}

TEST(SurfaceEngine, SafeguardFallsBackWhenSitesJump)
{
  // The same number of sites crowded into a corner of the image but one: cells far larger than
  // the shortened step reaches. The safeguard must label again from the full step.
  const cvt::GeometryImage gi = TorusGeometryImage(256, 128);
  std::vector<long long> pixels;
  const std::vector<double> sites = cvt::SampleSurfaceSites(gi, 400, 9, pixels);
  vtkNew<vtkCVTSurfaceEngine> engine;
  ASSERT_TRUE(engine->SetGeometryImage(gi));
  ASSERT_TRUE(engine->SetSites(sites, pixels));
  cvt::CellSums sums;
  ASSERT_TRUE(engine->ComputeCellSums(sums));
  ASSERT_TRUE(engine->ComputeCellSums(sums));
  ASSERT_LT(engine->GetLastInitialStep(), 128);

  std::vector<double> crowded(sites.size());
  std::vector<long long> crowdedPixels(pixels.size());
  for (size_t s = 0; s < crowdedPixels.size(); ++s)
  {
    const long long p = s == 0 ? 100 * 256 + 200 : static_cast<long long>(s / 20) * 256 + s % 20;
    crowdedPixels[s] = p;
    for (int c = 0; c < 3; ++c)
    {
      crowded[3 * s + c] = gi.Position[3 * p + c];
    }
  }
  const int before = engine->GetNumberOfSafeguardFallbacks();
  ASSERT_TRUE(engine->SetSites(crowded, crowdedPixels));
  ASSERT_TRUE(engine->ComputeCellSums(sums));
  EXPECT_EQ(engine->GetNumberOfSafeguardFallbacks(), before + 1);
  EXPECT_EQ(engine->GetLastInitialStep(), 128);
  std::vector<int> labels;
  ASSERT_TRUE(engine->GetLabels(labels));
  const int wrong = CountSurfaceMislabels(gi, crowded, labels);
  std::cout << "[ measured ] surface safeguard: " << wrong << " of " << gi.NumberOfPixels()
            << " mislabelled after the fallback\n";
  EXPECT_LE(wrong, gi.NumberOfPixels() / 200);
}

TEST(SurfaceEngine, SitesSharingAPixelKeepTheirCells)
{
  // Pairs of sites given the same pixel (one pair on the wrapped column): the lower id wins
  // the pixel, and the other, nearer to the next pixel, must still get the pixels its cell
  // holds (seeded in the nearest free neighbour), as in the plane.
  const cvt::GeometryImage gi = TorusGeometryImage(128, 64);
  std::vector<long long> pixels;
  std::vector<double> sites = cvt::SampleSurfaceSites(gi, 40, 6, pixels);
  const long long sharedPixel[3] = { 20 * 128 + 40, 40 * 128 + 64, 5 * 128 + 127 };
  for (int k = 0; k < 3; ++k)
  {
    const long long p = sharedPixel[k];
    const long long next = p - p % 128 + (p + 1) % 128; // the pixel to the right, wrapped
    for (int j = 0; j < 2; ++j)
    {
      const int s = 2 * k + j;
      pixels[s] = p;
      for (int c = 0; c < 3; ++c)
      {
        sites[3 * s + c] =
          gi.Position[3 * p + c] + 0.45 * j * (gi.Position[3 * next + c] - gi.Position[3 * p + c]);
      }
    }
  }
  cvt::CellSums sums;
  std::vector<int> labels;
  ASSERT_TRUE(LabelOnce(gi, sites, pixels, sums, labels));
  // Brute force: how many pixels each site's cell holds.
  std::vector<int> owned(40, 0);
  for (long long p = 0; p < gi.NumberOfPixels(); ++p)
  {
    double best = std::numeric_limits<double>::infinity();
    int nearest = -1;
    for (int s = 0; s < 40; ++s)
    {
      double d2 = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        d2 += std::pow(gi.Position[3 * p + c] - sites[3 * s + c], 2);
      }
      if (d2 < best)
      {
        best = d2;
        nearest = s;
      }
    }
    ++owned[nearest];
  }
  for (int s = 0; s < 6; ++s)
  {
    ASSERT_GT(owned[s], 0) << "site " << s << ": the test's pairs must both own pixels";
  }
  for (int s = 0; s < 40; ++s)
  {
    EXPECT_GT(sums.Mass[s], 0.0) << "site " << s << " lost its cell of " << owned[s] << " pixels";
  }
  EXPECT_LE(CountSurfaceMislabels(gi, sites, labels), gi.NumberOfPixels() / 200);
}

TEST(SurfaceEngine, AtlasCellsCrossSeams)
{
  // Surfaces cut into charts: with the seams, every pixel's label is the nearest site in 3D,
  // chart-border pixels included; without them, cells stop at the chart borders.
  const std::pair<const char*, cvt::SurfaceMesh> meshes[] = { { "sphere", cvttest::Sphere(4) },
    { "sphere and torus",
      cvttest::TwoParts(cvttest::Sphere(3), cvttest::Torus(1.0, 0.3, 48, 16), 3.0) } };
  for (const auto& named : meshes)
  {
    SCOPED_TRACE(named.first);
    cvt::AtlasOptions options;
    options.Width = 400;
    options.Height = 300;
    cvt::Atlas atlas;
    ASSERT_EQ(cvt::BuildAtlas(named.second, options, atlas), "");
    const cvt::GeometryImage& gi = atlas.Image;
    long long valid = 0, seamPixels = 0;
    double area = 0.0;
    for (long long p = 0; p < gi.NumberOfPixels(); ++p)
    {
      valid += gi.IsValid(p) ? 1 : 0;
      seamPixels += gi.SeamPartner[p] >= 0 ? 1 : 0;
      area += gi.AreaWeight[p];
    }
    std::vector<long long> pixels;
    const std::vector<double> sites = cvt::SampleSurfaceSites(gi, 150, 5, pixels);
    cvt::CellSums sums;
    std::vector<int> labels;
    ASSERT_TRUE(LabelOnce(gi, sites, pixels, sums, labels));
    const int wrong = CountSurfaceMislabels(gi, sites, labels);
    const int wrongOnSeams = CountSurfaceMislabels(gi, sites, labels, true);
    double mass = 0.0;
    for (double m : sums.Mass)
    {
      mass += m;
    }
    EXPECT_NEAR(mass, area, 1e-4 * area);

    cvt::GeometryImage cut = gi;
    cut.SeamPartner.clear();
    std::vector<int> cutLabels;
    ASSERT_TRUE(LabelOnce(cut, sites, pixels, sums, cutLabels));
    const int wrongWithoutSeams = CountSurfaceMislabels(gi, sites, cutLabels);
    std::cout << "[ measured ] atlas of the " << named.first << ", " << atlas.NumberOfCharts
              << " charts: " << wrong << " of " << valid << " pixels mislabelled (" << wrongOnSeams
              << " of " << seamPixels << " seam pixels); without the seams " << wrongWithoutSeams
              << "\n";
    EXPECT_LE(wrong, valid / 200);             // under 0.5%
    EXPECT_LE(wrongOnSeams, seamPixels / 100); // under 1%
    EXPECT_GT(wrongWithoutSeams, 4 * wrong + valid / 100);
  }
}
