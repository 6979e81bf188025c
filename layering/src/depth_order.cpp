#include "hair25d/layering/depth_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::layering {
namespace {

// Groups of regions at one depth (merged by "equal"), and the relations
// placed so far between groups, as edges lower → upper.
class GroupDag {
 public:
  explicit GroupDag(int n) : parent_(n), up_(n), mark_(n, -1) {
    std::iota(parent_.begin(), parent_.end(), 0);
  }
  int find(int a) {
    while (parent_[a] != a) a = parent_[a] = parent_[parent_[a]];
    return a;
  }
  // Whether group `to` lies above group `from` along placed relations.
  bool reaches(int from, int to) {
    from = find(from);
    to = find(to);
    ++stamp_;
    std::vector<int> stack{from};
    mark_[from] = stamp_;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      if (v == to) return true;
      for (int w : up_[v]) {
        w = find(w);
        if (mark_[w] != stamp_) {
          mark_[w] = stamp_;
          stack.push_back(w);
        }
      }
    }
    return false;
  }
  void add_edge(int lower, int upper) { up_[find(lower)].push_back(find(upper)); }
  void merge(int a, int b) {
    a = find(a);
    b = find(b);
    if (a == b) return;
    if (a > b) std::swap(a, b);
    parent_[b] = a;
    up_[a].insert(up_[a].end(), up_[b].begin(), up_[b].end());
    up_[b].clear();
  }
  // Longest chain of groups below each region's group (Kahn's algorithm).
  std::vector<int> levels() {
    const int n = static_cast<int>(parent_.size());
    std::vector<std::vector<int>> up(n);
    std::vector<int> indegree(n, 0), level(n, 0);
    for (int g = 0; g < n; ++g)
      for (int h : up_[g]) {
        up[find(g)].push_back(find(h));
        ++indegree[find(h)];
      }
    std::vector<int> ready;
    for (int g = 0; g < n; ++g)
      if (find(g) == g && indegree[g] == 0) ready.push_back(g);
    while (!ready.empty()) {
      const int g = ready.back();
      ready.pop_back();
      for (int h : up[g]) {
        level[h] = std::max(level[h], level[g] + 1);
        if (--indegree[h] == 0) ready.push_back(h);
      }
    }
    std::vector<int> out(n);
    for (int i = 0; i < n; ++i) out[i] = level[find(i)];
    return out;
  }

 private:
  std::vector<int> parent_;
  std::vector<std::vector<int>> up_;
  std::vector<int> mark_;
  int stamp_ = 0;
};

}  // namespace

DepthOrder order_regions(const std::vector<int>& regions,
                         const std::vector<RegionRelation>& relations) {
  return order_regions(regions, relations, {});
}

DepthOrder order_regions(const std::vector<int>& regions,
                         const std::vector<RegionRelation>& relations,
                         const std::vector<char>& firm) {
  if (!firm.empty() && firm.size() != relations.size())
    throw Error("layering::order_regions: firm flags = " + std::to_string(firm.size()) + " for " +
                std::to_string(relations.size()) + " relations; must be none or one per relation");
  std::map<int, int> index;
  for (int id : regions) index.emplace(id, static_cast<int>(index.size()));
  const int n = static_cast<int>(index.size());
  auto at = [&](int id, const char* role) {
    auto it = index.find(id);
    if (it == index.end())
      throw Error(std::string("layering::order_regions: relation names region ") + role + " = " +
                  std::to_string(id) + ", which is not in the list of regions");
    return it->second;
  };
  for (const RegionRelation& r : relations) {
    at(r.a, "a");
    at(r.b, "b");
    if (r.a == r.b)
      throw Error("layering::order_regions: relation of region " + std::to_string(r.a) +
                  " with itself; a and b must differ");
  }

  // Strongest first, so a cycle is broken at its weakest link: user-fixed
  // relations, then above/below by |score|, then "equal" (which has no
  // score): a same-depth claim never undoes a placed above/below — unless
  // it is flagged firm.
  std::vector<int> order(relations.size());
  std::iota(order.begin(), order.end(), 0);
  // Firm "equal" relations come right after the user-fixed ones.
  auto rank = [&](int k) {
    const RegionRelation& r = relations[k];
    if (r.user_fixed) return 0;
    if (r.relation != Relation::kEqual) return 2;
    return !firm.empty() && firm[k] ? 1 : 3;
  };
  std::stable_sort(order.begin(), order.end(), [&](int p, int q) {
    const RegionRelation& a = relations[p];
    const RegionRelation& b = relations[q];
    if (rank(p) != rank(q)) return rank(p) < rank(q);
    return std::abs(a.score) > std::abs(b.score);
  });

  DepthOrder out;
  out.relations = relations;
  GroupDag dag(n);
  for (int k : order) {
    RegionRelation& r = out.relations[k];
    const int a = at(r.a, "a");
    const int b = at(r.b, "b");
    if (r.relation == Relation::kEqual) {
      if (dag.find(a) == dag.find(b)) continue;
      // Equal contradicts an order already implied between the two.
      if (dag.reaches(a, b) || dag.reaches(b, a)) {
        r.overridden = true;
        r.relation = dag.reaches(a, b) ? Relation::kBelow : Relation::kAbove;
        out.overridden.emplace_back(r.a, r.b);
        continue;
      }
      dag.merge(a, b);
      continue;
    }
    const int lower = r.relation == Relation::kAbove ? b : a;
    const int upper = r.relation == Relation::kAbove ? a : b;
    // A relation inside one merged group, or whose reverse already follows
    // from stronger relations, contradicts the order.
    if (dag.find(lower) == dag.find(upper) || dag.reaches(upper, lower)) {
      r.overridden = true;
      r.relation = dag.find(lower) == dag.find(upper) ? Relation::kEqual : reversed(r.relation);
      out.overridden.emplace_back(r.a, r.b);
      continue;
    }
    dag.add_edge(lower, upper);
  }
  const std::vector<int> level = dag.levels();
  for (const auto& [id, i] : index) out.depth[id] = level[i];
  return out;
}

}  // namespace hair25d::layering
