// The exact CPU engine: the cvt::Engine seam served by clipped Voronoi polygons, so that the
// optimisers run unchanged on exact integrals (the reference the GPU engine is measured
// against, and the engine of machines without a GPU). Cells are clipped and integrated in
// parallel (vtkSMPTools); with a density, row prefix sums integrate the pixels inside a cell.
#ifndef cvtExactEngine_h
#define cvtExactEngine_h

#include "cvtEngine.h"
#include "cvtExactVoronoi.h"   // for DensityTables
#include "cvtNumericsModule.h" // for export macro

namespace cvt
{

/// Under MPI (ShareWork) each part clips and integrates only the cells of its share of the
/// sites (part `part` of `parts` equal runs of site ids): each cell is integrated by one part
/// only, so the summed sums are, to the bit, those of one process alone.
class CVTNUMERICS_EXPORT ExactEngine
  : public Engine
  , public SharedCellSums
{
public:
  ExactEngine();
  /// An all-ones density is treated as uniform (exact polygon integrals, no pixel cuts).
  bool SetDomain(const Grid& grid, const std::vector<float>& density) override;
  bool SetSites(const std::vector<double>& sites) override;
  bool ComputeCellSums(CellSums& sums) override;
  bool MoveSitesToCentroids() override;
  bool GetSites(std::vector<double>& sites) override;
  bool GetLabels(std::vector<int>& labels) override;

private:
  Grid Domain;
  std::vector<float> Density; // empty: uniform
  DensityTables Tables;
  std::vector<double> Sites;
  CellSums LastSums;
  bool HaveSums = false;
};

} // namespace cvt

#endif
