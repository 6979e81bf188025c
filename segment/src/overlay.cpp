#include "hair25d/segment/overlay.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>

#include "hair25d/core/error.h"

namespace hair25d::segment {

Rgba label_colour(int id) {
  if (id <= 0) return {150, 150, 150, 255};
  // Golden-angle hues: consecutive ids land far apart on the colour wheel.
  const double h = std::fmod(id * 137.50776, 360.0) / 60.0;
  const double s = id % 2 ? 0.85 : 0.6, v = id % 3 == 0 ? 0.8 : 0.95;
  const double c = v * s, x = c * (1 - std::abs(std::fmod(h, 2.0) - 1)), m = v - c;
  double r = 0, g = 0, b = 0;
  switch (static_cast<int>(h)) {
    case 0:
      r = c, g = x;
      break;
    case 1:
      r = x, g = c;
      break;
    case 2:
      g = c, b = x;
      break;
    case 3:
      g = x, b = c;
      break;
    case 4:
      r = x, b = c;
      break;
    default:
      r = c, b = x;
      break;
  }
  auto u8 = [&](double q) { return static_cast<std::uint8_t>(std::lround((q + m) * 255.0)); };
  return {u8(r), u8(g), u8(b), 255};
}

Image draw_overlay(const Image& image, const Segmentation& seg, const LabelMap& regions) {
  if (regions.width() != image.width() || regions.height() != image.height())
    throw Error("segment::draw_overlay: label map is " + std::to_string(regions.width()) + "x" +
                std::to_string(regions.height()) + "; must match the " +
                std::to_string(image.width()) + "x" + std::to_string(image.height()) + " image");
  Image out(image.width(), image.height());
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      // Transparent paper shows as white.
      const Rgba q = image.at(x, y);
      auto over_white = [&](std::uint8_t c) {
        return static_cast<std::uint8_t>((c * q.a + 255 * (255 - q.a) + 127) / 255);
      };
      const Rgba p{over_white(q.r), over_white(q.g), over_white(q.b), 255};
      const int id = regions.at(x, y);
      const Rgba c = label_colour(id);
      // Background stays a faded drawing; regions get a strong tint.
      const double k = id > 0 ? 0.55 : 0.0;
      const double fade = id > 0 ? 1.0 : 0.5;
      auto mix = [&](std::uint8_t a, std::uint8_t b) {
        const double base = a * fade + 255.0 * (1.0 - fade);
        return static_cast<std::uint8_t>(std::lround(base * (1.0 - k) + b * k));
      };
      out.at(x, y) = {mix(p.r, c.r), mix(p.g, c.g), mix(p.b, c.b), 255};
    }
  }
  if (out.empty()) return out;
  try {
    cv::Mat canvas(out.height(), out.width(), CV_8UC4, out.bytes());
    constexpr int kShift = 4;
    auto pt = [](const Vec2& p) {
      // Our pixel centres are at +0.5; OpenCV's are at integers.
      return cv::Point(static_cast<int>(std::lround((p.x() - 0.5) * 16)),
                       static_cast<int>(std::lround((p.y() - 0.5) * 16)));
    };
    const auto& M = seg.mesh;
    for (int t = 0; t < M.triangle_count(); ++t) {
      for (int k = 0; k < 3; ++k) {
        const int a = M.F(t, k), b = M.F(t, (k + 1) % 3);
        if (a > b) continue;  // each shared edge once
        cv::line(canvas, pt(M.V.row(a).transpose()), pt(M.V.row(b).transpose()),
                 cv::Scalar(70, 70, 70, 255), 1, cv::LINE_8, kShift);
      }
    }
    for (const Curve& c : seg.curves) {
      for (std::size_t i = 0; i + 1 < c.points.size(); ++i)
        cv::line(canvas, pt(c.points[i]), pt(c.points[i + 1]), cv::Scalar(230, 20, 20, 255), 2,
                 cv::LINE_AA, kShift);
      if (c.closed && c.points.size() > 2)
        cv::line(canvas, pt(c.points.back()), pt(c.points.front()), cv::Scalar(230, 20, 20, 255), 2,
                 cv::LINE_AA, kShift);
    }
    for (const Curve& c : seg.curves) {
      if (c.closed) continue;
      for (int e = 0; e < 2; ++e) {
        const Vec2& p = e == 0 ? c.points.front() : c.points.back();
        const cv::Scalar colour = c.ends[e] == CurveEnd::kJunction ? cv::Scalar(20, 60, 255, 255)
                                                                   : cv::Scalar(20, 200, 40, 255);
        cv::circle(canvas, pt(p), 3 << kShift, colour, cv::FILLED, cv::LINE_AA, kShift);
      }
    }
  } catch (const cv::Exception& e) {
    throw Error(std::string("segment::draw_overlay: OpenCV failed: ") + e.what());
  }
  return out;
}

}  // namespace hair25d::segment
