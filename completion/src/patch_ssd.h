// The inner loop of the exemplar inpainting (inpaint.cpp): the sum of squared
// colour differences between one target patch's known pixels and a candidate
// patch, one patch row at a time, four RGBA pixels a step (SSE2 where the
// compiler targets it, the same sums in plain C++ otherwise).
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace hair25d::completion::detail {

class PatchRows {
 public:
  // A new target patch of radius r in an image `width` pixels wide.
  void reset(int radius, int width) {
    radius_ = radius;
    width_ = width;
    chunks_ = (2 * radius + 1 + 3) / 4;
    offsets_.clear();
    bytes_.clear();
    masks_.clear();
  }

  // Adds the target row `dy` (relative to the patch centre): `pixels` are its
  // 2r+1 RGBA pixels, use[k] says whether pixel k counts; `alpha` whether the
  // alpha channel counts as well as the colour.
  void add_row(int dy, const std::uint8_t* pixels, const std::vector<bool>& use, bool alpha) {
    offsets_.push_back((static_cast<std::ptrdiff_t>(dy) * width_ - radius_) * 4);
    const std::size_t at = bytes_.size();
    bytes_.resize(at + 16 * chunks_, 0);
    masks_.resize(at + 16 * chunks_, 0);
    for (int k = 0; k < 2 * radius_ + 1; ++k) {
      if (!use[k]) continue;
      for (int ch = 0; ch < 4; ++ch) {
        if (ch == 3 && !alpha) continue;
        bytes_[at + 4 * k + ch] = pixels[4 * k + ch];
        masks_[at + 4 * k + ch] = 0xFF;
      }
    }
  }

  std::size_t rows() const { return offsets_.size(); }

  // SSD of row `row` against the candidate centred at `centre` (RGBA bytes).
  // Reads up to 12 bytes past the candidate patch's last pixel: the source
  // buffer must be padded.
  int row_ssd(std::size_t row, const std::uint8_t* centre) const {
    const std::uint8_t* c = centre + offsets_[row];
    const std::uint8_t* t = bytes_.data() + 16 * chunks_ * row;
    const std::uint8_t* m = masks_.data() + 16 * chunks_ * row;
#if defined(__SSE2__)
    const __m128i zero = _mm_setzero_si128();
    __m128i acc = zero;
    for (int k = 0; k < chunks_; ++k) {
      const __m128i mask = _mm_loadu_si128(reinterpret_cast<const __m128i*>(m + 16 * k));
      const __m128i tv = _mm_loadu_si128(reinterpret_cast<const __m128i*>(t + 16 * k));
      const __m128i cv =
          _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(c + 16 * k)), mask);
      const __m128i dlo = _mm_sub_epi16(_mm_unpacklo_epi8(tv, zero), _mm_unpacklo_epi8(cv, zero));
      const __m128i dhi = _mm_sub_epi16(_mm_unpackhi_epi8(tv, zero), _mm_unpackhi_epi8(cv, zero));
      acc = _mm_add_epi32(acc, _mm_madd_epi16(dlo, dlo));
      acc = _mm_add_epi32(acc, _mm_madd_epi16(dhi, dhi));
    }
    acc = _mm_add_epi32(acc, _mm_shuffle_epi32(acc, _MM_SHUFFLE(1, 0, 3, 2)));
    acc = _mm_add_epi32(acc, _mm_shuffle_epi32(acc, _MM_SHUFFLE(2, 3, 0, 1)));
    return _mm_cvtsi128_si32(acc);
#else
    int sum = 0;
    for (int i = 0; i < 16 * chunks_; ++i) {
      const int d = t[i] - (c[i] & m[i]);
      sum += d * d;
    }
    return sum;
#endif
  }

 private:
  int radius_ = 0, width_ = 0, chunks_ = 0;
  std::vector<std::ptrdiff_t> offsets_;  // bytes from the centre to each row's first pixel
  std::vector<std::uint8_t> bytes_;      // target bytes, masked, 16 × chunks_ a row
  std::vector<std::uint8_t> masks_;      // 0xFF where a byte counts
};

}  // namespace hair25d::completion::detail
