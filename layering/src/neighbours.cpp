#include "neighbours.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <set>

namespace hair25d::layering::detail {
namespace {
std::pair<int, int> key(int a, int b) { return {std::min(a, b), std::max(a, b)}; }
}  // namespace

// Regions that meet only where several lines cross (a thick junction) share
// no boundary: the crossing keeps a small island of unfilled line pixels
// between them (or they share just a junction). They are neighbours all the
// same, and the drawing order already says which one is drawn over the other.
// An island is a set of label-0 boundaries linked through junctions whose
// length is under `island_perimeter`.
void add_island_neighbours(const BoundaryGraph& graph, double island_perimeter, double sliver_reach,
                           Result& out) {
  const auto& bs = graph.boundaries;
  const int nb = static_cast<int>(bs.size());
  std::vector<int> parent(nb);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  auto zero_side = [&](int i) { return bs[i].left == 0 || bs[i].right == 0; };
  for (const Junction& j : graph.junctions) {
    int first = -1;
    for (int b : j.boundaries) {
      if (!zero_side(b)) continue;
      if (first < 0)
        first = b;
      else
        parent[find(b)] = find(first);
    }
  }
  std::map<int, double> perimeter;
  std::map<int, std::set<int>> island_labels;
  std::set<int> open;  // touch the image border: the paper, not an island
  for (int i = 0; i < nb; ++i) {
    if (!zero_side(i) || bs[i].closed()) continue;
    const int r = find(i);
    perimeter[r] += bs[i].length();
    const int other = bs[i].left == 0 ? bs[i].right : bs[i].left;
    if (other > 0) island_labels[r].insert(other);
    if (other == kOutsideLabel) open.insert(r);
  }
  // Junctions where hair regions meet with no boundary of their own between them.
  std::vector<std::set<int>> groups;
  for (const auto& [r, ls] : island_labels)
    if (!open.contains(r) && perimeter[r] < island_perimeter) groups.push_back(ls);
  for (const Junction& j : graph.junctions) {
    std::set<int> around;
    for (int b : j.boundaries)
      for (int l : {bs[b].left, bs[b].right})
        if (l > 0) around.insert(l);
    groups.push_back(std::move(around));
  }
  // Across a sliver: a strand narrower than a line width or two drawn between
  // two others leaves them a few line widths apart. Look across every hair
  // boundary, along its normal, `reach` pixels each way.
  const LabelMap& labels = out.labels;
  auto label_at = [&](const Vec2& p) {
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    return x < 0 || y < 0 || x >= labels.width() || y >= labels.height() ? 0 : labels.at(x, y);
  };
  for (const Boundary& b : bs) {
    if (b.left <= 0 || b.right <= 0) continue;
    const int n = static_cast<int>(b.points.size());
    for (int i = 2; i + 2 < n; i += 2) {
      const Vec2 t = b.points[i + 2] - b.points[i - 2];
      if (t.squaredNorm() == 0) continue;
      const Vec2 normal = Vec2(t.y(), -t.x()).normalized();
      const int l = label_at(b.points[i] + sliver_reach * normal);
      const int r = label_at(b.points[i] - sliver_reach * normal);
      // Beyond the right region lies r: a neighbour of the left one, and so on.
      if (r > 0 && r != b.left && r != b.right) groups.push_back({b.left, r});
      if (l > 0 && l != b.left && l != b.right) groups.push_back({b.right, l});
    }
  }
  std::set<std::pair<int, int>> related;
  for (const RegionRelation& r : out.relations) related.insert(key(r.a, r.b));
  for (const std::set<int>& g : groups)
    for (auto p = g.begin(); p != g.end(); ++p)
      for (auto q = std::next(p); q != g.end(); ++q) {
        const auto k = key(*p, *q);
        if (!related.insert(k).second) continue;
        const int da = out.depth.at(k.first), db = out.depth.at(k.second);
        RegionRelation r;
        r.a = k.first;
        r.b = k.second;
        r.relation = da > db ? Relation::kAbove : da < db ? Relation::kBelow : Relation::kEqual;
        out.relations.push_back(r);
        out.anchors.push_back({});
      }
}

}  // namespace hair25d::layering::detail
