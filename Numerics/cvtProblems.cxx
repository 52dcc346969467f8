#include "cvtProblems.h"

#include <algorithm>
#include <cmath>

namespace cvt
{

namespace
{
/// Each site with a non-empty cell moved to its cell's centroid (moments are about the site).
std::vector<double> Centroids(const std::vector<double>& sites, const CellSums& sums)
{
  std::vector<double> centroids = sites;
  for (size_t i = 0; i < sums.Size(); ++i)
  {
    if (sums.Mass[i] > 0.0)
    {
      centroids[3 * i] += sums.MomentX[i] / sums.Mass[i];
      centroids[3 * i + 1] += sums.MomentY[i] / sums.Mass[i];
      centroids[3 * i + 2] += sums.MomentZ[i] / sums.Mass[i];
    }
  }
  return centroids;
}
}

// --- Plane

PlaneProblem::PlaneProblem(Engine& engine, const Grid& grid)
  : Engine_(engine)
  , Domain(grid)
{
}

bool PlaneProblem::SetState(const SiteState& state)
{
  return this->Relay(this->Engine_.SetSites(state.Sites), this->Engine_);
}

bool PlaneProblem::GetState(SiteState& state)
{
  state.Pixels.clear();
  return this->Relay(this->Engine_.GetSites(state.Sites), this->Engine_);
}

bool PlaneProblem::ComputeCellSums(CellSums& sums)
{
  return this->Relay(this->Engine_.ComputeCellSums(sums), this->Engine_);
}

bool PlaneProblem::MoveSitesToCentroids(const CellSums&)
{
  // The engine moves them from its own last sums (on the device, for the OpenGL engine).
  return this->Relay(this->Engine_.MoveSitesToCentroids(), this->Engine_);
}

void PlaneProblem::SolverFrame(const std::vector<double>&, double center[3], double& scale) const
{
  const Grid& g = this->Domain;
  center[0] = 0.5 * (g.XMin() + g.XMax());
  center[1] = 0.5 * (g.YMin() + g.YMax());
  center[2] = 0.0;
  scale = std::max(g.XMax() - g.XMin(), g.YMax() - g.YMin());
}

void PlaneProblem::SolverBounds(const double[3], double scale, std::vector<double>& lower,
  std::vector<double>& upper, size_t size) const
{
  // The domain grown by 1% on every side. With bounds exactly at the domain's edge, LBFGS++
  // 0.1's bounded line search stalls as soon as a site touches one. The energy is smooth for
  // sites just outside (their cells still cover the border), and Conform moves them back.
  const double margin = 0.01 * scale;
  const Grid& g = this->Domain;
  lower.resize(size);
  upper.resize(size);
  for (size_t k = 0; k < size; ++k)
  {
    lower[k] = (k % 2 == 0 ? g.XMin() : g.YMin()) - margin;
    upper[k] = (k % 2 == 0 ? g.XMax() : g.YMax()) + margin;
  }
}

bool PlaneProblem::Conform(std::vector<double>& sites) const
{
  bool moved = false;
  for (size_t k = 0; k < sites.size(); ++k)
  {
    const Grid& g = this->Domain;
    const double inside =
      std::clamp(sites[k], k % 2 == 0 ? g.XMin() : g.YMin(), k % 2 == 0 ? g.XMax() : g.YMax());
    moved = moved || inside != sites[k];
    sites[k] = inside;
  }
  return moved;
}

// --- Geometry image

GeometryImageProblem::GeometryImageProblem(SurfaceEngine& engine, const GeometryImage& image)
  : Engine_(engine)
  , Image(image)
{
}

bool GeometryImageProblem::SetState(const SiteState& state)
{
  if (state.Pixels.size() * 3 != state.Sites.size())
  {
    return this->Fail("every site on a geometry image needs the pixel holding it");
  }
  this->Current = state;
  return this->Relay(this->Engine_.SetSites(state.Sites, state.Pixels), this->Engine_);
}

bool GeometryImageProblem::GetState(SiteState& state)
{
  state = this->Current;
  return true;
}

bool GeometryImageProblem::ComputeCellSums(CellSums& sums)
{
  return this->Relay(this->Engine_.ComputeCellSums(sums), this->Engine_);
}

bool GeometryImageProblem::MoveSitesToCentroids(const CellSums& sums)
{
  // The constrained centroid: the point of each cell nearest to its 3D centroid.
  return this->MoveSitesTo(Centroids(this->Current.Sites, sums));
}

bool GeometryImageProblem::MoveSitesTo(const std::vector<double>& targets)
{
  SiteState moved = this->Current;
  return this->Relay(
           this->Engine_.NearestPointsInCells(targets, moved.Sites, moved.Pixels), this->Engine_) &&
    this->SetState(moved);
}

void GeometryImageProblem::Gradient(const CellSums& sums, std::vector<double>& gradient) const
{
  // -2 M_i without its component along the surface normal at the site.
  this->Problem::Gradient(sums, gradient);
  const std::vector<long long>& pixels = this->Current.Pixels;
  for (size_t i = 0; i < pixels.size() && i < sums.Size(); ++i)
  {
    double* g = &gradient[3 * i];
    const float* n = &this->Image.Normal[3 * pixels[i]];
    const double along = g[0] * n[0] + g[1] * n[1] + g[2] * n[2];
    for (int k = 0; k < 3; ++k)
    {
      g[k] -= along * n[k];
    }
  }
}

void GeometryImageProblem::SolverFrame(
  const std::vector<double>& sites, double center[3], double& scale) const
{
  // About the origin, scaled by the largest coordinate: the sites are projected onto the
  // surface after every step, so the frame only sets the size of the first one.
  std::fill(center, center + 3, 0.0);
  scale = 1e-12;
  for (double c : sites)
  {
    scale = std::max(scale, std::abs(c));
  }
}

// --- Restricted Voronoi on a mesh

RestrictedProblem::RestrictedProblem(RestrictedVoronoi& engine)
  : Engine_(engine)
{
}

bool RestrictedProblem::SetState(const SiteState& state)
{
  this->Sites = state.Sites;
  return this->Relay(this->Engine_.SetSites(state.Sites), this->Engine_);
}

bool RestrictedProblem::GetState(SiteState& state)
{
  state.Sites = this->Sites;
  state.Pixels.clear();
  return true;
}

bool RestrictedProblem::ComputeCellSums(CellSums& sums)
{
  return this->Relay(this->Engine_.ComputeCellSums(sums), this->Engine_);
}

bool RestrictedProblem::MoveSitesToCentroids(const CellSums& sums)
{
  return this->SetState(SiteState{ Centroids(this->Sites, sums), {} });
}

} // namespace cvt
