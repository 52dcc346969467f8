// Offscreen regression image: a small CVT rendered headless against a baseline in Data/.
// Set CVT_UPDATE_BASELINES=1 to rewrite the baseline after an intended change.
#include "vtkCVTImageFilter.h"
#include "vtkCVTSceneRenderer.h"

#include "vtkImageData.h"
#include "vtkImageDifference.h"
#include "vtkNew.h"
#include "vtkPNGReader.h"
#include "vtkPNGWriter.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
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
