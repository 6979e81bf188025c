// Internal to layering: the views of the smoothed window and the label map
// that LineResponse::measure() samples, and the AVX2 paths of the line
// response (line_response_avx2.cpp), chosen at run time.
#pragma once

#include <cstddef>
#include <cstdint>

#include "hair25d/core/image.h"
#include "line_response.h"

#if defined(__x86_64__) && defined(__GNUC__)
#define HAIR25D_LAYERING_AVX2 1
#endif

namespace hair25d::layering::detail {

inline constexpr int kOutside = -2147483647;

// std::floor to an int for coordinates well inside int's range, without the
// round trip through double that std::floor costs on baseline x86-64.
inline int floor_int(double v) {
  const int i = static_cast<int>(v);  // truncates towards zero
  return i - (v < i ? 1 : 0);
}

// The smoothed window and the label map as measure() reads them, copied into
// locals: through the members, every sample reloaded them (the vectors it
// appends to might alias them), and the bounds were converted again each time.
struct GreyView {
  const float* grey;
  int w, h;
  double x0, y0;      // the window's position
  double xmax, ymax;  // w − 1, h − 1

  double at(int xx, int yy) const { return static_cast<double>(grey[yy * w + xx]); }

  // Bilinear, pixel centres at +0.5, clamped to the window. Inlined: called
  // a few dozen times per point measured.
  // The same where (x, y) is known to lie well inside the window.
  [[gnu::always_inline]] double sample_inside(double x, double y) const {
    x = x - 0.5 - x0;
    y = y - 0.5 - y0;
    const int xi = static_cast<int>(x), yi = static_cast<int>(y);
    const double fx = x - xi, fy = y - yi;
    const float* p = grey + yi * w + xi;
    return (1 - fy) * ((1 - fx) * static_cast<double>(p[0]) + fx * static_cast<double>(p[1])) +
           fy * ((1 - fx) * static_cast<double>(p[w]) + fx * static_cast<double>(p[w + 1]));
  }
  // Whether the segment from (x + dx, y + dy) to (x − dx, y − dy) lies well
  // inside the window: then so does every sample along it.
  bool holds(double x, double y, double dx, double dy) const {
    const double ax = std::min(x - dx, x + dx) - 0.5 - x0, bx = std::max(x - dx, x + dx) - 0.5 - x0;
    const double ay = std::min(y - dy, y + dy) - 0.5 - y0, by = std::max(y - dy, y + dy) - 0.5 - y0;
    return ax >= 1.0 && ay >= 1.0 && bx < xmax - 1.0 && by < ymax - 1.0;
  }

  [[gnu::always_inline]] double sample(double x, double y) const {
    x = x - 0.5 - x0;
    y = y - 0.5 - y0;
    // Inside the window (almost always) the clamps below change nothing.
    if (x >= 0.0 && y >= 0.0 && x < xmax && y < ymax) {
      const int xi = static_cast<int>(x), yi = static_cast<int>(y);
      const double fx = x - xi, fy = y - yi;
      const float* p = grey + yi * w + xi;
      return (1 - fy) * ((1 - fx) * static_cast<double>(p[0]) + fx * static_cast<double>(p[1])) +
             fy * ((1 - fx) * static_cast<double>(p[w]) + fx * static_cast<double>(p[w + 1]));
    }
    x = std::clamp(x, 0.0, xmax);
    y = std::clamp(y, 0.0, ymax);
    const int xi = std::min(static_cast<int>(x), w - 2 < 0 ? 0 : w - 2);
    const int yi = std::min(static_cast<int>(y), h - 2 < 0 ? 0 : h - 2);
    const int x1 = std::min(xi + 1, w - 1);
    const int y1 = std::min(yi + 1, h - 1);
    const double fx = x - xi, fy = y - yi;
    return (1 - fy) * ((1 - fx) * at(xi, yi) + fx * at(x1, yi)) +
           fy * ((1 - fx) * at(xi, y1) + fx * at(x1, y1));
  }
};

struct LabelView {
  const int* labels;
  int w, h;
  // The same where (x, y) is known to lie in the map (so x, y >= 0: the
  // truncation is the floor).
  int at_inside(double x, double y) const {
    return labels[static_cast<std::size_t>(static_cast<int>(y)) * w + static_cast<int>(x)];
  }
  // Whether the segment from (x + dx, y + dy) to (x − dx, y − dy) lies well
  // inside the map.
  bool holds(double x, double y, double dx, double dy) const {
    return std::min(x - dx, x + dx) >= 1.0 && std::min(y - dy, y + dy) >= 1.0 &&
           std::max(x - dx, x + dx) < w - 1.0 && std::max(y - dy, y + dy) < h - 1.0;
  }
  // The label of the pixel holding (x, y), kOutside beyond the map.
  int at(double x, double y) const {
    const int xi = floor_int(x), yi = floor_int(y);
    return xi >= 0 && yi >= 0 && xi < w && yi < h ? labels[static_cast<std::size_t>(yi) * w + xi]
                                                  : kOutside;
  }
};

// measure()'s grey samples of one point where all of them lie well inside
// the window and the map, four at a time: each lane does GreyView::
// sample_inside's products and sums in its order (no fused multiply-add: the
// target is AVX2 alone), and min / max do not depend on the order they are
// taken in, so the same values.
struct PointSamples {
  double centre, paper_left, paper_right;
};

#if defined(HAIR25D_LAYERING_AVX2)
// grey_into's opaque formula eight pixels at a time (returns how many pixels
// it did, a multiple of 8, and ANDs their alphas into `alpha`).
__attribute__((target("avx2"))) int grey_row_avx2(const Rgba* src, int n, float* row,
                                                  unsigned* alpha);
// The same sixteen pixels at a time (AVX-512F).
__attribute__((target("avx2,avx512f"))) int grey_row_avx512(const Rgba* src, int n, float* row,
                                                            unsigned* alpha);

// smoothed_colour's opaque path, two pixels per register: the weighted sum
// of `groups` groups of four columns.
__attribute__((target("avx2"))) Rgb3f colour_sum_avx2(const Rgba* centre, std::ptrdiff_t iw, int r,
                                                      int groups, const float* kernel,
                                                      const float* column_weights);

// The same with four pixels per register (AVX-512F).
__attribute__((target("avx2,avx512f"))) Rgb3f colour_sum_avx512(const Rgba* centre,
                                                                std::ptrdiff_t iw, int r,
                                                                int groups, const float* kernel,
                                                                const float* column_weights);

// `offsets`: the centre search's steps along the normal, `count` of them
// padded to a multiple of four (eight for AVX-512) by repeating the last;
// the paper search
// steps 1, 2, ... up to `paper_steps`.
__attribute__((target("avx2"))) PointSamples point_samples_avx2(
    const GreyView& grey, const LabelView& label, double px, double py, double nx, double ny,
    const double* offsets, int count, int paper_steps, int left, int right);
// The same eight samples at a time (AVX-512F); `count` a multiple of eight.
__attribute__((target("avx2,avx512f"))) PointSamples point_samples_avx512(
    const GreyView& grey, const LabelView& label, double px, double py, double nx, double ny,
    const double* offsets, int count, int paper_steps, int left, int right);
#endif

}  // namespace hair25d::layering::detail
