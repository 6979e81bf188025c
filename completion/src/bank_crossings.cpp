#include "bank_crossings.h"

#include <algorithm>
#include <set>

namespace hair25d::completion::detail {
namespace {

// Farthest a piece is followed inwards behind an edge, pixels.
constexpr double kMaxDepth = 200.0;
// A ray lands next to an edge when it ends within this many pixels of it.
constexpr double kLandingReach = 3.0;
// Minimum depth behind both edges, in widths crossed.
constexpr double kMinDepthRatio = 1.5;

std::vector<BankRay> landing_next_to(const std::vector<BankRay>& hits, const Edge& target) {
  std::vector<BankRay> kept;
  for (const BankRay& h : hits) {
    double best = 1e18;
    for (const Vec2& p : target.points) best = std::min(best, (p - std::get<2>(h)).squaredNorm());
    if (best <= kLandingReach * kLandingReach) kept.push_back(h);
  }
  return kept;
}

// Runs of consecutive rays as closed polygons: starts, then ends back.
std::vector<Polyline> ray_bands(const std::vector<BankRay>& rays) {
  std::vector<Polyline> out;
  std::size_t k = 0;
  while (k < rays.size()) {
    std::size_t end = k + 1;
    while (end < rays.size() && std::get<0>(rays[end]) - std::get<0>(rays[end - 1]) <= 4) ++end;
    if (end - k >= 2) {
      Polyline band;
      for (std::size_t r = k; r < end; ++r) band.push_back(std::get<1>(rays[r]));
      for (std::size_t r = end; r-- > k;) band.push_back(std::get<2>(rays[r]));
      out.push_back(std::move(band));
    }
    k = end;
  }
  return out;
}

}  // namespace

BankCrossings cross_occluders(const Context& ctx, const Edge& edge) {
  BankCrossings out;
  const Polyline& pts = edge.points;
  const int n = static_cast<int>(pts.size());
  // The far bank lies within a fraction of the edge's length only when the
  // piece is wide compared with the occluder over it.
  const double reach = std::max(6.0, 0.6 * n);
  for (int i = 0; i < n; i += 2) {
    const Vec2 t = pts[std::min(i + 3, n - 1)] - pts[std::max(i - 3, 0)];
    if (t.norm() < 1.0) continue;
    Vec2 normal(-t.y(), t.x());
    normal.normalize();
    if (ctx.label(pts[i] + 2.0 * normal) == edge.region) normal = -normal;
    ++out.rays;
    double inside = 0.0;
    while (inside < kMaxDepth && ctx.label(pts[i] - (inside + 1.0) * normal) == edge.region)
      inside += 1.0;
    out.depth += inside;
    std::set<int> crossed;
    for (double s = 1.0; s <= reach; s += 0.7) {
      const Vec2 x = pts[i] + s * normal;
      const int l = ctx.label(x);
      if (l == edge.region && s < 3.0) continue;  // the outline pixels next to the start
      if (l == 0 || l == edge.region) break;
      if (ctx.is_above(l, edge.region)) {
        crossed.insert(l);
        continue;
      }
      bool under = !crossed.empty();
      for (int c : crossed) under = under && ctx.is_above(c, l);
      if (under) out.hits[l].emplace_back(i, pts[i], x);
      break;
    }
  }
  if (out.rays > 0) out.depth /= out.rays;
  return out;
}

BankJoin bank_join(const BankCrossings& ca, const BankCrossings& cb, const Edge& a, const Edge& b) {
  BankJoin join;
  auto ia = ca.hits.find(b.region);
  auto ib = cb.hits.find(a.region);
  if (ia == ca.hits.end() || ib == cb.hits.end() || ca.rays == 0 || cb.rays == 0) return join;
  const std::vector<BankRay> from_a = landing_next_to(ia->second, b);
  const std::vector<BankRay> from_b = landing_next_to(ib->second, a);
  if (from_a.empty() || from_b.empty()) return join;
  double across = 0.0;
  for (const BankRay& r : from_a) across += (std::get<2>(r) - std::get<1>(r)).norm();
  across /= static_cast<double>(from_a.size());
  if (std::min(ca.depth, cb.depth) < kMinDepthRatio * across) return join;
  join.share = std::min(static_cast<double>(from_a.size()) / ca.rays,
                        static_cast<double>(from_b.size()) / cb.rays);
  join.bands = ray_bands(from_a);
  return join;
}

}  // namespace hair25d::completion::detail
