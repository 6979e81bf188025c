#include "join_crop.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

namespace hair25d::completion::detail {
namespace {

// A join between touching cuts still shows the pieces' shapes around it.
constexpr double kMinCropSide = 16.0;

}  // namespace

Vec2 JoinCropFrame::to_drawing(double col, double row) const {
  const double u = (col + 0.5) / size - 0.5, v = (row + 0.5) / size - 0.5;
  return centre + side * (u * along + v * across);
}

Vec2 JoinCropFrame::to_crop(const Vec2& p) const {
  const Vec2 d = p - centre;
  return {(d.dot(along) / side + 0.5) * size - 0.5, (d.dot(across) / side + 0.5) * size - 0.5};
}

JoinCropFrame join_crop_frame(const Vec2& pa, const Vec2& qa, const Vec2& pb, const Vec2& qb,
                              int size) {
  JoinCropFrame f;
  f.size = size;
  const Vec2 ca = 0.5 * (pa + qa), cb = 0.5 * (pb + qb);
  f.centre = 0.5 * (ca + cb);
  const double chord = (cb - ca).norm();
  if (chord > 1e-9) {
    f.along = (cb - ca) / chord;
  } else {
    // Cuts on one spot: across a's cut, whichever way.
    const Vec2 cut = qa - pa;
    f.along = cut.norm() > 1e-9 ? Vec2(-cut.y(), cut.x()).normalized() : Vec2(1, 0);
  }
  f.across = Vec2(-f.along.y(), f.along.x());
  f.side = std::max({2.0 * chord, 2.0 * (qa - pa).norm(), 2.0 * (qb - pb).norm(), kMinCropSide});
  return f;
}

std::vector<std::uint8_t> render_join_crop(const Image& image, const LabelMap& labels, int a, int b,
                                           const std::function<bool(int)>& above,
                                           const Polyline& patch, const JoinCropFrame& frame) {
  const int n = frame.size;
  const std::size_t plane = static_cast<std::size_t>(n) * n;
  std::vector<std::uint8_t> out(plane * kJoinCropChannels, 0);
  for (int row = 0; row < n; ++row)
    for (int col = 0; col < n; ++col) {
      const Vec2 p = frame.to_drawing(col, row);
      const int x = static_cast<int>(std::floor(p.x())), y = static_cast<int>(std::floor(p.y()));
      const std::size_t at = static_cast<std::size_t>(row) * n + col;
      if (!image.contains(x, y)) {
        for (int c = 0; c < 3; ++c) out[c * plane + at] = 255;
        continue;
      }
      const Rgba px = image.at(x, y);
      const double alpha = px.a / 255.0;
      const std::uint8_t rgb[3] = {px.r, px.g, px.b};
      for (int c = 0; c < 3; ++c)
        out[c * plane + at] =
            static_cast<std::uint8_t>(std::lround(rgb[c] * alpha + 255.0 * (1.0 - alpha)));
      const int l = labels.contains(x, y) ? labels.at(x, y) : 0;
      const int channel = l == 0 ? -1 : l == a ? 3 : l == b ? 4 : above(l) ? 5 : 6;
      if (channel >= 0) out[channel * plane + at] = 255;
    }
  if (patch.size() >= 3) {
    // Filled in crop coordinates, 4 bits of sub-pixel precision.
    std::vector<cv::Point> poly;
    poly.reserve(patch.size());
    for (const Vec2& p : patch) {
      const Vec2 c = frame.to_crop(p);
      poly.emplace_back(static_cast<int>(std::lround(c.x() * 16)),
                        static_cast<int>(std::lround(c.y() * 16)));
    }
    cv::Mat mask(n, n, CV_8U, out.data() + 7 * plane);
    cv::fillPoly(mask, std::vector<std::vector<cv::Point>>{poly}, cv::Scalar(255), cv::LINE_8, 4);
  }
  return out;
}

std::vector<std::uint8_t> join_crop(const Context& ctx, const Edge& a, const Edge& b,
                                    const Polyline& patch, int size) {
  const int ra = a.region, rb = b.region;
  return render_join_crop(
      *ctx.image, ctx.labels, ra, rb,
      [&](int l) { return ctx.is_above(l, ra) || ctx.is_above(l, rb); }, patch,
      join_crop_frame(a.p, a.q, b.p, b.q, size));
}

}  // namespace hair25d::completion::detail
