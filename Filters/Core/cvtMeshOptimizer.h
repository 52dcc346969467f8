// Lloyd and L-BFGS for sites free in space whose cells are restricted to a triangle mesh (the
// energy of Levy and Liu's restricted CVT, Liu et al. 2009 section 6), on the exact CPU engine.
// The sites converge onto the surface; the remesh projects them onto it.
#ifndef cvtMeshOptimizer_h
#define cvtMeshOptimizer_h

#include "cvtCoreModule.h" // for export macro
#include "cvtLloyd.h"      // for OptimizerOptions, OptimizerResult, ProgressCallback
#include "cvtRestrictedVoronoi.h"

namespace cvt
{

/// Lloyd: every site moves to the centroid of its restricted cell.
CVTCORE_EXPORT bool RunMeshLloyd(RestrictedVoronoi& engine, const std::vector<double>& sites,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error);

/// L-BFGS on the restricted CVT energy (gradient 2 m_i (x_i - c_i)).
CVTCORE_EXPORT bool RunMeshLBFGS(RestrictedVoronoi& engine, const std::vector<double>& sites,
  const OptimizerOptions& options, const ProgressCallback& progress, OptimizerResult& result,
  std::string& error);

} // namespace cvt

#endif
