// Soak: each filter updated 300 times in one process with a property changed each time, as a
// ParaView user does. Resident memory must stop growing after a warm-up: a leak of a few
// kilobytes per update (an engine, a context, a texture or framebuffer in llvmpipe's system
// memory, an output array) adds up to megabytes over the 250 updates measured. Also two
// filters with their own engines alternately, and one filter updated from two threads in turn.
#include "cvtMemory.h"
#include "vtkCVTGeometryImageSource.h"
#include "vtkCVTImageFilter.h"
#include "vtkCVTRemeshFilter.h"
#include "vtkCVTSurfaceFilter.h"

#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkParametricTorus.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"

#include <gtest/gtest.h>

#include <fstream>
#include <functional>
#include <thread>

namespace
{
/// Resident memory of this process in MiB.
double ResidentMiB()
{
  return cvt::ResidentMemory() / (1024.0 * 1024.0);
}

#if defined(__SANITIZE_ADDRESS__)
// AddressSanitizer keeps freed memory in quarantine, so resident memory grows regardless; its
// LeakSanitizer checks for leaks at exit instead (tools/sanitize.sh).
constexpr bool MeasureMemory = false;
#else
constexpr bool MeasureMemory = true;
#endif

/// Runs `update(i)` 300 times; the growth of resident memory from update 50 to 300 must stay
/// under `boundMiB`. Returns the growth.
double Soak(const std::function<void(int)>& update, double boundMiB)
{
  double warm = 0.0;
  for (int i = 0; i < 300; ++i)
  {
    update(i);
    if (i == 49)
    {
      warm = ResidentMiB();
    }
  }
  const double growth = ResidentMiB() - warm;
  if (!MeasureMemory)
  {
    return growth;
  }
  EXPECT_LT(growth, boundMiB) << "resident memory grew by " << growth << " MiB over 250 updates";
  std::cout << "resident memory after warm-up: " << warm
            << " MiB, growth over 250 updates: " << growth << " MiB\n";
  return growth;
}

vtkSmartPointer<vtkImageData> Square(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, 1);
  return image;
}
}

// A bound of 4 MiB over 250 updates: 16 KiB per update, far below one leaked engine (textures
// and framebuffers of a 64 x 64 grid alone are ~100 KiB) and above allocator noise.
constexpr double BoundMiB = 4.0;

TEST(Soak, ImageFilterOnBothEngines)
{
  for (int engine : { vtkCVTImageFilter::CPU, vtkCVTImageFilter::OPENGL })
  {
    vtkNew<vtkCVTImageFilter> filter;
    filter->SetInputData(Square(64));
    filter->SetEngine(engine);
    filter->SetMaximumNumberOfIterations(3);
    Soak(
      [&](int i)
      {
        filter->SetNumberOfSites(20 + i % 7); // a property changes every time
        filter->Update();
        ASSERT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 20 + i % 7);
      },
      BoundMiB);
  }
}

TEST(Soak, RemeshFilter)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(24);
  sphere->SetPhiResolution(24);
  vtkNew<vtkCVTRemeshFilter> filter;
  filter->SetInputConnection(sphere->GetOutputPort());
  filter->SetMaximumNumberOfIterations(3);
  Soak(
    [&](int i)
    {
      filter->SetRandomSeed(1 + i);
      filter->Update();
      ASSERT_GT(filter->GetRemeshOutput()->GetNumberOfPolys(), 0);
    },
    BoundMiB);
}

TEST(Soak, SurfaceFilterOnTheGPUEngine)
{
  vtkNew<vtkParametricTorus> torus;
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetParametricFunction(torus);
  source->SetResolution(64, 32);
  vtkNew<vtkCVTSurfaceFilter> filter;
  filter->SetInputConnection(source->GetOutputPort());
  filter->SetEngine(vtkCVTSurfaceFilter::OPENGL);
  filter->SetMaximumNumberOfIterations(3);
  Soak(
    [&](int i)
    {
      filter->SetNumberOfSites(40 + i % 5);
      filter->Update();
      ASSERT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 40 + i % 5);
    },
    BoundMiB);
}

TEST(Soak, TwoFiltersAlternatelyAndOneFromTwoThreads)
{
  vtkNew<vtkCVTImageFilter> first, second;
  for (vtkCVTImageFilter* filter : { first.Get(), second.Get() })
  {
    filter->SetInputData(Square(48));
    filter->SetEngineToOpenGL();
    filter->SetMaximumNumberOfIterations(3);
  }
  Soak(
    [&](int i)
    {
      vtkCVTImageFilter* filter = i % 2 ? first.Get() : second.Get();
      filter->SetNumberOfSites(10 + i % 3);
      filter->Update();
      ASSERT_EQ(filter->GetSitesOutput()->GetNumberOfPoints(), 10 + i % 3);
    },
    BoundMiB);
  // The same filter from another thread, then this one again: each update makes its context
  // current on the calling thread.
  for (int round = 0; round < 3; ++round)
  {
    int sites = 0;
    std::thread other(
      [&]
      {
        first->SetNumberOfSites(15 + round);
        first->Update();
        sites = static_cast<int>(first->GetSitesOutput()->GetNumberOfPoints());
      });
    other.join();
    EXPECT_EQ(sites, 15 + round);
    first->SetNumberOfSites(5 + round);
    first->Update();
    EXPECT_EQ(first->GetSitesOutput()->GetNumberOfPoints(), 5 + round);
  }
}
