#include "join_shapes.h"

#include <algorithm>
#include <climits>
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
  struct Shape {
    double share_a, share_b;
    Polyline patch;
    cv::Rect box;  // polygon_box
    cv::Mat mask;  // the patch filled in its box, once
  };
  std::vector<Shape> patches;
  int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;  // the boxes' union
  for (double sa : shares)
    for (double sb : shares) {
      Polyline patch = join_patch(a, b, sa, sb);
      const cv::Rect box = polygon_box(patch);
      if (box.empty()) return best;
      x0 = std::min(x0, box.x), y0 = std::min(y0, box.y);
      x1 = std::max(x1, box.x + box.width), y1 = std::max(y1, box.y + box.height);
      patches.push_back({sa, sb, std::move(patch), box});
    }
  if (patches.empty()) return best;
  const cv::Point origin(x0, y0);
  const int w = x1 - x0, h = y1 - y0;
  if (static_cast<double>(w) * h > kMaxPolygonBoxPixels) return best;
  // counted: a pixel outside both pieces; under: one of those under cover.
  // What the relations say of a label is asked once (a box holds few).
  // Only pixels some patch covers are asked: the box of long slanted
  // patches is mostly outside them (session 36: the cover refusals' inputs
  // ask this for every such candidate).
  cv::Mat any(h, w, CV_8U, cv::Scalar(0));
  for (Shape& shape : patches) {
    shape.mask = cv::Mat(shape.box.size(), CV_8U, cv::Scalar(0));
    fill_polygon(shape.mask, shape.patch, shape.box.tl(), 255);
    cv::Mat in_union = any(shape.box - origin);
    cv::bitwise_or(in_union, shape.mask, in_union);
  }
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
  // Each patch is counted within its own box, not the union's.
  for (const Shape& shape : patches) {
    const cv::Rect box = shape.box - origin;
    cv::Mat both;
    cv::bitwise_and(shape.mask, counted(box), both);
    const int total = cv::countNonZero(both);
    cv::bitwise_and(shape.mask, under(box), both);
    const int hidden = cv::countNonZero(both);
    const double cover = total > 0 ? static_cast<double>(hidden) / total : 1.0;
    if (cover > best.cover) best = {shape.share_a, shape.share_b, cover};
  }
  return best;
}

}  // namespace hair25d::completion::detail
