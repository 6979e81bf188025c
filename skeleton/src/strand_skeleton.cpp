#include "hair25d/skeleton/strand_skeleton.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>

#include "axis_ends.h"
#include "hair25d/core/error.h"
#include "inside_test.h"
#include "medial_graph.h"
#include "polygon_sampling.h"
#include "tips.h"

namespace hair25d::skeleton {
namespace {

using detail::MedialGraph;

// Tree distances and parents from `source` (the graph is a forest).
void shortest_paths(const MedialGraph& g, int source, std::vector<double>* dist,
                    std::vector<int>* parent) {
  const int n = static_cast<int>(g.nodes.size());
  dist->assign(n, std::numeric_limits<double>::infinity());
  parent->assign(n, -1);
  using Item = std::pair<double, int>;
  std::priority_queue<Item, std::vector<Item>, std::greater<>> queue;
  (*dist)[source] = 0.0;
  queue.push({0.0, source});
  while (!queue.empty()) {
    const auto [d, u] = queue.top();
    queue.pop();
    if (d > (*dist)[u]) continue;
    for (int v : g.adjacent[u]) {
      const double nd = d + (g.nodes[u] - g.nodes[v]).norm();
      if (nd < (*dist)[v]) {
        (*dist)[v] = nd;
        (*parent)[v] = u;
        queue.push({nd, v});
      }
    }
  }
}

// Connected piece of every node (the axis is a forest when the outline
// touches itself).
std::vector<int> components(const MedialGraph& g) {
  const int n = static_cast<int>(g.nodes.size());
  std::vector<int> piece(n, -1);
  int count = 0;
  for (int start = 0; start < n; ++start) {
    if (piece[start] >= 0) continue;
    std::vector<int> stack{start};
    piece[start] = count;
    while (!stack.empty()) {
      const int v = stack.back();
      stack.pop_back();
      for (int u : g.adjacent[v])
        if (piece[u] < 0) piece[u] = count, stack.push_back(u);
    }
    ++count;
  }
  return piece;
}

int nearest_node(const MedialGraph& g, const Vec2& p, const std::vector<bool>* allowed) {
  int best = -1;
  double best_d = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < g.nodes.size(); ++i) {
    if (allowed != nullptr && !(*allowed)[i]) continue;
    // stableNorm: a hint far away (1e200) must not square to infinity for
    // every node, which left no node nearest.
    const double d = (g.nodes[i] - p).stableNorm();
    if (best < 0 || d < best_d) {
      best_d = d;
      best = static_cast<int>(i);
    }
  }
  return best;
}

// Resamples the subtree made of the paths tip -> root into a Skeleton whose
// parents come before their children.
// The chordal axis zig-zags where the triangulation fans out in wide parts:
// a few Laplacian passes straighten a branch (ends fixed); a point that would
// leave the shape keeps its place.
Polyline smooth_branch(const Polyline& branch, const detail::InsideTest& outline, int passes) {
  Polyline cur = branch;
  for (int k = 0; k < passes; ++k) {
    Polyline next = cur;
    for (std::size_t i = 1; i + 1 < cur.size(); ++i) {
      const Vec2 p = 0.5 * cur[i] + 0.25 * (cur[i - 1] + cur[i + 1]);
      if (outline.contains(p)) next[i] = p;
    }
    cur = std::move(next);
  }
  return cur;
}

Skeleton resample_tree(const MedialGraph& g, int root, const std::vector<int>& parent,
                       const std::vector<int>& tip_nodes, double spacing, const Polyline& outline,
                       int smoothing) {
  const int n = static_cast<int>(g.nodes.size());
  const detail::InsideTest inside(outline);
  std::vector<bool> used(n, false);
  for (int t : tip_nodes)
    for (int v = t; v >= 0 && !used[v]; v = parent[v]) used[v] = true;
  std::vector<std::vector<int>> children(n);
  for (int v = 0; v < n; ++v)
    if (used[v] && v != root && parent[v] >= 0) children[parent[v]].push_back(v);

  Skeleton s;
  s.nodes.push_back(g.nodes[root]);
  s.parent.push_back(-1);
  // Each queue item: a graph key node and its index in the output skeleton.
  std::queue<std::pair<int, int>> queue;
  queue.push({root, 0});
  while (!queue.empty()) {
    const auto [key, out_index] = queue.front();
    queue.pop();
    for (int child : children[key]) {
      Polyline branch{g.nodes[key]};
      int v = child;
      while (true) {
        branch.push_back(g.nodes[v]);
        if (children[v].size() != 1) break;
        v = children[v][0];
      }
      const Polyline resampled =
          resample_polyline(smooth_branch(branch, inside, smoothing), spacing);
      int prev = out_index;
      for (std::size_t k = 1; k < resampled.size(); ++k) {
        s.nodes.push_back(resampled[k]);
        s.parent.push_back(prev);
        prev = static_cast<int>(s.nodes.size()) - 1;
      }
      if (children[v].empty())
        s.tips.push_back(prev);
      else
        queue.push({v, prev});
    }
  }
  return s;
}

}  // namespace

Result build_skeleton(const Input& input, const Options& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (!input.covered.empty() && input.covered.size() != input.outline.size()) {
    throw Error("skeleton::build_skeleton: covered has " + std::to_string(input.covered.size()) +
                " flags for " + std::to_string(input.outline.size()) +
                " outline points; must be empty or one per point");
  }
  if (input.root_hint &&
      (!std::isfinite(input.root_hint->x()) || !std::isfinite(input.root_hint->y()))) {
    throw Error("skeleton::build_skeleton: root_hint is not finite");
  }
  std::vector<int> kept;
  const Polyline clean = detail::clean_polygon(input.outline, "skeleton::build_skeleton", &kept);

  Result result;
  const double area = std::abs(signed_area(clean));
  if (area < 1.0) {
    Vec2 centre = Vec2::Zero();
    for (const Vec2& p : clean) centre += p;
    centre /= static_cast<double>(clean.size());
    result.skeleton.nodes = {centre};
    result.skeleton.parent = {-1};
    result.skeleton.tips = {};
    result.root = centre;
    result.status = SkeletonStatus::kDegenerate;
    return result;
  }

  std::vector<int> source;
  const Polyline samples = detail::resample_closed(clean, options.sample_spacing, &source);
  std::vector<bool> covered;
  if (!input.covered.empty()) {
    covered.resize(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) covered[i] = input.covered[kept[source[i]]];
  }
  const MedialGraph g = detail::build_medial_graph(samples);
  if (g.nodes.empty()) {
    result.skeleton.nodes = {samples.front()};
    result.skeleton.parent = {-1};
    result.root = samples.front();
    result.status = SkeletonStatus::kDegenerate;
    return result;
  }
  const int n = static_cast<int>(g.nodes.size());
  std::vector<bool> leaf(n);
  for (int i = 0; i < n; ++i) leaf[i] = g.adjacent[i].size() <= 1;

  // Tip corners -> their end-triangle nodes (the corner itself).
  const std::vector<int> corners = detail::sharp_corners(samples, covered, options);
  std::vector<int> tip_nodes;
  std::vector<Vec2> tip_points;
  for (int c : corners) {
    int node = g.apex_of_sample[c];
    if (node < 0) node = nearest_node(g, samples[c], nullptr);
    tip_nodes.push_back(node);
    tip_points.push_back(samples[c]);
  }
  const double separation =
      options.min_tip_separation > 0 ? options.min_tip_separation : 2.0 * options.corner_arm;
  // Free corners: no covered outline within a tip separation along the
  // outline (the corners' arms and as much again).
  std::vector<int> free_corner_nodes;
  for (std::size_t k = 0; k < corners.size(); ++k)
    if (!detail::near_covered(samples, covered, corners[k], separation))
      free_corner_nodes.push_back(tip_nodes[k]);

  // Root first, then tips (paper §6: tips are the sharp corners "locally
  // above" their neighbours; the root is the end by the head or under the
  // occluder). The root is the axis end nearest to the hint, sharp corners
  // included: a strand's head end is often a sharp visible corner too (a
  // bang's top where its lines meet), and when corners could not be roots
  // such a bang took its root at its bottom tip (session 8, wikipe-tan).
  // Without a hint, the end farthest along the axis from the sharpest tip.
  // Ends of spurs (a notch or bump of the outline) are not candidates:
  // wikipe-tan's right tail lock took its root at a notch half-way down and
  // its whole completed upper part was left without skeleton.
  const detail::PrunedAxis axis = detail::prune_spurs(g, tip_nodes);
  // Where the outline touches itself the axis falls apart; the root is on
  // the largest piece (a lone triangle's node near the hint took it once).
  const std::vector<int> piece = components(g);
  std::vector<int> piece_size(n, 0);
  for (int v = 0; v < n; ++v) ++piece_size[piece[v]];
  const int main_piece =
      static_cast<int>(std::max_element(piece_size.begin(), piece_size.end()) - piece_size.begin());
  std::vector<bool> candidates(n, false);
  for (int e : axis.ends) candidates[e] = piece[e] == main_piece;
  if (std::find(candidates.begin(), candidates.end(), true) == candidates.end()) candidates = leaf;
  std::vector<double> dist;
  std::vector<int> parent;
  int root = -1;
  if (input.root_hint) {
    root = detail::choose_root(g, candidates, leaf, free_corner_nodes, *input.root_hint);
    if (root < 0) root = nearest_node(g, *input.root_hint, nullptr);
  } else {
    std::vector<bool> not_tip = candidates;
    for (int t : free_corner_nodes) not_tip[t] = false;
    if (std::find(not_tip.begin(), not_tip.end(), true) == not_tip.end()) {
      not_tip = leaf;
      for (int t : free_corner_nodes) not_tip[t] = false;
    }
    if (std::find(not_tip.begin(), not_tip.end(), true) != not_tip.end()) candidates = not_tip;
    const int from = tip_nodes.empty() ? 0 : tip_nodes.front();
    shortest_paths(g, from, &dist, &parent);
    double best = -1.0;
    for (int i = 0; i < n; ++i) {
      if (std::isfinite(dist[i]) && dist[i] > best && candidates[i]) {
        best = dist[i];
        root = i;
      }
    }
    if (root < 0) root = from;
  }
  result.root = g.nodes[root];
  shortest_paths(g, root, &dist, &parent);

  // Tips among the remaining ends: reachable, and not at the root end.
  std::vector<int> tips;
  for (std::size_t k = 0; k < tip_nodes.size(); ++k) {
    const int t = tip_nodes[k];
    if (!std::isfinite(dist[t]) || dist[t] < separation) continue;
    if (std::find(tips.begin(), tips.end(), t) != tips.end()) continue;
    tips.push_back(t);
    result.tip_corners.push_back(tip_points[k]);
  }
  for (int t : tips) candidates[t] = false;

  // Rounded tips: a visible axis end that tapers but has no sharp corner
  // (a completed tip drawn blunt, a brush stroke's round end). §6 asks for
  // sharp corners; a rounded end would otherwise get no skeleton at all.
  std::vector<bool> visible_end(n, false);
  for (std::size_t i = 0; i < samples.size(); ++i) {
    const int node = g.apex_of_sample[i];
    if (node >= 0) visible_end[node] = covered.empty() || !covered[i];
  }
  visible_end[root] = false;
  const std::vector<int> rounded =
      options.find_rounded_tips
          ? detail::rounded_tips(g, axis, dist, parent, visible_end, separation, options.corner_arm)
          : std::vector<int>{};
  for (int end : rounded) {
    if (static_cast<int>(tips.size()) >= options.max_tips) break;
    bool near_tip = false;
    for (int t : tips) near_tip = near_tip || (g.nodes[t] - g.nodes[end]).norm() < separation;
    if (near_tip) continue;
    // The pruning kept one ear of the rounded end, maybe at its side: the
    // tip is the visible axis end next to it that reaches farthest.
    int front = end;
    for (int v = 0; v < n; ++v)
      if (leaf[v] && visible_end[v] && std::isfinite(dist[v]) && dist[v] > dist[front] &&
          (g.nodes[v] - g.nodes[end]).norm() <= options.corner_arm)
        front = v;
    tips.push_back(front);
    result.tip_corners.push_back(g.nodes[front]);
    ++result.rounded_tips;
  }
  result.status = SkeletonStatus::kTips;
  if (tips.empty()) {
    int far = -1;
    for (int i = 0; i < n; ++i)
      if (candidates[i] && std::isfinite(dist[i]) && (far < 0 || dist[i] > dist[far])) far = i;
    if (far < 0) {
      far = root;
      for (int i = 0; i < n; ++i)
        if (std::isfinite(dist[i]) && dist[i] > dist[far]) far = i;
    }
    tips.push_back(far);
    result.status = SkeletonStatus::kFarthestTip;
  }
  result.skeleton =
      resample_tree(g, root, parent, tips, options.node_spacing, samples, options.smoothing_passes);
  return result;
}

}  // namespace hair25d::skeleton
