// The filters' OpenGL engines: kept across updates (no new storage for a new seed, only slot
// textures for a new site count), and nothing left behind on a handed-in render window.
#include "cvtFilterTestSupport.h"
#include "cvtRenderingTestSupport.h"
#include "vtkCVTGeometryImageSource.h"
#include "vtkCVTImageFilter.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkCVTSurfaceFilter.h"

#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkRenderWindow.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

using cvttest::LiveGLObjects;

using cvttest::TorusImage;

namespace
{
/// A uniform 96 x 96 image for the image filter.
vtkSmartPointer<vtkImageData> FlatImage()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(96, 96, 1);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfTuples(96 * 96);
  density->Fill(1.0);
  image->GetPointData()->AddArray(density);
  return image;
}
}

// Filters keep their OpenGL engine across updates: a second update with a new seed gives no
// texture new storage (a new engine would make all of them again), a new site count only the
// slot textures; both filters on the OpenGL engine.
TEST(GLObjects, FiltersKeepTheirEngineAcrossUpdates)
{
  vtkNew<vtkCVTImageFilter> flat;
  flat->SetInputData(FlatImage());
  flat->SetEngineToOpenGL();
  flat->SetNumberOfSites(50);
  flat->SetMaximumNumberOfIterations(3);
  vtkNew<vtkCVTSurfaceFilter> surface;
  surface->SetInputData(TorusImage(128, 64));
  surface->SetEngine(vtkCVTSurfaceFilter::OPENGL);
  surface->SetNumberOfSites(50);
  surface->SetMaximumNumberOfIterations(3);
  flat->Update();
  surface->Update();
  ASSERT_EQ(flat->GetSitesOutput()->GetNumberOfPoints(), 50);
  ASSERT_EQ(surface->GetSitesOutput()->GetNumberOfPoints(), 50);
  const long long first = vtkCVTOpenGLContext::GetNumberOfTextureAllocations();
  flat->SetRandomSeed(7);
  surface->SetRandomSeed(7);
  flat->Update();
  surface->Update();
  EXPECT_EQ(vtkCVTOpenGLContext::GetNumberOfTextureAllocations(), first)
    << "an update with a new seed made textures again";
  flat->SetNumberOfSites(300);
  flat->Update();
  const long long added = vtkCVTOpenGLContext::GetNumberOfTextureAllocations() - first;
  EXPECT_GT(added, 0);
  EXPECT_LE(added, 4) << "a new site count should only resize the four slot textures";
  EXPECT_EQ(flat->GetSitesOutput()->GetNumberOfPoints(), 300);
}

// Engines and filters made and destroyed in a loop on one handed-in render window: after the
// first round (which fills the window's shader cache), its live GL objects return to the same
// count after every round, and the filters' results match those on a context of their own.
TEST(GLObjects, FiltersOnAHandedInWindowLeaveNothingBehind)
{
  vtkNew<vtkCVTOpenGLContext> holder;
  ASSERT_TRUE(holder->Initialize()) << holder->GetLastError();
  vtkRenderWindow* window = holder->GetRenderWindow();
  vtkSmartPointer<vtkImageData> image = FlatImage();
  vtkSmartPointer<vtkImageData> torus = TorusImage(128, 64);
  const auto run = [&](vtkRenderWindow* context, double energies[2])
  {
    vtkNew<vtkCVTImageFilter> flat;
    flat->SetInputData(image);
    flat->SetEngineToOpenGL();
    flat->SetNumberOfSites(40);
    flat->SetMaximumNumberOfIterations(4);
    flat->SetRenderWindow(context);
    flat->Update();
    vtkNew<vtkCVTSurfaceFilter> surface;
    surface->SetInputData(torus);
    surface->SetEngine(vtkCVTSurfaceFilter::OPENGL);
    surface->SetNumberOfSites(40);
    surface->SetMaximumNumberOfIterations(4);
    surface->SetRenderWindow(context);
    surface->Update();
    energies[0] = flat->GetSitesOutput()->GetFieldData()->GetArray("Energy")->GetTuple1(0);
    energies[1] = surface->GetSitesOutput()->GetFieldData()->GetArray("Energy")->GetTuple1(0);
    if (context)
    {
      EXPECT_EQ(flat->GetContextDescription().rfind("handed-in", 0), 0u)
        << flat->GetContextDescription();
      EXPECT_EQ(surface->GetContextDescription().rfind("handed-in", 0), 0u);
    }
  };
  double own[2], handedIn[2];
  run(nullptr, own);
  run(window, handedIn);
  EXPECT_NEAR(handedIn[0], own[0], 1e-6 * own[0]);
  EXPECT_NEAR(handedIn[1], own[1], 1e-6 * own[1]);
  const int start = LiveGLObjects(holder);
  for (int round = 0; round < 5; ++round)
  {
    run(window, handedIn);
    {
      vtkNew<vtkCVTOpenGLEngine> engine;
      engine->SetRenderWindow(window);
      cvt::Grid grid;
      grid.Width = grid.Height = 32;
      ASSERT_TRUE(engine->SetDomain(grid, std::vector<float>(32 * 32, 1.0f)));
      EXPECT_GT(LiveGLObjects(holder), start);
    }
    EXPECT_EQ(LiveGLObjects(holder), start) << "round " << round;
  }
  std::cout << "[ measured ] live GL objects of the handed-in window: " << start << " before, "
            << LiveGLObjects(holder) << " after 5 rounds of two filters and an engine\n";
}
// A filter that has run moves to a handed-in window and back with the same site count (its
// engine releases everything on a change of context, so the site slots must be made again): same
// results on the three contexts, for Lloyd (site slots updated on the GPU) and L-BFGS (uploaded).
TEST(GLObjects, FiltersMoveBetweenContextsAfterRunning)
{
  vtkNew<vtkCVTOpenGLContext> holder;
  ASSERT_TRUE(holder->Initialize()) << holder->GetLastError();
  for (const int method : { vtkCVTImageFilter::LLOYD, vtkCVTImageFilter::LBFGS })
  {
    vtkNew<vtkCVTImageFilter> flat;
    flat->SetInputData(FlatImage());
    flat->SetEngineToOpenGL();
    flat->SetMethod(method);
    flat->SetNumberOfSites(40);
    flat->SetMaximumNumberOfIterations(4);
    vtkNew<vtkCVTSurfaceFilter> surface;
    surface->SetInputData(TorusImage(128, 64));
    surface->SetEngine(vtkCVTSurfaceFilter::OPENGL);
    surface->SetMethod(method);
    surface->SetNumberOfSites(40);
    surface->SetMaximumNumberOfIterations(4);
    double energies[3][2];
    for (int run = 0; run < 3; ++run)
    {
      vtkRenderWindow* context = run == 1 ? holder->GetRenderWindow() : nullptr;
      flat->SetRenderWindow(context);
      surface->SetRenderWindow(context);
      flat->Update();
      surface->Update();
      ASSERT_EQ(flat->GetSitesOutput()->GetNumberOfPoints(), 40) << "method " << method;
      ASSERT_EQ(surface->GetSitesOutput()->GetNumberOfPoints(), 40) << "method " << method;
      energies[run][0] = flat->GetSitesOutput()->GetFieldData()->GetArray("Energy")->GetTuple1(0);
      energies[run][1] =
        surface->GetSitesOutput()->GetFieldData()->GetArray("Energy")->GetTuple1(0);
    }
    for (int run = 1; run < 3; ++run)
    {
      EXPECT_NEAR(energies[run][0], energies[0][0], 1e-6 * energies[0][0]) << "run " << run;
      EXPECT_NEAR(energies[run][1], energies[0][1], 1e-6 * energies[0][1]) << "run " << run;
    }
  }
}

// The context description belongs to the last run: set by a run on the OpenGL engine, empty
// after a run on the CPU engine by the same filter.
TEST(GLObjects, ContextDescriptionIsTheLastRuns)
{
  vtkNew<vtkCVTImageFilter> flat;
  flat->SetInputData(FlatImage());
  flat->SetNumberOfSites(20);
  flat->SetMaximumNumberOfIterations(2);
  vtkNew<vtkCVTSurfaceFilter> surface;
  surface->SetInputData(TorusImage(64, 32));
  surface->SetNumberOfSites(20);
  surface->SetMaximumNumberOfIterations(2);
  for (vtkCVTGPUAlgorithm* filter : { static_cast<vtkCVTGPUAlgorithm*>(flat.Get()),
         static_cast<vtkCVTGPUAlgorithm*>(surface.Get()) })
  {
    filter->SetEngineToOpenGL();
    filter->Update();
    EXPECT_FALSE(filter->GetContextDescription().empty()) << filter->GetClassName();
    filter->SetEngineToCPU();
    filter->Update();
    ASSERT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 20);
    EXPECT_EQ(filter->GetContextDescription(), "") << filter->GetClassName();
  }
}
