// The multi-chart atlas of a mesh: charts are disks covering the surface, pixels carry its
// area, neighbouring pixels of a chart are neighbours on the surface (no fold, no flip), and
// every chart-border pixel of a closed surface has a seam partner next to it in 3D.
#include "cvtAtlas.h"
#include "cvtTestMeshes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{

struct Case
{
  std::string Name;
  cvt::SurfaceMesh Mesh;
  bool Closed;
  cvt::Atlas Atlas; // in a 600 x 500 image
  std::string Error;
};

std::vector<Case> Cases()
{
  std::vector<Case> cases{ { "sphere", cvttest::Sphere(4), true, {}, "" },
    { "torus", cvttest::Torus(1.0, 0.4, 64, 24), true, {}, "" },
    { "tube", cvttest::Tube(0.3, 32, 12), false, {}, "" },
    { "two parts", cvttest::TwoParts(cvttest::Sphere(3), cvttest::Torus(1.0, 0.3, 40, 16), 3.0),
      true, {}, "" } };
  cvt::AtlasOptions options;
  options.Width = 600;
  options.Height = 500;
  for (Case& c : cases)
  {
    c.Error = cvt::BuildAtlas(c.Mesh, options, c.Atlas);
  }
  return cases;
}

double Distance(const cvt::GeometryImage& image, long long p, long long q)
{
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k)
  {
    d2 += std::pow(image.Position[3 * p + k] - image.Position[3 * q + k], 2);
  }
  return std::sqrt(d2);
}

long long ValidPixels(const cvt::GeometryImage& image)
{
  long long valid = 0;
  for (long long p = 0; p < image.NumberOfPixels(); ++p)
  {
    valid += image.IsValid(p) ? 1 : 0;
  }
  return valid;
}

} // namespace

TEST(Atlas, ChartsAreDisksThatCarryTheWholeSurface)
{
  for (const Case& c : Cases())
  {
    SCOPED_TRACE(c.Name);
    ASSERT_EQ(c.Error, "");
    const cvt::Atlas& atlas = c.Atlas;
    const cvt::GeometryImage& image = atlas.Image;
    EXPECT_EQ(image.Width, 600);
    EXPECT_EQ(image.Height, 500);
    EXPECT_EQ(cvt::CheckGeometryImage(image, 1), "");
    EXPECT_GT(atlas.NumberOfCharts, 1);
    // Every chart a disk: one part, genus 0, one boundary loop.
    std::vector<std::vector<std::array<int, 3>>> charts(atlas.NumberOfCharts);
    for (size_t t = 0; t < c.Mesh.Triangles.size(); ++t)
    {
      ASSERT_GE(atlas.TriangleChart[t], 0);
      ASSERT_LT(atlas.TriangleChart[t], atlas.NumberOfCharts);
      charts[atlas.TriangleChart[t]].push_back(c.Mesh.Triangles[t]);
    }
    for (const auto& triangles : charts)
    {
      const cvt::MeshTopology topology =
        cvt::ComputeMeshTopology(c.Mesh.NumberOfPoints(), triangles);
      ASSERT_EQ(topology.Components, 1);
      ASSERT_EQ(topology.Genus, 0);
      ASSERT_EQ(topology.BoundaryLoops, 1);
    }
    // The pixels carry the surface's area, and neighbouring pixels of one chart lie a pixel
    // apart on the surface: no fold, no jump.
    double weights = 0.0;
    for (long long p = 0; p < image.NumberOfPixels(); ++p)
    {
      weights += image.AreaWeight[p];
    }
    const long long valid = ValidPixels(image);
    const double area = cvt::SurfaceArea(c.Mesh);
    EXPECT_NEAR(weights, area, 1e-4 * area);
    const double pixel = std::sqrt(area / valid);
    double farthest = 0.0;
    for (int j = 0; j < image.Height; ++j)
    {
      for (int i = 0; i + 1 < image.Width; ++i)
      {
        const long long p = static_cast<long long>(j) * image.Width + i;
        if (atlas.Chart[p] >= 0 && atlas.Chart[p] == atlas.Chart[p + 1])
        {
          farthest = std::max(farthest, Distance(image, p, p + 1));
        }
      }
    }
    EXPECT_LT(farthest, 4.0 * pixel);
    EXPECT_GE(atlas.MinimumAreaStretch, 0.2);
    EXPECT_LE(atlas.MaximumAreaStretch, 5.0);
    EXPECT_GT(atlas.SeamLength, 0.0);
  }
}

TEST(Atlas, BorderPixelsOfAClosedSurfaceContinueAcrossSeams)
{
  for (const Case& c : Cases())
  {
    SCOPED_TRACE(c.Name);
    ASSERT_EQ(c.Error, "");
    const cvt::Atlas& atlas = c.Atlas;
    const cvt::GeometryImage& image = atlas.Image;
    const long long valid = ValidPixels(image);
    const double pixel = std::sqrt(cvt::SurfaceArea(c.Mesh) / valid);
    long long border = 0, continued = 0, far = 0;
    double farthest = 0.0;
    for (int j = 1; j + 1 < image.Height; ++j)
    {
      for (int i = 1; i + 1 < image.Width; ++i)
      {
        const long long p = static_cast<long long>(j) * image.Width + i;
        const int partner = image.SeamPartner[p];
        if (partner >= 0)
        {
          ASSERT_TRUE(image.IsValid(partner));
          ASSERT_NE(atlas.Chart[partner], atlas.Chart[p]);
          farthest = std::max(farthest, Distance(image, p, partner) / pixel);
          far += Distance(image, p, partner) > 4 * pixel ? 1 : 0;
        }
        if (atlas.Chart[p] < 0)
        {
          continue;
        }
        bool onBorder = false;
        for (long long q : { p - 1, p + 1, p - image.Width, p + image.Width })
        {
          onBorder = onBorder || atlas.Chart[q] != atlas.Chart[p];
        }
        border += onBorder ? 1 : 0;
        continued += onBorder && partner >= 0 ? 1 : 0;
      }
    }
    // Partners are where the surface goes on: a few pixels away in 3D, not across the model.
    EXPECT_LT(farthest, 6.0) << far << " far of " << continued;
    ASSERT_GT(border, 0);
    if (c.Closed)
    {
      EXPECT_GE(continued, border * 99 / 100) << continued << " of " << border;
    }
    else
    {
      EXPECT_LT(continued, border); // the tube's two rims go on nowhere
    }
  }
}

// Pixels by the surface's own border (edges of one triangle) are marked, and only those: none on
// a closed surface, on the open tube its chart-border pixels that go on nowhere, at its rims.
TEST(Atlas, PixelsByTheSurfacesOwnBorderAreMarked)
{
  for (const Case& c : Cases())
  {
    SCOPED_TRACE(c.Name);
    ASSERT_EQ(c.Error, "");
    const cvt::GeometryImage& image = c.Atlas.Image;
    ASSERT_EQ(image.Border.size(), static_cast<size_t>(image.NumberOfPixels()));
    const double pixel = std::sqrt(cvt::SurfaceArea(c.Mesh) / ValidPixels(image));
    long long marked = 0, unmarked = 0, offRim = 0;
    for (int j = 1; j + 1 < image.Height; ++j)
    {
      for (int i = 1; i + 1 < image.Width; ++i)
      {
        const long long p = static_cast<long long>(j) * image.Width + i;
        if (image.Border[p])
        {
          ASSERT_TRUE(image.IsValid(p));
          ++marked;
          const double z = image.Position[3 * p + 2];
          offRim += std::min(z, 1.0 - z) > 2.0 * pixel ? 1 : 0;
        }
        bool chartBorder = false;
        for (long long q : { p - 1, p + 1, p - image.Width, p + image.Width })
        {
          chartBorder = chartBorder || c.Atlas.Chart[q] != c.Atlas.Chart[p];
        }
        unmarked += image.IsValid(p) && chartBorder && image.SeamPartner[p] < 0 && !image.Border[p];
      }
    }
    if (c.Closed)
    {
      EXPECT_EQ(marked, 0);
    }
    else
    {
      EXPECT_GT(marked, 0);
      EXPECT_EQ(offRim, 0) << "of " << marked;
      EXPECT_LT(unmarked, marked / 50) << "chart-border pixels without a partner left unmarked";
    }
  }
  cvt::GeometryImage image = Cases()[0].Atlas.Image;
  image.Border.pop_back();
  EXPECT_NE(cvt::CheckGeometryImage(image, 1).find("border marks do not hold one value per pixel"),
    std::string::npos);
}

TEST(Atlas, ATooSmallImageIsAnError)
{
  cvt::AtlasOptions options;
  options.Width = 3;
  options.Height = 3;
  cvt::Atlas atlas;
  const std::string error = cvt::BuildAtlas(cvttest::Sphere(3), options, atlas);
  EXPECT_NE(error.find("give a larger resolution"), std::string::npos) << error;
  EXPECT_NE(cvt::BuildAtlas(cvt::SurfaceMesh(), options, atlas), "");
}

TEST(Atlas, SeamPartnersOutsideTheImageOrOnMaskedPixelsAreRefused)
{
  std::vector<Case> cases = Cases();
  ASSERT_EQ(cases[0].Error, "");
  cvt::GeometryImage image = cases[0].Atlas.Image;
  long long masked = 0;
  while (image.IsValid(masked))
  {
    ++masked;
  }
  for (const int partner :
    { static_cast<int>(image.NumberOfPixels()), static_cast<int>(masked), -2 })
  {
    cvt::GeometryImage bad = image;
    bad.SeamPartner[0] = partner;
    const std::string error = cvt::CheckGeometryImage(bad, 1);
    EXPECT_NE(error.find("seam partner (" + std::to_string(partner) + ")"), std::string::npos)
      << error;
  }
  image.SeamPartner.pop_back();
  EXPECT_NE(cvt::CheckGeometryImage(image, 1).find("seam partners do not hold one value per pixel"),
    std::string::npos);
}
