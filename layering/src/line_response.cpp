#include "line_response.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <future>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <type_traits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR25D_LAYERING_AVX2 1
#endif

#include "hair25d/core/error.h"
#include "raster_scan.h"

namespace hair25d::layering::detail {
namespace {

constexpr int kOutside = -2147483647;

// Transparent pixels read as white paper.
inline float grey_value(const Rgba& p) {
  const double a = p.a / 255.0;
  const double lum = 0.299 * p.r + 0.587 * p.g + 0.114 * p.b;
  return static_cast<float>(a * lum + (1.0 - a) * 255.0);
}

// Four floats (r, g, b, a) in one SSE register: the colour smoothing works
// on a pixel's three channels at once.
using Float4 = float __attribute__((vector_size(16)));
using Byte4 = std::uint8_t __attribute__((vector_size(4)));

inline Float4 opaque_value(const Rgba& p) {
  Byte4 b;
  std::memcpy(&b, &p, sizeof b);
  return __builtin_convertvector(b, Float4);
}

// Transparent pixels read as white paint, as in grey_value.
inline Float4 colour_value(const Rgba& p) {
  if (p.a == 255) return opaque_value(p);  // the common case, where the blend is exact
  const float a = p.a / 255.0f;
  return Float4{a * p.r + (1 - a) * 255.0f, a * p.g + (1 - a) * 255.0f, a * p.b + (1 - a) * 255.0f,
                0.0f};
}

#if defined(HAIR25D_LAYERING_AVX2)
// grey_into's opaque formula eight pixels at a time, four per double vector:
// the same products and sums in the same order, so the same floats. Returns
// how many pixels it did (a multiple of 8) and ANDs their alphas into `alpha`.
__attribute__((target("avx2"))) int grey_row_avx2(const Rgba* src, int n, float* row,
                                                  unsigned* alpha) {
  const __m256i byte = _mm256_set1_epi32(0xFF);
  const __m256d wr = _mm256_set1_pd(0.299), wg = _mm256_set1_pd(0.587), wb = _mm256_set1_pd(0.114);
  __m256i alphas = _mm256_set1_epi32(-1);
  int x = 0;
  for (; x + 8 <= n; x += 8) {
    const __m256i px = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(src + x));
    const __m256i r8 = _mm256_and_si256(px, byte);
    const __m256i g8 = _mm256_and_si256(_mm256_srli_epi32(px, 8), byte);
    const __m256i b8 = _mm256_and_si256(_mm256_srli_epi32(px, 16), byte);
    alphas = _mm256_and_si256(alphas, px);
    __m128 half[2];
    for (int h = 0; h < 2; ++h) {
      const __m128i r4 = h == 0 ? _mm256_castsi256_si128(r8) : _mm256_extracti128_si256(r8, 1);
      const __m128i g4 = h == 0 ? _mm256_castsi256_si128(g8) : _mm256_extracti128_si256(g8, 1);
      const __m128i b4 = h == 0 ? _mm256_castsi256_si128(b8) : _mm256_extracti128_si256(b8, 1);
      const __m256d lum = _mm256_add_pd(_mm256_add_pd(_mm256_mul_pd(wr, _mm256_cvtepi32_pd(r4)),
                                                      _mm256_mul_pd(wg, _mm256_cvtepi32_pd(g4))),
                                        _mm256_mul_pd(wb, _mm256_cvtepi32_pd(b4)));
      half[h] = _mm256_cvtpd_ps(lum);
    }
    _mm256_storeu_ps(row + x, _mm256_set_m128(half[1], half[0]));
  }
  alignas(32) std::uint32_t lanes[8];
  _mm256_store_si256(reinterpret_cast<__m256i*>(lanes), alphas);
  for (std::uint32_t v : lanes) *alpha &= v >> 24;
  return x;
}
#endif

// Fills `grey` (window-sized) in `r` from the window at (x0, y0) of `image`.
// Rows are made as if opaque (a = 1 leaves lum unchanged, exactly) and only
// redone pixel by pixel when some alpha is not 255.
// `translucent`, if given, gets a flag per row of `r`: does it hold a pixel
// with alpha below 255?
void grey_into(const Image& image, int x0, int y0, const cv::Rect& r, cv::Mat& grey,
               std::uint8_t* translucent = nullptr, bool wide = false) {
  static_assert(sizeof(Rgba) == 4);
  for (int y = r.y; y < r.y + r.height; ++y) {
    float* row = grey.ptr<float>(y) + r.x;
    const Rgba* src = image.data() + static_cast<std::size_t>(y0 + y) * image.width() + x0 + r.x;
    unsigned alpha = 255;
    int x = 0;
#if defined(HAIR25D_LAYERING_AVX2)
    if (wide) x = grey_row_avx2(src, r.width, row, &alpha);
#else
    (void)wide;
#endif
#if defined(__SSE2__)
    // Four pixels at a time, two per double vector: the same products and
    // sums in the same order as below, so the same floats.
    const __m128i byte = _mm_set1_epi32(0xFF);
    const __m128d wr = _mm_set1_pd(0.299), wg = _mm_set1_pd(0.587), wb = _mm_set1_pd(0.114);
    __m128i alphas = _mm_set1_epi32(-1);
    auto lum = [&](__m128i r4, __m128i g4, __m128i b4) {
      return _mm_add_pd(
          _mm_add_pd(_mm_mul_pd(wr, _mm_cvtepi32_pd(r4)), _mm_mul_pd(wg, _mm_cvtepi32_pd(g4))),
          _mm_mul_pd(wb, _mm_cvtepi32_pd(b4)));
    };
    for (; x + 4 <= r.width; x += 4) {
      const __m128i px = _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + x));
      const __m128i r4 = _mm_and_si128(px, byte);
      const __m128i g4 = _mm_and_si128(_mm_srli_epi32(px, 8), byte);
      const __m128i b4 = _mm_and_si128(_mm_srli_epi32(px, 16), byte);
      alphas = _mm_and_si128(alphas, px);
      const __m128d lo = lum(r4, g4, b4);
      const __m128d hi = lum(_mm_shuffle_epi32(r4, 0x0E), _mm_shuffle_epi32(g4, 0x0E),
                             _mm_shuffle_epi32(b4, 0x0E));
      _mm_storeu_ps(row + x, _mm_movelh_ps(_mm_cvtpd_ps(lo), _mm_cvtpd_ps(hi)));
    }
    alignas(16) std::uint32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), alphas);
    for (std::uint32_t v : lanes) alpha &= v >> 24;
#endif
    for (; x < r.width; ++x) {
      const Rgba p = src[x];
      row[x] = static_cast<float>(0.299 * p.r + 0.587 * p.g + 0.114 * p.b);
      alpha &= p.a;
    }
    if (translucent) translucent[y - r.y] = alpha != 255;
    if (alpha != 255)
      for (int i = 0; i < r.width; ++i)
        if (src[i].a != 255) row[i] = grey_value(src[i]);
  }
}

#if defined(HAIR25D_LAYERING_AVX2)
// smoothed_colour's opaque path with two pixels per register instead of one:
// every lane does the same float products and sums in the same order (no
// fused multiply-add: the target is AVX2 alone), so the same floats. The
// column sums of a group of four pixels are two registers; they are weighted
// into `sum` column by column, in the SSE2 path's order.
// 16 bytes (four pixels) to sixteen 16-bit lanes; two of the pixels (half 0
// or 1) to eight floats.
__attribute__((target("avx2"))) inline __m256i widen_avx2(const Rgba* four_pixels) {
  return _mm256_cvtepu8_epi16(_mm_loadu_si128(reinterpret_cast<const __m128i*>(four_pixels)));
}
template <int kHalf>
__attribute__((target("avx2"))) inline __m256 to_float_avx2(__m256i sixteen) {
  const __m128i part =
      kHalf == 0 ? _mm256_castsi256_si128(sixteen) : _mm256_extracti128_si256(sixteen, kHalf);
  return _mm256_cvtepi32_ps(_mm256_cvtepu16_epi32(part));
}

__attribute__((target("avx2"))) Rgb3f colour_sum_avx2(const Rgba* centre, std::ptrdiff_t iw, int r,
                                                      int groups, const float* kernel,
                                                      const float* column_weights) {
  __m128 sum = _mm_setzero_ps();
  for (int g = 0; g < groups; ++g) {
    const Rgba* mid = centre + 4 * g;
    const __m256i c = widen_avx2(mid);
    __m256 w = _mm256_set1_ps(kernel[r]);
    __m256 c01 = _mm256_mul_ps(w, to_float_avx2<0>(c));
    __m256 c23 = _mm256_mul_ps(w, to_float_avx2<1>(c));
    const Rgba* above = mid;
    const Rgba* below = mid;
    for (int j = 1; j <= r; ++j) {
      above -= iw;
      below += iw;
      const __m256i pair = _mm256_add_epi16(widen_avx2(above), widen_avx2(below));
      w = _mm256_set1_ps(kernel[r + j]);
      c01 = _mm256_add_ps(c01, _mm256_mul_ps(w, to_float_avx2<0>(pair)));
      c23 = _mm256_add_ps(c23, _mm256_mul_ps(w, to_float_avx2<1>(pair)));
    }
    const float* wg = column_weights + 16 * g;
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg), _mm256_castps256_ps128(c01)));
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 4), _mm256_extractf128_ps(c01, 1)));
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 8), _mm256_castps256_ps128(c23)));
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 12), _mm256_extractf128_ps(c23, 1)));
  }
  alignas(16) float out[4];
  _mm_store_ps(out, sum);
  return {out[0], out[1], out[2]};
}
#endif

// Grey levels of the window [x0, x0 + w) × [y0, y0 + h) of `image`.
cv::Mat grey_of(const Image& image, int x0, int y0, int w, int h) {
  cv::Mat grey(h, w, CV_32F);
  grey_into(image, x0, y0, cv::Rect(0, 0, w, h), grey, nullptr,
            LineResponse::wide_vectors_available());
  return grey;
}

// std::floor to an int for coordinates well inside int's range, without the
// round trip through double that std::floor costs on baseline x86-64.
inline int floor_int(double v) {
  const int i = static_cast<int>(v);  // truncates towards zero
  return i - (v < i ? 1 : 0);
}

double median_of(std::vector<double>& v) {
  if (v.empty()) return 0.0;
  auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

// How far from a boundary point measure() looks (pixels): for the line
// centre, for paper, and for paint on each side.
struct Reach {
  double half, paper, paint_near, paint_far;
};
Reach reach_of(double line_width) {
  return {0.5 * line_width + 1.0, 3.0 * line_width + 2.0, line_width + 2.0, 2.5 * line_width + 3.0};
}

double grey_sigma(double line_width) { return std::max(0.6, 0.25 * line_width); }
double colour_sigma(double line_width) { return std::max(1.0, 0.5 * line_width); }
// At least the radius of the kernel cv::GaussianBlur makes for a float image
// (size round(8σ + 1) | 1).
int kernel_radius(double sigma) { return static_cast<int>(std::ceil(4.0 * sigma)) + 1; }

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
#if defined(HAIR25D_LAYERING_AVX2)
// measure()'s grey samples of one point where all of them lie well inside
// the window and the map, four at a time: each lane does GreyView::
// sample_inside's products and sums in its order (no fused multiply-add: the
// target is AVX2 alone), and min / max do not depend on the order they are
// taken in, so the same values.
struct PointSamples {
  double centre, paper_left, paper_right;
};

// grey[index[k] + offset] and the float after it, for k = 0..3, in order.
__attribute__((target("avx2"))) inline __m256i pixel_pairs_avx2(const float* grey, const int* index,
                                                                int offset) {
  auto pair = [&](int k) {
    return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(grey + index[k] + offset));
  };
  return _mm256_set_m128i(_mm_unpacklo_epi64(pair(2), pair(3)),
                          _mm_unpacklo_epi64(pair(0), pair(1)));
}

// Bilinear samples at (x, y) (four lanes), as GreyView::sample_inside.
__attribute__((target("avx2"))) inline __m256d bilinear_avx2(const GreyView& g, __m256d x,
                                                             __m256d y) {
  const __m256d half = _mm256_set1_pd(0.5);
  x = _mm256_sub_pd(_mm256_sub_pd(x, half), _mm256_set1_pd(g.x0));
  y = _mm256_sub_pd(_mm256_sub_pd(y, half), _mm256_set1_pd(g.y0));
  const __m128i xi = _mm256_cvttpd_epi32(x), yi = _mm256_cvttpd_epi32(y);
  const __m256d fx = _mm256_sub_pd(x, _mm256_cvtepi32_pd(xi));
  const __m256d fy = _mm256_sub_pd(y, _mm256_cvtepi32_pd(yi));
  const __m128i at = _mm_add_epi32(_mm_mullo_epi32(yi, _mm_set1_epi32(g.w)), xi);
  // Each pixel with its right-hand neighbour, as one 8-byte load per lane
  // (four loads, not a gather: gathers are slow on some processors).
  alignas(16) int index[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(index), at);
  const __m256i top = pixel_pairs_avx2(g.grey, index, 0);
  const __m256i bottom = pixel_pairs_avx2(g.grey, index, g.w);
  const __m256i split = _mm256_setr_epi32(0, 2, 4, 6, 1, 3, 5, 7);
  const __m256 t = _mm256_castsi256_ps(_mm256_permutevar8x32_epi32(top, split));
  const __m256 b = _mm256_castsi256_ps(_mm256_permutevar8x32_epi32(bottom, split));
  const __m256d p0 = _mm256_cvtps_pd(_mm256_castps256_ps128(t));
  const __m256d p1 = _mm256_cvtps_pd(_mm256_extractf128_ps(t, 1));
  const __m256d p2 = _mm256_cvtps_pd(_mm256_castps256_ps128(b));
  const __m256d p3 = _mm256_cvtps_pd(_mm256_extractf128_ps(b, 1));
  const __m256d one = _mm256_set1_pd(1.0);
  const __m256d gx = _mm256_sub_pd(one, fx), gy = _mm256_sub_pd(one, fy);
  const __m256d upper = _mm256_add_pd(_mm256_mul_pd(gx, p0), _mm256_mul_pd(fx, p1));
  const __m256d lower = _mm256_add_pd(_mm256_mul_pd(gx, p2), _mm256_mul_pd(fx, p3));
  return _mm256_add_pd(_mm256_mul_pd(gy, upper), _mm256_mul_pd(fy, lower));
}

__attribute__((target("avx2"))) inline double min_of_avx2(__m256d v) {
  const __m128d m = _mm_min_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_min_sd(m, _mm_unpackhi_pd(m, m)));
}
__attribute__((target("avx2"))) inline double max_of_avx2(__m256d v) {
  const __m128d m = _mm_max_pd(_mm256_castpd256_pd128(v), _mm256_extractf128_pd(v, 1));
  return _mm_cvtsd_f64(_mm_max_sd(m, _mm_unpackhi_pd(m, m)));
}

// All ones in the lanes whose pixel of `label` holds `want`.
__attribute__((target("avx2"))) inline __m256d label_mask_avx2(const LabelView& label, __m256d x,
                                                               __m256d y, __m128i want) {
  const __m128i at = _mm_add_epi32(_mm_mullo_epi32(_mm256_cvttpd_epi32(y), _mm_set1_epi32(label.w)),
                                   _mm256_cvttpd_epi32(x));
  alignas(16) int index[4];
  _mm_store_si128(reinterpret_cast<__m128i*>(index), at);
  const int* l = label.labels;
  const __m128i hit =
      _mm_cmpeq_epi32(_mm_setr_epi32(l[index[0]], l[index[1]], l[index[2]], l[index[3]]), want);
  return _mm256_castsi256_pd(_mm256_cvtepi32_epi64(hit));
}

// `offsets`: the centre search's steps along the normal, `count` of them
// padded to a multiple of four by repeating the last; the paper search
// steps 1, 2, ... up to `paper_steps`.
__attribute__((target("avx2"))) PointSamples point_samples_avx2(
    const GreyView& grey, const LabelView& label, double px, double py, double nx, double ny,
    const double* offsets, int count, int paper_steps, int left, int right) {
  const __m256d vpx = _mm256_set1_pd(px), vpy = _mm256_set1_pd(py);
  const __m256d vnx = _mm256_set1_pd(nx), vny = _mm256_set1_pd(ny);
  __m256d centre = _mm256_set1_pd(1e9);
  for (int k = 0; k < count; k += 4) {
    const __m256d sv = _mm256_loadu_pd(offsets + k);
    centre = _mm256_min_pd(centre, bilinear_avx2(grey, _mm256_add_pd(vpx, _mm256_mul_pd(sv, vnx)),
                                                 _mm256_add_pd(vpy, _mm256_mul_pd(sv, vny))));
  }
  const __m256d none = _mm256_set1_pd(-1.0);
  __m256d paper_left = none, paper_right = none;
  const __m128i vleft = _mm_set1_epi32(left), vright = _mm_set1_epi32(right);
  for (int k = 1; k <= paper_steps; k += 4) {
    __m256d sv = _mm256_setr_pd(k, k + 1, k + 2, k + 3);
    // Steps past the last repeat it (max ignores the repeat).
    sv = _mm256_min_pd(sv, _mm256_set1_pd(paper_steps));
    const __m256d ox = _mm256_mul_pd(sv, vnx), oy = _mm256_mul_pd(sv, vny);
    const __m256d lx = _mm256_add_pd(vpx, ox), ly = _mm256_add_pd(vpy, oy);
    const __m256d rx = _mm256_sub_pd(vpx, ox), ry = _mm256_sub_pd(vpy, oy);
    paper_left = _mm256_max_pd(paper_left, _mm256_blendv_pd(none, bilinear_avx2(grey, lx, ly),
                                                            label_mask_avx2(label, lx, ly, vleft)));
    paper_right =
        _mm256_max_pd(paper_right, _mm256_blendv_pd(none, bilinear_avx2(grey, rx, ry),
                                                    label_mask_avx2(label, rx, ry, vright)));
  }
  return {min_of_avx2(centre), max_of_avx2(paper_left), max_of_avx2(paper_right)};
}
#endif

// Noise: MAD of a 3x3 Laplacian on the raw grey window (its edges
// reflected, as if it were the whole image), over every fourth pixel of
// every fourth row, scaled for a Gaussian. Only those pixels' Laplacian is
// computed (laplacian_at: the values of cv::Laplacian over the window, a
// sixteenth of its work).
double noise_of(const cv::Mat& grey) {
  std::vector<double> mags;
  mags.reserve(static_cast<std::size_t>(grey.total()) / 16 + 1);
  for (int y = 0; y < grey.rows; y += 4)
    for (int x = 0; x < grey.cols; x += 4)
      mags.push_back(std::abs(laplacian_at(grey.ptr<float>(), grey.cols, grey.rows,
                                           static_cast<std::ptrdiff_t>(grey.step1()), x, y)));
  // A 4-neighbour Laplacian of i.i.d. noise has σ·√20.
  return median_of(mags) * 1.4826 / std::sqrt(20.0);
}

// Whether each row of `image` holds a pixel with alpha below 255.
std::vector<std::uint8_t> translucent_rows_of(const Image& image) {
  std::vector<std::uint8_t> out(image.height(), 0);
  for (int y = 0; y < image.height(); ++y) {
    const Rgba* src = image.data() + static_cast<std::size_t>(y) * image.width();
    unsigned alpha = 255;
    int x = 0;
#if defined(__SSE2__)
    __m128i all = _mm_set1_epi32(-1);
    for (; x + 4 <= image.width(); x += 4)
      all = _mm_and_si128(all, _mm_loadu_si128(reinterpret_cast<const __m128i*>(src + x)));
    alignas(16) std::uint32_t lanes[4];
    _mm_store_si128(reinterpret_cast<__m128i*>(lanes), all);
    for (std::uint32_t v : lanes) alpha &= v >> 24;
#endif
    for (; x < image.width(); ++x) alpha &= src[x].a;
    out[y] = alpha != 255;
  }
  return out;
}

}  // namespace

float laplacian_at(const float* grey, int w, int h, std::ptrdiff_t stride, int x, int y) {
  if (x > 0 && y > 0 && x + 1 < w && y + 1 < h) {  // inside: no edge to reflect
    const float* p = grey + y * stride + x;
    float s = 0.0f;
    s += p[-stride];
    s += p[-1];
    s += -4.0f * p[0];
    s += p[1];
    s += p[stride];
    return s;
  }
  auto reflect = [](int i, int n) {
    if (n == 1) return 0;
    if (i < 0) return -i;
    if (i >= n) return 2 * n - 2 - i;
    return i;
  };
  auto at = [&](int xx, int yy) { return grey[yy * stride + xx]; };
  const int xl = reflect(x - 1, w), xr = reflect(x + 1, w);
  const int yu = reflect(y - 1, h), yd = reflect(y + 1, h);
  // The kernel's non-zero taps in raster order added to 0 one after another,
  // as OpenCV's 2-D filter adds them; the products by 1 and −4 are exact, so
  // with or without fused multiply-adds the float is the same.
  float s = 0.0f;
  s += at(x, yu);
  s += at(xl, y);
  s += -4.0f * at(x, y);
  s += at(xr, y);
  s += at(x, yd);
  return s;
}

void grey_levels(const Image& image, int x0, int y0, int w, int h, float* out) {
  cv::Mat grey(h, w, CV_32F, out);
  grey_into(image, x0, y0, cv::Rect(0, 0, w, h), grey, nullptr,
            LineResponse::wide_vectors_available());
}

bool LineResponse::wide_vectors_available() {
#if defined(HAIR25D_LAYERING_AVX2)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

int LineResponse::window_margin(double line_width) {
  const double lw = std::max(1.0, line_width);
  const Reach reach = reach_of(lw);
  // A sample reads pixels up to 2 beyond its point (bilinear footprint,
  // pixel centres), and a smoothed pixel reads the kernel's radius around it.
  const double grey = std::max(reach.half, reach.paper) + 2.0 + kernel_radius(grey_sigma(lw));
  const double colour = reach.paint_far + 2.0 + kernel_radius(colour_sigma(lw));
  return static_cast<int>(std::ceil(std::max(grey, colour)));
}

LineResponse::LineResponse(const Image& image, const LabelMap* regions) : image_(&image) {
  wide_vectors_ = wide_vectors_available();
  const int w = image.width(), h = image.height();
  raw_ = std::make_unique_for_overwrite<float[]>(static_cast<std::size_t>(w) * h);
  // The grey levels need nothing but the image: a second core converts them
  // while the caller fills outlines and traces boundaries. It writes only
  // raw_, its box and image_translucent_, which nothing reads before
  // prepare()'s blur or smooth() waits.
  auto convert = [this, regions, w, h, wide = wide_vectors_] {
    // Grey levels are needed in the window of the filled boundaries and a
    // kernel's reach around it: near the regions, within the outline fill's
    // reach and the window's margin at the line widths of most drawings
    // (wider lines, or no regions, convert the rest when a window needs it).
    int x0 = 0, y0 = 0, x1 = w, y1 = h;
    int bx0, by0, bx1, by1;
    if (regions && regions->width() == w && regions->height() == h &&
        detail::label_box(*regions, &bx0, &by0, &bx1, &by1)) {
      constexpr int kNear = 56;  // outline fill 7 + margin 28 + kernel 6 at 4.6 px lines, and more
      x0 = std::max(0, bx0 - kNear), y0 = std::max(0, by0 - kNear);
      x1 = std::min(w, bx1 + 1 + kNear), y1 = std::min(h, by1 + 1 + kNear);
    }
    image_translucent_ = translucent_rows_of(*image_);
    cv::Mat raw(h, w, CV_32F, raw_.get());
    grey_into(*image_, 0, 0, cv::Rect(x0, y0, x1 - x0, y1 - y0), raw, nullptr, wide);
    raw_x0_ = x0, raw_y0_ = y0, raw_x1_ = x1, raw_y1_ = y1;
  };
  converting_ = worker_.submit(convert);
}

void LineResponse::ensure_raw(int x0, int y0, int x1, int y1) {
  const Image& image = *image_;
  x0 = std::max(0, x0), y0 = std::max(0, y0);
  x1 = std::min(image.width(), x1), y1 = std::min(image.height(), y1);
  if (x0 >= raw_x0_ && y0 >= raw_y0_ && x1 <= raw_x1_ && y1 <= raw_y1_) return;
  cv::Mat raw(image.height(), image.width(), CV_32F, raw_.get());
  grey_into(image, 0, 0, cv::Rect(0, 0, image.width(), image.height()), raw, nullptr,
            wide_vectors_);
  raw_x0_ = 0, raw_y0_ = 0, raw_x1_ = image.width(), raw_y1_ = image.height();
}

LineResponse::LineResponse(const Image& image, double line_width, int x0, int y0, int x1, int y1)
    : LineResponse(image) {
  smooth(line_width, x0, y0, x1, y1);
}

LineResponse::~LineResponse() {
  // The conversion, the early blur and the noise read the image or this
  // object's buffers and write them: they must end before those go (also
  // when smooth() was never called). The early blur waits for the
  // conversion itself, so it is waited for first.
  if (noise_.valid()) noise_.wait();
  if (smoothing_.valid()) smoothing_.wait();
  if (converting_.valid()) converting_.wait();
}

void LineResponse::prepare(double line_width, const LabelMap& filled) {
  if (smoothing_.valid() || filled.width() != image_->width() ||
      filled.height() != image_->height())
    return;
  // Every boundary smooth() will be given has a non-zero label on one side,
  // so it lies in the box of those labels' pixel corners; that box grown by
  // the margin holds smooth()'s window. Blurring it here, on a second core
  // while the caller traces the boundaries, gives the same values there: a
  // window's blur reads the pixels beyond it from the image.
  // No blur is under way (smoothing_ is not valid): a new one starts from
  // its first band.
  next_early_band_ = 0;
  early_ready_ = false;
  auto blur = [this, lw = std::max(1.0, line_width), &filled] {
    if (converting_.valid()) converting_.get();  // (not after a first smooth())
    int bx0, by0, bx1, by1;
    if (!detail::label_box(filled, &bx0, &by0, &bx1, &by1)) return;
    const Image& image = *image_;
    const int margin = window_margin(lw);
    const int x0 = std::max(0, bx0 - margin), y0 = std::max(0, by0 - margin);
    const int x1 = std::min(image.width(), bx1 + 1 + margin);
    const int y1 = std::min(image.height(), by1 + 1 + margin);
    // The blur reads a kernel's radius beyond the box.
    const int kr = kernel_radius(grey_sigma(lw));
    ensure_raw(x0 - kr, y0 - kr, x1 + kr, y1 + kr);
    early_grey_ =
        std::make_unique_for_overwrite<float[]>(static_cast<std::size_t>(x1 - x0) * (y1 - y0));
    early_ = {x0, y0, x1 - x0, y1 - y0, lw};
    early_ready_.store(true, std::memory_order_release);
    blur_early_bands();
  };
  smoothing_ = worker_.submit(blur);
}

void LineResponse::blur_early_bands() {
  // A band's blur reads the rows around it from the image, as the blur of
  // the whole box does inside it: the values are those of one call.
  const Image& image = *image_;
  const cv::Mat raw(image.height(), image.width(), CV_32F, raw_.get());
  cv::Mat smooth(early_.h, early_.w, CV_32F, early_grey_.get());
  const double sigma = grey_sigma(early_.line_width);
  for (int b = next_early_band_++; b < kEarlyBands; b = next_early_band_++) {
    const int r0 = early_.h * b / kEarlyBands, r1 = early_.h * (b + 1) / kEarlyBands;
    if (r1 <= r0) continue;
    try {
      cv::Mat dst = smooth.rowRange(r0, r1);
      cv::GaussianBlur(raw(cv::Rect(early_.x0, early_.y0 + r0, early_.w, r1 - r0)), dst,
                       cv::Size(0, 0), sigma, sigma, cv::BORDER_REPLICATE);
    } catch (const cv::Exception& e) {
      throw Error(std::string("layering: OpenCV failed while smoothing grey levels: ") + e.what());
    }
  }
}

void LineResponse::smooth(double line_width, int x0, int y0, int x1, int y1) {
  // Blur the early bands still left here, then rethrow what the conversion
  // or the early blur threw.
  if (smoothing_.valid()) {
    if (early_ready_.load(std::memory_order_acquire)) blur_early_bands();
    smoothing_.get();
  }
  if (converting_.valid()) converting_.get();
  const Image& image = *image_;
  line_width_ = std::max(1.0, line_width);
  x0_ = std::clamp(x0, 0, std::max(0, image.width() - 1));
  y0_ = std::clamp(y0, 0, std::max(0, image.height() - 1));
  w_ = std::clamp(x1, x0_ + 1, image.width()) - x0_;
  h_ = std::clamp(y1, y0_ + 1, image.height()) - y0_;
  // The window's blur reads a kernel's radius beyond it.
  const int kr = kernel_radius(grey_sigma(line_width_));
  ensure_raw(x0_ - kr, y0_ - kr, x0_ + w_ + kr, y0_ + h_ + kr);
  // The noise is measured on this window; the smoothed grey levels may be
  // kept for the larger one blurred early, whose values here are the same.
  const cv::Rect window(x0_, y0_, w_, h_);
  const bool early = early_grey_ && early_.line_width == line_width_ && early_.x0 <= x0_ &&
                     early_.y0 <= y0_ && x0_ + w_ <= early_.x0 + early_.w &&
                     y0_ + h_ <= early_.y0 + early_.h;
  if (early) {
    x0_ = early_.x0, y0_ = early_.y0, w_ = early_.w, h_ = early_.h;
    grey_ = std::move(early_grey_);
  }
  const std::size_t n = static_cast<std::size_t>(w_) * h_;
  if (!early) grey_ = std::make_unique_for_overwrite<float[]>(n);
  translucent_rows_.assign(h_ + 1, 0);
  for (int y = 0; y < h_; ++y)
    translucent_rows_[y + 1] = translucent_rows_[y] + image_translucent_[y0_ + y];
  try {
    // Colours for the paint on each side are smoothed at half a line width
    // (screentone dots and JPEG blocks average to their tone) only where
    // they are sampled, two pixels per point measured: a few percent of the
    // window, where blurring all of it cost as much as the rest of the
    // layering. The kernel is OpenCV's, as cv::GaussianBlur would use it.
    const double cs = colour_sigma(line_width_);
    const int ksize = static_cast<int>(std::lround(cs * 4 * 2 + 1)) | 1;
    const cv::Mat k = cv::getGaussianKernel(ksize, cs, CV_32F);
    colour_kernel_.assign(k.ptr<float>(), k.ptr<float>() + ksize);
#if defined(__SSE2__)
    colour_weights_.assign((ksize + 3) / 4 * 16, 0.0f);
    for (int i = 0; i < 4 * ksize; ++i) colour_weights_[i] = colour_kernel_[i / 4];
#endif
    const cv::Mat raw(image.height(), image.width(), CV_32F, raw_.get());
    const cv::Mat grey = raw(cv::Rect(x0_, y0_, w_, h_));
    cv::Mat smooth(h_, w_, CV_32F, grey_.get());
    if (early) {
      // Only the threshold needs the noise, after every line is measured: a
      // second core estimates it meanwhile (the measurements leave the
      // grey levels unchanged).
      auto noise = [raw_window = raw(window)] {
        try {
          return noise_of(raw_window);
        } catch (const cv::Exception& e) {
          throw Error(std::string("layering: OpenCV failed while estimating noise: ") + e.what());
        }
      };
      noise_ = worker_.submit(noise).share();
      return;
    }
    // Smooth at about a quarter line width: tones (screentone dots, JPEG
    // ringing) average out while a line keeps most of its depth. The top
    // rows on a second core, the bottom ones here after the noise. A band
    // reads the rows around it from the image (a pixel beyond the window
    // differs from the replicated edge, but no sample reads that far:
    // window_margin), so the values are those of one call.
    const double sigma = grey_sigma(line_width_);
    const int split = h_ * 11 / 20;
    auto blur_rows = [&](int r0, int r1) {
      if (r1 <= r0) return;
      cv::Mat dst = smooth.rowRange(r0, r1);
      cv::GaussianBlur(grey.rowRange(r0, r1), dst, cv::Size(0, 0), sigma, sigma,
                       cv::BORDER_REPLICATE);
    };
    // Not worth a thread for small windows; where no thread can be made,
    // the band runs here at get().
    const auto policy =
        n > 20000 ? std::launch::async | std::launch::deferred : std::launch::deferred;
    auto top = std::async(policy, [&] { blur_rows(0, split); });
    noise_sigma_ = noise_of(grey);
    blur_rows(split, h_);
    top.get();
  } catch (const cv::Exception& e) {
    throw Error(std::string("layering: OpenCV failed while measuring lines: ") + e.what());
  }
}

Rgb3f LineResponse::smoothed_colour(int x, int y) const {
  const int xi = std::clamp(x - x0_, 0, w_ - 1);
  const int yi = std::clamp(y - y0_, 0, h_ - 1);
  const int r = static_cast<int>(colour_kernel_.size()) / 2;
  const float* k = colour_kernel_.data();
  const int iw = image_->width();
  const Rgba* window = image_->data() + static_cast<std::size_t>(y0_) * iw + x0_;
#if defined(__SSE2__)
  // Columns first, four at a time (the kernel's width rounded up; the
  // weights past its end are 0), each pixel widened to four float lanes
  // (r, g, b, a). The kernel is symmetric: rows y − j and y + j are added as
  // integers (exact) before they are weighted. Only where the footprint lies
  // in the window and all its pixels are opaque.
  const int groups = (2 * r + 4) / 4;
  if (xi - r >= 0 && xi - r + 4 * groups <= w_ && yi - r >= 0 && yi + r < h_ &&
      translucent_rows_[yi + r + 1] == translucent_rows_[yi - r]) {
    const Rgba* centre = window + static_cast<std::size_t>(yi) * iw + xi - r;
#if defined(HAIR25D_LAYERING_AVX2)
    if (wide_vectors_)
      return colour_sum_avx2(centre, iw, r, groups, colour_kernel_.data(), colour_weights_.data());
#endif
    const __m128i zero = _mm_setzero_si128();
    __m128 sum = _mm_setzero_ps();
    const float* wv = colour_weights_.data() + 4 * r;  // wv + 4j: weight j in four lanes
    auto widen = [&](__m128i half, __m128 w, bool high) {
      return _mm_mul_ps(w, _mm_cvtepi32_ps(high ? _mm_unpackhi_epi16(half, zero)
                                                : _mm_unpacklo_epi16(half, zero)));
    };
    for (int g = 0; g < groups; ++g) {
      // The centre row, then the pairs of rows j above and below it.
      const __m128i mid = _mm_loadu_si128(reinterpret_cast<const __m128i*>(centre + 4 * g));
      __m128i lo = _mm_unpacklo_epi8(mid, zero), hi = _mm_unpackhi_epi8(mid, zero);
      __m128 w = _mm_loadu_ps(wv);
      __m128 c0 = widen(lo, w, false), c1 = widen(lo, w, true);
      __m128 c2 = widen(hi, w, false), c3 = widen(hi, w, true);
      const Rgba* above = centre + 4 * g;
      const Rgba* below = centre + 4 * g;
      for (int j = 1; j <= r; ++j) {
        above -= iw;
        below += iw;
        const __m128i up = _mm_loadu_si128(reinterpret_cast<const __m128i*>(above));
        const __m128i down = _mm_loadu_si128(reinterpret_cast<const __m128i*>(below));
        lo = _mm_add_epi16(_mm_unpacklo_epi8(up, zero), _mm_unpacklo_epi8(down, zero));
        hi = _mm_add_epi16(_mm_unpackhi_epi8(up, zero), _mm_unpackhi_epi8(down, zero));
        w = _mm_loadu_ps(wv + 4 * j);
        c0 = _mm_add_ps(c0, widen(lo, w, false));
        c1 = _mm_add_ps(c1, widen(lo, w, true));
        c2 = _mm_add_ps(c2, widen(hi, w, false));
        c3 = _mm_add_ps(c3, widen(hi, w, true));
      }
      const float* wg = colour_weights_.data() + 16 * g;
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg), c0));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 4), c1));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 8), c2));
      sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 12), c3));
    }
    alignas(16) float out[4];
    _mm_store_ps(out, sum);
    return {out[0], out[1], out[2]};
  }
#endif
  // Near the window's edges (the edge pixel repeats, BORDER_REPLICATE, as a
  // blur of the whole window would) and around translucent pixels.
  Float4 sum = {0, 0, 0, 0};
  for (int j = -r; j <= r; ++j) {
    const Rgba* row = window + static_cast<std::size_t>(std::clamp(yi + j, 0, h_ - 1)) * iw;
    Float4 acc = {0, 0, 0, 0};
    for (int i = -r; i <= r; ++i)
      acc += k[i + r] * colour_value(row[std::clamp(xi + i, 0, w_ - 1)]);
    sum += k[j + r] * acc;
  }
  return {sum[0], sum[1], sum[2]};
}

std::array<double, 3> LineResponse::sample_colour(double x, double y) const {
  // Nearest pixel: colours are smoothed.
  const Rgb3f c = smoothed_colour(floor_int(x), floor_int(y));
  return {c[0], c[1], c[2]};
}

BoundaryLine LineResponse::measure(const Polyline& curve, double skip, const LabelMap& labels,
                                   int left, int right) const {
  BoundaryLine out;
  if (curve.size() < 2) return out;
  const Polyline pts = resample_polyline(curve, 1.0);
  const int n = static_cast<int>(pts.size());
  const double total = polyline_length(curve);
  // Near short boundaries keep at least the middle third.
  skip = std::min(skip, total / 3.0);
  const Reach r = reach_of(line_width_);  // smooth_tiles() must cover it
  const double half = r.half;             // search for the line centre
  const double reach = r.paper;           // search for paper
  const int span = std::max(2, static_cast<int>(std::lround(line_width_)));
  const GreyView grey{grey_.get(), w_,      h_, static_cast<double>(x0_), static_cast<double>(y0_),
                      w_ - 1.0,    h_ - 1.0};
  const LabelView label{labels.data(), labels.width(), labels.height()};
  std::vector<double> values, colours;
  values.reserve(n);
  // Paint is sampled past the line, its anti-aliased rim and the colour
  // smoothing (the boundary may sit half a pixel off the line's centre), and
  // before the next line of a thin strand.
  const double paint_near = r.paint_near;
  const double paint_far = r.paint_far;
  const double farthest = std::max({half, reach, paint_far}) + 1.0;
  // The steps of the centre and paper searches below, made as they make
  // them, for the wide-vector path (padded to four by repeating the last).
  std::vector<double> centre_steps;
  for (double s = -half; s <= half + 1e-9; s += 0.5) centre_steps.push_back(s);
  const int centre_count = static_cast<int>(centre_steps.size());
  while (centre_steps.size() % 4 != 0) centre_steps.push_back(centre_steps.back());
  int paper_steps = 0;
  for (double s = 1.0; s <= reach; s += 1.0) ++paper_steps;
  double along = 0.0;
  // Every other point is plenty for a median, except on short boundaries.
  const int stride = n > 40 ? 2 : 1;
  for (int i = 0; i < n; ++i) {
    if (i > 0) along += (pts[i] - pts[i - 1]).norm();
    if (i % stride != 0 || along < skip || along > total - skip) continue;
    const Vec2 t = pts[std::min(n - 1, i + span)] - pts[std::max(0, i - span)];
    if (t.squaredNorm() == 0.0) continue;
    // On the screen the left of travel t is (t.y, −t.x).
    const Vec2 to_left = Vec2(t.y(), -t.x()).normalized();
    const double px = pts[i].x(), py = pts[i].y(), nx = to_left.x(), ny = to_left.y();
    // Every sample below lies within `farthest` of the point along the
    // normal; where that segment is well inside the window and the map (almost
    // always) the bounds need no checks, and coordinates are >= 0, so
    // truncation is the floor: the same values, fewer instructions.
    const bool inside = !check_every_sample_ && grey.holds(px, py, farthest * nx, farthest * ny) &&
                        label.holds(px, py, farthest * nx, farthest * ny);
    auto point = [&](auto fast) {
      auto sample = [&](double x, double y) {
        if constexpr (decltype(fast)::value)
          return grey.sample_inside(x, y);
        else
          return grey.sample(x, y);
      };
      auto label_at = [&](double x, double y) {
        if constexpr (decltype(fast)::value)
          return label.at_inside(x, y);
        else
          return label.at(x, y);
      };
      double centre = 1e9;
      double paper_left = -1.0, paper_right = -1.0;
#if defined(HAIR25D_LAYERING_AVX2)
      if (decltype(fast)::value && wide_vectors_ && centre_count > 0) {
        const PointSamples got =
            point_samples_avx2(grey, label, px, py, nx, ny, centre_steps.data(),
                               static_cast<int>(centre_steps.size()), paper_steps, left, right);
        centre = got.centre, paper_left = got.paper_left, paper_right = got.paper_right;
      } else
#endif
      {
        for (double s = -half; s <= half + 1e-9; s += 0.5)
          centre = std::min(centre, sample(px + s * nx, py + s * ny));
        for (double s = 1.0; s <= reach; s += 1.0) {
          const double lx = px + s * nx, ly = py + s * ny;
          const double rx = px - s * nx, ry = py - s * ny;
          if (label_at(lx, ly) == left) paper_left = std::max(paper_left, sample(lx, ly));
          if (label_at(rx, ry) == right) paper_right = std::max(paper_right, sample(rx, ry));
        }
      }
      if (paper_left < 0 || paper_right < 0) return;
      values.push_back(std::min(paper_left, paper_right) - centre);
      std::array<double, 3> paint_left{}, paint_right{};
      bool found_left = false, found_right = false;
      for (double s = paint_near; s <= paint_far + 1e-9 && !(found_left && found_right); s += 1.0) {
        const double lx = px + s * nx, ly = py + s * ny;
        const double rx = px - s * nx, ry = py - s * ny;
        if (!found_left && label_at(lx, ly) == left) {
          paint_left = sample_colour(lx, ly);
          found_left = true;
        }
        if (!found_right && label_at(rx, ry) == right) {
          paint_right = sample_colour(rx, ry);
          found_right = true;
        }
      }
      if (found_left && found_right) {
        double d2 = 0.0;
        for (int c = 0; c < 3; ++c)
          d2 += (paint_left[c] - paint_right[c]) * (paint_left[c] - paint_right[c]);
        colours.push_back(std::sqrt(d2 / 3.0));
      }
    };
    if (inside)
      point(std::true_type{});
    else
      point(std::false_type{});
  }
  if (!values.empty()) {
    std::vector<double> low = values;
    auto q = low.begin() + static_cast<std::ptrdiff_t>(low.size() / 4);
    std::nth_element(low.begin(), q, low.end());
    out.contrast_low = *q;
  }
  out.contrast = median_of(values);
  out.colour_difference = median_of(colours);
  return out;
}

double LineResponse::estimate_line_width(const Image& image) {
  // Dark runs: pixels well below the local paper level. Widths of runs along
  // rows and columns; the mode of the short ones is the typical line width.
  const cv::Mat grey = grey_of(image, 0, 0, image.width(), image.height());
  cv::Mat bright;
  cv::dilate(grey, bright, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(15, 15)));
  std::vector<int> histogram(32, 0);
  auto scan = [&](bool rows) {
    const int outer = rows ? grey.rows : grey.cols;
    const int inner = rows ? grey.cols : grey.rows;
    for (int o = 0; o < outer; o += 2) {
      int run = 0;
      for (int i = 0; i < inner; ++i) {
        const int y = rows ? o : i, x = rows ? i : o;
        const bool dark = grey.at<float>(y, x) < 0.5f * bright.at<float>(y, x);
        if (dark) {
          ++run;
        } else {
          if (run > 0 && run < static_cast<int>(histogram.size())) ++histogram[run];
          run = 0;
        }
      }
    }
  };
  scan(true);
  scan(false);
  const auto best = std::max_element(histogram.begin() + 1, histogram.end());
  if (*best == 0) return 2.0;
  // Runs cross lines at all angles, so the mode slightly overestimates.
  return static_cast<double>(best - histogram.begin());
}

}  // namespace hair25d::layering::detail
