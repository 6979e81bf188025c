#include "angle_retry.h"

#include <algorithm>
#include <cmath>
#include <vector>

#include "raster.h"

namespace hair25d::completion::detail {
namespace {

using Kind = TriedTangents::Kind;

// Every reading of one edge's tangents. Duplicates (one end's for both when
// both ends agree) cost only a few angles.
std::vector<TriedTangents> readings(const Edge& e, bool turn_round) {
  std::vector<TriedTangents> out;
  out.push_back({e.tangent_p, e.tangent_q, Kind::kOwn});
  out.push_back({e.tangent_p, e.tangent_p, Kind::kEitherEnd});
  out.push_back({e.tangent_q, e.tangent_q, Kind::kEitherEnd});
  if (turn_round) out.push_back({-e.tangent_p, -e.tangent_q, Kind::kReversed});
  if (e.side_tangent.norm() > 0) out.push_back({e.side_tangent, e.side_tangent, Kind::kSide});
  if (turn_round && e.turned_tangent.norm() > 0)
    out.push_back({e.turned_tangent, e.turned_tangent, Kind::kTurned});
  return out;
}

double polyline_length(const Polyline& line) {
  double n = 0;
  for (std::size_t i = 1; i < line.size(); ++i) n += (line[i] - line[i - 1]).norm();
  return n;
}

}  // namespace

RetriedTangents retry_tangents(const Edge& a, const Edge& b, const Vec2& c1, const Vec2& c2,
                               double max_angle, bool turn_round) {
  RetriedTangents best;
  best.worst = max_angle;
  for (const TriedTangents& ta : readings(a, turn_round))
    for (const TriedTangents& tb : readings(b, turn_round)) {
      if (ta.kind == Kind::kOwn && tb.kind == Kind::kOwn) continue;
      const double tried[4] = {angle(ta.p, c1), angle(-tb.q, c1), angle(tb.p, c2),
                               angle(-ta.q, c2)};
      const double w = *std::max_element(tried, tried + 4);
      // Strictly better than the best so far (the first reading wins a tie:
      // one end's tangent before a reversed or side one).
      if (w > best.worst || (best.found && w >= best.worst)) continue;
      best.found = true;
      best.a = ta, best.b = tb;
      best.worst = w;
      std::copy(tried, tried + 4, best.angles);
    }
  return best;
}

void add_retry_terms(const Edge& a, const Edge& b, const RetriedTangents& r, double own_worst,
                     double fit_length, JoinTerms* t) {
  t->retried = true;
  t->own_worst_angle = own_worst;
  const double arms[4] = {a.arm_p, a.arm_q, b.arm_p, b.arm_q};
  const double fit = std::max(fit_length, 1.0);
  t->arm_min = *std::min_element(arms, arms + 4) / fit;
  t->arm_mean = (arms[0] + arms[1] + arms[2] + arms[3]) / 4 / fit;
  t->ends_part = std::max(a.ends_part, b.ends_part) / M_PI;
  for (const TriedTangents* x : {&r.a, &r.b}) {
    t->retried_either_end = t->retried_either_end || x->kind == Kind::kEitherEnd;
    t->retried_reversed = t->retried_reversed || x->kind == Kind::kReversed;
    t->retried_side = t->retried_side || x->kind == Kind::kSide;
    t->retried_turned = t->retried_turned || x->kind == Kind::kTurned;
  }
  // A sliver's occluded run is its long side: far longer than its chord.
  auto run = [](const Edge& e) {
    return std::log(std::max(polyline_length(e.points), 1.0) / std::max(e.width, 1.0));
  };
  t->sliver = std::max(run(a), run(b));
}

}  // namespace hair25d::completion::detail
