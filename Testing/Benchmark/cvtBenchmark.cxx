// Benchmark of the GPU CVT engine and the optimisers, with the exact CPU engine as the baseline
// run in the same process.
//   timing:  milliseconds per Lloyd iteration (labelling = seed + 1+JFA; reduction = split,
//            collect, scatter, readback; Lloyd update) and per L-BFGS evaluation, for 1000
//            sites at 512x512 and 10,000 sites at 2048x2048; medians.
//   targets: 1000 uniformly random sites on [-1,1]^2 at 512x512:
//            216 GPU Lloyd iterations against exact CPU Lloyd from the same sites;
//            GPU L-BFGS against exact CPU L-BFGS, and L-BFGS evaluations to Lloyd's energy;
//            the density exp(-20x^2-20y^2) + 0.05 sin^2(pi x) sin^2(pi y) with L-BFGS
//            against the paper's CPU energy 6.116e-5.
//   surface: the torus (R = 1, r = 0.4, 1000 sites): milliseconds per Lloyd iteration and per
//            L-BFGS evaluation at 512x256 and 1024x512 (adaptive JFA step, then the full
//            step as the baseline), and the L-BFGS target run: energy of
//            the final sites evaluated on a dense 2048x1024 geometry image, remesh valence and
//            angles.
//   cpu:     the exact CPU engine (multi-threaded) on the Table 1 job (Lloyd, 216 iterations,
//            uniform and the paper's density) and the Table 2 job (L-BFGS with the density to
//            convergence), against the OpenGL engine's time per iteration in the same process;
//            10,000 sites at 2048x2048. Then the cost of one parallel loop (1000 light items in
//            chunks of 256, microseconds, median of 5 runs of 500 loops): the engines' loops
//            (cvt::For: oneTBB's threads, kept between loops) against vtkSMPTools::For.
//   scaling: milliseconds per Lloyd iteration (median) and resident memory of both engines
//            against pixels (512^2 .. MAX_SIDE^2, 1000 sites) and against sites (1000 ..
//            MAX_SITES at MAX_SIDE^2), uniform random sites and density; one CSV line each
//            ("scaling,engine,side,sites,ms_per_iteration,resident_mib,iterations"), drawn by
//            Examples/plot_scaling.py. A software OpenGL that needs more than 5 s for one
//            iteration is measured once and left out of the larger sizes.
//   dual:    the exact CPU surface engine's restricted Delaunay dual (cvt::RestrictedVoronoi::
//            ComputeDual, which the remesh's topology and fidelity rounds call once per candidate)
//            against its cell sums (ComputeCellSums, an optimiser evaluation) in the same process,
//            milliseconds, medians of 21: on an OFF mesh (repaired as the remesh filter does) or
//            a 200 x 100 torus grid (40,000 triangles), SITES sites (1000) after 5 Lloyd steps.
//   shape:   the remesh's shaping against the input (cvt::BuildRemesh with a cvt::RemeshInput,
//            which the remesh filter runs once per candidate remesh) and its measure
//            (cvt::MeasureFidelity, alone and against the same remesh measured before, as the
//            fidelity rounds measure a candidate), milliseconds, medians of 11: on the dual of
//            SITES sites (1000) after 30 Lloyd steps on an OFF mesh or the torus grid.
//   lifetime: the filters on the OpenGL engine (image filter at 512x512, surface filter at
//            1024x512, 1000 sites, 2 Lloyd iterations; medians of 3): the first update, and a
//            second update after changing NumberOfSites (1000 -> 1100) by the same filter (it keeps
//            its engine, context and shaders) and by a new filter (a new engine, as every update
//            made before).
// Usage: cvtBenchmark [timing|targets|surface|cpu|lifetime|all]
//        cvtBenchmark scaling [MAX_SIDE (4096)] [MAX_SITES (100000)]
//        cvtBenchmark dual|shape [MESH.off|torus] [SITES (1000)]
#include "cvtExactEngine.h"
#include "cvtExactVoronoi.h"
#include "cvtMemory.h"
#include "cvtOptimizer.h"
#include "cvtProblems.h"
#include "cvtQuality.h"
#include "cvtRemesh.h"
#include "cvtRestrictedVoronoi.h"
#include "cvtSampling.h"
#include "cvtSurfaceMesh.h"
#include "cvtThreads.h"
#include "vtkCVTGeometryImageSource.h"
#include "vtkCVTImageFilter.h"
#include "vtkCVTOFFReader.h"
#include "vtkCVTOpenGLEngine.h"
#include "vtkCVTSurfaceEngine.h"
#include "vtkCVTSurfaceFilter.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkVariant.h"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
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

double SecondsSince(Clock::time_point start)
{
  return std::chrono::duration<double>(Clock::now() - start).count();
}

bool Timing(int resolution, int sites, int iterations, bool adaptive)
{
  const cvt::Grid grid = cvt::Grid::Square(resolution, -1.0, 1.0);
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  vtkNew<vtkCVTOpenGLEngine> engine;
  engine->SetMeasureTimings(true);
  engine->SetAdaptiveStep(adaptive);
  const std::vector<double> initial = cvt::SampleSites(grid, {}, sites, 1);
  if (!engine->SetDomain(grid, density) || !engine->SetSites(initial))
  {
    std::fprintf(stderr, "engine failed: %s\n", engine->GetLastError().c_str());
    return false;
  }
  std::vector<double> label, reduce, update, total, evaluation;
  cvt::CellSums sums;
  std::vector<double> current;
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
    label.push_back(engine->GetLastLabelMilliseconds());
    reduce.push_back(engine->GetLastReductionMilliseconds());
    update.push_back(1e3 * SecondsSince(updateStart));
    total.push_back(1e3 * SecondsSince(start));
  }
  // An L-BFGS evaluation: upload the sites, label, reduce, read the sums back.
  engine->GetSites(current);
  for (int k = 0; k < std::max(3, iterations / 3); ++k)
  {
    const auto start = Clock::now();
    engine->SetSites(current);
    engine->ComputeCellSums(sums);
    evaluation.push_back(1e3 * SecondsSince(start));
  }
  std::printf("%5d sites %4dx%-4d %-8s label %7.1f  reduce %7.1f  update %5.2f  "
              "Lloyd iteration %7.1f  L-BFGS evaluation %7.1f ms  (step %d)\n",
    sites, resolution, resolution, adaptive ? "adaptive" : "full", Median(label), Median(reduce),
    Median(update), Median(total), Median(evaluation), engine->GetLastInitialStep());
  return true;
}

struct Run
{
  cvt::OptimizerResult Result;
  double Seconds = 0.0;
};

bool Optimize(cvt::Engine& engine, const cvt::Grid& grid, const std::vector<float>& density,
  const std::vector<double>& sites, bool lbfgs, int iterations, Run& run)
{
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = iterations;
  std::string error;
  const auto start = Clock::now();
  cvt::PlaneProblem problem(engine, grid);
  const cvt::SiteState initial{ sites, {} };
  const bool ok = engine.SetDomain(grid, density) &&
    (lbfgs ? cvt::RunLBFGS(problem, initial, options, nullptr, run.Result, error)
           : cvt::RunLloyd(problem, initial, options, nullptr, run.Result, error));
  run.Seconds = SecondsSince(start);
  if (!ok)
  {
    std::fprintf(stderr, "optimiser failed: %s %s\n", engine.GetLastError().c_str(), error.c_str());
  }
  return ok;
}

/// The density of Rong et al.'s Table 2: exp(-20x^2-20y^2) + 0.05 sin^2(pi x) sin^2(pi y).
std::vector<float> PaperDensity(const cvt::Grid& grid)
{
  std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()));
  const double pi = 3.14159265358979323846;
  for (int j = 0; j < grid.Height; ++j)
  {
    const double y = grid.Origin[1] + (j + 0.5) * grid.Spacing[1];
    for (int i = 0; i < grid.Width; ++i)
    {
      const double x = grid.Origin[0] + (i + 0.5) * grid.Spacing[0];
      density[static_cast<size_t>(j) * grid.Width + i] =
        static_cast<float>(std::exp(-20.0 * x * x - 20.0 * y * y) +
          0.05 * std::pow(std::sin(pi * x), 2) * std::pow(std::sin(pi * y), 2));
    }
  }
  return density;
}

/// Microseconds per loop of `run(sum)` (500 loops; median of 5).
template<class Loop>
double MicrosecondsPerLoop(const Loop& run)
{
  std::vector<double> seconds;
  std::atomic<long long> sum{ 0 };
  for (int repeat = 0; repeat < 5; ++repeat)
  {
    const Clock::time_point start = Clock::now();
    for (int loop = 0; loop < 500; ++loop)
    {
      run(sum);
    }
    seconds.push_back(SecondsSince(start));
  }
  return 1e6 * Median(seconds) / 500.0;
}

/// What one parallel loop costs beside its work: the CPU engines run three per evaluation.
void LoopOverhead()
{
  const auto body = [](std::atomic<long long>& sum)
  { return [&sum](vtkIdType begin, vtkIdType end) { sum += end - begin; }; };
  const double engines =
    MicrosecondsPerLoop([&](std::atomic<long long>& sum) { cvt::For(0, 1000, 256, body(sum)); });
  const double smp = MicrosecondsPerLoop(
    [&](std::atomic<long long>& sum) { vtkSMPTools::For(0, 1000, 256, body(sum)); });
  std::printf("Parallel loop of 1000 light items in chunks of 256, %d threads: %.2f us "
              "(cvt::For) against %.2f us (vtkSMPTools::For, %s backend): %.0f times less\n",
    vtkSMPTools::GetEstimatedNumberOfThreads(), engines, smp, vtkSMPTools::GetBackend(),
    smp / engines);
}

/// The CPU engine (exact polygons, vtkSMPTools threads) on the paper's jobs, with the OpenGL
/// engine's milliseconds per Lloyd iteration from the same process as the baseline.
bool CPUEngine()
{
  const cvt::Grid grid = cvt::Grid::Square(512, -1.0, 1.0);
  const std::vector<float> uniform(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  const std::vector<float> paper = PaperDensity(grid);
  const std::vector<double> initial = cvt::SampleSites(grid, {}, 1000, 2011);
  cvt::ExactEngine cpu;
  vtkNew<vtkCVTOpenGLEngine> gpu;
  Run cpuUniform, cpuDensity, gpuUniform, cpuLBFGS;
  if (!Optimize(cpu, grid, uniform, initial, false, 216, cpuUniform) ||
    !Optimize(cpu, grid, paper, initial, false, 216, cpuDensity) ||
    !Optimize(*gpu, grid, uniform, initial, false, 10, gpuUniform) ||
    !Optimize(cpu, grid, paper, cvt::SampleSites(grid, paper, 1000, 2011), true, 1000, cpuLBFGS))
  {
    return false;
  }
  const double gpuPerIteration = 1e3 * gpuUniform.Seconds / 10.0;
  std::printf("CPU engine, 1000 sites, 512x512, Lloyd 216 iterations (Table 1 job):\n");
  std::printf("  uniform density: %.3f s (%.2f ms per iteration; target <= 0.55 s)\n",
    cpuUniform.Seconds, 1e3 * cpuUniform.Seconds / 216.0);
  std::printf("  paper's density: %.3f s (%.2f ms per iteration; target <= 1.1 s)\n",
    cpuDensity.Seconds, 1e3 * cpuDensity.Seconds / 216.0);
  std::printf("  OpenGL engine on this machine (%s): %.1f ms per iteration, %.0f times the CPU's\n",
    gpu->GetContextDescription().c_str(), gpuPerIteration,
    gpuPerIteration / (1e3 * cpuUniform.Seconds / 216.0));
  std::printf("CPU engine, L-BFGS to convergence with the paper's density (Table 2 job): %.3f s, "
              "%d iterations, energy %.6e (target <= 2.3 s)\n",
    cpuLBFGS.Seconds, cpuLBFGS.Result.Iterations, cpuLBFGS.Result.Sums.TotalEnergy());
  const cvt::Grid large = cvt::Grid::Square(2048, -1.0, 1.0);
  const std::vector<float> largeUniform(static_cast<size_t>(large.NumberOfPixels()), 1.0f);
  Run largeRun, largeDensity;
  const std::vector<double> largeSites = cvt::SampleSites(large, {}, 10000, 2011);
  if (!Optimize(cpu, large, largeUniform, largeSites, false, 10, largeRun) ||
    !Optimize(cpu, large, PaperDensity(large), largeSites, false, 10, largeDensity))
  {
    return false;
  }
  std::printf("CPU engine, 10,000 sites, 2048x2048: %.1f ms per Lloyd iteration (uniform), "
              "%.1f ms (paper's density)\n",
    1e3 * largeRun.Seconds / 10.0, 1e3 * largeDensity.Seconds / 10.0);
  LoopOverhead();
  return true;
}

/// One point of the scaling curves: `engine` at side x side pixels with `sites` uniform random
/// sites; up to 5 Lloyd iterations after a warm-up one, within about 10 s. Prints a CSV line;
/// returns the milliseconds per iteration (negative on failure).
double ScalingPoint(cvt::Engine& engine, const char* name, int side, int sites)
{
  const cvt::Grid grid = cvt::Grid::Square(side, -1.0, 1.0);
  const double before = cvt::ResidentMemory();
  const std::vector<float> density(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  cvt::CellSums sums;
  std::vector<double> times;
  auto start = Clock::now();
  bool ok =
    engine.SetDomain(grid, density) && engine.SetSites(cvt::SampleSites(grid, {}, sites, 7));
  for (int k = 0; ok && k < 6; ++k)
  {
    const auto iteration = Clock::now();
    ok = engine.ComputeCellSums(sums) && engine.MoveSitesToCentroids();
    const double ms = 1e3 * SecondsSince(iteration);
    if (k > 0 || ms > 5e3) // the first is a warm-up, unless it is already slow
    {
      times.push_back(ms);
    }
    if (SecondsSince(start) > 10.0 && !times.empty())
    {
      break;
    }
  }
  if (!ok)
  {
    std::fprintf(stderr, "%s engine failed at %d^2, %d sites: %s\n", name, side, sites,
      engine.GetLastError().c_str());
    return -1.0;
  }
  const double resident = (cvt::ResidentMemory() - before) / (1024.0 * 1024.0);
  std::printf("scaling,%s,%d,%d,%.2f,%.0f,%zu\n", name, side, sites, Median(times),
    std::max(0.0, resident), times.size());
  std::fflush(stdout);
  return Median(times);
}

bool Scaling(int maximumSide, int maximumSites)
{
  std::printf("scaling,engine,side,sites,ms_per_iteration,resident_mib,iterations\n");
  bool openglTooSlow = false;
  const auto point = [&](int side, int sites)
  {
    {
      cvt::ExactEngine cpu;
      if (ScalingPoint(cpu, "CPU", side, sites) < 0.0)
      {
        return false;
      }
    }
    if (!openglTooSlow)
    {
      vtkNew<vtkCVTOpenGLEngine> gpu;
      const double ms = ScalingPoint(*gpu, "OpenGL", side, sites);
      if (ms < 0.0)
      {
        return false;
      }
      openglTooSlow = ms > 5e3;
    }
    return true;
  };
  for (int side = 512; side <= maximumSide; side *= 2)
  {
    if (!point(side, std::min(1000, side * side / 4)))
    {
      return false;
    }
  }
  for (int sites = 10000; sites <= maximumSites; sites *= 10)
  {
    if (!point(maximumSide, std::min(sites, maximumSide * maximumSide / 4)))
    {
      return false;
    }
  }
  return true;
}

double Percent(double value, double reference)
{
  return 100.0 * (value - reference) / reference;
}

bool Targets()
{
  const cvt::Grid grid = cvt::Grid::Square(512, -1.0, 1.0);
  const std::vector<float> uniform(static_cast<size_t>(grid.NumberOfPixels()), 1.0f);
  const std::vector<double> initial = cvt::SampleSites(grid, {}, 1000, 2011);
  vtkNew<vtkCVTOpenGLEngine> gpu;
  cvt::ExactEngine exact;

  // Lloyd, 216 iterations.
  Run gpuLloyd, cpuLloyd;
  if (!Optimize(*gpu, grid, uniform, initial, false, 216, gpuLloyd) ||
    !Optimize(exact, grid, uniform, initial, false, 216, cpuLloyd))
  {
    return false;
  }
  const double gpuLloydExact = cvt::ExactCellSums(grid, gpuLloyd.Result.Sites, {}).TotalEnergy();
  const double cpuLloydEnergy = cpuLloyd.Result.Sums.TotalEnergy();
  std::printf(
    "Lloyd, 1000 sites, 512x512, 216 iterations (%s)\n", gpu->GetContextDescription().c_str());
  std::printf("  GPU: exact energy of its sites %.6e (reported %.6e), %.1f s\n", gpuLloydExact,
    gpuLloyd.Result.Sums.TotalEnergy(), gpuLloyd.Seconds);
  std::printf("  exact CPU Lloyd: %.6e, %.1f s\n", cpuLloydEnergy, cpuLloyd.Seconds);
  std::printf(
    "  GPU vs exact: %+.3f%% (target: within 0.35%%)\n", Percent(gpuLloydExact, cpuLloydEnergy));

  // L-BFGS to convergence (iteration cap 1000, stops when no sufficient decrease is possible).
  Run gpuLBFGS, cpuLBFGS;
  if (!Optimize(*gpu, grid, uniform, initial, true, 1000, gpuLBFGS) ||
    !Optimize(exact, grid, uniform, initial, true, 1000, cpuLBFGS))
  {
    return false;
  }
  const double gpuLBFGSExact = cvt::ExactCellSums(grid, gpuLBFGS.Result.Sites, {}).TotalEnergy();
  const double cpuLBFGSEnergy = cpuLBFGS.Result.Sums.TotalEnergy();
  int toLloyd = -1;
  for (const auto& entry : gpuLBFGS.Result.History)
  {
    if (toLloyd < 0 && entry.Energy <= gpuLloyd.Result.Sums.TotalEnergy())
    {
      toLloyd = entry.Evaluations;
    }
  }
  std::printf("L-BFGS (M = 7), same sites\n");
  std::printf("  GPU: exact energy %.6e, %d iterations, %d evaluations, %.1f s (%s)\n",
    gpuLBFGSExact, gpuLBFGS.Result.Iterations, gpuLBFGS.Result.Evaluations, gpuLBFGS.Seconds,
    gpuLBFGS.Result.StopReason.c_str());
  std::printf("  exact CPU L-BFGS: %.6e, %d iterations, %.1f s (%s)\n", cpuLBFGSEnergy,
    cpuLBFGS.Result.Iterations, cpuLBFGS.Seconds, cpuLBFGS.Result.StopReason.c_str());
  std::printf(
    "  GPU vs exact: %+.3f%% (target: within 0.3%%)\n", Percent(gpuLBFGSExact, cpuLBFGSEnergy));
  std::printf("  evaluations to Lloyd's 216-iteration energy: L-BFGS %d, Lloyd 217\n", toLloyd);

  // The paper's density.
  const std::vector<float> density = PaperDensity(grid);
  const std::vector<double> weighted = cvt::SampleSites(grid, density, 1000, 2011);
  Run gpuDensity;
  if (!Optimize(*gpu, grid, density, weighted, true, 1000, gpuDensity))
  {
    return false;
  }
  const double densityExact =
    cvt::ExactCellSums(grid, gpuDensity.Result.Sites, density).TotalEnergy();
  std::printf(
    "L-BFGS, rho = exp(-20x^2-20y^2) + 0.05 sin^2(pi x) sin^2(pi y), 1000 sites, 512x512\n");
  std::printf("  GPU: energy %.6e (exact for the pixelwise density %.6e), %d iterations, %d "
              "evaluations, %.1f s (%s)\n",
    gpuDensity.Result.Sums.TotalEnergy(), densityExact, gpuDensity.Result.Iterations,
    gpuDensity.Result.Evaluations, gpuDensity.Seconds, gpuDensity.Result.StopReason.c_str());
  std::printf("  vs the paper's CPU result 6.116e-5: %+.3f%% (target: within 0.5%%)\n",
    Percent(densityExact, 6.116e-5));
  std::printf("total time of the two L-BFGS target runs on the GPU: %.1f s\n",
    gpuLBFGS.Seconds + gpuDensity.Seconds);
  return true;
}
}

cvt::GeometryImage TorusImage(int width, int height)
{
  vtkNew<vtkCVTGeometryImageSource> source; // default: R = 1, r = 0.4
  source->SetResolution(width, height);
  source->Update();
  cvt::GeometryImage image;
  std::string error;
  vtkCVTSurfaceFilter::ReadGeometryImage(source->GetOutput(), image, error);
  return image;
}

bool SurfaceTiming(int width, int height, bool adaptive)
{
  const cvt::GeometryImage image = TorusImage(width, height);
  std::vector<long long> pixels;
  const std::vector<double> sites = cvt::SampleSurfaceSites(image, 1000, 1, pixels);
  vtkNew<vtkCVTSurfaceEngine> engine;
  engine->SetMeasureTimings(true);
  engine->SetAdaptiveStep(adaptive);
  if (!engine->SetGeometryImage(image))
  {
    std::fprintf(stderr, "engine failed: %s\n", engine->GetLastError().c_str());
    return false;
  }
  cvt::OptimizerOptions options;
  options.MaximumNumberOfIterations = 15;
  cvt::OptimizerResult lloyd, lbfgs;
  std::string error;
  cvt::GeometryImageProblem problem(*engine, image);
  if (!cvt::RunLloyd(problem, { sites, pixels }, options, nullptr, lloyd, error) ||
    !cvt::RunLBFGS(problem, { sites, pixels }, options, nullptr, lbfgs, error))
  {
    std::fprintf(stderr, "optimiser failed: %s\n", error.c_str());
    return false;
  }
  std::vector<double> perIteration, perEvaluation;
  for (size_t k = 1; k < lloyd.History.size(); ++k)
  {
    perIteration.push_back(1e3 * (lloyd.History[k].Seconds - lloyd.History[k - 1].Seconds));
  }
  for (size_t k = 1; k < lbfgs.History.size(); ++k)
  {
    const int evaluations = lbfgs.History[k].Evaluations - lbfgs.History[k - 1].Evaluations;
    perEvaluation.push_back(
      1e3 * (lbfgs.History[k].Seconds - lbfgs.History[k - 1].Seconds) / std::max(1, evaluations));
  }
  std::printf("torus 1000 sites %4dx%-4d %s step %4d  label %7.1f  reduce %6.1f  Lloyd "
              "iteration %7.1f  L-BFGS evaluation %7.1f ms (medians; %d fallbacks)\n",
    width, height, adaptive ? "adaptive" : "full    ", engine->GetLastInitialStep(),
    engine->GetLastLabelMilliseconds(), engine->GetLastReductionMilliseconds(),
    Median(perIteration), Median(perEvaluation), engine->GetNumberOfSafeguardFallbacks());
  return true;
}

/// Seconds of one Update() of `filter` after setting its site count.
template<typename Filter>
double TimedUpdate(Filter* filter, int sites)
{
  filter->SetNumberOfSites(sites);
  const auto start = Clock::now();
  filter->Update();
  return filter->GetSitesOutput()->GetNumberOfPoints() == sites ? SecondsSince(start) : -1.0;
}

/// First update, and a second one with 1100 sites by the same filter and by a new one; medians
/// of three rounds.
template<typename Filter>
bool Lifetime(const char* name, vtkDataObject* input, int engine)
{
  const auto make = [&]()
  {
    vtkSmartPointer<Filter> filter = vtkSmartPointer<Filter>::New();
    filter->SetInputData(input);
    filter->SetEngine(engine);
    filter->SetMethod(Filter::LLOYD);
    filter->SetMaximumNumberOfIterations(2);
    filter->SetTolerance(0.0);
    return filter;
  };
  std::vector<double> first, again, fresh;
  std::string context;
  for (int round = 0; round < 3; ++round)
  {
    vtkSmartPointer<Filter> kept = make();
    first.push_back(TimedUpdate(kept.Get(), 1000));
    again.push_back(TimedUpdate(kept.Get(), 1100));
    fresh.push_back(TimedUpdate(make().Get(), 1100));
    context = kept->GetContextDescription();
    if (first.back() < 0 || again.back() < 0 || fresh.back() < 0)
    {
      std::fprintf(stderr, "%s: an update failed\n", name);
      return false;
    }
  }
  std::printf("%s, 2 Lloyd iterations: first update %.3f s; after NumberOfSites 1000 -> 1100: "
              "%.3f s by the same filter, %.3f s by a new filter (medians of 3) [%s]\n",
    name, Median(first), Median(again), Median(fresh), context.c_str());
  return true;
}

bool FilterLifetimes()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(512, 512, 1);
  vtkNew<vtkFloatArray> density;
  density->SetName("density");
  density->SetNumberOfTuples(512 * 512);
  density->Fill(1.0);
  image->GetPointData()->AddArray(density);
  vtkNew<vtkCVTGeometryImageSource> torus;
  torus->SetResolution(1024, 512);
  torus->Update();
  return Lifetime<vtkCVTImageFilter>("image filter 512x512", image, vtkCVTImageFilter::OPENGL) &&
    Lifetime<vtkCVTSurfaceFilter>(
      "surface filter 1024x512", torus->GetOutput(), vtkCVTSurfaceFilter::OPENGL);
}

bool SurfaceTarget()
{
  vtkNew<vtkCVTGeometryImageSource> source;
  source->SetResolution(1024, 512);
  vtkNew<vtkCVTSurfaceFilter> cvt;
  cvt->SetInputConnection(source->GetOutputPort());
  cvt->SetNumberOfSites(1000);
  cvt->SetMaximumNumberOfIterations(300);
  cvt->SetTolerance(0.0);
  const auto start = Clock::now();
  cvt->Update();
  const double seconds = SecondsSince(start);
  vtkPolyData* sites = cvt->GetSitesOutput();
  if (sites->GetNumberOfPoints() != 1000)
  {
    return false;
  }
  // Energy of the sites on the true torus, densely: a 2048 x 1024 geometry image, each site in
  // the pixel of its (u, v).
  const cvt::GeometryImage dense = TorusImage(2048, 1024);
  std::vector<double> xyz(3000);
  std::vector<long long> pixels(1000);
  const double pi = 3.14159265358979323846;
  for (vtkIdType i = 0; i < 1000; ++i)
  {
    double p[3];
    sites->GetPoint(i, p);
    std::copy(p, p + 3, xyz.begin() + 3 * i);
    const double u = std::atan2(p[1], p[0]), v = std::atan2(p[2], std::hypot(p[0], p[1]) - 1.0);
    const int column = static_cast<int>(std::floor((u + pi) / (2 * pi) * 2048 + 1024)) % 2048;
    const int row = static_cast<int>(std::floor((v + pi) / (2 * pi) * 1024 + 512)) % 1024;
    pixels[i] = static_cast<long long>(row) * 2048 + column;
  }
  vtkNew<vtkCVTSurfaceEngine> engine;
  cvt::CellSums sums;
  if (!engine->SetGeometryImage(dense) || !engine->SetSites(xyz, pixels) ||
    !engine->ComputeCellSums(sums))
  {
    std::fprintf(stderr, "dense evaluation failed: %s\n", engine->GetLastError().c_str());
    return false;
  }
  vtkPolyData* remesh = cvt->GetRemeshOutput();
  std::printf("torus R = 1, r = 0.4, 1000 sites, L-BFGS at 1024x512: %g iterations, %g "
              "evaluations, %.1f s (%s)\n",
    sites->GetFieldData()->GetArray("Iterations")->GetTuple1(0),
    sites->GetFieldData()->GetArray("Evaluations")->GetTuple1(0), seconds,
    sites->GetFieldData()->GetAbstractArray("StopReason")->GetVariantValue(0).ToString().c_str());
  std::printf("  energy: %.6e at 1024x512, %.6e on a dense 2048x1024 image; Geogram's exact "
              "restricted-Voronoi CVT 4.036e-2: %+.2f%% (target within 1.5%%)\n",
    sites->GetFieldData()->GetArray("Energy")->GetTuple1(0), sums.TotalEnergy(),
    Percent(sums.TotalEnergy(), 4.036e-2));
  std::printf("  remesh: valence 6 %.1f%% (target >= 80%%), smallest angle %.1f degrees "
              "(target >= 25)\n",
    100.0 * remesh->GetFieldData()->GetArray("Valence6Fraction")->GetTuple1(0),
    remesh->GetFieldData()->GetArray("MinimumAngle")->GetTuple1(0));
  return true;
}

/// The surface to time the dual on: an OFF file's polygons (fans), repaired, or a torus grid.
bool DualMesh(const std::string& path, cvt::SurfaceMesh& mesh)
{
  if (path == "torus")
  {
    const int columns = 200, rows = 100;
    const double pi = 3.14159265358979323846;
    for (int j = 0; j < rows; ++j)
    {
      for (int i = 0; i < columns; ++i)
      {
        const double u = 2 * pi * i / columns, v = 2 * pi * j / rows;
        const double r = 1.0 + 0.4 * std::cos(v);
        mesh.Points.insert(
          mesh.Points.end(), { r * std::cos(u), r * std::sin(u), 0.4 * std::sin(v) });
        const int a = j * columns + i, b = j * columns + (i + 1) % columns;
        const int c = ((j + 1) % rows) * columns + i,
                  d = ((j + 1) % rows) * columns + (i + 1) % columns;
        mesh.Triangles.push_back({ a, b, d });
        mesh.Triangles.push_back({ a, d, c });
      }
    }
    return true;
  }
  vtkNew<vtkCVTOFFReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* polyData = reader->GetOutput();
  if (polyData->GetNumberOfPolys() == 0)
  {
    std::fprintf(stderr, "no polygons read from %s\n", path.c_str());
    return false;
  }
  for (vtkIdType p = 0; p < polyData->GetNumberOfPoints(); ++p)
  {
    double x[3];
    polyData->GetPoint(p, x);
    mesh.Points.insert(mesh.Points.end(), x, x + 3);
  }
  vtkNew<vtkIdList> ids;
  vtkCellArray* polys = polyData->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      mesh.Triangles.push_back({ static_cast<int>(ids->GetId(0)), static_cast<int>(ids->GetId(k)),
        static_cast<int>(ids->GetId(k + 1)) });
    }
  }
  cvt::MeshRepairReport report;
  const std::string error = cvt::RepairSurfaceMesh(mesh, report);
  if (!error.empty())
  {
    std::fprintf(stderr, "%s: %s\n", path.c_str(), error.c_str());
    return false;
  }
  return true;
}

/// An engine on `mesh` (DualMesh of `path`) with `siteCount` sites after `lloydSteps` Lloyd
/// steps, as the dual and shape timings start from.
bool SettledEngine(const std::string& path, int siteCount, int lloydSteps, cvt::SurfaceMesh& mesh,
  cvt::RestrictedVoronoi& engine)
{
  if (siteCount < 3 || !DualMesh(path, mesh))
  {
    return false;
  }
  cvt::RestrictedProblem problem(engine);
  cvt::OptimizerOptions lloyd;
  lloyd.MaximumNumberOfIterations = lloydSteps;
  cvt::OptimizerResult settled;
  std::string error;
  if (!engine.SetMesh(mesh) ||
    !cvt::RunLloyd(problem, cvt::SiteState{ cvt::SampleMeshSites(mesh, siteCount, 1), {} }, lloyd,
      nullptr, settled, error) ||
    !engine.SetSites(settled.Sites))
  {
    std::fprintf(
      stderr, "engine failed: %s\n", error.empty() ? engine.GetLastError().c_str() : error.c_str());
    return false;
  }
  return true;
}

bool DualTiming(const std::string& path, int siteCount)
{
  cvt::SurfaceMesh mesh;
  cvt::RestrictedVoronoi engine;
  if (!SettledEngine(path, siteCount, 5, mesh, engine)) // cells of the sizes the remesh sees
  {
    return false;
  }
  std::vector<double> dualTimes, sumTimes;
  cvt::RestrictedDual dual;
  cvt::CellSums sums;
  for (int k = 0; k < 21; ++k)
  {
    auto start = Clock::now();
    if (!engine.ComputeDual(dual))
    {
      std::fprintf(stderr, "engine failed: %s\n", engine.GetLastError().c_str());
      return false;
    }
    dualTimes.push_back(1e3 * SecondsSince(start));
    start = Clock::now();
    engine.ComputeCellSums(sums);
    sumTimes.push_back(1e3 * SecondsSince(start));
  }
  std::printf("%s: %d triangles, %d sites: dual %.2f ms, cell sums %.2f ms, ratio %.2f (%zu dual "
              "triangles, %d thin parts)\n",
    path.c_str(), mesh.NumberOfTriangles(), siteCount, Median(dualTimes), Median(sumTimes),
    Median(dualTimes) / Median(sumTimes), dual.Triangles.size(), dual.ThinParts);
  return true;
}

bool ShapeTiming(const std::string& path, int siteCount)
{
  cvt::SurfaceMesh mesh;
  cvt::RestrictedVoronoi engine;
  cvt::RestrictedDual dual;
  if (!SettledEngine(path, siteCount, 30, mesh, engine))
  {
    return false;
  }
  if (!engine.ComputeDual(dual))
  {
    std::fprintf(stderr, "engine failed: %s\n", engine.GetLastError().c_str());
    return false;
  }
  auto start = Clock::now();
  const cvt::RemeshInput input(mesh);
  const double inputTime = 1e3 * SecondsSince(start);
  const double share = 0.009; // the remesh filter's FarInputShare
  const size_t budget = static_cast<size_t>(siteCount) / 100;
  std::vector<double> shapeTimes, measureTimes, againTimes;
  cvt::Remesh remesh;
  cvt::RemeshFidelity fidelity;
  for (int k = 0; k < 11; ++k)
  {
    start = Clock::now();
    remesh = cvt::BuildRemesh(dual, input.Loops.size(), 8, input);
    shapeTimes.push_back(1e3 * SecondsSince(start));
    start = Clock::now();
    fidelity = cvt::MeasureFidelity(remesh, input, share, budget, budget);
    measureTimes.push_back(1e3 * SecondsSince(start));
    start = Clock::now();
    cvt::MeasureFidelity(remesh, input, share, budget, budget, &remesh, &fidelity);
    againTimes.push_back(1e3 * SecondsSince(start));
  }
  std::printf("%s: %d triangles, %zu probes, %d sites: input %.2f ms, shaping %.2f ms, measure "
              "%.2f ms, measure against the same %.2f ms (%zu vertices, %zu triangles, "
              "two-way distance %.3f%% of the diagonal)\n",
    path.c_str(), mesh.NumberOfTriangles(), input.Probes.size() / 3, siteCount, inputTime,
    Median(shapeTimes), Median(measureTimes), Median(againTimes), remesh.SiteIds.size(),
    remesh.Triangles.size(), 100.0 * fidelity.TwoWay());
  return true;
}

int main(int argc, char* argv[])
{
  const std::string what = argc > 1 ? argv[1] : "all";
  if (what == "scaling")
  {
    const int side = argc > 2 ? std::atoi(argv[2]) : 4096;
    const int sites = argc > 3 ? std::atoi(argv[3]) : 100000;
    if (side < 512 || sites < 1000)
    {
      std::fprintf(stderr, "usage: %s scaling [MAX_SIDE >= 512] [MAX_SITES >= 1000]\n", argv[0]);
      return 2;
    }
    return Scaling(side, sites) ? 0 : 1;
  }
  if (what == "dual")
  {
    return DualTiming(argc > 2 ? argv[2] : "torus", argc > 3 ? std::atoi(argv[3]) : 1000) ? 0 : 1;
  }
  if (what == "shape")
  {
    return ShapeTiming(argc > 2 ? argv[2] : "torus", argc > 3 ? std::atoi(argv[3]) : 1000) ? 0 : 1;
  }
  if (what != "timing" && what != "targets" && what != "surface" && what != "cpu" &&
    what != "lifetime" && what != "all")
  {
    std::fprintf(stderr,
      "usage: %s [timing|targets|surface|cpu|lifetime|all] | scaling [MAX_SIDE] [MAX_SITES] | "
      "dual|shape [MESH.off|torus] [SITES]\n",
      argv[0]);
    return 2;
  }
  bool ok = true;
  if (what == "timing" || what == "all")
  {
    ok = ok && Timing(512, 1000, 30, true) && Timing(512, 1000, 10, false);
    ok = ok && Timing(2048, 10000, 8, true) && Timing(2048, 10000, 4, false);
  }
  if (what == "targets" || what == "all")
  {
    ok = ok && Targets();
  }
  if (what == "cpu" || what == "all")
  {
    ok = ok && CPUEngine();
  }
  if (what == "surface" || what == "all")
  {
    ok = ok && SurfaceTiming(512, 256, true) && SurfaceTiming(512, 256, false) &&
      SurfaceTiming(1024, 512, true) && SurfaceTiming(1024, 512, false) && SurfaceTarget();
  }
  if (what == "lifetime" || what == "all")
  {
    ok = ok && FilterLifetimes();
  }
  return ok ? 0 : 1;
}
