#include "patch_model.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "hair25d/core/error.h"

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR25D_PATCH_AVX512 1
#endif

namespace hair25d::layering::detail {

namespace {

// The grey level of a pixel as the line measurements read it (Rec. 601).
float grey_at(const Image& image, int x, int y) {
  const Rgba& c = image.at(x, y);
  return 0.299f * c.r + 0.587f * c.g + 0.114f * c.b;
}

constexpr int kSamples = 2 * kPatchCells;

// One row of samples wholly inside the map: for each sample (at
// (ax[i] + bx, ay[i] + by), truncated), adds to `a_minus_b` +1 where the label
// is a, −1 where it is b, and to `other` 1 where it is another region (with
// `first`, writes those counts instead: no arrays to clear beforehand);
// with `pixels`, writes each sample's grey level to `grey` (grey_at's
// value). Written for the vectoriser: the two clones do the same integer
// and float operations lane by lane.
__attribute__((target_clones("avx512f", "avx2", "default"), optimize("fp-contract=off"))) void
sample_row(const int* labels, const Rgba* pixels, int w, const double* ax, const double* ay,
           double bx, double by, int a, int b, bool first, int* a_minus_b, int* other,
           float* grey) {
  std::array<int, kSamples> at, l;
  for (int i = 0; i < kSamples; ++i)
    at[i] = static_cast<int>(ay[i] + by) * w + static_cast<int>(ax[i] + bx);
  for (int i = 0; i < kSamples; ++i) l[i] = labels[at[i]];
  for (int i = 0; i < kSamples; ++i) {
    const int is_a = l[i] == a;
    const int is_b = (l[i] == b) & (is_a ^ 1);
    a_minus_b[i] = (first ? 0 : a_minus_b[i]) + is_a - is_b;
    other[i] = (first ? 0 : other[i]) + ((l[i] > 0) & ((is_a | is_b) ^ 1));
  }
  if (pixels == nullptr) return;
  std::array<std::uint32_t, kSamples> px;
  for (int i = 0; i < kSamples; ++i) std::memcpy(&px[i], pixels + at[i], sizeof(std::uint32_t));
  for (int i = 0; i < kSamples; ++i) {
    // Rgba's bytes r, g, b, a in memory order.
    const float r = static_cast<float>(static_cast<int>(px[i] & 0xff));
    const float g = static_cast<float>(static_cast<int>((px[i] >> 8) & 0xff));
    const float bl = static_cast<float>(static_cast<int>((px[i] >> 16) & 0xff));
    grey[i] = 0.299f * r + 0.587f * g + 0.114f * bl;
  }
}

#if defined(HAIR25D_PATCH_AVX512)
// GCC 12's AVX-512 intrinsics start many results from an "undefined"
// register, which its uninitialised-use check reports wherever they are
// inlined.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
// Sixteen doubles (two registers) truncated to ints.
__attribute__((target("avx512f"))) inline __m512i truncated(__m512d lo, __m512d hi) {
  const __mmask8 all = 0xff;
  return _mm512_maskz_inserti64x4(all, _mm512_zextsi256_si512(_mm512_maskz_cvttpd_epi32(all, lo)),
                                  _mm512_maskz_cvttpd_epi32(all, hi), 1);
}

// sample_row with the processor's gathers (AVX-512F), sixteen samples a
// load: where the compiler's clones extract each index and insert each label
// one at a time. The same indices (truncated sums of the same doubles), the
// same integer counts and the grey levels' products and sums in the same
// order, each apart (no fused multiply-adds), so the same values.
// With kBytes the labels are read from the map as bytes (byte_labels), each
// sample's four bytes from its own on, the first kept.
template <bool kBytes>
__attribute__((target("avx512f"))) inline __m512i gather_labels(__m512i zero, __mmask16 in,
                                                                __m512i at, const void* labels) {
  if constexpr (kBytes)
    return _mm512_and_si512(_mm512_mask_i32gather_epi32(zero, in, at, labels, 1),
                            _mm512_set1_epi32(0xff));
  else
    return _mm512_mask_i32gather_epi32(zero, in, at, labels, 4);
}

template <bool kBytes>
__attribute__((target("avx512f"), optimize("fp-contract=off"))) void sample_row_avx512(
    const void* labels, const Rgba* pixels, int w, const double* ax, const double* ay, double bx,
    double by, int a, int b, bool first, int* a_minus_b, int* other, float* grey) {
  const __m512d vbx = _mm512_set1_pd(bx), vby = _mm512_set1_pd(by);
  const __m512i vw = _mm512_set1_epi32(w), va = _mm512_set1_epi32(a), vb = _mm512_set1_epi32(b);
  const __m512i one = _mm512_set1_epi32(1), zero = _mm512_setzero_si512();
  const __m512i bytes = _mm512_set1_epi32(0xff);
  for (int i = 0; i < kSamples; i += 16) {
    const __m512i x = truncated(_mm512_add_pd(_mm512_loadu_pd(ax + i), vbx),
                                _mm512_add_pd(_mm512_loadu_pd(ax + i + 8), vbx));
    const __m512i y = truncated(_mm512_add_pd(_mm512_loadu_pd(ay + i), vby),
                                _mm512_add_pd(_mm512_loadu_pd(ay + i + 8), vby));
    const __m512i at = _mm512_add_epi32(_mm512_mullo_epi32(y, vw), x);
    const __m512i l = gather_labels<kBytes>(zero, 0xffff, at, labels);
    const __mmask16 is_a = _mm512_cmpeq_epi32_mask(l, va);
    const __mmask16 is_b = _mm512_mask_cmpeq_epi32_mask(static_cast<__mmask16>(~is_a), l, vb);
    const __mmask16 is_other =
        _mm512_mask_cmpgt_epi32_mask(static_cast<__mmask16>(~(is_a | is_b)), l, zero);
    __m512i d = first ? zero : _mm512_loadu_si512(a_minus_b + i);
    d = _mm512_mask_sub_epi32(_mm512_mask_add_epi32(d, is_a, d, one), is_b, d, one);
    _mm512_storeu_si512(a_minus_b + i, d);
    const __m512i o = first ? zero : _mm512_loadu_si512(other + i);
    _mm512_storeu_si512(other + i, _mm512_mask_add_epi32(o, is_other, o, one));
    if (pixels == nullptr) continue;
    const __m512i px = _mm512_mask_i32gather_epi32(zero, 0xffff, at, pixels, 4);
    const __m512 r = _mm512_cvtepi32_ps(_mm512_and_si512(px, bytes));
    const __m512 g = _mm512_cvtepi32_ps(_mm512_and_si512(_mm512_srli_epi32(px, 8), bytes));
    const __m512 bl = _mm512_cvtepi32_ps(_mm512_and_si512(_mm512_srli_epi32(px, 16), bytes));
    _mm512_storeu_ps(grey + i,
                     _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(_mm512_set1_ps(0.299f), r),
                                                 _mm512_mul_ps(_mm512_set1_ps(0.587f), g)),
                                   _mm512_mul_ps(_mm512_set1_ps(0.114f), bl)));
  }
}
// sample_row_avx512 for a row that may reach past the map: each sample at
// the floor of its sum (as the sample-by-sample loop takes it), samples
// outside the map read nothing (masked gathers): they add no label count,
// grey level 0 (adding +0 to a sum of non-negative levels leaves it as it
// is, bit for bit) and `inside` 0, where the others get 1.
template <bool kBytes>
__attribute__((target("avx512f"), optimize("fp-contract=off"))) void sample_row_clipped_avx512(
    const void* labels, const Rgba* pixels, int w, int h, const double* ax, const double* ay,
    double bx, double by, int a, int b, bool first, int* a_minus_b, int* other, float* grey,
    int* inside) {
  const __m512d vbx = _mm512_set1_pd(bx), vby = _mm512_set1_pd(by);
  const __m512i vw = _mm512_set1_epi32(w), vh = _mm512_set1_epi32(h);
  const __m512i va = _mm512_set1_epi32(a), vb = _mm512_set1_epi32(b);
  const __m512i one = _mm512_set1_epi32(1), zero = _mm512_setzero_si512();
  const __m512i bytes = _mm512_set1_epi32(0xff);
  constexpr int kFloor = _MM_FROUND_TO_NEG_INF | _MM_FROUND_NO_EXC;
  for (int i = 0; i < kSamples; i += 16) {
    const __m512i x =
        truncated(_mm512_roundscale_pd(_mm512_add_pd(_mm512_loadu_pd(ax + i), vbx), kFloor),
                  _mm512_roundscale_pd(_mm512_add_pd(_mm512_loadu_pd(ax + i + 8), vbx), kFloor));
    const __m512i y =
        truncated(_mm512_roundscale_pd(_mm512_add_pd(_mm512_loadu_pd(ay + i), vby), kFloor),
                  _mm512_roundscale_pd(_mm512_add_pd(_mm512_loadu_pd(ay + i + 8), vby), kFloor));
    // 0 <= x < w and 0 <= y < h, as unsigned compares.
    const __mmask16 in = _mm512_cmplt_epu32_mask(x, vw) & _mm512_cmplt_epu32_mask(y, vh);
    const __m512i at = _mm512_add_epi32(_mm512_mullo_epi32(y, vw), x);
    const __m512i l = gather_labels<kBytes>(zero, in, at, labels);
    const __mmask16 is_a = _mm512_cmpeq_epi32_mask(l, va) & in;
    const __mmask16 is_b = _mm512_mask_cmpeq_epi32_mask(static_cast<__mmask16>(~is_a & in), l, vb);
    const __mmask16 is_other =
        _mm512_mask_cmpgt_epi32_mask(static_cast<__mmask16>(~(is_a | is_b) & in), l, zero);
    __m512i d = first ? zero : _mm512_loadu_si512(a_minus_b + i);
    d = _mm512_mask_sub_epi32(_mm512_mask_add_epi32(d, is_a, d, one), is_b, d, one);
    _mm512_storeu_si512(a_minus_b + i, d);
    const __m512i o = first ? zero : _mm512_loadu_si512(other + i);
    _mm512_storeu_si512(other + i, _mm512_mask_add_epi32(o, is_other, o, one));
    if (pixels == nullptr) continue;
    _mm512_storeu_si512(inside + i, _mm512_maskz_mov_epi32(in, one));
    const __m512i px = _mm512_mask_i32gather_epi32(zero, in, at, pixels, 4);
    const __m512 r = _mm512_cvtepi32_ps(_mm512_and_si512(px, bytes));
    const __m512 g = _mm512_cvtepi32_ps(_mm512_and_si512(_mm512_srli_epi32(px, 8), bytes));
    const __m512 bl = _mm512_cvtepi32_ps(_mm512_and_si512(_mm512_srli_epi32(px, 16), bytes));
    _mm512_storeu_ps(grey + i,
                     _mm512_add_ps(_mm512_add_ps(_mm512_mul_ps(_mm512_set1_ps(0.299f), r),
                                                 _mm512_mul_ps(_mm512_set1_ps(0.587f), g)),
                                   _mm512_mul_ps(_mm512_set1_ps(0.114f), bl)));
  }
}
bool gathers_avx512_available() { return __builtin_cpu_supports("avx512f"); }
#pragma GCC diagnostic pop
#else
bool gathers_avx512_available() { return false; }
template <bool kBytes>
void sample_row_avx512(const void*, const Rgba*, int, const double*, const double*, double, double,
                       int, int, bool, int*, int*, float*) {}
template <bool kBytes>
void sample_row_clipped_avx512(const void*, const Rgba*, int, int, const double*, const double*,
                               double, double, int, int, bool, int*, int*, float*, int*) {}
#endif

}  // namespace

__attribute__((target_clones("avx512f", "default"), optimize("fp-contract=off"))) Patch
junction_patch(const LabelMap& labels, const PatchImage& drawing, const Vec2& centre,
               const Vec2& direction, int a, int b, bool a_on_left, double radius) {
  if (!(std::isfinite(radius) && radius > 0))
    throw Error("layering::junction_patch: radius = " + std::to_string(radius) +
                "; must be finite and > 0");
  const double norm = direction.norm();
  if (!(std::isfinite(norm) && norm > 0))
    throw Error("layering::junction_patch: direction (" + std::to_string(direction.x()) + ", " +
                std::to_string(direction.y()) + ") must be a finite non-zero vector");
  if (!(centre.allFinite() && centre.cwiseAbs().maxCoeff() < 1e8 && radius < 1e6))
    throw Error("layering::junction_patch: centre (" + std::to_string(centre.x()) + ", " +
                std::to_string(centre.y()) + ") and radius " + std::to_string(radius) +
                " must lie within 1e8 and 1e6 pixels");
  const Image* image = drawing.image;
  if (image != nullptr && (image->width() != labels.width() || image->height() != labels.height()))
    throw Error("layering::junction_patch: image " + std::to_string(image->width()) + " x " +
                std::to_string(image->height()) + " must be the label map's size " +
                std::to_string(labels.width()) + " x " + std::to_string(labels.height()));
  if (image != nullptr && !(std::isfinite(drawing.contrast) && drawing.contrast > 0))
    throw Error("layering::junction_patch: contrast = " + std::to_string(drawing.contrast) +
                "; must be finite and > 0");
  const Vec2 u = direction / norm;
  // On the screen (y down) the left of travel u is (u.y, −u.x).
  const Vec2 left(u.y(), -u.x());
  const Vec2 v = a_on_left ? left : Vec2(-left);
  Patch p{};
  // Grey sums of the first scale's cells and their sample counts (samples
  // outside the image are left out).
  std::array<float, kPatchGreyInputs> grey{};
  std::array<std::uint8_t, kPatchGreyInputs> counted{};
  // Sample offsets along u and v, products taken once: each sample point is
  // then (centre + cu·u) + cv·v, the same sums as written out per sample.
  std::array<double, kSamples> ax{}, ay{}, bx{}, by{};
  // Rows of samples with the processor's gathers (AVX-512F), from the map
  // as bytes where it is given and both regions have a byte of their own.
  const bool gathers = drawing.widest && gathers_avx512_available();
  const std::uint8_t* bytes = gathers && drawing.bytes != nullptr && a > 0 && a < kByteLabelMax &&
                                      b > 0 && b < kByteLabelMax
                                  ? drawing.bytes
                                  : nullptr;
  // The label scales: fine, wide, then the coarse one (after the grey
  // channel) when asked for.
  for (int scale = 0; scale < kPatchScales + (drawing.coarse ? 1 : 0); ++scale) {
    const double r = scale == 0             ? radius
                     : scale < kPatchScales ? kPatchWide * radius
                                            : kPatchCoarse * radius;
    const double cell = 2 * r / kPatchCells;
    for (int k = 0; k < kSamples; ++k) {
      const double c = -r + (k / 2 + 0.25 + 0.5 * (k % 2)) * cell;
      ax[k] = centre.x() + c * u.x();
      ay[k] = centre.y() + c * u.y();
      bx[k] = c * v.x();
      by[k] = c * v.y();
    }
    float* out = p.data() + (scale < kPatchScales ? scale * kPatchScaleInputs : kPatchCoarseStart);
    auto add = [&](float* c, int l) {
      if (l == a)
        c[0] += 0.25f;
      else if (l == b)
        c[0] -= 0.25f;
      else if (l > 0)
        c[1] += 0.25f;
    };
    const auto [ax0, ax1] = std::minmax_element(ax.begin(), ax.end());
    const auto [ay0, ay1] = std::minmax_element(ay.begin(), ay.end());
    const auto [bx0, bx1] = std::minmax_element(bx.begin(), bx.end());
    const auto [by0, by1] = std::minmax_element(by.begin(), by.end());
    // Every sample a pixel or more inside the map (most junctions): no
    // bounds checks, and truncation is the floor of a positive value.
    const bool inside = *ax0 + *bx0 >= 1 && *ay0 + *by0 >= 1 && *ax1 + *bx1 < labels.width() - 1 &&
                        *ay1 + *by1 < labels.height() - 1;
    const bool with_grey = scale == 0 && image != nullptr;
    // Inside the map (most junctions), a row of samples at a time: the
    // indices first (vectorisable), then the labels counted per cell (each
    // cell's channels are sums of ±0.25, exact in any order, so counts give
    // them to the bit) and the grey levels added in the samples' order.
    if (inside && static_cast<double>(labels.width()) * labels.height() < 2e9) {
      const int* label_data = labels.data();
      const Rgba* pixels = with_grey ? image->data() : nullptr;
      const int w = labels.width();
      for (int sj = 0; sj < kSamples; sj += 2) {
        std::array<int, kSamples> diff, other;
        std::array<float, kSamples> g;
        float* grey_row = grey.data() + (sj / 2) * kPatchCells;
        for (int half = 0; half < 2; ++half) {
          const double bxs = bx[sj + half], bys = by[sj + half];
          if (bytes != nullptr)
            sample_row_avx512<true>(bytes, pixels, w, ax.data(), ay.data(), bxs, bys, a, b,
                                    half == 0, diff.data(), other.data(), g.data());
          else if (gathers)
            sample_row_avx512<false>(label_data, pixels, w, ax.data(), ay.data(), bxs, bys, a, b,
                                     half == 0, diff.data(), other.data(), g.data());
          else
            sample_row(label_data, pixels, w, ax.data(), ay.data(), bxs, bys, a, b, half == 0,
                       diff.data(), other.data(), g.data());
          if (pixels == nullptr) continue;
          for (int i = 0; i < kPatchCells; ++i)
            grey_row[i] = (grey_row[i] + g[2 * i]) + g[2 * i + 1];
        }
        float* row = out + (sj / 2) * kPatchCells * kPatchChannels;
        for (int i = 0; i < kPatchCells; ++i) {
          row[2 * i] = 0.25f * static_cast<float>(diff[2 * i] + diff[2 * i + 1]);
          row[2 * i + 1] = 0.25f * static_cast<float>(other[2 * i] + other[2 * i + 1]);
        }
        if (pixels != nullptr) {
          std::uint8_t* count_row = counted.data() + (sj / 2) * kPatchCells;
          for (int i = 0; i < kPatchCells; ++i) count_row[i] = 4;
        }
      }
      continue;
    }
    // Reaching past the map (the coarse scale at most junctions): the same
    // rows with masked gathers where the processor has them.
    if (gathers && static_cast<double>(labels.width()) * labels.height() < 2e9) {
      const Rgba* pixels = with_grey ? image->data() : nullptr;
      for (int sj = 0; sj < kSamples; sj += 2) {
        std::array<int, kSamples> diff, other, in;
        std::array<float, kSamples> g;
        float* grey_row = grey.data() + (sj / 2) * kPatchCells;
        std::uint8_t* count_row = counted.data() + (sj / 2) * kPatchCells;
        for (int half = 0; half < 2; ++half) {
          const double bxs = bx[sj + half], bys = by[sj + half];
          if (bytes != nullptr)
            sample_row_clipped_avx512<true>(bytes, pixels, labels.width(), labels.height(),
                                            ax.data(), ay.data(), bxs, bys, a, b, half == 0,
                                            diff.data(), other.data(), g.data(), in.data());
          else
            sample_row_clipped_avx512<false>(labels.data(), pixels, labels.width(), labels.height(),
                                             ax.data(), ay.data(), bxs, bys, a, b, half == 0,
                                             diff.data(), other.data(), g.data(), in.data());
          if (pixels == nullptr) continue;
          for (int i = 0; i < kPatchCells; ++i) {
            grey_row[i] = (grey_row[i] + g[2 * i]) + g[2 * i + 1];
            count_row[i] = static_cast<std::uint8_t>(count_row[i] + in[2 * i] + in[2 * i + 1]);
          }
        }
        float* row = out + (sj / 2) * kPatchCells * kPatchChannels;
        for (int i = 0; i < kPatchCells; ++i) {
          row[2 * i] = 0.25f * static_cast<float>(diff[2 * i] + diff[2 * i + 1]);
          row[2 * i + 1] = 0.25f * static_cast<float>(other[2 * i] + other[2 * i + 1]);
        }
      }
      continue;
    }
    for (int sj = 0; sj < kSamples; ++sj) {
      float* row = out + (sj / 2) * kPatchCells * kPatchChannels;
      float* grey_row = grey.data() + (sj / 2) * kPatchCells;
      std::uint8_t* count_row = counted.data() + (sj / 2) * kPatchCells;
      for (int si = 0; si < kSamples; ++si) {
        const double qx = ax[si] + bx[sj];
        const double qy = ay[si] + by[sj];
        // floor without a library call (the values are within 1e8)
        int x = static_cast<int>(qx), y = static_cast<int>(qy);
        x -= qx < x;
        y -= qy < y;
        if (!labels.contains(x, y)) continue;
        add(row + (si / 2) * kPatchChannels, labels.at(x, y));
        if (with_grey) grey_row[si / 2] += grey_at(*image, x, y), ++count_row[si / 2];
      }
    }
  }
  if (image == nullptr) return p;
  // Darkness below the brightest of the 3 × 3 cells about each cell, as a
  // bar detector reads a line against the paint on both sides (a flat tone
  // reads 0 however dark; cells wholly outside the image are left out).
  std::array<float, kPatchGreyInputs> mean{}, across{};
  for (int c = 0; c < kPatchGreyInputs; ++c)
    mean[c] = counted[c] > 0 ? grey[c] / counted[c] : -1.0f;
  // The 3 × 3 maximum as a maximum along rows, then down columns (exact, so
  // the same as over the nine cells at once; uncounted cells never win).
  for (int j = 0; j < kPatchCells; ++j) {
    const float* m = mean.data() + j * kPatchCells;
    float* row_max = across.data() + j * kPatchCells;
    for (int i = 0; i < kPatchCells; ++i) {
      float best = m[i];
      if (i > 0) best = std::max(best, m[i - 1]);
      if (i + 1 < kPatchCells) best = std::max(best, m[i + 1]);
      row_max[i] = best;
    }
  }
  const float scale = static_cast<float>(1.0 / drawing.contrast);
  float* dark = p.data() + kPatchLabelInputs;
  for (int j = 0; j < kPatchCells; ++j)
    for (int i = 0; i < kPatchCells; ++i) {
      const int c = j * kPatchCells + i;
      if (counted[c] == 0) continue;
      float bright = across[c];
      if (j > 0) bright = std::max(bright, across[c - kPatchCells]);
      if (j + 1 < kPatchCells) bright = std::max(bright, across[c + kPatchCells]);
      dark[c] = std::min((bright - mean[c]) * scale, 2.0f);
    }
  return p;
}

__attribute__((target_clones("avx512f", "avx2", "default"))) void byte_labels(
    const LabelMap& labels, int x0, int x1, int y0, int y1, std::uint8_t* bytes) {
  const int w = labels.width();
  for (int y = y0; y < y1; ++y) {
    const int* row = labels.data() + static_cast<std::ptrdiff_t>(y) * w;
    std::uint8_t* out = bytes + static_cast<std::ptrdiff_t>(y) * w;
    for (int x = x0; x < x1; ++x)
      out[x] = static_cast<std::uint8_t>(std::min(std::max(row[x], 0), kByteLabelMax));
  }
}

bool patch_gathers_available() { return gathers_avx512_available(); }

Patch swapped(const Patch& patch) {
  Patch s{};
  for (int scale = 0; scale <= kPatchScales; ++scale)
    for (int j = 0; j < kPatchCells; ++j)
      for (int i = 0; i < kPatchCells; ++i) {
        const int base = scale < kPatchScales ? scale * kPatchScaleInputs : kPatchCoarseStart;
        const int from = base + (j * kPatchCells + i) * kPatchChannels;
        const int to = base + ((kPatchCells - 1 - j) * kPatchCells + i) * kPatchChannels;
        s[to] = -patch[from];
        s[to + 1] = patch[from + 1];
      }
  for (int j = 0; j < kPatchCells; ++j)
    for (int i = 0; i < kPatchCells; ++i)
      s[kPatchLabelInputs + (kPatchCells - 1 - j) * kPatchCells + i] =
          patch[kPatchLabelInputs + j * kPatchCells + i];
  return s;
}

double patch_radius(double reach) { return reach; }

double patch_contrast(double line_threshold) { return 2.5 * line_threshold; }

namespace {

#if defined(HAIR25D_PATCH_AVX512) && defined(HAIR25D_PATCH_MVEC)
// glibc's vector tanh (libmvec), eight doubles at a time with AVX-512.
extern "C" __m512d _ZGVeN8v_tanh(__m512d);  // NOLINT: glibc's vector ABI name

// The hidden units' tanh(0.5 α x) eight at a time (AVX-512F): libmvec's
// results are within a few units in the last place of std::tanh's, not the
// same bits.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
__attribute__((target("avx512f"))) void hidden_tanh_avx512(
    const PatchNet& net, const std::array<float, kPatchHidden>& sum,
    std::array<double, kPatchHidden>& out) {
  const __m512d half_alpha = _mm512_set1_pd(0.5 * net.alpha);
  for (int h = 0; h < kPatchHidden; h += 8) {
    const __m512d x = _mm512_cvtps_pd(_mm256_loadu_ps(sum.data() + h));
    _mm512_storeu_pd(out.data() + h, _ZGVeN8v_tanh(_mm512_mul_pd(half_alpha, x)));
  }
}
#pragma GCC diagnostic pop
bool tanh_avx512_available() { return __builtin_cpu_supports("avx512f"); }
#else
void hidden_tanh_avx512(const PatchNet&, const std::array<float, kPatchHidden>&,
                        std::array<double, kPatchHidden>&) {}
bool tanh_avx512_available() { return false; }
#endif

// The output layer on the hidden sums: β (1 − e^{−αx}) / (1 + e^{−αx}),
// written so that it cannot overflow. The hidden units' tanh by libmvec
// eight at a time where the processor has AVX-512F (a few units in the last
// place from std::tanh's: the scores differ from the plain path's in about
// the 15th digit), else one by one.
double net_output(const PatchNet& net, const std::array<float, kPatchHidden>& sum) {
  static const bool vector_tanh = tanh_avx512_available();
  std::array<double, kPatchHidden> t;
  if (vector_tanh && kPatchHidden % 8 == 0) {
    hidden_tanh_avx512(net, sum, t);
  } else {
    for (int h = 0; h < kPatchHidden; ++h) t[h] = std::tanh(0.5 * net.alpha * sum[h]);
  }
  double total = 0.0;
  for (int m = 0; m < kPatchMembers; ++m) {
    double out = net.b2[m];
    for (int h = m * kPatchMemberHidden; h < (m + 1) * kPatchMemberHidden; ++h)
      out += net.w2[h] * (net.beta * t[h]);
    total += net.beta * std::tanh(0.5 * net.alpha * out);
  }
  return total;
}

// A patch's non-zero inputs in increasing index order (the order in which
// patch_net adds them), and where each row of cells begins among them: the
// rows of the label scales (kPatchCells × kPatchChannels inputs each), then
// those of the grey channel (kPatchCells each), then the coarse scale's.
// Blocks of kPatchCells rows: the scales, the grey channel (block
// kPatchScales), the coarse scale.
constexpr int kPatchRows = (kPatchScales + 2) * kPatchCells;
constexpr bool label_block(int block) { return block != kPatchScales; }
// (Sixteen entries of room at the end: the AVX-512 path writes sixteen at
// a time past the last one.)
struct NonZeroInputs {
  int n = 0;
  std::array<std::uint16_t, kPatchInputs + 16> k;
  std::array<float, kPatchInputs + 16> x;
  std::array<int, kPatchRows + 1> row_start;
};

int row_begin(int r) {
  constexpr int grey_rows = kPatchScales * kPatchCells, coarse_rows = grey_rows + kPatchCells;
  return r <= grey_rows     ? r * kPatchCells * kPatchChannels
         : r <= coarse_rows ? kPatchLabelInputs + (r - grey_rows) * kPatchCells
                            : kPatchCoarseStart + (r - coarse_rows) * kPatchCells * kPatchChannels;
}

// The bits of the non-zero values among the n ≤ 32 floats at `x` (NaN
// counts as non-zero, −0 as zero, as `x == 0` reads them).
__attribute__((target_clones("avx2", "default"))) std::uint32_t non_zero_bits(const float* x,
                                                                              int n) {
  std::uint32_t bits = 0;
  for (int i = 0; i < n; ++i) bits |= static_cast<std::uint32_t>(!(x[i] == 0)) << i;
  return bits;
}

void non_zero_inputs(const Patch& patch, NonZeroInputs& out) {
  out.n = 0;
  for (int r = 0; r < kPatchRows; ++r) {
    out.row_start[r] = out.n;
    const int k0 = row_begin(r);
    for (std::uint32_t bits = non_zero_bits(patch.data() + k0, row_begin(r + 1) - k0); bits != 0;
         bits &= bits - 1) {
      const int k = k0 + std::countr_zero(bits);
      out.k[out.n] = static_cast<std::uint16_t>(k);
      out.x[out.n++] = patch[k];
    }
  }
  out.row_start[kPatchRows] = out.n;
}

// The non-zero inputs of swapped(patch) from those of the patch: rows in
// reverse order within each block, the A − B channel negated: its sign bit
// flipped (what negation does) without a branch, which mispredicted on the
// channels' mix of non-zero values.
void swapped_inputs(const NonZeroInputs& in, NonZeroInputs& out) {
  out.n = 0;
  for (int r = 0; r < kPatchRows; ++r) {
    out.row_start[r] = out.n;
    const int block = r / kPatchCells, j = r % kPatchCells;
    const int from = block * kPatchCells + (kPatchCells - 1 - j);
    const int shift = row_begin(r) - row_begin(from);
    const std::uint32_t sign = label_block(block) ? 0x80000000u : 0u;
    for (int e = in.row_start[from]; e < in.row_start[from + 1]; ++e) {
      const int k = in.k[e];
      const std::uint32_t flip = sign & (0u - static_cast<std::uint32_t>(k % kPatchChannels == 0));
      out.k[out.n] = static_cast<std::uint16_t>(k + shift);
      out.x[out.n++] = std::bit_cast<float>(std::bit_cast<std::uint32_t>(in.x[e]) ^ flip);
    }
  }
  out.row_start[kPatchRows] = out.n;
}

#if defined(HAIR25D_PATCH_AVX512)
bool inputs_avx512_available() { return __builtin_cpu_supports("avx512f"); }

// The non-zero ones of the sixteen inputs `x` (indices k, k + 1, ...) to
// the end of `list`, which then holds `n` entries: `x != 0` unordered,
// so NaN counts and −0 does not, as above.
__attribute__((target("avx512f"))) inline void pack_avx512(NonZeroInputs& list, int& n, __m512 x,
                                                           int k) {
  const __m512i lanes = _mm512_setr_epi32(0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15);
  const __mmask16 m = _mm512_cmp_ps_mask(x, _mm512_setzero_ps(), _CMP_NEQ_UQ);
  _mm512_storeu_ps(list.x.data() + n, _mm512_maskz_compress_ps(m, x));
  const __m512i at = _mm512_maskz_compress_epi32(m, _mm512_add_epi32(_mm512_set1_epi32(k), lanes));
  _mm256_storeu_si256(reinterpret_cast<__m256i*>(list.k.data() + n),
                      _mm512_maskz_cvtepi32_epi16(0xffff, at));
  n += std::popcount(static_cast<unsigned>(m));
}

// non_zero_inputs and swapped_inputs at once, sixteen inputs a compare
// (AVX-512F): the non-zero ones and their indices are packed to the lists'
// ends. The swapped list reads each row of the patch as the row it becomes,
// the A − B channel (the even inputs of the label rows) with its sign bit
// flipped: the same entries as swapped_inputs makes from the first list.
__attribute__((target("avx512f"))) void both_inputs_avx512(const Patch& patch, NonZeroInputs& in,
                                                           NonZeroInputs& swapped) {
  const __m512i even_signs = _mm512_set1_epi64(0x80000000);  // bit 31 of the even lanes
  int n = 0, ns = 0;
  for (int r = 0; r < kPatchRows; ++r) {
    in.row_start[r] = n;
    swapped.row_start[r] = ns;
    const int block = r / kPatchCells, j = r % kPatchCells;
    const int from = block * kPatchCells + (kPatchCells - 1 - j);
    const int k0 = row_begin(r), k1 = row_begin(r + 1), from0 = row_begin(from);
    const __m512i flip = label_block(block) ? even_signs : _mm512_setzero_si512();
    for (int k = k0; k < k1; k += 16) {
      pack_avx512(in, n, _mm512_loadu_ps(patch.data() + k), k);
      const __m512i other = _mm512_loadu_si512(patch.data() + from0 + (k - k0));
      pack_avx512(swapped, ns, _mm512_castsi512_ps(_mm512_xor_si512(other, flip)), k);
    }
  }
  in.n = in.row_start[kPatchRows] = n;
  swapped.n = swapped.row_start[kPatchRows] = ns;
}
#else
bool inputs_avx512_available() { return false; }
void both_inputs_avx512(const Patch&, NonZeroInputs&, NonZeroInputs&) {}
#endif

// The hidden sums of two networks on the non-zero inputs of `lists` patches
// (at most kMaxLists), the first network reading those below `first_inputs`:
// for each patch the same sums in the same order as patch_net's, without
// scanning the zeros. The patches are taken a row of cells at a time, all of
// them before the next row: a row's weights (8 KB of the 320 KB of both
// networks) are read from the second-level cache once for all the patches
// and then from the first level, where one patch after another read them all
// from the second level each.
constexpr int kMaxLists = 4;

// One input into all hidden sums: s += w · x per unit, with kFused as one
// fused multiply-add (one rounding), else a product and a sum.
template <bool kFused>
__attribute__((always_inline)) inline void add_input(std::array<float, kPatchHidden>& s,
                                                     const std::array<float, kPatchHidden>& w,
                                                     float x) {
  for (int h = 0; h < kPatchHidden; ++h) {
    if constexpr (kFused)
      s[h] = __builtin_fmaf(w[h], x, s[h]);
    else
      s[h] += w[h] * x;
  }
}

template <bool kFused>
__attribute__((always_inline)) inline void sparse_sums_body(
    const PatchNet& first, int first_inputs, const PatchNet& second, int second_inputs,
    const NonZeroInputs* const* in, int lists, std::array<float, kPatchHidden>* first_sum,
    std::array<float, kPatchHidden>* second_sum) {
  const int both_inputs = std::min(first_inputs, second_inputs);
  for (int l = 0; l < lists; ++l) {
    first_sum[l] = first.b1;
    second_sum[l] = second.b1;
  }
  for (int r = 0; r < kPatchRows; ++r) {
    for (int l = 0; l < lists; ++l) {
      const NonZeroInputs& list = *in[l];
      int e = list.row_start[r];
      const int end = list.row_start[r + 1];
      if (e == end) continue;
      std::array<float, kPatchHidden> s1 = first_sum[l], s2 = second_sum[l];
      for (; e < end && list.k[e] < both_inputs; ++e) {
        add_input<kFused>(s1, first.w1[list.k[e]], list.x[e]);
        add_input<kFused>(s2, second.w1[list.k[e]], list.x[e]);
      }
      for (; e < end && list.k[e] < first_inputs; ++e)
        add_input<kFused>(s1, first.w1[list.k[e]], list.x[e]);
      for (; e < end && list.k[e] < second_inputs; ++e)
        add_input<kFused>(s2, second.w1[list.k[e]], list.x[e]);
      first_sum[l] = s1;
      second_sum[l] = s2;
    }
  }
}

__attribute__((target_clones("avx512f", "avx2", "default"), optimize("fp-contract=off"))) void
sparse_sums(const PatchNet& first, int first_inputs, const PatchNet& second, int second_inputs,
            const NonZeroInputs* const* in, int lists, std::array<float, kPatchHidden>* first_sum,
            std::array<float, kPatchHidden>* second_sum) {
  sparse_sums_body<false>(first, first_inputs, second, second_inputs, in, lists, first_sum,
                          second_sum);
}

#if defined(HAIR25D_PATCH_AVX512)
// The same with fused multiply-adds (AVX-512F and FMA): half the operations;
// each sum rounds once per input, so the sums differ from the plain ones in
// the last bits, and patch_net adds the same way on such processors.
__attribute__((target("avx512f,fma"))) void sparse_sums_fused(
    const PatchNet& first, int first_inputs, const PatchNet& second, int second_inputs,
    const NonZeroInputs* const* in, int lists, std::array<float, kPatchHidden>* first_sum,
    std::array<float, kPatchHidden>* second_sum) {
  sparse_sums_body<true>(first, first_inputs, second, second_inputs, in, lists, first_sum,
                         second_sum);
}
bool fused_available() {
  return __builtin_cpu_supports("avx512f") && __builtin_cpu_supports("fma");
}
#else
void sparse_sums_fused(const PatchNet&, int, const PatchNet&, int, const NonZeroInputs* const*, int,
                       std::array<float, kPatchHidden>*, std::array<float, kPatchHidden>*) {}
bool fused_available() { return false; }
#endif

// Whether the hidden sums are taken with fused multiply-adds (the same
// choice for patch_net and patch_scores).
bool sums_fused() {
  static const bool fused = fused_available();
  return fused;
}

template <bool kFused>
__attribute__((always_inline)) inline std::array<float, kPatchHidden> net_sums_body(
    const PatchNet& net, const Patch& patch, int inputs) {
  // Most cells are background or one region on the fine scale's far side:
  // only non-zero inputs are added, each into all hidden sums at once.
  std::array<float, kPatchHidden> sum = net.b1;
  for (int k = 0; k < inputs; ++k) {
    const float x = patch[k];
    if (x == 0) continue;
    add_input<kFused>(sum, net.w1[k], x);
  }
  return sum;
}

// Two clones, chosen when the library loads: AVX2 adds the 16 hidden sums
// eight at a time. Neither has fused multiply-adds, so each lane does the
// same product and sum as the other clone and the sums are the same.
__attribute__((target_clones("avx2", "default"), optimize("fp-contract=off")))
std::array<float, kPatchHidden>
net_sums(const PatchNet& net, const Patch& patch, int inputs) {
  return net_sums_body<false>(net, patch, inputs);
}

#if defined(HAIR25D_PATCH_AVX512)
__attribute__((target("avx512f,fma"))) std::array<float, kPatchHidden> net_sums_fused(
    const PatchNet& net, const Patch& patch, int inputs) {
  return net_sums_body<true>(net, patch, inputs);
}
#else
std::array<float, kPatchHidden> net_sums_fused(const PatchNet& net, const Patch& patch,
                                               int inputs) {
  return net_sums(net, patch, inputs);
}
#endif

}  // namespace

double patch_net(const PatchNet& net, const Patch& patch, int inputs) {
  return net_output(
      net, sums_fused() ? net_sums_fused(net, patch, inputs) : net_sums(net, patch, inputs));
}

double patch_score(const PatchNet& net, const Patch& patch) {
  return patch_net(net, patch) - patch_net(net, swapped(patch));
}

double patch_same_score(const PatchNet& net, const Patch& patch) {
  return patch_net(net, patch) + patch_net(net, swapped(patch));
}

int patch_inputs_used(const PatchNet& net) {
  int used = 0;
  for (int k = 0; k < kPatchInputs; ++k)
    for (float w : net.w1[k])
      if (w != 0) used = k + 1;
  return used;
}

PatchScores patch_scores(const PatchNet& order, int order_inputs, const PatchNet& same,
                         const Patch& patch) {
  PatchScores out;
  patch_scores(order, order_inputs, same, &patch, 1, &out);
  return out;
}

void patch_scores(const PatchNet& order, int order_inputs, const PatchNet& same,
                  const Patch* patches, int count, PatchScores* out, bool widest, int same_inputs) {
  const bool avx512 = widest && inputs_avx512_available();
  // The zeros are found once per patch and the swapped patch's inputs taken
  // from the patch's; the sums of both networks over two patches (four
  // lists of inputs) at a time.
  constexpr int kAtOnce = kMaxLists / 2;
  std::array<NonZeroInputs, kMaxLists> lists;
  std::array<const NonZeroInputs*, kMaxLists> in;
  std::array<std::array<float, kPatchHidden>, kMaxLists> order_sum, same_sum;
  for (int p0 = 0; p0 < count; p0 += kAtOnce) {
    const int n = std::min(kAtOnce, count - p0);
    for (int p = 0; p < n; ++p) {
      if (avx512) {
        both_inputs_avx512(patches[p0 + p], lists[2 * p], lists[2 * p + 1]);
      } else {
        non_zero_inputs(patches[p0 + p], lists[2 * p]);
        swapped_inputs(lists[2 * p], lists[2 * p + 1]);
      }
      in[2 * p] = &lists[2 * p];
      in[2 * p + 1] = &lists[2 * p + 1];
    }
    (sums_fused() ? sparse_sums_fused : sparse_sums)(order, order_inputs, same, same_inputs,
                                                     in.data(), 2 * n, order_sum.data(),
                                                     same_sum.data());
    for (int p = 0; p < n; ++p)
      out[p0 + p] = {net_output(order, order_sum[2 * p]) - net_output(order, order_sum[2 * p + 1]),
                     net_output(same, same_sum[2 * p]) + net_output(same, same_sum[2 * p + 1])};
  }
}

std::vector<Patch> boundary_patches(const LabelMap& labels, const PatchImage& drawing,
                                    const BoundaryGraph& graph, const Boundary& b,
                                    const Vec2& start_direction, const Vec2& end_direction,
                                    double radius) {
  std::vector<Patch> out;
  if (b.closed() || b.points.empty()) return out;
  // Walking away from the start, b.left is on the left; away from the end,
  // on the right.
  if (start_direction.squaredNorm() > 0)
    out.push_back(junction_patch(labels, drawing, graph.junctions[b.start].position,
                                 start_direction, b.left, b.right, true, radius));
  if (end_direction.squaredNorm() > 0)
    out.push_back(junction_patch(labels, drawing, graph.junctions[b.end].position, end_direction,
                                 b.left, b.right, false, radius));
  return out;
}

}  // namespace hair25d::layering::detail
