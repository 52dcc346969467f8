// Benchmark of the GPU CVT engine.
//   timing:   milliseconds per Lloyd iteration (labelling = seed + 1+JFA, reduction =
//             reduction + readback, Lloyd update) for 1000 sites at 512x512 and 10,000 sites
//             at 2048x2048, medians over the iterations, adaptive and full JFA step.
//   accuracy: 1000 uniformly random sites on [-1,1]^2 at 512x512, 216 GPU Lloyd iterations;
//             exact continuous energy of the result against exact (polygon-integrated) CPU
//             Lloyd from the same sites, run in the same process.
#include "cvtExactVoronoi.h"
#include "cvtLloyd.h"
#include "cvtSampling.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkNew.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

namespace
{
using Clock = std::chrono::steady_clock;

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::sort(values.begin(), values.end());
  return values[values.size() / 2];
}

bool Timing(int resolution, int sites, int iterations, bool adaptive)
{
  const cvt::Grid grid = cvt::Grid::Square(resolution, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  vtkNew<vtkCVTOpenGLEngine> engine;
  engine->SetMeasureTimings(true);
  engine->SetAdaptiveStep(adaptive);
  if (!engine->SetDomain(grid, density) || !engine->SetSites(cvt::SampleSites(grid, {}, sites, 1)))
  {
    std::fprintf(stderr, "engine failed: %s\n", engine->GetLastError().c_str());
    return false;
  }
  std::vector<double> label, reduce, update, total;
  cvt::CellSums sums;
  for (int k = 0; k < iterations; ++k)
  {
    const auto start = Clock::now();
    if (!engine->ComputeCellSums(sums))
    {
      std::fprintf(stderr, "engine failed: %s\n", engine->GetLastError().c_str());
      return false;
    }
    const auto updateStart = Clock::now();
    engine->MoveSitesToCentroids();
    const auto end = Clock::now();
    label.push_back(engine->GetLastLabelMilliseconds());
    reduce.push_back(engine->GetLastReductionMilliseconds());
    update.push_back(std::chrono::duration<double, std::milli>(end - updateStart).count());
    total.push_back(std::chrono::duration<double, std::milli>(end - start).count());
  }
  std::printf("%5d sites %4dx%-4d %-8s  label %8.2f ms  reduce %8.2f ms  update %6.2f ms  "
              "iteration %8.2f ms  (medians of %d; last initial step %d)\n",
    sites, resolution, resolution, adaptive ? "adaptive" : "full", Median(label), Median(reduce),
    Median(update), Median(total), iterations, engine->GetLastInitialStep());
  return true;
}

bool Accuracy()
{
  const int iterations = 216;
  const cvt::Grid grid = cvt::Grid::Square(512, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  const std::vector<double> initial = cvt::SampleSites(grid, {}, 1000, 2011);

  vtkNew<vtkCVTOpenGLEngine> engine;
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = iterations;
  options.Tolerance = 0.0;
  cvt::OptimizerResult gpu;
  std::string error;
  auto start = Clock::now();
  if (!engine->SetDomain(grid, density) || !engine->SetSites(initial) ||
    !cvt::RunLloyd(*engine, options, nullptr, gpu, error))
  {
    std::fprintf(stderr, "engine failed: %s %s\n", engine->GetLastError().c_str(), error.c_str());
    return false;
  }
  const double gpuSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double gpuExactEnergy = cvt::ExactCellSums(grid, gpu.Sites, {}).TotalEnergy();

  // Exact Lloyd on the CPU: polygon-integrated centroids of the clipped Voronoi cells.
  start = Clock::now();
  std::vector<double> sites = initial;
  for (int k = 0; k < iterations; ++k)
  {
    const cvt::CellSums sums = cvt::ExactCellSums(grid, sites, {});
    for (size_t i = 0; i < sums.Size(); ++i)
    {
      if (sums.Mass[i] > 0.0)
      {
        sites[2 * i] += sums.MomentX[i] / sums.Mass[i];
        sites[2 * i + 1] += sums.MomentY[i] / sums.Mass[i];
      }
    }
  }
  const double cpuSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  const double cpuEnergy = cvt::ExactCellSums(grid, sites, {}).TotalEnergy();
  std::printf("accuracy: 1000 sites, 512x512, %d Lloyd iterations on %s\n", iterations,
    engine->GetContextDescription().c_str());
  std::printf("  GPU Lloyd: energy reported %.6e, exact energy of its sites %.6e (%.1f s)\n",
    gpu.Sums.TotalEnergy(), gpuExactEnergy, gpuSeconds);
  std::printf("  exact CPU Lloyd: energy %.6e (%.1f s)\n", cpuEnergy, cpuSeconds);
  std::printf("  relative difference: %+.3f%% (target: within 0.35%%)\n",
    100.0 * (gpuExactEnergy - cpuEnergy) / cpuEnergy);
  return true;
}
}

int main(int argc, char* argv[])
{
  const std::string what = argc > 1 ? argv[1] : "all";
  if (what != "timing" && what != "accuracy" && what != "all")
  {
    std::fprintf(stderr, "usage: %s [timing|accuracy|all]\n", argv[0]);
    return 2;
  }
  bool ok = true;
  if (what == "timing" || what == "all")
  {
    ok = ok && Timing(512, 1000, 30, true) && Timing(512, 1000, 10, false);
    ok = ok && Timing(2048, 10000, 8, true) && Timing(2048, 10000, 4, false);
  }
  if (what == "accuracy" || what == "all")
  {
    ok = ok && Accuracy();
  }
  return ok ? 0 : 1;
}
