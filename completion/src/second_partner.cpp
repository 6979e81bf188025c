#include "second_partner.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "hair25d/core/error.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Faced parts nearer than this (px) overlap: the two partners face the
// same stretch of the cut (one above the other, or one of them wrong).
constexpr double kOverlapPx = 2.0;

// Distance between the chords p q of two edges (0 when they cross is not
// told apart from touching: either way the pieces lie side by side).
double chord_gap(const Edge& u, const Edge& v) {
  return std::min({segment_distance(u.p, v.p, v.q), segment_distance(u.q, v.p, v.q),
                   segment_distance(v.p, u.p, u.q), segment_distance(v.q, u.p, u.q)});
}

float clamped(double v, double lo, double hi) {
  return static_cast<float>(std::isfinite(v) ? std::clamp(v, lo, hi) : hi);
}

}  // namespace

int taken_edge(const Join& j, const std::vector<Edge>& edges, const std::set<int>& used) {
  int taken = -1;
  for (int e : {j.edge_a, j.edge_b})
    for (int atom : edges[e].atoms) {
      if (!used.count(atom)) continue;
      if (taken >= 0 && taken != e) return -1;
      taken = e;
    }
  return taken;
}

Polyline faced_part(const Edge& cut, const Edge& other) {
  if (cut.points.empty()) return {};
  auto nearest = [&](const Vec2& x) {
    std::size_t at = 0;
    for (std::size_t i = 1; i < cut.points.size(); ++i)
      if ((cut.points[i] - x).squaredNorm() < (cut.points[at] - x).squaredNorm()) at = i;
    return at;
  };
  const std::size_t u = nearest(other.p), v = nearest(other.q);
  return Polyline(cut.points.begin() + std::min(u, v), cut.points.begin() + std::max(u, v) + 1);
}

void add_second_terms(const std::vector<Edge>& edges, const Join& j, int taken,
                      const std::vector<FirstPartner>& firsts, JoinFeatures* f) {
  if (firsts.empty()) throw Error("add_second_terms: no first partner");
  const Edge& cut = edges[taken];
  const Edge& mine = edges[taken == j.edge_a ? j.edge_b : j.edge_a];
  const double width = std::max(cut.width, 1.0);
  const Polyline faced = faced_part(cut, mine);
  // The first partner nearest along the cut is the one this one lies
  // beside (or on top of).
  double best_gap = std::numeric_limits<double>::infinity(), best_overlap = 0.0;
  const FirstPartner* first = &firsts.front();
  for (const FirstPartner& fp : firsts) {
    const Polyline theirs = faced_part(edges[fp.own], edges[fp.other]);
    double gap = std::numeric_limits<double>::infinity();
    int near = 0;
    for (const Vec2& y : faced) {
      double d = std::numeric_limits<double>::infinity();
      for (const Vec2& x : theirs) d = std::min(d, (x - y).norm());
      gap = std::min(gap, d);
      near += d <= kOverlapPx;
    }
    const double overlap = faced.empty() ? 0.0 : static_cast<double>(near) / faced.size();
    if (overlap > best_overlap || (overlap == best_overlap && gap < best_gap))
      best_gap = gap, best_overlap = overlap, first = &fp;
  }
  const Edge& partner = edges[first->other];
  const double mine_w = std::max(mine.width, 1.0), partner_w = std::max(partner.width, 1.0);
  const Vec2 to_mine = 0.5 * (mine.p + mine.q) - 0.5 * (cut.p + cut.q);
  const Vec2 to_partner = 0.5 * (partner.p + partner.q) - 0.5 * (cut.p + cut.q);
  const double lengths = to_mine.norm() * to_partner.norm();
  JoinFeatures& x = *f;
  x[kSecondCut] = 1.0f;
  x[kSecondCut + 1] = static_cast<float>(j.probability);
  x[kSecondCut + 2] = static_cast<float>(first->probability);
  x[kSecondCut + 3] = clamped(j.cost - first->cost, -4.0, 4.0);
  x[kSecondCut + 4] = clamped(best_gap / width, 0.0, 3.0);
  x[kSecondCut + 5] = static_cast<float>(best_overlap);
  x[kSecondCut + 6] = clamped(cut.width / (mine_w + partner_w), 0.0, 4.0);
  x[kSecondCut + 7] = clamped(std::abs(std::log(mine_w / partner_w)), 0.0, 3.0);
  x[kSecondCut + 8] = clamped(chord_gap(mine, partner) / width, 0.0, 3.0);
  x[kSecondCut + 9] = lengths > 0 ? static_cast<float>(to_mine.dot(to_partner) / lengths) : 1.0f;
  x[kSecondCut + 10] = static_cast<float>(std::min<std::size_t>(firsts.size(), 3));
}

}  // namespace hair25d::completion::detail
