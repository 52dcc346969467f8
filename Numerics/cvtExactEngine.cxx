#include "cvtExactEngine.h"
#include "cvtMemory.h"

#include "cvtExactVoronoi.h"
#include "cvtThreads.h"

#include <algorithm>

namespace cvt
{

ExactEngine::ExactEngine()
  : SharedCellSums(Split::Cells)
{
  UseThreads();
}

bool ExactEngine::SetDomain(const Grid& grid, const std::vector<float>& density)
{
  if (grid.Width <= 0 || grid.Height <= 0)
  {
    return this->Fail("the domain has no pixels");
  }
  if (static_cast<long long>(density.size()) != grid.NumberOfPixels())
  {
    return this->Fail("the density must hold one value per pixel");
  }
  // Per pixel: the labels and the k-d tree's work (12 bytes measured with a uniform density),
  // with a density also its copy and the four row prefix sums in double (36 more).
  const bool uniform =
    std::all_of(density.begin(), density.end(), [](float v) { return v == 1.0f; });
  const std::string memory = CheckMemory(
    static_cast<double>(grid.NumberOfPixels()) * (uniform ? 12.0 : 48.0), AvailableSystemMemory(),
    "the CPU engine's domain of " + std::to_string(grid.Width) + " x " +
      std::to_string(grid.Height) + " pixels",
    "memory", "use a coarser image");
  if (!memory.empty())
  {
    return this->Fail(memory);
  }
  this->Domain = grid;
  this->Density = uniform ? std::vector<float>() : density;
  this->Tables = DensityTables(grid, this->Density);
  this->HaveSums = false;
  return true;
}

bool ExactEngine::SetSites(const std::vector<double>& sites)
{
  if (sites.size() < 2)
  {
    return this->Fail("there are no sites");
  }
  this->Sites = sites;
  this->HaveSums = false;
  return true;
}

bool ExactEngine::ComputeCellSums(CellSums& sums)
{
  if (this->Sites.empty())
  {
    return this->Fail("SetSites must succeed before ComputeCellSums");
  }
  int first = 0, last = 0;
  this->PartRange(static_cast<int>(this->Sites.size() / 2), first, last);
  this->LastSums =
    ExactCellSums(this->Domain, this->Sites, this->Density, this->Tables, first, last);
  if (!this->SumAcrossParts(this->LastSums))
  {
    return this->Fail("the cell sums of the other processes sharing the work did not arrive");
  }
  this->HaveSums = true;
  sums = this->LastSums;
  return true;
}

bool ExactEngine::MoveSitesToCentroids()
{
  if (!this->HaveSums)
  {
    return this->Fail("ComputeCellSums must run before MoveSitesToCentroids");
  }
  for (size_t i = 0; i < this->LastSums.Size(); ++i)
  {
    if (this->LastSums.Mass[i] > 0.0)
    {
      this->Sites[2 * i] += this->LastSums.MomentX[i] / this->LastSums.Mass[i];
      this->Sites[2 * i + 1] += this->LastSums.MomentY[i] / this->LastSums.Mass[i];
    }
  }
  this->HaveSums = false;
  return true;
}

bool ExactEngine::GetSites(std::vector<double>& sites)
{
  sites = this->Sites;
  return true;
}

bool ExactEngine::GetLabels(std::vector<int>& labels)
{
  labels = NearestSiteLabels(this->Domain, this->Sites);
  return true;
}

} // namespace cvt
