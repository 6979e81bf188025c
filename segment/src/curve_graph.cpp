#include "curve_graph.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <utility>

#include "hair25d/core/geometry.h"

namespace hair25d::segment::detail {
namespace {

struct Edge {
  int a = -1, b = -1;  // node ids; -1 for both on a closed curve
  Polyline points;
  bool alive = true;
  bool closed = false;
};

struct Graph {
  std::vector<Vec2> nodes;
  std::vector<std::vector<int>> incident;  // per node: edge ids, a loop twice
  std::vector<Edge> edges;

  int add_node(const Vec2& p) {
    nodes.push_back(p);
    incident.emplace_back();
    return static_cast<int>(nodes.size()) - 1;
  }
  int add_edge(int a, int b, Polyline pts) {
    const int id = static_cast<int>(edges.size());
    edges.push_back({a, b, std::move(pts), true, false});
    incident[a].push_back(id);
    incident[b].push_back(id);
    return id;
  }
  int degree(int n) const { return static_cast<int>(incident[n].size()); }
  void detach(int e, int n) {
    auto& inc = incident[n];
    auto it = std::find(inc.begin(), inc.end(), e);
    if (it != inc.end()) inc.erase(it);
  }
  void remove_edge(int e) {
    Edge& ed = edges[e];
    ed.alive = false;
    if (ed.closed) return;
    detach(e, ed.a);
    detach(e, ed.b);
  }

  // Joins the two edges through a node of degree 2 into one.
  bool merge_at(int n) {
    if (degree(n) != 2) return false;
    const int e1 = incident[n][0], e2 = incident[n][1];
    if (e1 == e2) {
      Edge& e = edges[e1];
      incident[n].clear();
      e.closed = true;
      e.a = e.b = -1;
      if (e.points.size() > 1 && (e.points.front() - e.points.back()).norm() < 1e-9)
        e.points.pop_back();
      return true;
    }
    Edge first = edges[e1], second = edges[e2];
    if (first.b != n) {
      std::reverse(first.points.begin(), first.points.end());
      std::swap(first.a, first.b);
    }
    if (second.a != n) {
      std::reverse(second.points.begin(), second.points.end());
      std::swap(second.a, second.b);
    }
    Polyline pts = first.points;
    pts.insert(pts.end(), second.points.begin() + 1, second.points.end());
    remove_edge(e1);
    remove_edge(e2);
    add_edge(first.a, second.b, std::move(pts));
    return true;
  }
};

struct FreeEnd {
  int curve = 0;
  int end = 0;
  Vec2 pos;
  Vec2 dir;  // pointing out of the curve
};

Vec2 end_direction(const Polyline& pts, int end) {
  const int n = static_cast<int>(pts.size());
  const int k = std::min(5, n - 1);
  const Vec2 tip = end == 0 ? pts[0] : pts[n - 1];
  const Vec2 back = end == 0 ? pts[k] : pts[n - 1 - k];
  const Vec2 d = tip - back;
  return d.norm() > 1e-9 ? Vec2(d.normalized()) : Vec2(1.0, 0.0);
}

int nearest_point(const Polyline& pts, const Vec2& p) {
  int best = 0;
  double bd = 1e300;
  for (int i = 0; i < static_cast<int>(pts.size()); ++i) {
    const double d = (pts[i] - p).squaredNorm();
    if (d < bd) bd = d, best = i;
  }
  return best;
}

}  // namespace

std::vector<Curve> link_curves(const TraceResult& traced, int width, int height,
                               const GraphOptions& options) {
  const auto& curves = traced.curves;
  const int nc = static_cast<int>(curves.size());
  const double gap = options.gap_length;

  // Where each attached end meets its target: (target curve, point index).
  std::vector<std::array<std::pair<int, int>, 2>> attach(nc, {std::pair{-1, -1}, {-1, -1}});
  auto target_of = [&](int pixel) {
    const int c = traced.owner[pixel];
    int i = traced.owner_point[pixel];
    if (i < 0 || i >= static_cast<int>(curves[c].points.size()))
      i = nearest_point(curves[c].points, Vec2(pixel % width + 0.5, pixel / width + 0.5));
    return std::pair{c, i};
  };
  for (const Attachment& a : traced.attachments) attach[a.curve][a.end] = target_of(a.target);

  // Free ends: first join pairs of ends that nearly touch (broken corners),
  // then send the rest along their direction into a line they point at.
  std::vector<FreeEnd> free_ends;
  for (int c = 0; c < nc; ++c) {
    if (curves[c].closed || curves[c].points.size() < 2) continue;
    for (int e = 0; e < 2; ++e) {
      if (attach[c][e].first >= 0) continue;
      const Polyline& pts = curves[c].points;
      free_ends.push_back({c, e, e == 0 ? pts.front() : pts.back(), end_direction(pts, e)});
    }
  }
  struct Pair {
    double d;
    int i, j;
  };
  std::vector<Pair> pairs;
  for (std::size_t i = 0; i < free_ends.size(); ++i) {
    for (std::size_t j = i + 1; j < free_ends.size(); ++j) {
      const FreeEnd &p = free_ends[i], &q = free_ends[j];
      if (p.curve == q.curve && polyline_length(curves[p.curve].points) < 3.0 * gap) continue;
      const Vec2 v = q.pos - p.pos;
      const double d = v.norm();
      if (d > gap) continue;
      if (d > 1e-9 && (p.dir.dot(v / d) < -0.3 || q.dir.dot(-v / d) < -0.3)) continue;
      pairs.push_back({d, static_cast<int>(i), static_cast<int>(j)});
    }
  }
  std::sort(pairs.begin(), pairs.end(), [](const Pair& a, const Pair& b) { return a.d < b.d; });
  std::vector<char> used(free_ends.size(), 0);
  std::vector<std::pair<int, int>> end_links;  // pairs of free_ends indices
  for (const Pair& p : pairs) {
    if (used[p.i] || used[p.j]) continue;
    used[p.i] = used[p.j] = 1;
    end_links.emplace_back(p.i, p.j);
  }
  // Ends that run out of the image within the gap are extended to the border.
  std::vector<std::array<std::optional<Vec2>, 2>> border_point(nc);
  for (std::size_t k = 0; k < free_ends.size(); ++k) {
    if (used[k]) continue;
    const FreeEnd& f = free_ends[k];
    const Polyline& pts = curves[f.curve].points;
    const int end_index = f.end == 0 ? 0 : static_cast<int>(pts.size()) - 1;
    for (double t = 1.0; t <= gap; t += 0.5) {
      const Vec2 p = f.pos + t * f.dir;
      if (p.x() < 0 || p.y() < 0 || p.x() >= width || p.y() >= height) {
        if (t > options.border_gap_length + 1.0) break;
        border_point[f.curve][f.end] =
            Vec2(std::clamp(p.x(), 0.0, double(width)), std::clamp(p.y(), 0.0, double(height)));
        break;
      }
      const int px = static_cast<int>(p.x()), py = static_cast<int>(p.y());
      bool found = false;
      constexpr int kOff[5][2] = {{0, 0}, {1, 0}, {-1, 0}, {0, 1}, {0, -1}};
      for (const auto& o : kOff) {
        const int qx = px + o[0], qy = py + o[1];
        if (qx < 0 || qy < 0 || qx >= width || qy >= height) continue;
        const int q = qy * width + qx;
        const int owner = traced.owner[q];
        if (owner < 0) continue;
        const auto target = target_of(q);
        if (owner == f.curve && std::abs(target.second - end_index) < 3.0 * gap + 4) continue;
        attach[f.curve][f.end] = target;
        found = true;
        break;
      }
      if (found) break;
    }
  }

  // Nodes at curve ends and at every point another curve runs into.
  Graph g;
  std::vector<std::map<int, int>> split(nc);  // per curve: point index -> node
  auto node_at = [&](int c, int i) {
    auto it = split[c].find(i);
    if (it != split[c].end()) return it->second;
    const int n = g.add_node(curves[c].points[i]);
    split[c][i] = n;
    return n;
  };
  for (int c = 0; c < nc; ++c) {
    if (curves[c].points.size() < 2) continue;
    if (!curves[c].closed) {
      node_at(c, 0);
      node_at(c, static_cast<int>(curves[c].points.size()) - 1);
    }
    for (int e = 0; e < 2; ++e) {
      const auto [tc, ti] = attach[c][e];
      if (tc >= 0 && curves[tc].points.size() >= 2) node_at(tc, ti);
    }
  }
  for (int c = 0; c < nc; ++c) {
    const Polyline& pts = curves[c].points;
    if (pts.size() < 2) continue;
    std::vector<int> idx;
    for (const auto& [i, n] : split[c]) idx.push_back(i);
    auto piece = [&](int from, int to) {  // inclusive, may wrap on closed curves
      Polyline out;
      for (int i = from;; i = (i + 1) % static_cast<int>(pts.size())) {
        out.push_back(pts[i]);
        if (i == to) break;
      }
      return out;
    };
    if (curves[c].closed) {
      if (idx.empty()) {
        Edge e;
        e.points = pts;
        e.closed = true;
        g.edges.push_back(std::move(e));
        continue;
      }
      for (std::size_t k = 0; k < idx.size(); ++k) {
        const int from = idx[k], to = idx[(k + 1) % idx.size()];
        Polyline p = piece(from, to);
        if (idx.size() == 1) p.push_back(pts[from]);  // the whole loop back to its node
        g.add_edge(split[c][from], split[c][to], std::move(p));
      }
    } else {
      for (std::size_t k = 0; k + 1 < idx.size(); ++k)
        g.add_edge(split[c][idx[k]], split[c][idx[k + 1]], piece(idx[k], idx[k + 1]));
    }
  }
  // The short straight links that close the gaps.
  for (int c = 0; c < nc; ++c) {
    const Polyline& pts = curves[c].points;
    if (curves[c].closed || pts.size() < 2) continue;
    for (int e = 0; e < 2; ++e) {
      const int end_index = e == 0 ? 0 : static_cast<int>(pts.size()) - 1;
      const int from = split[c][end_index];
      if (const auto [tc, ti] = attach[c][e]; tc >= 0 && curves[tc].points.size() >= 2) {
        const int to = split[tc][ti];
        if (to != from) g.add_edge(from, to, {pts[end_index], curves[tc].points[ti]});
      } else if (border_point[c][e]) {
        const int to = g.add_node(*border_point[c][e]);
        g.add_edge(from, to, {pts[end_index], *border_point[c][e]});
      }
    }
  }
  for (const auto& [i, j] : end_links) {
    const FreeEnd &p = free_ends[i], &q = free_ends[j];
    const int np = split[p.curve][p.end == 0 ? 0 : int(curves[p.curve].points.size()) - 1];
    const int nq = split[q.curve][q.end == 0 ? 0 : int(curves[q.curve].points.size()) - 1];
    if (np != nq) g.add_edge(np, nq, {p.pos, q.pos});
  }

  // Merge chains, then prune stray bits and spurs, until nothing changes.
  auto merge_all = [&] {
    for (int n = 0; n < static_cast<int>(g.nodes.size()); ++n) g.merge_at(n);
  };
  merge_all();
  for (int round = 0; round < 4; ++round) {
    bool changed = false;
    for (int e = 0; e < static_cast<int>(g.edges.size()); ++e) {
      Edge& ed = g.edges[e];
      if (!ed.alive) continue;
      const double len = polyline_length(ed.points);
      if (ed.closed) {
        if (len < options.min_curve_length) g.remove_edge(e), changed = true;
        continue;
      }
      const int da = g.degree(ed.a), db = g.degree(ed.b);
      const bool isolated = da == 1 && db == 1;
      const bool spur = (da == 1) != (db == 1) && std::max(da, db) >= 3;
      if ((isolated && len < options.min_curve_length) || (spur && len < options.spur_length)) {
        g.remove_edge(e);
        changed = true;
      }
    }
    merge_all();
    if (!changed) break;
  }

  std::vector<Curve> out;
  for (const Edge& e : g.edges) {
    if (!e.alive || e.points.size() < 2) continue;
    Curve c;
    c.points = e.points;
    if (e.closed) {
      if (c.points.size() < 3) continue;
      c.closed = true;
      c.ends = {CurveEnd::kFree, CurveEnd::kFree};
    } else {
      auto kind = [&](int n) {
        return g.degree(n) >= 3 ? CurveEnd::kJunction : CurveEnd::kEndpoint;
      };
      c.ends = {kind(e.a), kind(e.b)};
    }
    out.push_back(std::move(c));
  }
  return out;
}

}  // namespace hair25d::segment::detail
