#include "hair25d/layering/depth_order.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::layering {
namespace {

int find(std::vector<int>& parent, int a) {
  while (parent[a] != a) a = parent[a] = parent[parent[a]];
  return a;
}

// Whether `to` can be reached from `from` along `above` edges (lower → upper).
bool reaches(const std::vector<std::vector<int>>& up, int from, int to, std::vector<int>& mark,
             int stamp) {
  std::vector<int> stack{from};
  mark[from] = stamp;
  while (!stack.empty()) {
    const int v = stack.back();
    stack.pop_back();
    if (v == to) return true;
    for (int w : up[v])
      if (mark[w] != stamp) {
        mark[w] = stamp;
        stack.push_back(w);
      }
  }
  return false;
}

}  // namespace

DepthOrder order_regions(const std::vector<int>& regions,
                         const std::vector<RegionRelation>& relations) {
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

  // Strongest first, so a cycle is broken at its weakest link.
  std::vector<int> order(relations.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int p, int q) {
    const RegionRelation& a = relations[p];
    const RegionRelation& b = relations[q];
    if (a.user_fixed != b.user_fixed) return a.user_fixed;
    return std::abs(a.score) > std::abs(b.score);
  });

  // Equal relations merge regions into one group first.
  std::vector<int> group(n);
  std::iota(group.begin(), group.end(), 0);
  for (const RegionRelation& r : relations)
    if (r.relation == Relation::kEqual) {
      const int ga = find(group, at(r.a, "a"));
      const int gb = find(group, at(r.b, "b"));
      if (ga != gb) group[std::max(ga, gb)] = std::min(ga, gb);
    }

  DepthOrder out;
  out.relations = relations;
  std::vector<std::vector<int>> up(n);  // group → groups directly above it
  std::vector<int> mark(n, -1);
  int stamp = 0;
  for (int k : order) {
    RegionRelation& r = out.relations[k];
    if (r.relation == Relation::kEqual) continue;
    int lower = find(group, at(r.a, "a"));
    int upper = find(group, at(r.b, "b"));
    if (r.relation == Relation::kAbove) std::swap(lower, upper);
    // A relation inside one merged group, or one whose reverse already
    // follows from stronger relations, contradicts the order.
    if (lower == upper || reaches(up, upper, lower, mark, stamp++)) {
      r.overridden = true;
      if (lower != upper)
        r.relation = reversed(r.relation);
      else
        r.relation = Relation::kEqual;
      out.overridden.emplace_back(r.a, r.b);
      continue;
    }
    up[lower].push_back(upper);
  }

  // Longest chain below each group: Kahn's algorithm over the group DAG.
  std::vector<int> indegree(n, 0), level(n, 0);
  for (int g = 0; g < n; ++g)
    for (int h : up[g]) ++indegree[h];
  std::vector<int> ready;
  for (int g = 0; g < n; ++g)
    if (find(group, g) == g && indegree[g] == 0) ready.push_back(g);
  while (!ready.empty()) {
    const int g = ready.back();
    ready.pop_back();
    for (int h : up[g]) {
      level[h] = std::max(level[h], level[g] + 1);
      if (--indegree[h] == 0) ready.push_back(h);
    }
  }
  for (const auto& [id, i] : index) out.depth[id] = level[find(group, i)];
  return out;
}

}  // namespace hair25d::layering
