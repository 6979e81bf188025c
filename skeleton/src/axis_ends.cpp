#include "axis_ends.h"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <vector>

namespace hair25d::skeleton::detail {
namespace {

// A branch shorter than twice the strand's half-width where it joins only
// reaches the outline next to the axis: the chordal axis puts such a branch
// at every ear triangle of a bumpy outline (pixel steps, notches), about one
// half-width long.
constexpr double kSpurRatio = 2.0;

// The widest the axis gets within `reach` of `junction` (a tree walk over
// active nodes, not back into the branch through `from`): the width of the
// body a branch joins. The junction's own triangle is no measure of it: a
// notch in the outline makes small junctions next to the boundary.
double body_half_width(const MedialGraph& g, const std::vector<bool>& active, int junction,
                       int from, double reach) {
  double widest = g.radius[junction];
  std::vector<std::tuple<int, int, double>> stack{{junction, from, 0.0}};
  while (!stack.empty()) {
    const auto [v, prev, d] = stack.back();
    stack.pop_back();
    widest = std::max(widest, g.radius[v]);
    for (int u : g.adjacent[v]) {
      if (!active[u] || u == prev) continue;
      const double du = d + (g.nodes[u] - g.nodes[v]).norm();
      if (du <= reach) stack.emplace_back(u, v, du);
    }
  }
  return widest;
}

int active_degree(const MedialGraph& g, const std::vector<bool>& active, int v) {
  int d = 0;
  for (int u : g.adjacent[v]) d += active[u];
  return d;
}

}  // namespace

PrunedAxis prune_spurs(const MedialGraph& g, const std::vector<int>& keep) {
  const int n = static_cast<int>(g.nodes.size());
  PrunedAxis axis;
  axis.active.assign(n, true);
  std::vector<bool> kept(n, false);
  for (int k : keep)
    if (k >= 0 && k < n) kept[k] = true;
  double widest = 0.0;
  for (double r : g.radius) widest = std::max(widest, r);
  // Spurs go in passes, the shortest (relative to the body) first, at most
  // one per junction per pass: a pruned spur can turn its junction into a
  // plain axis node, which makes a neighbouring ear's branch longer, so of
  // a rounded end's ears the one straight ahead stays. Every pass but the
  // last removes nodes, so this ends.
  struct Spur {
    double ratio;
    int junction;
    std::vector<int> path;
  };
  while (true) {
    std::vector<Spur> spurs;
    for (int leaf = 0; leaf < n; ++leaf) {
      if (!axis.active[leaf] || kept[leaf] || active_degree(g, axis.active, leaf) != 1) continue;
      std::vector<int> path{leaf};
      double length = 0.0;
      int prev = -1, v = leaf;
      while (true) {
        int next = -1;
        for (int u : g.adjacent[v])
          if (axis.active[u] && u != prev) next = u;
        length += (g.nodes[next] - g.nodes[v]).norm();
        prev = v;
        v = next;
        if (active_degree(g, axis.active, v) != 2 || kept[v]) break;
        path.push_back(v);
      }
      // Only a branch that ends at a junction is a spur; a path whose other
      // end is a leaf (or a kept tip) is the whole axis.
      if (active_degree(g, axis.active, v) < 3 || length >= kSpurRatio * widest) continue;
      const double width = body_half_width(g, axis.active, v, prev, length);
      if (width > 0.0 && length < kSpurRatio * width)
        spurs.push_back({length / width, v, std::move(path)});
    }
    if (spurs.empty()) break;
    std::sort(spurs.begin(), spurs.end(),
              [](const Spur& a, const Spur& b) { return a.ratio < b.ratio; });
    std::vector<bool> touched(n, false);
    for (const Spur& spur : spurs) {
      if (touched[spur.junction]) continue;
      touched[spur.junction] = true;
      for (int v : spur.path) axis.active[v] = false;
    }
  }
  for (int v = 0; v < n; ++v)
    if (axis.active[v] && active_degree(g, axis.active, v) <= 1) axis.ends.push_back(v);
  return axis;
}

std::vector<int> rounded_tips(const MedialGraph& g, const PrunedAxis& axis,
                              const std::vector<double>& dist, const std::vector<int>& parent,
                              const std::vector<bool>& visible_end, double min_distance,
                              double arm) {
  std::vector<int> tips;
  for (int end : axis.ends) {
    if (!visible_end[end] || !std::isfinite(dist[end]) || dist[end] < min_distance) continue;
    // Walking towards the root: past the cap of the end (the first node
    // at least two half-widths back), the half-width r1 there, then whether
    // the strand gets 1.3 times as wide within the next max(4 r1, 6 arms).
    // A flat or sausage-like end keeps its width and is no tip.
    double r1 = -1.0, s1 = 0.0;
    bool tapers = false;
    for (int v = end; v >= 0; v = parent[v]) {
      const double back = dist[end] - dist[v];
      if (r1 < 0.0) {
        if (back >= 2.0 * g.radius[v] && g.radius[v] > 0.0) r1 = g.radius[v], s1 = back;
        continue;
      }
      if (back > s1 + std::max(4.0 * r1, 6.0 * arm)) break;
      if (g.radius[v] >= 1.3 * r1) {
        tapers = true;
        break;
      }
    }
    if (tapers) tips.push_back(end);
  }
  return tips;
}

int choose_root(const MedialGraph& g, const std::vector<bool>& candidates,
                const std::vector<bool>& leaves, const std::vector<int>& free_corners,
                const Vec2& hint) {
  const auto without_free = [&](std::vector<bool> allowed) {
    for (int c : free_corners)
      if (c >= 0 && c < static_cast<int>(allowed.size())) allowed[c] = false;
    return allowed;
  };
  const auto none = [](const std::vector<bool>& a) {
    return std::find(a.begin(), a.end(), true) == a.end();
  };
  // A pruned axis that runs from one free corner to another (a lock pointed
  // at both ends) roots at a leaf of the whole axis next to the head end.
  std::vector<bool> allowed = without_free(candidates);
  if (none(allowed)) allowed = without_free(leaves);
  if (none(allowed)) allowed = candidates;
  int best = -1;
  double best_d = 0.0;
  for (std::size_t v = 0; v < g.nodes.size(); ++v) {
    if (!allowed[v]) continue;
    // stableNorm: a hint far away (1e200) must not square to infinity.
    const double d = (g.nodes[v] - hint).stableNorm();
    if (best < 0 || d < best_d) best = static_cast<int>(v), best_d = d;
  }
  return best;
}

}  // namespace hair25d::skeleton::detail
