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

} // namespace cvt

#endif
