// Private to CVT::Numerics: nanoflann's view of a flat point array (x, y[, z] per point) and the
// k-d tree over it, shared by the engines' nearest-site searches.
#ifndef cvtPointCloud_h
#define cvtPointCloud_h

#include <nanoflann.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace cvt
{

template<int Dimension>
struct PointCloud
{
  const std::vector<double>* Points = nullptr;
  size_t kdtree_get_point_count() const { return this->Points->size() / Dimension; }
  double kdtree_get_pt(size_t i, size_t d) const { return (*this->Points)[Dimension * i + d]; }
  template<class Box>
  bool kdtree_get_bbox(Box&) const
  {
    return false; // nanoflann computes the bounding box
  }
};

template<int Dimension>
using PointTree =
  nanoflann::KDTreeSingleIndexAdaptor<nanoflann::L2_Simple_Adaptor<double, PointCloud<Dimension>>,
    PointCloud<Dimension>, Dimension, std::uint32_t>;

/// The nearest point of `tree` to `x`, given a `hint`: a point of the tree near x (as the answer
/// for the point before, in a run of nearby queries). The walk then only looks for points
/// strictly nearer than the hint, and skips most of the tree; where several points are nearest,
/// the hint is kept.
template<int Dimension>
std::uint32_t NearestPoint(const PointTree<Dimension>& tree, const double* x, std::uint32_t hint)
{
  struct NearerThanHint // nanoflann's result-set interface
  {
    double Distance2;
    std::uint32_t Index;
    size_t size() const { return 1; }
    bool full() const { return true; }
    double worstDist() const { return this->Distance2; }
    bool addPoint(double distance2, std::uint32_t index)
    {
      if (distance2 < this->Distance2)
      {
        this->Distance2 = distance2;
        this->Index = index;
      }
      return true;
    }
  };
  // The hint's distance as the tree's own metric measures the points it offers.
  NearerThanHint nearest{ tree.distance.evalMetric(x, hint, Dimension), hint };
  tree.findNeighbors(nearest, x, nanoflann::SearchParams());
  return nearest.Index;
}

} // namespace cvt

#endif
