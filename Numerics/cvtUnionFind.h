// Private to CVT::Numerics: disjoint sets of 0..n-1, for the connected parts of meshes (mesh
// topology, the engine's parts of the input and its feature lines, the restricted dual's cell
// parts, the remesh's pieces).
#ifndef cvtUnionFind_h
#define cvtUnionFind_h

#include <algorithm>
#include <cstddef>
#include <numeric>
#include <vector>

namespace cvt
{

struct UnionFind
{
  explicit UnionFind(size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  /// The representative of i's set (with path halving).
  int Find(int i)
  {
    while (this->Parent[i] != i)
    {
      i = this->Parent[i] = this->Parent[this->Parent[i]];
    }
    return i;
  }
  /// Joins a's and b's sets. The later root goes under the earlier: a set joined in index order
  /// keeps its first member as its root, so its trees stay flat. With a's root always put under
  /// b's, each new member joined to the set before it became the root of the whole set, and the
  /// restricted dual's joining of its pieces took 4.4 instead of 2.4 ms of armadillo's 17.4 ms
  /// dual at 1000 sites. The sets are the same either way.
  void Join(int a, int b)
  {
    a = this->Find(a);
    b = this->Find(b);
    this->Parent[static_cast<size_t>(std::max(a, b))] = std::min(a, b);
  }
  /// Makes 0..n-1 singletons again, in the storage already held (made afresh each time, a large
  /// one's pages are faulted in again).
  void Reset(size_t n)
  {
    this->Parent.resize(n);
    std::iota(this->Parent.begin(), this->Parent.end(), 0);
  }
  std::vector<int> Parent;
};

} // namespace cvt

#endif
