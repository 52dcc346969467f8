// Constrained CVT on a surface given as a geometry image: Lloyd with constrained centroids
// (Rong 4.3) and L-BFGS with the tangential gradient and projection onto the surface (Rong 4.4,
// Liu et al. section 6), through the cvt::SurfaceEngine seam.
#ifndef cvtSurfaceOptimizer_h
#define cvtSurfaceOptimizer_h

#include "cvtCoreModule.h" // for export macro
#include "cvtLloyd.h"      // for OptimizerOptions, OptimizerResult, ProgressCallback
#include "cvtSurface.h"

namespace cvt
{

struct SurfaceResult : OptimizerResult
{
  std::vector<long long> Pixels; // the pixel holding each final site
  std::vector<int> Labels;       // the labelling of the final sites
};

/// |grad F| restricted to the surface: each site's gradient -2 M_i without its normal part.
CVTCORE_EXPORT double TangentialGradientNorm(
  const GeometryImage& image, const CellSums& sums, const std::vector<long long>& pixels);

/// Lloyd: every site moves to the point of its cell nearest to the cell's 3D centroid.
CVTCORE_EXPORT bool RunSurfaceLloyd(SurfaceEngine& engine, const GeometryImage& image,
  const std::vector<double>& sites, const std::vector<long long>& pixels,
  const OptimizerOptions& options, const ProgressCallback& progress, SurfaceResult& result,
  std::string& error);

/// L-BFGS on the energy of the sites projected onto their cells, with tangential gradients.
CVTCORE_EXPORT bool RunSurfaceLBFGS(SurfaceEngine& engine, const GeometryImage& image,
  const std::vector<double>& sites, const std::vector<long long>& pixels,
  const OptimizerOptions& options, const ProgressCallback& progress, SurfaceResult& result,
  std::string& error);

} // namespace cvt

#endif
