// The AVX2 paths of the line response (line_samples.h): each lane does the
// same float and double products and sums, in the same order, as the SSE2
// and scalar paths of line_response.cpp (no fused multiply-add: the target is
// AVX2 alone), so the results are the same to the bit.
#include "line_samples.h"

#if defined(HAIR25D_LAYERING_AVX2)
#include <immintrin.h>

// GCC 12's AVX-512 intrinsics start many results from an "undefined"
// register, which its uninitialised-use check reports wherever they are
// inlined.
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"

namespace hair25d::layering::detail {
namespace {

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

// Sixteen 16-bit lanes (four pixels) to sixteen floats, in order.
__attribute__((target("avx2,avx512f"))) inline __m512 to_float_avx512(__m256i sixteen) {
  return _mm512_maskz_cvtepi32_ps(0xFFFF, _mm512_maskz_cvtepu16_epi32(0xFFFF, sixteen));
}
// Pixel k (four lanes) of a register of four.
template <int kQuarter>
__attribute__((target("avx2,avx512f"))) inline __m128 quarter_avx512(__m512 v) {
  return _mm512_maskz_extractf32x4_ps(0xF, v, kQuarter);
}
// Floats 0..7 (kHalf 0) or 8..15 (kHalf 1) of a register, as doubles.
template <int kHalf>
__attribute__((target("avx2,avx512f"))) inline __m512d half_to_double_avx512(__m512i v) {
  const __m256i part =
      kHalf == 0 ? _mm512_castsi512_si256(v) : _mm512_maskz_extracti64x4_epi64(0xF, v, 1);
  return _mm512_cvtps_pd(_mm256_castsi256_ps(part));
}
// Bilinear samples at (x, y) (eight lanes), as GreyView::sample_inside:
// bilinear_avx2's products and sums per lane (no fused multiply-adds).
__attribute__((target("avx2,avx512f"), optimize("fp-contract=off"))) inline __m512d bilinear_avx512(
    const GreyView& g, __m512d x, __m512d y) {
  const __m512d half = _mm512_set1_pd(0.5);
  x = _mm512_sub_pd(_mm512_sub_pd(x, half), _mm512_set1_pd(g.x0));
  y = _mm512_sub_pd(_mm512_sub_pd(y, half), _mm512_set1_pd(g.y0));
  const __m256i xi = _mm512_maskz_cvttpd_epi32(0xFF, x), yi = _mm512_maskz_cvttpd_epi32(0xFF, y);
  const __m512d fx = _mm512_sub_pd(x, _mm512_maskz_cvtepi32_pd(0xFF, xi));
  const __m512d fy = _mm512_sub_pd(y, _mm512_maskz_cvtepi32_pd(0xFF, yi));
  const __m256i at = _mm256_add_epi32(_mm256_mullo_epi32(yi, _mm256_set1_epi32(g.w)), xi);
  // Each pixel and its right-hand neighbour as one 64-bit lane, gathered
  // (the processor's gathers: one instruction for eight pairs where loading
  // them one by one and inserting them took two dozen); lanes 0..7 the
  // pixels, 8..15 their right-hand neighbours.
  const __m512i split = _mm512_setr_epi32(0, 2, 4, 6, 8, 10, 12, 14, 1, 3, 5, 7, 9, 11, 13, 15);
  const long long* pairs = reinterpret_cast<const long long*>(g.grey);
  const __m512i t =
      _mm512_maskz_permutexvar_epi32(0xFFFF, split, _mm512_i32gather_epi64(at, pairs, 4));
  const __m512i b = _mm512_maskz_permutexvar_epi32(
      0xFFFF, split,
      _mm512_i32gather_epi64(_mm256_add_epi32(at, _mm256_set1_epi32(g.w)), pairs, 4));
  const __m512d p0 = half_to_double_avx512<0>(t), p1 = half_to_double_avx512<1>(t);
  const __m512d p2 = half_to_double_avx512<0>(b), p3 = half_to_double_avx512<1>(b);
  const __m512d one = _mm512_set1_pd(1.0);
  const __m512d gx = _mm512_sub_pd(one, fx), gy = _mm512_sub_pd(one, fy);
  const __m512d upper = _mm512_add_pd(_mm512_mul_pd(gx, p0), _mm512_mul_pd(fx, p1));
  const __m512d lower = _mm512_add_pd(_mm512_mul_pd(gx, p2), _mm512_mul_pd(fx, p3));
  return _mm512_add_pd(_mm512_mul_pd(gy, upper), _mm512_mul_pd(fy, lower));
}
// The least and the largest of eight lanes.
__attribute__((target("avx2,avx512f"))) inline double min_of_avx512(__m512d v) {
  return min_of_avx2(
      _mm256_min_pd(_mm512_castpd512_pd256(v), _mm512_maskz_extractf64x4_pd(0xF, v, 1)));
}
__attribute__((target("avx2,avx512f"))) inline double max_of_avx512(__m512d v) {
  return max_of_avx2(
      _mm256_max_pd(_mm512_castpd512_pd256(v), _mm512_maskz_extractf64x4_pd(0xF, v, 1)));
}
// The lanes whose pixel of `label` holds `want`.
__attribute__((target("avx2,avx512f"))) inline __mmask8 label_mask_avx512(const LabelView& label,
                                                                          __m512d x, __m512d y,
                                                                          int want) {
  const __m256i at = _mm256_add_epi32(
      _mm256_mullo_epi32(_mm512_maskz_cvttpd_epi32(0xFF, y), _mm256_set1_epi32(label.w)),
      _mm512_maskz_cvttpd_epi32(0xFF, x));
  const __m256i got = _mm256_i32gather_epi32(label.labels, at, 4);
  return static_cast<__mmask8>(
      _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(got, _mm256_set1_epi32(want)))));
}
}  // namespace

// grey_into's opaque formula sixteen pixels at a time, eight per double
// vector (AVX-512F): the same products and sums in the same order, no fused
// multiply-adds, so the same floats. Returns how many pixels it did (a
// multiple of 16) and ANDs their alphas into `alpha`.
__attribute__((target("avx2,avx512f"), optimize("fp-contract=off"))) int grey_row_avx512(
    const Rgba* src, int n, float* row, unsigned* alpha) {
  const __m512i byte = _mm512_set1_epi32(0xFF);
  const __m512d wr = _mm512_set1_pd(0.299), wg = _mm512_set1_pd(0.587), wb = _mm512_set1_pd(0.114);
  __m512i alphas = _mm512_set1_epi32(-1);
  int x = 0;
  for (; x + 16 <= n; x += 16) {
    const __m512i px = _mm512_loadu_si512(src + x);
    const __m512i r16 = _mm512_and_si512(px, byte);
    const __m512i g16 = _mm512_and_si512(_mm512_srli_epi32(px, 8), byte);
    const __m512i b16 = _mm512_and_si512(_mm512_srli_epi32(px, 16), byte);
    alphas = _mm512_and_si512(alphas, px);
    __m256 half[2];
    for (int h = 0; h < 2; ++h) {
      auto part = [h](__m512i v) {
        return h == 0 ? _mm512_castsi512_si256(v) : _mm512_extracti64x4_epi64(v, 1);
      };
      const __m512d lum =
          _mm512_add_pd(_mm512_add_pd(_mm512_mul_pd(wr, _mm512_cvtepi32_pd(part(r16))),
                                      _mm512_mul_pd(wg, _mm512_cvtepi32_pd(part(g16)))),
                        _mm512_mul_pd(wb, _mm512_cvtepi32_pd(part(b16))));
      half[h] = _mm512_cvtpd_ps(lum);
    }
    _mm256_storeu_ps(row + x, half[0]);
    _mm256_storeu_ps(row + x + 8, half[1]);
  }
  alignas(64) std::uint32_t lanes[16];
  _mm512_store_si512(lanes, alphas);
  for (std::uint32_t v : lanes) *alpha &= v >> 24;
  return x;
}

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

// The column sums of kGroups groups of four pixels (groups g0 .. g0 +
// kGroups − 1), each group's in one 512-bit register, weighted into `sum`
// group by group. The groups' sums are independent chains of adds, run side
// by side (one alone waits on each add's latency).
template <int kGroups>
__attribute__((target("avx2,avx512f"), optimize("fp-contract=off"))) inline __m128
colour_groups_avx512(const Rgba* centre, std::ptrdiff_t iw, int r, int g0, const float* kernel,
                     const float* column_weights, __m128 sum) {
  __m512 c[kGroups];
  const __m512 w0 = _mm512_set1_ps(kernel[r]);
  for (int k = 0; k < kGroups; ++k)
    c[k] = _mm512_mul_ps(w0, to_float_avx512(widen_avx2(centre + 4 * (g0 + k))));
  const Rgba* above = centre + 4 * g0;
  const Rgba* below = centre + 4 * g0;
  for (int j = 1; j <= r; ++j) {
    above -= iw;
    below += iw;
    const __m512 w = _mm512_set1_ps(kernel[r + j]);
    for (int k = 0; k < kGroups; ++k) {
      const __m256i pair = _mm256_add_epi16(widen_avx2(above + 4 * k), widen_avx2(below + 4 * k));
      c[k] = _mm512_add_ps(c[k], _mm512_mul_ps(w, to_float_avx512(pair)));
    }
  }
  for (int k = 0; k < kGroups; ++k) {
    const float* wg = column_weights + 16 * (g0 + k);
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg), quarter_avx512<0>(c[k])));
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 4), quarter_avx512<1>(c[k])));
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 8), quarter_avx512<2>(c[k])));
    sum = _mm_add_ps(sum, _mm_mul_ps(_mm_loadu_ps(wg + 12), quarter_avx512<3>(c[k])));
  }
  return sum;
}

// colour_sum_avx2 with the four pixels of a group in one 512-bit register:
// every lane does the same float products and sums in the same order, and
// fused multiply-adds (which AVX-512 has) are kept out, so the same floats.
// Up to four groups' column sums are made side by side, then weighted in
// the groups' order.
__attribute__((target("avx2,avx512f"), optimize("fp-contract=off"))) Rgb3f colour_sum_avx512(
    const Rgba* centre, std::ptrdiff_t iw, int r, int groups, const float* kernel,
    const float* column_weights) {
  __m128 sum = _mm_setzero_ps();
  int g = 0;
  for (; g + 4 <= groups; g += 4)
    sum = colour_groups_avx512<4>(centre, iw, r, g, kernel, column_weights, sum);
  switch (groups - g) {
    case 3:
      sum = colour_groups_avx512<3>(centre, iw, r, g, kernel, column_weights, sum);
      break;
    case 2:
      sum = colour_groups_avx512<2>(centre, iw, r, g, kernel, column_weights, sum);
      break;
    case 1:
      sum = colour_groups_avx512<1>(centre, iw, r, g, kernel, column_weights, sum);
      break;
    default:
      break;
  }
  alignas(16) float out[4];
  _mm_store_ps(out, sum);
  return {out[0], out[1], out[2]};
}

// `offsets`: the centre search's steps along the normal, `count` of them
// padded to a multiple of eight by repeating the last; the paper search
// steps 1, 2, ... up to `paper_steps`.
// point_samples_avx2 eight samples at a time: the same values per lane
// (bilinear_avx512), and min / max do not depend on the order.
__attribute__((target("avx2,avx512f"), optimize("fp-contract=off"))) PointSamples
point_samples_avx512(const GreyView& grey, const LabelView& label, double px, double py, double nx,
                     double ny, const double* offsets, int count, int paper_steps, int left,
                     int right) {
  const __m512d vpx = _mm512_set1_pd(px), vpy = _mm512_set1_pd(py);
  const __m512d vnx = _mm512_set1_pd(nx), vny = _mm512_set1_pd(ny);
  __m512d centre = _mm512_set1_pd(1e9);
  for (int k = 0; k < count; k += 8) {
    const __m512d sv = _mm512_loadu_pd(offsets + k);
    centre = _mm512_min_pd(centre, bilinear_avx512(grey, _mm512_add_pd(vpx, _mm512_mul_pd(sv, vnx)),
                                                   _mm512_add_pd(vpy, _mm512_mul_pd(sv, vny))));
  }
  const __m512d none = _mm512_set1_pd(-1.0);
  __m512d paper_left = none, paper_right = none;
  for (int k = 1; k <= paper_steps; k += 8) {
    __m512d sv = _mm512_setr_pd(k, k + 1, k + 2, k + 3, k + 4, k + 5, k + 6, k + 7);
    // Steps past the last repeat it (max ignores the repeat).
    sv = _mm512_min_pd(sv, _mm512_set1_pd(paper_steps));
    const __m512d ox = _mm512_mul_pd(sv, vnx), oy = _mm512_mul_pd(sv, vny);
    const __m512d lx = _mm512_add_pd(vpx, ox), ly = _mm512_add_pd(vpy, oy);
    const __m512d rx = _mm512_sub_pd(vpx, ox), ry = _mm512_sub_pd(vpy, oy);
    paper_left =
        _mm512_max_pd(paper_left, _mm512_mask_blend_pd(label_mask_avx512(label, lx, ly, left), none,
                                                       bilinear_avx512(grey, lx, ly)));
    paper_right =
        _mm512_max_pd(paper_right, _mm512_mask_blend_pd(label_mask_avx512(label, rx, ry, right),
                                                        none, bilinear_avx512(grey, rx, ry)));
  }
  return {min_of_avx512(centre), max_of_avx512(paper_left), max_of_avx512(paper_right)};
}

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

}  // namespace hair25d::layering::detail
#endif
