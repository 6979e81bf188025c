#include "render.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

#include "strand_shape.h"

namespace hair25d::generator {

namespace {

constexpr int kShift = 8;  // fixed-point fraction bits of OpenCV's polygon drawing
constexpr double kOne = 1 << kShift;

// Pixel centre x of the 1× image lies at S·(x + 0.5) − 0.5 of the S× image, so
// area averaging S×S blocks lands each block on its 1× pixel.
std::vector<cv::Point> to_fixed(const Polyline& line, int scale, const cv::Point& origin) {
  std::vector<cv::Point> out;
  out.reserve(line.size());
  // Rounded before the shift by the box origin, so a shape rasterises to the
  // same pixels whichever box it is drawn in (masks then contain regions exactly).
  for (const Vec2& p : line) {
    const long x = std::lround(((p.x() + 0.5) * scale - 0.5) * kOne);
    const long y = std::lround(((p.y() + 0.5) * scale - 0.5) * kOne);
    out.emplace_back(static_cast<int>(x - (static_cast<long>(origin.x) << kShift)),
                     static_cast<int>(y - (static_cast<long>(origin.y) << kShift)));
  }
  return out;
}

cv::Scalar rgb(const Colour& c) {
  return {std::round(255.0 * std::clamp(c.x(), 0.0, 1.0)),
          std::round(255.0 * std::clamp(c.y(), 0.0, 1.0)),
          std::round(255.0 * std::clamp(c.z(), 0.0, 1.0))};
}

cv::Vec3b rgb8(const Colour& c) {
  const cv::Scalar s = rgb(c);
  return {static_cast<uchar>(s[0]), static_cast<uchar>(s[1]), static_cast<uchar>(s[2])};
}

struct Box {
  double x0, y0, x1, y1;
};

Box bounds(const Polyline& line) {
  Box b{1e300, 1e300, -1e300, -1e300};
  for (const Vec2& p : line) {
    b.x0 = std::min(b.x0, p.x());
    b.y0 = std::min(b.y0, p.y());
    b.x1 = std::max(b.x1, p.x());
    b.y1 = std::max(b.y1, p.y());
  }
  return b;
}

// The shape's box at `scale`, grown by the line width, clipped to the image.
cv::Rect roi_of(const Shape& s, double line_width, int scale, const cv::Size& size) {
  const Box b = bounds(s.outline);
  const double pad = line_width + 2.0;
  const int x0 = static_cast<int>(std::floor((b.x0 - pad + 0.5) * scale));
  const int y0 = static_cast<int>(std::floor((b.y0 - pad + 0.5) * scale));
  const int x1 = static_cast<int>(std::ceil((b.x1 + pad + 0.5) * scale));
  const int y1 = static_cast<int>(std::ceil((b.y1 + pad + 0.5) * scale));
  return cv::Rect(x0, y0, x1 - x0, y1 - y0) & cv::Rect(cv::Point(0, 0), size);
}

int thickness(double line_width, int scale) {
  return std::max(1, static_cast<int>(std::lround(line_width * scale)));
}

// Shading parameter in [0, 1] per pixel of the layer: along the strand for
// tapered strands (drawn as quads between samples), top to bottom for masses.
cv::Mat shading_param(const Shape& s, const cv::Rect& roi, int scale) {
  cv::Mat param(roi.size(), CV_32F, cv::Scalar(0.0));
  const cv::Point origin = roi.tl();
  if (s.geometry) {
    const StrandGeometry& g = *s.geometry;
    const std::size_t n = g.centre.size();
    const auto tip =
        to_fixed(ellipse_polygon(g.centre[n - 1], Vec2::Constant(g.width[n - 1] / 2 + 2), 0.0, 24),
                 scale, origin);
    cv::fillPoly(param, std::vector{tip}, cv::Scalar(1.0), cv::LINE_8, kShift);
    for (std::size_t i = 0; i + 1 < n; ++i) {
      // Quads grown a little past the sides so the outline never shows a gap.
      auto grow = [&](std::size_t k, const Polyline& side) {
        const Vec2 d = side[k] - g.centre[k];
        const double len = d.norm();
        return len > 1e-9 ? Vec2(g.centre[k] + d * (len + 2.0) / len) : side[k];
      };
      const Polyline quad = {grow(i, g.left), grow(i + 1, g.left), grow(i + 1, g.right),
                             grow(i, g.right)};
      cv::fillConvexPoly(param, to_fixed(quad, scale, origin),
                         cv::Scalar(0.5 * (g.t[i] + g.t[i + 1])), cv::LINE_8, kShift);
    }
  } else {
    const Box b = bounds(s.outline);
    for (int y = 0; y < roi.height; ++y) {
      const double y1x = (roi.y + y + 0.5) / scale - 0.5;
      param.row(y).setTo(std::clamp((y1x - b.y0) / std::max(1.0, b.y1 - b.y0), 0.0, 1.0));
    }
  }
  if (s.reverse_param) param = 1.0 - param;
  return param;
}

// The shape's fill before decorations and lines, over its whole box.
void fill_layer(const Scene& sc, const Shape& s, const cv::Rect& roi, int scale,
                const cv::Mat& mask, cv::Mat& layer) {
  layer.setTo(rgb(s.colour));
  const Colour dark = s.colour * 0.72;
  switch (sc.shading) {
    case Shading::kFlat:
      return;
    case Shading::kTwoTone: {
      if (!s.hair) return;
      if (s.geometry) {
        if (!s.band.empty()) {
          cv::fillPoly(layer, std::vector{to_fixed(s.band, scale, roi.tl())}, rgb(dark), cv::LINE_8,
                       kShift);
        }
        return;
      }
      // Masses: darker below a wavy level, like a cel shadow under the crown.
      const Box b = bounds(s.outline);
      const cv::Vec3b d8 = rgb8(dark);
      const double wave = 2.0 * std::numbers::pi / std::max(1.0, 0.3 * (b.x1 - b.x0));
      for (int y = 0; y < roi.height; ++y) {
        const double y1x = (roi.y + y + 0.5) / scale - 0.5;
        const double level = (y1x - b.y0) / std::max(1.0, b.y1 - b.y0);
        auto* row = layer.ptr<cv::Vec3b>(y);
        for (int x = 0; x < roi.width; ++x) {
          const double x1x = (roi.x + x + 0.5) / scale - 0.5;
          if (level > s.band_level + 0.04 * std::sin(x1x * wave)) row[x] = d8;
        }
      }
      return;
    }
    case Shading::kGradient: {
      if (!s.hair) return;
      const cv::Mat param = shading_param(s, roi, scale);
      const Colour light = (s.colour * 1.12).cwiseMin(1.0);
      constexpr int kSteps = 256;
      std::vector<cv::Vec3b> ramp(kSteps);
      for (int i = 0; i < kSteps; ++i) {
        ramp[i] = rgb8(light + (dark - light) * (i / (kSteps - 1.0)));
      }
      for (int y = 0; y < roi.height; ++y) {
        const auto* p = param.ptr<float>(y);
        const auto* m = mask.ptr<uchar>(y);
        auto* row = layer.ptr<cv::Vec3b>(y);
        for (int x = 0; x < roi.width; ++x) {
          if (m[x])
            row[x] = ramp[std::clamp(static_cast<int>(p[x] * (kSteps - 1) + 0.5f), 0, kSteps - 1)];
        }
      }
      return;
    }
    case Shading::kScreentone: {
      if (!s.hair || s.tone <= 0.0) return;
      const double radius2 = s.tone / std::numbers::pi;  // dot area share = tone
      const double c = std::cos(sc.tone_angle) / sc.tone_period;
      const double sn = std::sin(sc.tone_angle) / sc.tone_period;
      const cv::Vec3b ink = rgb8(sc.line_colour);
      for (int y = 0; y < roi.height; ++y) {
        const double y1x = (roi.y + y + 0.5) / scale - 0.5;
        const auto* m = mask.ptr<uchar>(y);
        auto* row = layer.ptr<cv::Vec3b>(y);
        for (int x = 0; x < roi.width; ++x) {
          if (!m[x]) continue;
          const double x1x = (roi.x + x + 0.5) / scale - 0.5;
          const double u = c * x1x + sn * y1x, v = -sn * x1x + c * y1x;
          const double fu = u - std::round(u), fv = v - std::round(v);
          if (fu * fu + fv * fv < radius2) row[x] = ink;
        }
      }
      return;
    }
  }
}

}  // namespace

cv::Mat render_picture(const Scene& sc, int scale) {
  const cv::Size big(sc.width * scale, sc.height * scale);
  cv::Mat canvas(big, CV_8UC3, rgb(sc.background));
  const cv::Scalar ink = rgb(sc.line_colour);
  const int line = thickness(sc.line_width, scale);
  for (const Shape& s : sc.shapes) {
    const cv::Rect roi = roi_of(s, sc.line_width, scale, big);
    if (roi.empty()) continue;
    const cv::Point origin = roi.tl();
    const auto outline = to_fixed(s.outline, scale, origin);
    cv::Mat target = canvas(roi);
    // Most shapes are drawn straight onto the canvas; a layer clipped by the
    // shape's mask is needed only where paint could leave the shape (fork
    // lines) or is computed per pixel.
    const bool per_pixel =
        s.hair && (sc.shading == Shading::kGradient || sc.shading == Shading::kScreentone ||
                   (sc.shading == Shading::kTwoTone && !s.geometry));
    cv::Mat layer = target;
    cv::Mat mask;
    if (per_pixel || !s.inner_lines.empty()) {
      mask = cv::Mat(roi.size(), CV_8U, cv::Scalar(0));
      cv::fillPoly(mask, std::vector{outline}, cv::Scalar(255), cv::LINE_8, kShift);
      layer = cv::Mat(roi.size(), CV_8UC3);
      fill_layer(sc, s, roi, scale, mask, layer);
    } else {
      cv::fillPoly(target, std::vector{outline}, rgb(s.colour), cv::LINE_8, kShift);
      if (sc.shading == Shading::kTwoTone && !s.band.empty()) {
        cv::fillPoly(target, std::vector{to_fixed(s.band, scale, origin)}, rgb(s.colour * 0.72),
                     cv::LINE_8, kShift);
      }
    }
    for (const FilledEllipse& e : s.decorations) {
      cv::fillPoly(
          layer,
          std::vector{to_fixed(ellipse_polygon(e.centre, e.radii, e.angle, 48), scale, origin)},
          rgb(e.colour), cv::LINE_8, kShift);
    }
    for (const Polyline& l : s.inner_lines) {
      cv::polylines(layer, std::vector{to_fixed(l, scale, origin)}, false, ink, line, cv::LINE_8,
                    kShift);
    }
    if (!mask.empty()) layer.copyTo(target, mask);
    cv::polylines(target, std::vector{outline}, true, ink, line, cv::LINE_8, kShift);
  }
  if (scale == 1) return canvas;
  cv::Mat out;
  cv::resize(canvas, out, cv::Size(sc.width, sc.height), 0, 0, cv::INTER_AREA);
  return out;
}

cv::Mat render_owner(const Scene& sc) {
  const cv::Size size(sc.width, sc.height);
  cv::Mat owner(size, CV_32S, cv::Scalar(0));
  const int line = thickness(sc.line_width, 1);
  for (std::size_t k = 0; k < sc.shapes.size(); ++k) {
    const Shape& s = sc.shapes[k];
    const cv::Rect roi = roi_of(s, sc.line_width, 1, size);
    if (roi.empty()) continue;
    const cv::Point origin = roi.tl();
    const auto outline = to_fixed(s.outline, 1, origin);
    cv::Mat mask(roi.size(), CV_8U, cv::Scalar(0));
    cv::fillPoly(mask, std::vector{outline}, cv::Scalar(255), cv::LINE_8, kShift);
    cv::Mat target = owner(roi);
    target.setTo(cv::Scalar(static_cast<int>(k) + 1), mask);
    if (!s.inner_lines.empty() || !s.hidden_lines.empty()) {
      cv::Mat lines(roi.size(), CV_8U, cv::Scalar(0));
      for (const Polyline& l : s.inner_lines) {
        cv::polylines(lines, std::vector{to_fixed(l, 1, origin)}, false, cv::Scalar(255), line,
                      cv::LINE_8, kShift);
      }
      // An 8-connected one-pixel line is enough to keep 4-connected pieces apart.
      for (const Polyline& l : s.hidden_lines) {
        cv::polylines(lines, std::vector{to_fixed(l, 1, origin)}, false, cv::Scalar(255), 1,
                      cv::LINE_8, kShift);
      }
      target.setTo(cv::Scalar(kLineOwner), lines & mask);
    }
    cv::polylines(target, std::vector{outline}, true, cv::Scalar(kLineOwner), line, cv::LINE_8,
                  kShift);
  }
  return owner;
}

LabelMap shape_mask(const Scene& sc, const Shape& s) {
  LabelMap out(sc.width, sc.height, 0);
  const cv::Rect roi = roi_of(s, sc.line_width, 1, cv::Size(sc.width, sc.height));
  if (roi.empty()) return out;
  cv::Mat mask(roi.size(), CV_8U, cv::Scalar(0));
  cv::fillPoly(mask, std::vector{to_fixed(s.outline, 1, roi.tl())}, cv::Scalar(1), cv::LINE_8,
               kShift);
  for (int y = 0; y < roi.height; ++y) {
    const auto* m = mask.ptr<uchar>(y);
    for (int x = 0; x < roi.width; ++x) out.at(roi.x + x, roi.y + y) = m[x];
  }
  return out;
}

}  // namespace hair25d::generator
