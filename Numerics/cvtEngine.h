// The narrow seam between the CVT optimisers and whatever computes Voronoi cells and their
// integrals (the OpenGL engine today; a CPU or compute-shader engine could slot in later).
#ifndef cvtEngine_h
#define cvtEngine_h

#include "cvtNumericsModule.h" // for export macro

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <functional>
#include <string>
#include <vector>

namespace cvt
{

/// A 2D image domain: Width x Height pixels, pixel (i, j) covers
/// [Origin + (i, j) * Spacing, Origin + (i + 1, j + 1) * Spacing] in physical units.
/// Origin is the lower corner of the domain, i.e. the first pixel centre minus half a spacing.
struct Grid
{
  int Width = 0;
  int Height = 0;
  double Origin[2] = { 0.0, 0.0 };
  double Spacing[2] = { 1.0, 1.0 };

  long long NumberOfPixels() const { return static_cast<long long>(this->Width) * this->Height; }
  double PixelArea() const { return this->Spacing[0] * this->Spacing[1]; }
  double XMin() const { return this->Origin[0]; }
  double XMax() const { return this->Origin[0] + this->Width * this->Spacing[0]; }
  double YMin() const { return this->Origin[1]; }
  double YMax() const { return this->Origin[1] + this->Height * this->Spacing[1]; }
  /// An n x n grid over the square [lo, hi]^2.
  static Grid Square(int n, double lo, double hi)
  {
    Grid grid;
    grid.Width = grid.Height = n;
    grid.Origin[0] = grid.Origin[1] = lo;
    grid.Spacing[0] = grid.Spacing[1] = (hi - lo) / n;
    return grid;
  }
  bool Contains(double x, double y) const
  {
    return x >= this->XMin() && x <= this->XMax() && y >= this->YMin() && y <= this->YMax();
  }
};

/// Per-site integrals over the Voronoi cells, in physical units. Moments are taken relative to
/// the site: MomentX[i] = integral of rho (x - x_i), so the centroid is x_i + Moment / Mass and
/// dF/dx_i = -2 Moment.
struct CellSums
{
  std::vector<double> Mass, MomentX, MomentY, Energy;
  std::vector<double> MomentZ; // surfaces only (3D sites); empty in 2D

  void Resize(size_t n, bool threeD = false)
  {
    this->Mass.assign(n, 0.0);
    this->MomentX.assign(n, 0.0);
    this->MomentY.assign(n, 0.0);
    this->MomentZ.assign(threeD ? n : 0, 0.0);
    this->Energy.assign(n, 0.0);
  }
  size_t Size() const { return this->Mass.size(); }
  double TotalEnergy() const
  {
    double e = 0.0;
    for (double v : this->Energy)
    {
      e += v;
    }
    return e;
  }
  /// |grad F| with dF/dx_i = 2 m_i (x_i - c_i) = -2 Moment_i.
  double GradientNorm() const
  {
    double g = 0.0;
    for (size_t i = 0; i < this->Size(); ++i)
    {
      g += 4.0 * (this->MomentX[i] * this->MomentX[i] + this->MomentY[i] * this->MomentY[i]);
      if (!this->MomentZ.empty())
      {
        g += 4.0 * this->MomentZ[i] * this->MomentZ[i];
      }
    }
    return std::sqrt(g);
  }
};

/// The error reporting shared by the engines: methods return false and leave a message.
class CVTNUMERICS_EXPORT EngineErrors
{
public:
  const std::string& GetLastError() const { return this->LastError; }

protected:
  bool Fail(const std::string& message)
  {
    this->LastError = message;
    return false;
  }
  std::string LastError;
};

/// Cell sums shared between processes that run the same job (MPI ranks): each computes its part
/// of the work, then the parts' sums are added so that every part goes on with the whole sums.
/// Every part must compute the same sequence of sums (the exchange is collective).
class CVTNUMERICS_EXPORT SharedCellSums
{
public:
  /// How an engine splits its work between the parts: parts can share only if they all split
  /// it the same way.
  enum class Split
  {
    Cells = 1,          // each part integrates the cells of its share of the sites
    TriangleBlocks = 2, // each part clips its share of the mesh's triangles
    ImageRows = 3       // each part reduces its band of the image's rows
  };
  explicit SharedCellSums(Split split)
    : WorkSplit(split)
  {
  }
  Split GetWorkSplit() const { return this->WorkSplit; }

  /// This process computes part `part` of `parts`; `sumAcrossParts` adds all parts' packed sums
  /// in place (every array of CellSums one after the other; false if that failed). One part
  /// (the default) shares nothing.
  void ShareWork(int part, int parts, std::function<bool(std::vector<double>&)> sumAcrossParts)
  {
    const bool valid = parts > 1 && part >= 0 && part < parts && sumAcrossParts;
    this->Part = valid ? part : 0;
    this->Parts = valid ? parts : 1;
    this->Exchange = valid ? std::move(sumAcrossParts) : nullptr;
  }

protected:
  /// Adds `sums` across the parts (nothing with one part); false if the exchange failed.
  bool SumAcrossParts(CellSums& sums) const
  {
    if (this->Parts <= 1)
    {
      return true;
    }
    std::vector<double>* arrays[] = { &sums.Mass, &sums.MomentX, &sums.MomentY, &sums.MomentZ,
      &sums.Energy };
    std::vector<double> packed;
    for (const auto* array : arrays)
    {
      packed.insert(packed.end(), array->begin(), array->end());
    }
    const size_t size = packed.size();
    if (!this->Exchange(packed) || packed.size() != size)
    {
      return false;
    }
    auto next = packed.begin();
    for (auto* array : arrays)
    {
      std::copy(next, next + static_cast<std::ptrdiff_t>(array->size()), array->begin());
      next += static_cast<std::ptrdiff_t>(array->size());
    }
    return true;
  }

  /// Every part's `values` (the same count from each), one part after the other in part order:
  /// each puts its own in its place among zeros and the exchange adds them. False if it failed.
  bool GatherAcrossParts(std::vector<double>& values) const
  {
    if (this->Parts <= 1)
    {
      return true;
    }
    const size_t count = values.size();
    std::vector<double> all(count * static_cast<size_t>(this->Parts), 0.0);
    std::copy(
      values.begin(), values.end(), all.begin() + static_cast<std::ptrdiff_t>(count * this->Part));
    if (!this->Exchange(all) || all.size() != count * static_cast<size_t>(this->Parts))
    {
      return false;
    }
    values.swap(all);
    return true;
  }

  /// The largest `value` of all parts; false if the exchange failed.
  bool MaximumAcrossParts(double& value) const
  {
    std::vector<double> values{ value };
    if (!this->GatherAcrossParts(values))
    {
      return false;
    }
    value = *std::max_element(values.begin(), values.end());
    return true;
  }

  /// This part's share [first, last) of `count` items (rows of an image, blocks of triangles).
  void PartRange(int count, int& first, int& last) const
  {
    first = static_cast<int>(static_cast<long long>(count) * this->Part / this->Parts);
    last = static_cast<int>(static_cast<long long>(count) * (this->Part + 1) / this->Parts);
  }

  int Part = 0, Parts = 1;

private:
  Split WorkSplit;
  std::function<bool(std::vector<double>&)> Exchange;
};

/// What an engine must do for the optimisers. Sites are flat (x0, y0, x1, y1, ...) physical
/// coordinates inside the grid's domain. Every method returns false on failure and leaves a
/// message in GetLastError().
class CVTNUMERICS_EXPORT Engine : public EngineErrors
{
public:
  virtual ~Engine() = default;

  /// Prepare for this domain and density (one value per pixel, row-major, x fastest).
  virtual bool SetDomain(const Grid& grid, const std::vector<float>& density) = 0;
  virtual bool SetSites(const std::vector<double>& sites) = 0;
  /// Label the domain for the current sites and integrate over every cell.
  virtual bool ComputeCellSums(CellSums& sums) = 0;
  /// Lloyd step: move every site with positive mass to the centroid found by the last
  /// ComputeCellSums (sites of empty cells stay). Engines may keep the sites on the device.
  virtual bool MoveSitesToCentroids() = 0;
  virtual bool GetSites(std::vector<double>& sites) = 0;
  /// Nearest-site label of every pixel centre (-1 where none), row-major.
  virtual bool GetLabels(std::vector<int>& labels) = 0;
};

} // namespace cvt

#endif
