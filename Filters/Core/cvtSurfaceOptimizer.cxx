#include "cvtSurfaceOptimizer.h"

#include "cvtOptimizerSupport.h"

#include <Eigen/Core>
#include <LBFGSB.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>

namespace cvt
{

namespace
{
using Clock = std::chrono::steady_clock;
using Vector = Eigen::VectorXd;

/// Tangential gradient of site i: -2 M_i minus its component along the normal at the site.
void TangentialGradient(const GeometryImage& image, const CellSums& sums,
  const std::vector<long long>& pixels, size_t i, double g[3])
{
  g[0] = -2.0 * sums.MomentX[i];
  g[1] = -2.0 * sums.MomentY[i];
  g[2] = -2.0 * sums.MomentZ[i];
  const float* n = &image.Normal[3 * pixels[i]];
  const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
  for (int k = 0; k < 3; ++k)
  {
    g[k] -= along * n[k];
  }
}

/// Shared bookkeeping of both surface optimisers: evaluation, history, stop conditions.
class SurfaceRun
{
public:
  SurfaceRun(SurfaceEngine& engine, const GeometryImage& image, const OptimizerOptions& options,
    const ProgressCallback& progress, SurfaceResult& result)
    : Engine(engine)
    , Image(image)
    , Options(options)
    , Progress(progress)
    , Result(result)
    , Start(Clock::now())
  {
  }

  /// Label and integrate for these sites; keeps the best state.
  double Evaluate(const std::vector<double>& sites, const std::vector<long long>& pixels)
  {
    if (!this->Engine.SetSites(sites, pixels) || !this->Engine.ComputeCellSums(this->Sums))
    {
      throw StopOptimizer{ this->Engine.GetLastError(), true };
    }
    ++this->Result.Evaluations;
    this->Sites = sites;
    this->Pixels = pixels;
    const double energy = this->Sums.TotalEnergy();
    if (energy < this->BestEnergy)
    {
      this->BestEnergy = energy;
      this->Result.Sites = sites;
      this->Result.Pixels = pixels;
      this->Result.Sums = this->Sums;
    }
    return energy;
  }

  /// Records an iterate and applies the stop conditions (throws StopOptimizer to stop).
  void Record(int iteration, double energy)
  {
    HistoryEntry entry;
    entry.Iteration = iteration;
    entry.Evaluations = this->Result.Evaluations;
    entry.Energy = energy;
    entry.GradientNorm = TangentialGradientNorm(this->Image, this->Sums, this->Pixels);
    entry.Seconds = std::chrono::duration<double>(Clock::now() - this->Start).count();
    RecordAndCheck(this->Options, this->Progress, this->Result, entry);
  }

  /// Ends a run: the engine relabelled for the best sites, and their labels read back (once,
  /// here, rather than after every evaluation).
  bool Finish(const StopOptimizer* stop, std::string& error)
  {
    if (stop && stop->EngineFailed)
    {
      error = stop->Reason;
      return false;
    }
    if (this->Result.Sites.empty())
    {
      error = "no sites were evaluated";
      return false;
    }
    if (this->Sites != this->Result.Sites)
    {
      CellSums sums;
      if (!this->Engine.SetSites(this->Result.Sites, this->Result.Pixels) ||
        !this->Engine.ComputeCellSums(sums))
      {
        error = this->Engine.GetLastError();
        return false;
      }
    }
    if (!this->Engine.GetLabels(this->Result.Labels))
    {
      error = this->Engine.GetLastError();
      return false;
    }
    return true;
  }

  SurfaceEngine& Engine;
  const GeometryImage& Image;
  const OptimizerOptions& Options;
  const ProgressCallback& Progress;
  SurfaceResult& Result;
  Clock::time_point Start;
  CellSums Sums;
  std::vector<double> Sites;
  std::vector<long long> Pixels;
  double BestEnergy = std::numeric_limits<double>::infinity();
};

/// The energy of the sites projected onto their cells, for LBFGS++; coordinates are scaled to
/// the surface's bounding box so the solver's unit first step fits any surface size.
class ProjectedObjective
{
public:
  ProjectedObjective(SurfaceRun& run, double scale)
    : Run(run)
    , Scale(scale)
  {
  }

  double operator()(const Vector& x, Vector& gradient)
  {
    std::vector<double> targets(x.size());
    for (Eigen::Index k = 0; k < x.size(); ++k)
    {
      targets[k] = x[k] * this->Scale;
    }
    std::vector<double> sites = this->Run.Sites;
    std::vector<long long> pixels = this->Run.Pixels;
    if (!this->Run.Engine.NearestPointsInCells(targets, sites, pixels))
    {
      throw StopOptimizer{ this->Run.Engine.GetLastError(), true };
    }
    const double energy = this->Run.Evaluate(sites, pixels);
    gradient.resize(x.size());
    for (size_t i = 0; i < pixels.size(); ++i)
    {
      double g[3];
      TangentialGradient(this->Run.Image, this->Run.Sums, pixels, i, g);
      for (int k = 0; k < 3; ++k)
      {
        gradient[3 * i + k] = g[k] * this->Scale;
      }
    }
    return energy;
  }

  void AcceptIterate(double energy, const Vector&)
  {
    this->Run.Record(this->Run.Result.Iterations + 1, energy);
  }

private:
  SurfaceRun& Run;
  double Scale;
};
}

double TangentialGradientNorm(
  const GeometryImage& image, const CellSums& sums, const std::vector<long long>& pixels)
{
  double total = 0.0;
  for (size_t i = 0; i < pixels.size() && i < sums.Size(); ++i)
  {
    double g[3];
    TangentialGradient(image, sums, pixels, i, g);
    total += g[0] * g[0] + g[1] * g[1] + g[2] * g[2];
  }
  return std::sqrt(total);
}

bool RunSurfaceLloyd(SurfaceEngine& engine, const GeometryImage& image,
  const std::vector<double>& sites, const std::vector<long long>& pixels,
  const OptimizerOptions& options, const ProgressCallback& progress, SurfaceResult& result,
  std::string& error)
{
  result = SurfaceResult();
  SurfaceRun run(engine, image, options, progress, result);
  std::vector<double> current = sites;
  std::vector<long long> currentPixels = pixels;
  try
  {
    for (int iteration = 0;; ++iteration)
    {
      const double energy = run.Evaluate(current, currentPixels);
      run.Record(iteration, energy);
      // Constrained centroids: the point of each cell nearest to its 3D centroid.
      std::vector<double> centroids = current;
      for (size_t i = 0; i < run.Sums.Size(); ++i)
      {
        if (run.Sums.Mass[i] > 0.0)
        {
          centroids[3 * i] += run.Sums.MomentX[i] / run.Sums.Mass[i];
          centroids[3 * i + 1] += run.Sums.MomentY[i] / run.Sums.Mass[i];
          centroids[3 * i + 2] += run.Sums.MomentZ[i] / run.Sums.Mass[i];
        }
      }
      if (!engine.NearestPointsInCells(centroids, current, currentPixels))
      {
        throw StopOptimizer{ engine.GetLastError(), true };
      }
    }
  }
  catch (const StopOptimizer& stop)
  {
    result.StopReason = stop.Reason;
    return run.Finish(&stop, error);
  }
}

bool RunSurfaceLBFGS(SurfaceEngine& engine, const GeometryImage& image,
  const std::vector<double>& sites, const std::vector<long long>& pixels,
  const OptimizerOptions& options, const ProgressCallback& progress, SurfaceResult& result,
  std::string& error)
{
  result = SurfaceResult();
  SurfaceRun run(engine, image, options, progress, result);
  double scale = 0.0;
  for (double c : sites)
  {
    scale = std::max(scale, std::abs(c));
  }
  scale = std::max(scale, 1e-12);
  try
  {
    // The first evaluation labels the initial sites, which later projections need.
    run.Record(0, run.Evaluate(sites, pixels));
    ProjectedObjective objective(run, scale);
    const LBFGSpp::LBFGSBParam<double> parameters = SolverParameters(options);
    LBFGSpp::LBFGSBSolver<double, ReportingLineSearch> solver(parameters);
    Vector x(sites.size());
    for (size_t k = 0; k < sites.size(); ++k)
    {
      x[k] = sites[k] / scale;
    }
    // The sites are projected onto the surface, so the box only keeps the solver finite.
    const Vector lower = Vector::Constant(x.size(), -1e3), upper = Vector::Constant(x.size(), 1e3);
    double energy = 0.0;
    solver.minimize(objective, x, energy, lower, upper);
    result.StopReason = "the solver reported convergence";
  }
  catch (const StopOptimizer& stop)
  {
    result.StopReason = stop.Reason;
    return run.Finish(&stop, error);
  }
  catch (const std::exception& failure)
  {
    result.StopReason = NoSufficientDecrease(failure);
  }
  return run.Finish(nullptr, error);
}

} // namespace cvt
