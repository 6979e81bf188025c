#include "colour_line.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

namespace hair25d::layering::detail {
namespace {

using Rgb = std::array<double, 3>;

// Bilinear colour of `image` at (x, y) in pixel-corner coordinates (pixel
// (i, j) covers [i, i + 1) × [j, j + 1), its centre at i + 0.5), clamped to
// the image; translucent pixels blended over white paper.
Rgb colour_at(const Image& image, double x, double y) {
  const double fx = x - 0.5, fy = y - 0.5;
  const int x0 = static_cast<int>(std::floor(fx)), y0 = static_cast<int>(std::floor(fy));
  const double tx = fx - x0, ty = fy - y0;
  Rgb out{0.0, 0.0, 0.0};
  for (int dy = 0; dy < 2; ++dy)
    for (int dx = 0; dx < 2; ++dx) {
      const double w = (dx ? tx : 1.0 - tx) * (dy ? ty : 1.0 - ty);
      if (w == 0.0) continue;
      const int xi = std::clamp(x0 + dx, 0, image.width() - 1);
      const int yi = std::clamp(y0 + dy, 0, image.height() - 1);
      const Rgba& p = image.at(xi, yi);
      const double a = p.a / 255.0;
      out[0] += w * (a * p.r + (1.0 - a) * 255.0);
      out[1] += w * (a * p.g + (1.0 - a) * 255.0);
      out[2] += w * (a * p.b + (1.0 - a) * 255.0);
    }
  return out;
}

// The colour of the pixel holding (x, y) (inside the image), over white.
Rgb pixel_at(const Image& image, double x, double y) {
  const Rgba& p = image.at(static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  const double a = p.a / 255.0;
  return {a * p.r + (1.0 - a) * 255.0, a * p.g + (1.0 - a) * 255.0, a * p.b + (1.0 - a) * 255.0};
}

double grey_of(const Rgb& c) { return 0.299 * c[0] + 0.587 * c[1] + 0.114 * c[2]; }

// Distance from c to the segment [a, b] in RGB.
double to_segment(const Rgb& c, const Rgb& a, const Rgb& b) {
  double ab2 = 0.0, t = 0.0;
  for (int k = 0; k < 3; ++k) {
    ab2 += (b[k] - a[k]) * (b[k] - a[k]);
    t += (c[k] - a[k]) * (b[k] - a[k]);
  }
  t = ab2 > 0.0 ? std::clamp(t / ab2, 0.0, 1.0) : 0.0;
  double d2 = 0.0;
  for (int k = 0; k < 3; ++k) {
    const double e = c[k] - (a[k] + t * (b[k] - a[k]));
    d2 += e * e;
  }
  return std::sqrt(d2);
}

int label_at(const LabelMap& labels, double x, double y) {
  const int xi = static_cast<int>(std::floor(x)), yi = static_cast<int>(std::floor(y));
  if (xi < 0 || yi < 0 || xi >= labels.width() || yi >= labels.height()) return -1;
  return labels.at(xi, yi);
}

}  // namespace

BoundaryLine colour_line(const Image& image, double line_width, const Polyline& curve, double skip,
                         const LabelMap& labels, int left, int right) {
  BoundaryLine out;
  if (curve.size() < 2) return out;
  const Polyline pts = resample_polyline(curve, 1.0);
  const int n = static_cast<int>(pts.size());
  const double total = polyline_length(curve);
  skip = std::min(skip, total / 3.0);
  // The reaches of LineResponse::measure.
  const Reach reaches = reach_of(line_width);
  const double half = reaches.half;
  const double reach = reaches.paper;
  const int span = std::max(2, static_cast<int>(std::lround(line_width)));
  const int stride = n > 40 ? 2 : 1;
  std::vector<double> values, grey_values, papers;
  double along = 0.0;
  for (int i = 0; i < n; ++i) {
    if (i > 0) along += (pts[i] - pts[i - 1]).norm();
    if (i % stride != 0 || along < skip || along > total - skip) continue;
    const Vec2 t = pts[std::min(n - 1, i + span)] - pts[std::max(0, i - span)];
    if (t.squaredNorm() == 0.0) continue;
    const Vec2 to_left = Vec2(t.y(), -t.x()).normalized();
    const Vec2 p = pts[i];
    // Paper on each side as the grey measurement takes it: the brightest
    // point within reach along the normal that lies in that side's region
    // (not a fixed distance: on a thin strand that lands on its next line),
    // the pixel itself, as its label is read (a bilinear read there mixes in
    // the rim of the other side's paint).
    Rgb paint_left{}, paint_right{};
    double grey_left = -1.0, grey_right = -1.0;
    // On dark paint the ink may be the brighter (grey ink on black-purple
    // paint), and the brightest point is then the line's rim or, on a thin
    // strand, its other outline: there the paper is the first point beyond
    // the line's cross-section.
    Rgb far_left{}, far_right{};
    double grey_far_left = -1.0, grey_far_right = -1.0;
    for (double s = 1.0; s <= reach + 1e-9; s += 1.0) {
      const Vec2 l = p + s * to_left, r = p - s * to_left;
      if (label_at(labels, l.x(), l.y()) == left) {
        const Rgb c = pixel_at(image, l.x(), l.y());
        if (grey_of(c) > grey_left) grey_left = grey_of(c), paint_left = c;
        if (s > half && grey_far_left < 0.0) grey_far_left = grey_of(c), far_left = c;
      }
      if (label_at(labels, r.x(), r.y()) == right) {
        const Rgb c = pixel_at(image, r.x(), r.y());
        if (grey_of(c) > grey_right) grey_right = grey_of(c), paint_right = c;
        if (s > half && grey_far_right < 0.0) grey_far_right = grey_of(c), far_right = c;
      }
    }
    const bool found_left = grey_left >= 0.0, found_right = grey_right >= 0.0;
    if (!found_left || !found_right) continue;
    if (std::max(grey_left, grey_right) <= kDarkPaper && grey_far_left >= 0.0 &&
        grey_far_right >= 0.0) {
      grey_left = grey_far_left, paint_left = far_left;
      grey_right = grey_far_right, paint_right = far_right;
    }
    // The line's colour may lift the side where the grey levels see no line
    // (paint as dark as the ink) up to the contrast the grey levels see on
    // the other side, not beyond: where both sides see a faint line in grey
    // (a fork line fading out) its hue does not make it stronger.
    double farthest = 0.0, darkest = 1e9;
    for (double s = -half; s <= half + 1e-9; s += 0.5) {
      const Vec2 q = p + s * to_left;
      const Rgb c = colour_at(image, q.x(), q.y());
      farthest = std::max(farthest, to_segment(c, paint_left, paint_right));
      darkest = std::min(darkest, grey_of(c));
    }
    const double grey_low = std::min(grey_left, grey_right) - darkest;
    const double grey_high = std::max(grey_left, grey_right) - darkest;
    // Where both paints are dark (black hair: two strands of one dark paint),
    // neither side leaves the grey levels room for a line, so neither is a
    // measure of how visible it is: the cap is then what black ink would
    // show in grey against the brighter paint, its grey level.
    const double bright = std::max(grey_left, grey_right);
    papers.push_back(bright);
    const double cap = bright <= kDarkPaper ? std::max(grey_high, bright) : grey_high;
    values.push_back(std::max(grey_low, std::min(farthest / std::sqrt(3.0), cap)));
    grey_values.push_back(grey_low);
  }
  if (values.empty()) return out;
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    const std::size_t m = v.size();
    return m % 2 ? v[m / 2] : 0.5 * (v[m / 2 - 1] + v[m / 2]);
  };
  // Only where the colour sees at least twice the line the grey levels see
  // (read here on the same pixels): elsewhere the grey contrast stands.
  const double line = median(values);
  out.paper = median(papers);
  if (median(grey_values) > 0.5 * line) return out;
  out.contrast = line;
  std::vector<double> sorted = values;
  std::sort(sorted.begin(), sorted.end());
  out.contrast_low = sorted[sorted.size() / 4];
  return out;
}

}  // namespace hair25d::layering::detail
