#include "vtkCVTEngineChoice.h"

#include "cvtExactEngine.h"
#include "cvtSampling.h"
#include "vtkCVTOpenGLContext.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkNew.h"
#include "vtkOpenGLRenderWindow.h"

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cstdio>
#include <mutex>
#include <vector>

namespace cvtvtk
{

namespace
{
/// Median milliseconds of a Lloyd iteration (cell sums and the move to the centroids) of
/// `engine` on a small uniform job, after a warm-up; negative on failure.
double MillisecondsPerIteration(cvt::Engine& engine)
{
  const cvt::Grid grid = cvt::Grid::Square(512, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  cvt::CellSums sums;
  if (!engine.SetDomain(grid, density) || !engine.SetSites(cvt::SampleSites(grid, {}, 1000, 7)))
  {
    return -1.0;
  }
  std::vector<double> times;
  for (int k = 0; k < 4; ++k)
  {
    const auto start = std::chrono::steady_clock::now();
    if (!engine.ComputeCellSums(sums) || !engine.MoveSitesToCentroids())
    {
      return -1.0;
    }
    times.push_back(
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count());
  }
  std::sort(times.begin() + 1, times.end()); // the first is a warm-up (shaders, threads)
  return times[2];
}

/// What Auto learns from one probe of the OpenGL context (the GPU does not change while a
/// process runs).
EngineChoice ProbeOpenGL()
{
  EngineChoice choice;
  vtkNew<vtkCVTOpenGLContext> context;
  if (!context->Initialize())
  {
    choice.Name = "CPU";
    choice.Reason = "Auto: no OpenGL context (" + context->GetLastError() + ")";
    return choice;
  }
  if (context->IsSoftwareRenderer())
  {
    choice.Name = "CPU";
    choice.Reason =
      "Auto: the only OpenGL is a software renderer (" + context->GetDescription() + ")";
    return choice;
  }
  return CompareEngines(context->GetRenderWindow(), context->GetDescription());
}
}

EngineChoice CompareEngines(vtkRenderWindow* window, const std::string& contextDescription)
{
  EngineChoice choice;
  choice.HardwareOpenGL = true;
  // A hardware GPU is not always the faster engine: on an H100 (a data-centre GPU with few
  // graphics-capable multiprocessors) the OpenGL engine took 13.7 ms per Lloyd iteration where
  // the CPU engine on 16 cores took 0.9 ms.
  double openGL = -1.0;
  {
    vtkNew<vtkCVTOpenGLEngine> gpu; // released before the CPU run
    gpu->SetRenderWindow(window);
    openGL = MillisecondsPerIteration(*gpu);
  }
  cvt::ExactEngine exact;
  const double cpu = MillisecondsPerIteration(exact);
  char times[160];
  std::snprintf(times, sizeof(times),
    "a calibration Lloyd iteration (1000 sites, 512x512) took %.3g ms on OpenGL and %.3g ms on "
    "the CPU",
    openGL, cpu);
  choice.OpenGLMilliseconds = openGL;
  choice.CPUMilliseconds = cpu;
  choice.UseOpenGL = openGL > 0.0 && (cpu <= 0.0 || openGL < cpu);
  choice.Name = choice.UseOpenGL ? "OpenGL" : "CPU";
  choice.Reason = "Auto: hardware OpenGL (" + contextDescription + "), " +
    (openGL > 0.0 ? times : "but the OpenGL engine failed on a calibration job") +
    (choice.UseOpenGL ? "" : "; the CPU engine is faster here");
  return choice;
}

EngineChoice ChooseEngine(int requested)
{
  if (requested == ENGINE_OPENGL)
  {
    return { true, false, "OpenGL", "asked for OpenGL" };
  }
  if (requested == ENGINE_CPU)
  {
    return { false, false, "CPU", "asked for the CPU" };
  }
  static std::once_flag probed;
  static EngineChoice automatic;
  std::call_once(probed, []() { automatic = ProbeOpenGL(); });
  return automatic;
}

const char* EngineKindName(int kind)
{
  return kind == ENGINE_OPENGL ? "OpenGL" : (kind == ENGINE_CPU ? "CPU" : "Auto");
}

} // namespace cvtvtk
