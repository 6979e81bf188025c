#include "join_shapes.h"

#include <algorithm>
#include <cmath>
#include <opencv2/core.hpp>
#include <utility>

#include "hair25d/completion/bezier.h"
#include "raster.h"

namespace hair25d::completion::detail {

Polyline join_patch(const Edge& a, const Edge& b, double share_a, double share_b) {
  const CubicBezier first = join_bezier_arms(a.p, a.tangent_p, b.q, -b.tangent_q, share_a, share_b);
  const CubicBezier second =
      join_bezier_arms(b.p, b.tangent_p, a.q, -a.tangent_q, share_b, share_a);
  const int s1 = std::max(4, static_cast<int>((a.p - b.q).norm() / 2));
  const int s2 = std::max(4, static_cast<int>((b.p - a.q).norm() / 2));
  Polyline patch = first.sample(s1);
  for (auto it = b.points.rbegin() + 1; it != b.points.rend(); ++it) patch.push_back(*it);
  const Polyline second_points = second.sample(s2);
  patch.insert(patch.end(), second_points.begin() + 1, second_points.end());
  for (auto it = a.points.rbegin() + 1; it != a.points.rend(); ++it) patch.push_back(*it);
  return patch;
}

JoinShape best_join_shape(const Context& ctx, const Edge& a, const Edge& b, const cv::Mat& face,
                          bool ink, const std::vector<double>& shares) {
  JoinShape best;
  std::vector<std::pair<std::pair<double, double>, Polyline>> patches;
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (double sa : shares)
    for (double sb : shares) {
      patches.push_back({{sa, sb}, join_patch(a, b, sa, sb)});
      for (const Vec2& p : patches.back().second) {
        x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
        x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
      }
    }
  if (patches.empty()) return best;
  const cv::Point origin(static_cast<int>(std::floor(x0)) - 1,
                         static_cast<int>(std::floor(y0)) - 1);
  const int w = static_cast<int>(std::ceil(x1)) - origin.x + 2;
  const int h = static_cast<int>(std::ceil(y1)) - origin.y + 2;
  if (w <= 0 || h <= 0 || static_cast<double>(w) * h > 4e6) return best;
  // counted: a pixel outside both pieces; under: one of those under cover.
  // What the relations say of a label is asked once (a box holds few).
  // Only pixels some patch covers are asked: the box of long slanted
  // patches is mostly outside them (session 36: the cover refusals' inputs
  // ask this for every such candidate).
  cv::Mat any(h, w, CV_8U, cv::Scalar(0));
  for (const auto& shape : patches) fill_polygon(any, shape.second, origin, 255);
  cv::Mat counted(h, w, CV_8U, cv::Scalar(0)), under(h, w, CV_8U, cv::Scalar(0));
  AboveEither above(ctx, a.region, b.region);
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* in = any.ptr<std::uint8_t>(y);
    std::uint8_t* c = counted.ptr<std::uint8_t>(y);
    std::uint8_t* u = under.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      if (!in[x]) continue;
      const int gx = x + origin.x, gy = y + origin.y;
      if (!ctx.labels.contains(gx, gy)) {
        c[x] = 255;
        continue;
      }
      const int l = ctx.labels.at(gx, gy);
      if (l == a.region || l == b.region) continue;
      c[x] = 255;
      if (above.hides(l, gx, gy, face, ink)) u[x] = 255;
    }
  }
  // Each patch is counted within its own box (a pixel's margin for the
  // fill's rounding), not the union's.
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  for (const auto& [arms, patch] : patches) {
    double px0 = 1e18, py0 = 1e18, px1 = -1e18, py1 = -1e18;
    for (const Vec2& p : patch) {
      px0 = std::min(px0, p.x()), py0 = std::min(py0, p.y());
      px1 = std::max(px1, p.x()), py1 = std::max(py1, p.y());
    }
    const int bx0 = std::max(0, static_cast<int>(std::floor(px0)) - origin.x - 1);
    const int by0 = std::max(0, static_cast<int>(std::floor(py0)) - origin.y - 1);
    const int bx1 = std::min(w - 1, static_cast<int>(std::ceil(px1)) - origin.x + 1);
    const int by1 = std::min(h - 1, static_cast<int>(std::ceil(py1)) - origin.y + 1);
    const cv::Rect box(bx0, by0, bx1 - bx0 + 1, by1 - by0 + 1);
    fill_polygon(mask, patch, origin, 255);
    cv::Mat m = mask(box), both;
    cv::bitwise_and(m, counted(box), both);
    const int total = cv::countNonZero(both);
    cv::bitwise_and(m, under(box), both);
    const int hidden = cv::countNonZero(both);
    m.setTo(0);  // cleared for the next patch
    const double cover = total > 0 ? static_cast<double>(hidden) / total : 1.0;
    if (cover > best.cover) best = {arms.first, arms.second, cover};
  }
  return best;
}

}  // namespace hair25d::completion::detail
