// Private to CVT::Numerics: disjoint sets of 0..n-1, for the connected parts of meshes (mesh
// topology, the engine's parts of the input, the remesh's pieces).
#ifndef cvtUnionFind_h
#define cvtUnionFind_h

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
  void Join(int a, int b) { this->Parent[this->Find(a)] = this->Find(b); }
  std::vector<int> Parent;
};

} // namespace cvt

#endif
