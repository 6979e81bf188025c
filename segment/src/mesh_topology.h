// Private: triangle neighbours across edges, and union-find, shared by the
// graph cut and the automatic regions.
#pragma once

#include <algorithm>
#include <array>
#include <numeric>
#include <vector>

#include "hair25d/core/tri_mesh.h"

namespace hair25d::segment::detail {

// #F × 3: the triangle across edge k (F(t,k) -> F(t,(k+1)%3)) of triangle t, or -1.
std::vector<std::array<int, 3>> triangle_neighbours(const TriMesh2& mesh);

bool edge_on_curve(const TriMesh2& mesh, int t, int k);

class UnionFind {
 public:
  explicit UnionFind(int n) : parent_(n) { std::iota(parent_.begin(), parent_.end(), 0); }
  int find(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  void unite(int a, int b) {
    a = find(a);
    b = find(b);
    if (a != b) parent_[std::max(a, b)] = std::min(a, b);
  }

 private:
  std::vector<int> parent_;
};

}  // namespace hair25d::segment::detail
