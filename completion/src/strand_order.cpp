#include "strand_order.h"

#include <deque>

namespace hair25d::completion::detail {

std::map<int, std::set<int>> chains_above(const std::map<int, std::set<int>>& above) {
  std::map<int, std::set<int>> out;
  for (const auto& [id, direct] : above) {
    std::vector<int> stack(direct.begin(), direct.end());
    std::set<int>& seen = out[id];
    while (!stack.empty()) {
      const int r = stack.back();
      stack.pop_back();
      if (!seen.insert(r).second) continue;
      const auto it = above.find(r);
      if (it != above.end()) stack.insert(stack.end(), it->second.begin(), it->second.end());
    }
  }
  return out;
}

int StrandGroups::find(int x) {
  auto it = parent_.find(x);
  if (it == parent_.end()) return parent_[x] = x;
  if (it->second == x) return x;
  return it->second = find(it->second);
}

void StrandGroups::unite(int a, int b) { parent_[find(a)] = find(b); }

void StrandGroups::add_firm_order(int lower, int upper) {
  find(lower), find(upper);
  firm_above_[lower].insert(upper);
  chains_stale_ = true;
}

void StrandGroups::add_weak_order(int lower, int upper) {
  find(lower), find(upper);
  weak_above_[lower].insert(upper);
}

bool StrandGroups::firmly_ordered(int ga, int gb) {
  if (chains_stale_) {
    firm_chains_ = chains_above(firm_above_);
    chains_stale_ = false;
  }
  std::vector<int> in_a, in_b;
  for (auto& [id, up] : parent_) {
    const int g = find(id);
    if (g == ga) in_a.push_back(id);
    if (g == gb) in_b.push_back(id);
  }
  const auto above_any = [&](const std::vector<int>& lower, const std::vector<int>& upper) {
    for (int x : lower) {
      const auto it = firm_chains_.find(x);
      if (it == firm_chains_.end()) continue;
      for (int y : upper)
        if (it->second.count(y)) return true;
    }
    return false;
  };
  return above_any(in_a, in_b) || above_any(in_b, in_a);
}

bool StrandGroups::above_through_others(int from, int to) {
  // The groups' order graph, built afresh: groups change with every merge and
  // are few (tens to a few hundred regions a drawing).
  std::map<int, std::set<int>> up;
  const auto add = [&](const std::map<int, std::set<int>>& orders) {
    for (const auto& [lower, uppers] : orders) {
      const int gl = find(lower);
      for (int u : uppers) {
        const int gu = find(u);
        if (gu != gl) up[gl].insert(gu);
      }
    }
  };
  add(firm_above_);
  if (guard_ == StrandOrderGuard::kAll) add(weak_above_);
  std::set<int> seen{from};
  std::deque<int> queue;
  if (const auto it = up.find(from); it != up.end())
    for (int g : it->second)
      if (g != to && seen.insert(g).second) queue.push_back(g);
  while (!queue.empty()) {
    const int g = queue.front();
    queue.pop_front();
    const auto it = up.find(g);
    if (it == up.end()) continue;
    for (int next : it->second) {
      if (next == to) return true;
      if (seen.insert(next).second) queue.push_back(next);
    }
  }
  return false;
}

bool StrandGroups::try_join(int a, int b) {
  const int ga = find(a), gb = find(b);
  if (ga == gb || firmly_ordered(ga, gb)) return false;
  if (guard_ != StrandOrderGuard::kOff &&
      (above_through_others(ga, gb) || above_through_others(gb, ga))) {
    guard_refusals_.push_back({a, b});
    return false;
  }
  unite(a, b);
  return true;
}

}  // namespace hair25d::completion::detail
