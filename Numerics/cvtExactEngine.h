// The exact CPU engine: the cvt::Engine seam served by clipped Voronoi polygons, so that the
// optimisers run unchanged on exact integrals (the reference the GPU engine is measured
// against, and the engine of machines without a GPU). Cells are clipped and integrated in
// parallel (vtkSMPTools); with a density, row prefix sums integrate the pixels inside a cell.
#ifndef cvtExactEngine_h
#define cvtExactEngine_h

#include "cvtEngine.h"
#include "cvtExactVoronoi.h"   // for DensityTables
#include "cvtNumericsModule.h" // for export macro

#include <functional> // for std::function

namespace cvt
{

class CVTNUMERICS_EXPORT ExactEngine : public Engine
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

  /// Shares ComputeCellSums between `parts` processes running the same job (MPI ranks): this
  /// one clips and integrates only the cells of its share of the sites (part `part` of `parts`
  /// equal runs of site ids), then `sumAcrossParts` adds all parts' sums in place (Mass, MomentX,
  /// MomentY and Energy one after the other; false if that failed), so that every part goes on
  /// with the whole sums. Each cell is integrated by one part only: the sums are, to the bit,
  /// those of one process alone. One part (the default) shares nothing.
  void ShareWork(int part, int parts, std::function<bool(std::vector<double>&)> sumAcrossParts);

private:
  Grid Domain;
  std::vector<float> Density; // empty: uniform
  DensityTables Tables;
  std::vector<double> Sites;
  CellSums LastSums;
  bool HaveSums = false;
  int Part = 0, Parts = 1;
  std::function<bool(std::vector<double>&)> SumAcrossParts;
};

} // namespace cvt

#endif
