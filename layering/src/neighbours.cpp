#include "neighbours.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <set>
#include <utility>
#include <vector>

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
IslandGroups island_groups(const BoundaryGraph& graph, const LabelMap& labels,
                           double island_perimeter, double sliver_reach) {
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
  // Per island (the root of its boundaries): perimeter, the hair labels
  // around it (sorted and made unique below) and whether it touches the
  // image border (then it is the paper, not an island).
  std::vector<double> perimeter(nb, 0.0);
  std::vector<std::vector<int>> island_labels(nb);
  std::vector<char> open(nb, 0), island(nb, 0);
  for (int i = 0; i < nb; ++i) {
    if (!zero_side(i) || bs[i].closed()) continue;
    const int r = find(i);
    perimeter[r] += bs[i].length();
    const int other = bs[i].left == 0 ? bs[i].right : bs[i].left;
    if (other > 0) {
      island_labels[r].push_back(other);
      island[r] = 1;
    }
    if (other == kOutsideLabel) open[r] = 1;
  }
  // Groups of labels that are neighbours of each other, each sorted and
  // without repeats, one after another in `members` (group g is
  // [starts[g], starts[g + 1])); their pairs are added in this order.
  IslandGroups groups;
  std::vector<int>& members = groups.members;
  std::vector<std::size_t>& starts = groups.starts;
  auto close_group = [&] {
    const auto first = members.begin() + static_cast<std::ptrdiff_t>(starts.back());
    std::sort(first, members.end());
    members.erase(std::unique(first, members.end()), members.end());
    starts.push_back(members.size());
  };
  // Junctions where hair regions meet with no boundary of their own between them.
  for (int r = 0; r < nb; ++r)
    if (island[r] && !open[r] && perimeter[r] < island_perimeter) {
      members.insert(members.end(), island_labels[r].begin(), island_labels[r].end());
      close_group();
    }
  for (const Junction& j : graph.junctions) {
    for (int b : j.boundaries)
      for (int l : {bs[b].left, bs[b].right})
        if (l > 0) members.push_back(l);
    close_group();
  }
  // Across a sliver: a strand narrower than a line width or two drawn between
  // two others leaves them a few line widths apart. Look across every hair
  // boundary, along its normal, `reach` pixels each way.
  auto label_at = [&](const Vec2& p) {
    const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
    return x < 0 || y < 0 || x >= labels.width() || y >= labels.height() ? 0 : labels.at(x, y);
  };
  // A boundary's labels across are read first, then looked at: the loads
  // (far apart in the map, mostly cache misses) overlap instead of each
  // waiting behind the branches on the one before.
  std::vector<std::pair<int, int>> across;  // (left, right) per point looked across
  for (const Boundary& b : bs) {
    if (b.left <= 0 || b.right <= 0) continue;
    const int n = static_cast<int>(b.points.size());
    across.clear();
    for (int i = 2; i + 2 < n; i += 2) {
      const Vec2 t = b.points[i + 2] - b.points[i - 2];
      if (t.squaredNorm() == 0) continue;
      const Vec2 normal = Vec2(t.y(), -t.x()).normalized();
      across.emplace_back(label_at(b.points[i] + sliver_reach * normal),
                          label_at(b.points[i] - sliver_reach * normal));
    }
    for (const auto& [l, r] : across) {
      // Beyond the right region lies r: a neighbour of the left one, and so on.
      if (r > 0 && r != b.left && r != b.right) {
        members.insert(members.end(), {std::min(b.left, r), std::max(b.left, r)});
        starts.push_back(members.size());
      }
      if (l > 0 && l != b.left && l != b.right) {
        members.insert(members.end(), {std::min(b.right, l), std::max(b.right, l)});
        starts.push_back(members.size());
      }
    }
  }
  return groups;
}

void add_island_neighbours(const IslandGroups& groups, Result& out) {
  const std::vector<int>& members = groups.members;
  const std::vector<std::size_t>& starts = groups.starts;
  std::set<std::pair<int, int>> related;
  for (const RegionRelation& r : out.relations) related.insert(key(r.a, r.b));
  for (std::size_t g = 0; g + 1 < starts.size(); ++g)
    for (std::size_t p = starts[g]; p < starts[g + 1]; ++p)
      for (std::size_t q = p + 1; q < starts[g + 1]; ++q) {
        const auto k = key(members[p], members[q]);
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
