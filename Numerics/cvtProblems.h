// The three CVT problems the optimisers of cvtOptimizer.h run on: sites in a planar image
// domain (cvt::Engine), sites on a surface given as a geometry image (cvt::SurfaceEngine:
// constrained CVT, Rong et al. 4.3-4.4) and sites in space whose cells are restricted to a
// triangle mesh (cvt::RestrictedVoronoi, Liu et al. 2009 section 6).
#ifndef cvtProblems_h
#define cvtProblems_h

#include "cvtEngine.h"
#include "cvtNumericsModule.h" // for export macro
#include "cvtOptimizer.h"
#include "cvtRestrictedVoronoi.h"
#include "cvtSurface.h"

namespace cvt
{

/// Sites in the plane of a grid. The engine may keep the sites on its device between Lloyd
/// steps. L-BFGS-B keeps them in the domain grown by 1%; the result is clamped into it.
class CVTNUMERICS_EXPORT PlaneProblem : public Problem
{
public:
  PlaneProblem(Engine& engine, const Grid& grid);
  int Dimension() const override { return 2; }
  bool SetState(const SiteState& state) override;
  bool GetState(SiteState& state) override;
  bool ComputeCellSums(CellSums& sums) override;
  bool MoveSitesToCentroids(const CellSums& sums) override;
  void SolverFrame(
    const std::vector<double>& sites, double center[3], double& scale) const override;
  void SolverBounds(const double center[3], double scale, std::vector<double>& lower,
    std::vector<double>& upper, size_t size) const override;
  bool Conform(std::vector<double>& sites) const override;

private:
  Engine& Engine_;
  Grid Domain;
};

/// Sites on the surface of a geometry image, each held by a pixel. Lloyd moves every site to
/// the point of its cell nearest to the cell's 3D centroid; an L-BFGS step moves it to the point
/// of its cell nearest to the solver's target; gradients are tangential.
class CVTNUMERICS_EXPORT GeometryImageProblem : public Problem
{
public:
  GeometryImageProblem(SurfaceEngine& engine, const GeometryImage& image);
  int Dimension() const override { return 3; }
  bool SetState(const SiteState& state) override;
  bool GetState(SiteState& state) override;
  bool ComputeCellSums(CellSums& sums) override;
  bool MoveSitesToCentroids(const CellSums& sums) override;
  bool MoveSitesTo(const std::vector<double>& targets) override;
  void Gradient(const CellSums& sums, std::vector<double>& gradient) const override;
  void SolverFrame(
    const std::vector<double>& sites, double center[3], double& scale) const override;

private:
  SurfaceEngine& Engine_;
  const GeometryImage& Image;
  SiteState Current;
};

/// Sites free in space whose cells are restricted to a mesh; they converge onto the surface.
class CVTNUMERICS_EXPORT RestrictedProblem : public Problem
{
public:
  explicit RestrictedProblem(RestrictedVoronoi& engine);
  int Dimension() const override { return 3; }
  bool SetState(const SiteState& state) override;
  bool GetState(SiteState& state) override;
  bool ComputeCellSums(CellSums& sums) override;
  bool MoveSitesToCentroids(const CellSums& sums) override;

private:
  RestrictedVoronoi& Engine_;
  std::vector<double> Sites;
};

} // namespace cvt

#endif
