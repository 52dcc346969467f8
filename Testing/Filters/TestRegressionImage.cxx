// Regression images: a small CVT drawn against a baseline in Data/, and a picture checked pixel
// by pixel.
// Set CVT_UPDATE_BASELINES=1 to rewrite the baseline after an intended change.
#include "vtkCVTImageFilter.h"
#include "vtkCVTSceneRenderer.h"

#include "vtkCellArray.h"
#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkIntArray.h"
#include "vtkMath.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <string>

TEST(RegressionImage, RenderedCVTMatchesTheBaseline)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(64, 64, 1);
  image->SetSpacing(1.0 / 32, 1.0 / 32, 1.0);
  image->SetOrigin(-1.0 + 1.0 / 64, -1.0 + 1.0 / 64, 0.0);
  vtkNew<vtkCVTImageFilter> cvt;
  cvt->SetInputData(image);
  cvt->SetNumberOfSites(30);
  cvt->SetRandomSeed(7);
  cvt->SetMethodToLloyd(); // the baseline is a Lloyd result
  cvt->SetMaximumNumberOfIterations(40);
  cvt->SetTolerance(0.0);
  cvt->Update();
  ASSERT_EQ(cvt->GetSitesOutput()->GetNumberOfPoints(), 30);

  vtkNew<vtkCVTSceneRenderer> scene;
  scene->SetSize(256);
  vtkSmartPointer<vtkImageData> picture =
    scene->Render(cvt->GetLabelsOutput(), cvt->GetSitesOutput());
  ASSERT_NE(picture, nullptr) << scene->GetLastError();
  int dims[3];
  picture->GetDimensions(dims);
  EXPECT_EQ(dims[0], 256);
  EXPECT_EQ(dims[1], 256);

  const std::string baseline = std::string(CVT_DATA_DIR) + "/Baseline/cvt_image_filter.png";
  const char* update = std::getenv("CVT_UPDATE_BASELINES");
  if (update && std::string(update) == "1")
  {
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(picture);
    writer->SetFileName(baseline.c_str());
    writer->Write();
    GTEST_SKIP() << "baseline rewritten: " << baseline;
  }
  ASSERT_TRUE(std::ifstream(baseline).good()) << "missing baseline " << baseline;
  vtkNew<vtkPNGReader> reader;
  reader->SetFileName(baseline.c_str());
  reader->Update();
  vtkNew<vtkImageDifference> difference;
  difference->SetInputData(picture);
  difference->SetImageConnection(reader->GetOutputPort());
  difference->Update();
  // vtkImageDifference's thresholded error: 0 for identical pictures; a few moved boundary
  // pixels (another GPU's rounding) stay far below this.
  std::cout << "[ measured ] thresholded image error: " << difference->GetThresholdedError()
            << "\n";
  EXPECT_LT(difference->GetThresholdedError(), 10.0);
}

// The picture against what it must show, pixel by pixel: each cell pixel the colour of the
// label under it (black for no site), one colour per label, the sites as dark round dots.
TEST(RegressionImage, PictureShowsLabelsAndSites)
{
  vtkNew<vtkImageData> labels; // 4 x 2 labels of 1 x 1, each drawn as 16 x 16 picture pixels
  labels->SetDimensions(4, 2, 1);
  vtkNew<vtkIntArray> ids;
  ids->SetName("SiteId");
  for (int id : { 0, 1, 2, 3, 4, 5, 6, -1 })
  {
    ids->InsertNextValue(id);
  }
  labels->GetPointData()->AddArray(ids);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0.0, 0.0, 0.0); // the centre of label 0: picture pixel (8, 8)
  vtkNew<vtkPolyData> sites;
  sites->SetPoints(points);

  vtkNew<vtkCVTSceneRenderer> scene;
  scene->SetSize(64);
  vtkSmartPointer<vtkImageData> picture = scene->Render(labels, sites);
  ASSERT_NE(picture, nullptr) << scene->GetLastError();
  int dims[3];
  picture->GetDimensions(dims);
  ASSERT_EQ(dims[0], 64);
  ASSERT_EQ(dims[1], 32);
  auto pixel = [&picture](int x, int y)
  {
    const auto* rgb = static_cast<unsigned char*>(picture->GetScalarPointer(x, y, 0));
    return std::array<int, 3>{ rgb[0], rgb[1], rgb[2] };
  };
  EXPECT_EQ(pixel(2, 2), pixel(14, 14));                     // label 0, away from the dot
  EXPECT_NE(pixel(2, 2), pixel(20, 2));                      // label 1
  EXPECT_EQ(pixel(20, 2), pixel(31, 15));                    // label 1 throughout
  EXPECT_NE(pixel(20, 2), pixel(20, 20));                    // label 5 above it
  EXPECT_EQ(pixel(56, 24), (std::array<int, 3>{ 0, 0, 0 })); // no site
  int dark = 0;
  for (int y = 0; y < 16; ++y)
  {
    for (int x = 0; x < 16; ++x)
    {
      const auto c = pixel(x, y);
      dark += c[0] < 64 && c[1] < 64 && c[2] < 64;
    }
  }
  EXPECT_LT(pixel(8, 8)[0], 32);
  EXPECT_GE(dark, 9); // a dot 4 pixels across covers about 12.6 pixels
  EXPECT_LE(dark, 16);

  scene->ShowCellsOff(); // stippling: white, the dot alone
  picture = scene->Render(labels, sites);
  ASSERT_NE(picture, nullptr);
  EXPECT_EQ(pixel(2, 2), (std::array<int, 3>{ 255, 255, 255 }));
  EXPECT_EQ(pixel(56, 24), (std::array<int, 3>{ 255, 255, 255 }));
  EXPECT_LT(pixel(8, 8)[0], 32);
}

// Labels it cannot draw: no picture, and a message saying what is wrong, never a read past the
// labels' array.
TEST(RegressionImage, PictureOfBadLabelsIsRefused)
{
  vtkNew<vtkCVTSceneRenderer> scene;
  vtkNew<vtkImageData> labels;
  labels->SetDimensions(4, 2, 1);
  EXPECT_EQ(scene->Render(labels, nullptr), nullptr);
  EXPECT_NE(scene->GetLastError().find("no SiteId array"), std::string::npos);

  vtkNew<vtkIntArray> ids; // 3 labels for 8 pixels
  ids->SetName("SiteId");
  for (int id : { 0, 1, 2 })
  {
    ids->InsertNextValue(id);
  }
  labels->GetPointData()->AddArray(ids);
  EXPECT_EQ(scene->Render(labels, nullptr), nullptr);
  EXPECT_NE(scene->GetLastError().find("shorter than the image"), std::string::npos);
  EXPECT_EQ(scene->Render(nullptr, nullptr), nullptr);
}

namespace
{
/// What a mesh picture shows: its pixels other than the white background, by colour, and the
/// box round them.
struct DrawnPixels
{
  std::map<std::array<int, 3>, int> Colours; // colour -> pixels
  int Count = 0, XMin = 0, XMax = -1, YMin = 0, YMax = -1;

  explicit DrawnPixels(vtkImageData* picture)
  {
    int dims[3];
    picture->GetDimensions(dims);
    this->XMin = dims[0];
    this->YMin = dims[1];
    const auto* rgb = static_cast<unsigned char*>(picture->GetScalarPointer());
    for (int y = 0; y < dims[1]; ++y)
    {
      for (int x = 0; x < dims[0]; ++x)
      {
        const unsigned char* p = rgb + 3 * (x + y * dims[0]);
        const std::array<int, 3> colour = { p[0], p[1], p[2] };
        if (colour == std::array<int, 3>{ 255, 255, 255 })
        {
          continue;
        }
        ++this->Colours[colour];
        ++this->Count;
        this->XMin = std::min(this->XMin, x);
        this->XMax = std::max(this->XMax, x);
        this->YMin = std::min(this->YMin, y);
        this->YMax = std::max(this->YMax, y);
      }
    }
  }
};
}

// A flat 3 x 2 sheet tilted so that its normal is (1, 1, 1): its bounding box is nearly a cube
// and says nothing of which way it faces (a box-aligned camera saw it nearly edge-on, a sixth
// of the picture). Fitted to the sheet's principal axes, the camera sees it face on, large.
TEST(RegressionImage, MeshPictureFacesATiltedSheet)
{
  const double normal[3] = { 1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0), 1.0 / std::sqrt(3.0) };
  const double along[3] = { 1.0 / std::sqrt(2.0), -1.0 / std::sqrt(2.0), 0.0 };
  double across[3];
  vtkMath::Cross(normal, along, across);
  const int columns = 12, rows = 8;
  vtkNew<vtkPoints> points;
  for (int j = 0; j <= rows; ++j)
  {
    for (int i = 0; i <= columns; ++i)
    {
      const double u = 3.0 * i / columns, v = 2.0 * j / rows;
      points->InsertNextPoint(
        u * along[0] + v * across[0], u * along[1] + v * across[1], u * along[2] + v * across[2]);
    }
  }
  vtkNew<vtkCellArray> triangles;
  for (int j = 0; j < rows; ++j)
  {
    for (int i = 0; i < columns; ++i)
    {
      const vtkIdType corner = i + j * (columns + 1);
      const vtkIdType first[3] = { corner, corner + 1, corner + columns + 2 };
      const vtkIdType second[3] = { corner, corner + columns + 2, corner + columns + 1 };
      triangles->InsertNextCell(3, first);
      triangles->InsertNextCell(3, second);
    }
  }
  vtkNew<vtkPolyData> sheet;
  sheet->SetPoints(points);
  sheet->SetPolys(triangles);

  vtkNew<vtkCVTSceneRenderer> scene;
  scene->SetSize(200);
  vtkSmartPointer<vtkImageData> picture = scene->RenderMesh(sheet);
  ASSERT_NE(picture, nullptr) << scene->GetLastError();
  int dims[3];
  picture->GetDimensions(dims);
  const DrawnPixels drawn(picture);
  // Face on (tilted by the camera's 31 degrees): about 3 x 1.7 of a 2.9-high view, nearly half
  // the picture, the long side across; and framed, clear of the borders.
  EXPECT_GT(drawn.Count, dims[0] * dims[1] / 3);
  EXPECT_GT(drawn.XMax - drawn.XMin, 2 * (drawn.YMax - drawn.YMin) * 3 / 4);
  EXPECT_GT(drawn.XMin, 0);
  EXPECT_LT(drawn.XMax, dims[0] - 1);
  EXPECT_GT(drawn.YMin, 0);
  EXPECT_LT(drawn.YMax, dims[1] - 1);
}

namespace
{
/// An x by y by z box from the origin, two triangles per face: -x, +x, -y (front), +y, -z
/// (bottom), +z (top).
vtkSmartPointer<vtkPolyData> Box(double x, double y, double z)
{
  vtkNew<vtkPoints> points;
  for (int corner = 0; corner < 8; ++corner)
  {
    points->InsertNextPoint(corner & 1 ? x : 0.0, corner & 2 ? y : 0.0, corner & 4 ? z : 0.0);
  }
  const vtkIdType faces[6][4] = { { 0, 4, 6, 2 }, { 1, 3, 7, 5 }, { 0, 1, 5, 4 }, { 2, 6, 7, 3 },
    { 0, 2, 3, 1 }, { 4, 5, 7, 6 } };
  vtkNew<vtkCellArray> triangles;
  for (const auto& face : faces)
  {
    const vtkIdType first[3] = { face[0], face[1], face[2] };
    const vtkIdType second[3] = { face[0], face[2], face[3] };
    triangles->InsertNextCell(3, first);
    triangles->InsertNextCell(3, second);
  }
  auto box = vtkSmartPointer<vtkPolyData>::New();
  box->SetPoints(points);
  box->SetPolys(triangles);
  return box;
}
} // namespace

// A box seen from above and in front, drawn on the CPU: framed whole, edges drawn, and only the
// two faces turned to the camera visible. The box's triangles come bottom (hidden) after front
// (seen), so a picture without depth testing would show the bottom's colours over the front.
TEST(RegressionImage, MeshPictureShowsOnlyTheFacesInFront)
{
  // A 3 x 2 x 1 box: the camera looks along its thinnest axis (z) tilted towards -y, so the
  // top (+z) and front (-y) faces are in view.
  const vtkSmartPointer<vtkPolyData> box = Box(3.0, 2.0, 1.0);

  vtkNew<vtkCVTSceneRenderer> scene;
  scene->SetSize(200);
  vtkSmartPointer<vtkImageData> picture = scene->RenderMesh(box);
  ASSERT_NE(picture, nullptr) << scene->GetLastError();
  int dims[3];
  picture->GetDimensions(dims);
  ASSERT_EQ(dims[0], 200);
  ASSERT_EQ(dims[1], 150);
  const auto* rgb = static_cast<unsigned char*>(picture->GetScalarPointer());
  DrawnPixels drawn(picture);
  // Framed: the whole box, clear of the picture's borders, across most of its width.
  EXPECT_GT(drawn.XMin, 0);
  EXPECT_LT(drawn.XMax, dims[0] - 1);
  EXPECT_GT(drawn.YMin, 0);
  EXPECT_LT(drawn.YMax, dims[1] - 1);
  EXPECT_GT(drawn.XMax - drawn.XMin, dims[0] / 2);
  // Edges drawn dark.
  const std::array<int, 3> edge = { 25, 25, 25 };
  EXPECT_GT(drawn.Colours[edge], 100);
  // Four triangles in view (top and front), each in its own colour; nothing of the others.
  int large = 0;
  for (const auto& [colour, count] : drawn.Colours)
  {
    large += colour != edge && count >= 30;
  }
  EXPECT_EQ(large, 4);

  // The same mesh gives the same picture; a mesh without polygons gives none and says why.
  vtkSmartPointer<vtkImageData> again = scene->RenderMesh(box);
  ASSERT_NE(again, nullptr);
  EXPECT_TRUE(std::equal(
    rgb, rgb + 3 * dims[0] * dims[1], static_cast<unsigned char*>(again->GetScalarPointer())));
  vtkNew<vtkPolyData> pointsOnly;
  pointsOnly->SetPoints(box->GetPoints());
  EXPECT_EQ(scene->RenderMesh(pointsOnly), nullptr);
  EXPECT_NE(scene->GetLastError().find("no triangles"), std::string::npos);
}

// A cube: its corners reach as far from its middle along every axis, so a camera fitted to its
// bounding sphere and zoomed for long shapes cut its top off; it is framed whole, across most
// of the picture's height.
TEST(RegressionImage, MeshPictureFramesACubeWhole)
{
  vtkNew<vtkCVTSceneRenderer> scene;
  scene->SetSize(200);
  vtkSmartPointer<vtkImageData> picture = scene->RenderMesh(Box(1.0, 1.0, 1.0));
  ASSERT_NE(picture, nullptr) << scene->GetLastError();
  int dims[3];
  picture->GetDimensions(dims);
  const DrawnPixels drawn(picture);
  EXPECT_GT(drawn.XMin, 0);
  EXPECT_LT(drawn.XMax, dims[0] - 1);
  EXPECT_GT(drawn.YMin, 0);
  EXPECT_LT(drawn.YMax, dims[1] - 1);
  EXPECT_GT(drawn.YMax - drawn.YMin, dims[1] * 3 / 4);
}
