#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "context.h"
#include "hair25d/completion/active_contour.h"
#include "hair25d/completion/bezier.h"
#include "hair25d/completion/hamiltonian.h"

namespace hair25d::completion::detail {
namespace {

double side(const Vec2& a, const Vec2& b, const Vec2& p) {
  return (b - a).x() * (p - a).y() - (b - a).y() * (p - a).x();
}

// C₀: the convex hull of the occluding boundary from p to q, on the side away
// from the region (§5.2 "the convex hull of the occluding boundary of R").
Polyline initial_curve(const Edge& e, const Vec2& region_centroid) {
  std::vector<cv::Point2f> pts;
  for (const Vec2& p : e.points)
    pts.emplace_back(static_cast<float>(p.x()), static_cast<float>(p.y()));
  std::vector<int> hull;
  cv::convexHull(pts, hull, false, false);
  const int h = static_cast<int>(hull.size());
  if (h < 3) return {e.p, e.q};
  // The hull vertices nearest p and q, then the chain between them that lies
  // on the far side of the chord from the region.
  auto nearest = [&](const Vec2& x) {
    int best = 0;
    double d = 1e300;
    for (int k = 0; k < h; ++k) {
      const double dd = (Vec2(pts[hull[k]].x, pts[hull[k]].y) - x).squaredNorm();
      if (dd < d) d = dd, best = k;
    }
    return best;
  };
  const int ip = nearest(e.p), iq = nearest(e.q);
  if (ip == iq) return {e.p, e.q};
  const double inner = side(e.p, e.q, region_centroid);
  Polyline best;
  double best_score = -1e300;
  for (int dir : {+1, -1}) {
    Polyline chain{e.p};
    double score = 0;
    for (int k = ip;; k = (k + dir + h) % h) {
      const Vec2 v(pts[hull[k]].x, pts[hull[k]].y);
      if (k != ip && k != iq) {
        chain.push_back(v);
        score += -side(e.p, e.q, v) * (inner >= 0 ? 1 : -1);
      }
      if (k == iq) break;
    }
    chain.push_back(e.q);
    if (chain.size() > 2) score /= static_cast<double>(chain.size() - 2);
    if (score > best_score) best_score = score, best = std::move(chain);
  }
  return best;
}

// §5.3: replace the round end by two cubics meeting at the farthest point with
// tangents along the growth direction, a sharp tip.
Polyline sharpen(const Polyline& curve, const Edge& e) {
  const Vec2 mid = 0.5 * (e.p + e.q);
  int far = 0;
  double d = -1;
  for (int i = 0; i < static_cast<int>(curve.size()); ++i) {
    const double dd = (curve[i] - mid).norm();
    if (dd > d) d = dd, far = i;
  }
  if (far == 0 || far == static_cast<int>(curve.size()) - 1 || d < 2.0) return curve;
  const Vec2 f = curve[far];
  const Vec2 axis = (f - mid).normalized();
  const CubicBezier a = join_bezier(e.p, e.tangent_p, f, axis, 1.2);
  const CubicBezier b = join_bezier(f, -axis, e.q, -e.tangent_q, 1.2);
  Polyline out = a.sample(std::max(4, static_cast<int>((f - e.p).norm() / 2)));
  const Polyline second = b.sample(std::max(4, static_cast<int>((e.q - f).norm() / 2)));
  out.insert(out.end(), second.begin() + 1, second.end());
  return out;
}

}  // namespace

Growth grow_edge(const Context& ctx, const Edge& e) {
  Growth g;
  if (e.width < 2.0) return g;
  const RegionInfo& region = ctx.regions.at(e.region);
  // An end without visible outline beside it (its side runs on under another
  // occluder: the back hair's long edge under the cap and the bangs) was left
  // uncompleted; it continues straight along its tangent instead.
  const auto piece_or_line = [](const Polyline& piece, const Vec2& end, const Vec2& tangent) {
    if (piece.size() >= 3) return piece;
    Polyline line;
    for (int k = 8; k >= 0; --k) line.push_back(end - static_cast<double>(k) * tangent);
    return line;
  };
  ContourFields fields;
  fields.at_p =
      fit_hamiltonian(piece_or_line(e.piece_p, e.p, e.tangent_p), ctx.options->fit_regularization);
  fields.at_q =
      fit_hamiltonian(piece_or_line(e.piece_q, e.q, e.tangent_q), ctx.options->fit_regularization);
  // Υ > 0 on the strand's side of each extended outline: the side the other
  // end lies on.
  const double dp = fields.at_p.value(e.p) - fields.at_p.value(e.q);
  const double dq = fields.at_q.value(e.q) - fields.at_q.value(e.p);
  fields.sign_p = dp >= 0 ? 1.0 : -1.0;
  fields.sign_q = dq >= 0 ? 1.0 : -1.0;

  // Case 2 or 3 (§5.4): an edge nearer the head than the visible region is the root.
  double edge_d = 0, visible_d = 0;
  for (const Vec2& p : e.points) edge_d += (p - ctx.head).norm();
  edge_d /= static_cast<double>(e.points.size());
  int visible = 0;
  for (std::size_t i = 0; i < region.contour.size(); i += 2) {
    visible_d += (Vec2(region.contour[i].x + 0.5, region.contour[i].y + 0.5) - ctx.head).norm();
    ++visible;
  }
  visible_d /= std::max(1, visible);
  g.tip = edge_d > visible_d;

  const auto allowed = [&](const Vec2& x) {
    const int l = ctx.label(x);
    return l != 0 && (l == e.region || ctx.is_above(l, e.region));
  };
  const ContourResult grown = grow_contour(initial_curve(e, region.centroid), e.tangent_p,
                                           e.tangent_q, fields, allowed, ctx.options->contour);
  g.stop = grown.stop;
  Polyline curve = grown.curve;
  if (g.tip && ctx.options->sharp_tips) curve = sharpen(curve, e);
  g.area = e.points;
  for (auto it = curve.rbegin() + 1; it + 1 != curve.rend(); ++it) g.area.push_back(*it);
  return g;
}

}  // namespace hair25d::completion::detail
