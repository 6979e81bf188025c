// Test helpers: tiny hand-made drawings with anti-aliased lines.
#pragma once

#include <algorithm>
#include <cmath>
#include <random>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "hair25d/core/strokes.h"

namespace hair25d::segment::testing {

// Paints segment a-b of width w (coverage by distance, so anti-aliased) in `ink`.
inline void draw_line(Image& img, Vec2 a, Vec2 b, double w, Rgba ink = {20, 20, 20, 255}) {
  const Vec2 d = b - a;
  const double len2 = std::max(d.squaredNorm(), 1e-12);
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) {
      const Vec2 p(x + 0.5, y + 0.5);
      const double t = std::clamp((p - a).dot(d) / len2, 0.0, 1.0);
      const double dist = (p - (a + t * d)).norm();
      const double cover = std::clamp(w / 2.0 + 0.5 - dist, 0.0, 1.0);
      if (cover <= 0.0) continue;
      Rgba& q = img.at(x, y);
      auto mix = [&](std::uint8_t o, std::uint8_t n) {
        return static_cast<std::uint8_t>(std::lround(o * (1.0 - cover) + n * cover));
      };
      q = {mix(q.r, ink.r), mix(q.g, ink.g), mix(q.b, ink.b), 255};
    }
  }
}

inline void draw_polyline(Image& img, const Polyline& pts, double w, Rgba ink = {20, 20, 20, 255},
                          bool closed = false) {
  for (std::size_t i = 0; i + 1 < pts.size(); ++i) draw_line(img, pts[i], pts[i + 1], w, ink);
  if (closed && pts.size() > 2) draw_line(img, pts.back(), pts.front(), w, ink);
}

inline Polyline circle(Vec2 c, double r, int n = 96) {
  Polyline out;
  for (int i = 0; i < n; ++i) {
    const double a = 2.0 * M_PI * i / n;
    out.emplace_back(c.x() + r * std::cos(a), c.y() + r * std::sin(a));
  }
  return out;
}

inline void fill_rect(Image& img, int x0, int y0, int x1, int y1, Rgba c) {
  for (int y = std::max(0, y0); y < std::min(img.height(), y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width(), x1); ++x) img.at(x, y) = c;
}

inline void add_noise(Image& img, double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> n(0.0, sigma);
  for (int y = 0; y < img.height(); ++y) {
    for (int x = 0; x < img.width(); ++x) {
      Rgba& p = img.at(x, y);
      auto f = [&](std::uint8_t v) {
        return static_cast<std::uint8_t>(std::clamp(std::lround(v + n(rng)), 0L, 255L));
      };
      p = {f(p.r), f(p.g), f(p.b), p.a};
    }
  }
}

inline Stroke stroke(int label, Polyline pts, double width = 3.0) {
  return {label, width, std::move(pts)};
}

// A W x H light drawing split by one vertical line at x = split.
inline Image split_rectangle(int w, int h, double split, double line_width = 3.0) {
  Image img(w, h, {235, 200, 120, 255});
  draw_line(img, Vec2(split, -5), Vec2(split, h + 5), line_width);
  return img;
}

}  // namespace hair25d::segment::testing
