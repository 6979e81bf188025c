#include "mesh_topology.h"

#include <algorithm>
#include <array>
#include <cstdint>

namespace hair25d::segment::detail {

std::vector<std::array<int, 3>> triangle_neighbours(const TriMesh2& mesh) {
  const int nf = mesh.triangle_count();
  std::vector<std::array<int, 3>> nb(nf, {-1, -1, -1});
  // Sort directed edges by their undirected key; twins end up side by side.
  struct HalfEdge {
    std::uint64_t key;
    int tri, k;
  };
  std::vector<HalfEdge> edges;
  edges.reserve(static_cast<std::size_t>(nf) * 3);
  for (int t = 0; t < nf; ++t) {
    for (int k = 0; k < 3; ++k) {
      const std::uint32_t a = mesh.F(t, k), b = mesh.F(t, (k + 1) % 3);
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      edges.push_back({key, t, k});
    }
  }
  std::sort(edges.begin(), edges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.tri < y.tri;
  });
  for (std::size_t i = 0; i + 1 < edges.size(); ++i) {
    if (edges[i].key != edges[i + 1].key) continue;
    nb[edges[i].tri][edges[i].k] = edges[i + 1].tri;
    nb[edges[i + 1].tri][edges[i + 1].k] = edges[i].tri;
    ++i;
  }
  return nb;
}

bool edge_on_curve(const TriMesh2& mesh, int t, int k) {
  return mesh.on_curve.rows() == mesh.F.rows() && mesh.on_curve(t, k);
}

}  // namespace hair25d::segment::detail
