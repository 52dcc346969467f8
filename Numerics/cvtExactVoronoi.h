// Exact CPU reference: continuous Voronoi cells clipped to the rectangular domain, their exact
// integrals (uniform or pixelwise-constant density), and brute-force nearest-site labels.
// Used by the tests and by users who want to check a GPU result.
#ifndef cvtExactVoronoi_h
#define cvtExactVoronoi_h

#include "cvtEngine.h"
#include "cvtNumericsModule.h" // for export macro

#include <vector>

namespace cvt
{

/// A convex polygon, counter-clockwise.
struct Polygon
{
  std::vector<double> X, Y;
  size_t Size() const { return this->X.size(); }
};

/// Integrals of a density of 1 over a polygon, relative to a centre c.
struct PolygonIntegrals
{
  double Area = 0.0;
  double MomentX = 0.0, MomentY = 0.0; // integral of (x - c)
  double SecondMoment = 0.0;           // integral of |x - c|^2
};

CVTNUMERICS_EXPORT PolygonIntegrals IntegratePolygon(const Polygon& polygon, double cx, double cy);
/// The same for n vertices given as coordinate arrays.
CVTNUMERICS_EXPORT PolygonIntegrals IntegrateVertices(
  const double* x, const double* y, size_t n, double cx, double cy);

/// Keeps the part of `polygon` where a x + b y <= c.
CVTNUMERICS_EXPORT Polygon ClipPolygon(const Polygon& polygon, double a, double b, double c);
/// The same into `out` (not `polygon`), reusing its storage.
CVTNUMERICS_EXPORT void ClipPolygon(
  const Polygon& polygon, double a, double b, double c, Polygon& out);

/// The Voronoi cells of all sites (flat x, y) clipped to the grid's domain, one polygon each;
/// only those of sites first to last - 1 when a range is given (the others stay empty).
CVTNUMERICS_EXPORT std::vector<Polygon> ClippedVoronoiCells(const Grid& grid,
  const std::vector<double>& sites, size_t first = 0, size_t last = static_cast<size_t>(-1));

/// Row prefix sums of rho, rho x, rho y and rho |x|^2 over pixel centres (relative to the
/// grid's origin): the pixels wholly inside a cell cost O(rows) instead of O(pixels).
struct CVTNUMERICS_EXPORT DensityTables
{
  DensityTables() = default;
  DensityTables(const Grid& grid, const std::vector<float>& density);
  size_t Stride = 0; // Width + 1
  std::vector<double> Rho, RhoX, RhoY, RhoR2;
};

/// Exact per-cell integrals, in parallel over the cells (vtkSMPTools). An empty density means
/// uniform density 1; otherwise the density is constant over each pixel (row-major, one value
/// per pixel).
CVTNUMERICS_EXPORT CellSums ExactCellSums(
  const Grid& grid, const std::vector<double>& sites, const std::vector<float>& density);
/// The same with the density's tables made once (the exact engine keeps them), for the cells
/// of sites first to last - 1 only when a range is given (the others' sums stay 0).
CVTNUMERICS_EXPORT CellSums ExactCellSums(const Grid& grid, const std::vector<double>& sites,
  const std::vector<float>& density, const DensityTables& tables, size_t first = 0,
  size_t last = static_cast<size_t>(-1));

/// Nearest site of every pixel centre, with a k-d tree, in parallel (ties: either site).
CVTNUMERICS_EXPORT std::vector<int> NearestSiteLabels(
  const Grid& grid, const std::vector<double>& sites);

/// Nearest site of every pixel centre, by brute force (ties: the lower index).
CVTNUMERICS_EXPORT std::vector<int> BruteForceLabels(
  const Grid& grid, const std::vector<double>& sites);

} // namespace cvt

#endif
