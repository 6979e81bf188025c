// Helpers for scans over label rasters where almost every flag is 0 (outline
// fill, crack-grid trace): look at eight bytes at once and stop only at the
// few set ones.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>
#include <cstring>
#include <set>
#include <vector>

#include "hair25d/core/image.h"
#include "parallel.h"

#if defined(__SSE2__)
#include <emmintrin.h>
#endif
#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR25D_SCAN_AVX512 1
#endif

namespace hair25d::layering::detail {

// Calls f(x) for every x in [from, to) with flags[x] != 0, in increasing x.
template <class T, class F>
void for_each_set(const std::vector<T>& flags, int from, int to, F&& f) {
  static_assert(sizeof(T) <= 8 && 8 % sizeof(T) == 0);
  constexpr int kPerWord = 8 / sizeof(T);
  int x = from;
  for (; x + kPerWord <= to; x += kPerWord) {
    std::uint64_t word;
    std::memcpy(&word, flags.data() + x, sizeof word);
    if (word == 0) continue;
    for (int k = 0; k < kPerWord; ++k)
      if (flags[x + k] != 0) f(x + k);
  }
  for (; x < to; ++x)
    if (flags[x] != 0) f(x);
}

// out[i] = a[i] != b[i] (1 or 0) for i in [0, n): sixteen labels at a time.
inline void not_equal(const int* a, const int* b, int n, std::uint8_t* out) {
  int i = 0;
#if defined(__SSE2__)
  auto at = [](const int* p) { return _mm_loadu_si128(reinterpret_cast<const __m128i*>(p)); };
  const __m128i one = _mm_set1_epi8(1);
  for (; i + 16 <= n; i += 16) {
    // −1 where equal, 0 where not, narrowed to bytes; + 1 gives 0 / 1.
    const __m128i e0 = _mm_cmpeq_epi32(at(a + i), at(b + i));
    const __m128i e1 = _mm_cmpeq_epi32(at(a + i + 4), at(b + i + 4));
    const __m128i e2 = _mm_cmpeq_epi32(at(a + i + 8), at(b + i + 8));
    const __m128i e3 = _mm_cmpeq_epi32(at(a + i + 12), at(b + i + 12));
    const __m128i bytes = _mm_packs_epi16(_mm_packs_epi32(e0, e1), _mm_packs_epi32(e2, e3));
    _mm_storeu_si128(reinterpret_cast<__m128i*>(out + i), _mm_add_epi8(bytes, one));
  }
#endif
  for (; i < n; ++i) out[i] = static_cast<std::uint8_t>(a[i] != b[i]);
}

// The box of a map's non-zero labels (inclusive), where one was found
// otherwise (label_box's answer, kept to pass on).
struct LabelBox {
  bool any = false;
  int x0 = 0, y0 = 0, x1 = -1, y1 = -1;
};

#if defined(HAIR25D_SCAN_AVX512)
// The first x in [x, end) with r[x] != 0, or end: sixteen labels a compare
// (AVX-512F).
__attribute__((target("avx512f"))) inline int first_nonzero_avx512(const int* r, int x, int end) {
  for (; x + 16 <= end; x += 16) {
    const __m512i v = _mm512_loadu_si512(r + x);
    const unsigned m = _mm512_test_epi32_mask(v, v);
    if (m != 0) return x + __builtin_ctz(m);
  }
  for (; x < end; ++x)
    if (r[x] != 0) return x;
  return end;
}

// The last x in (stop, x] with r[x] != 0, or stop.
__attribute__((target("avx512f"))) inline int last_nonzero_avx512(const int* r, int x, int stop) {
  for (; x - 16 >= stop; x -= 16) {
    const __m512i v = _mm512_loadu_si512(r + x - 15);
    const unsigned m = _mm512_test_epi32_mask(v, v);
    if (m != 0) return x - 15 + (31 - __builtin_clz(m));
  }
  for (; x > stop; --x)
    if (r[x] != 0) return x;
  return stop;
}
#endif

// Rows and columns holding non-zero labels; false if there are none. Rows
// are scanned only outside the box found so far: from the top and the bottom
// for its rows, then within those from each side up to its columns (sixteen
// labels a compare with `widest` where the processor has AVX-512F; the same
// box either way).
inline bool label_box(const LabelMap& labels, int* x0, int* y0, int* x1, int* y1,
                      bool widest = true) {
  const int w = labels.width();
  auto row = [&](int y) { return labels.data() + static_cast<std::size_t>(y) * w; };
  auto any = [&](int y) {
    int bits = 0;  // a branch-free OR: most rows of a drawing are all paper or all hair
    for (int x = 0; x < w; ++x) bits |= row(y)[x];
    return bits != 0;
  };
  *y0 = 0;
  while (*y0 < labels.height() && !any(*y0)) ++*y0;
  if (*y0 == labels.height()) return false;
  *y1 = labels.height() - 1;
  while (!any(*y1)) --*y1;
  *x0 = w, *x1 = -1;
  // Paper beside the hair is skipped eight pixels at a time (an OR, which
  // vectorises), then the first label is found pixel by pixel.
  constexpr int kBlock = 8;
  auto zero_block = [](const int* p) {
    int bits = 0;
    for (int k = 0; k < kBlock; ++k) bits |= p[k];
    return bits == 0;
  };
#if defined(HAIR25D_SCAN_AVX512)
  if (widest && __builtin_cpu_supports("avx512f")) {
    for (int y = *y0; y <= *y1; ++y) {
      const int* r = row(y);
      *x0 = first_nonzero_avx512(r, 0, *x0);
      *x1 = last_nonzero_avx512(r, w - 1, *x1);
    }
    return true;
  }
#else
  (void)widest;
#endif
  for (int y = *y0; y <= *y1; ++y) {
    const int* r = row(y);
    int x = 0;
    while (x + kBlock <= *x0 && zero_block(r + x)) x += kBlock;
    for (; x < *x0; ++x)
      if (r[x] != 0) *x0 = x;  // the loop ends at once
    x = w - 1;
    while (x - kBlock >= *x1 && zero_block(r + x - kBlock + 1)) x -= kBlock;
    for (; x > *x1; --x)
      if (r[x] != 0) *x1 = x;
  }
  return true;
}

// The distinct non-zero labels of labels[from, to) into `seen`, in one pass.
// Runs of one label are long: blocks of sixteen pixels equal to the last
// label are skipped by one compare each (four with SSE2), and a label met
// again (across a line, the same few regions alternate) is found in a small
// cache before the set is asked.
inline void distinct_labels_into(const int* data, std::size_t from, std::size_t to,
                                 std::set<int>& seen, bool widest_blocks = true);

#if defined(HAIR25D_SCAN_AVX512)
// distinct_labels_into with AVX-512F: every label that differs from the one
// before it (and the first), found sixteen at a time by one compare of a
// block with the block a pixel to its left, is looked up in the cache and
// the set; the others are labels met just before. The same set.
__attribute__((target("avx512f"))) inline void distinct_changes_avx512(const int* data,
                                                                       std::size_t from,
                                                                       std::size_t to,
                                                                       std::set<int>& seen,
                                                                       std::array<int, 64>& cache) {
  auto look_up = [&](int v) {
    int& slot = cache[static_cast<unsigned>(v) & 63];
    if (v == 0 || slot == v) return;
    slot = v;
    seen.insert(v);
  };
  if (from >= to) return;
  look_up(data[from]);
  std::size_t i = from + 1;
  for (; i + 16 <= to; i += 16) {
    unsigned changes =
        _mm512_cmpneq_epi32_mask(_mm512_loadu_si512(data + i), _mm512_loadu_si512(data + i - 1));
    for (; changes != 0; changes &= changes - 1) look_up(data[i + __builtin_ctz(changes)]);
  }
  for (; i < to; ++i)
    if (data[i] != data[i - 1]) look_up(data[i]);
}
#endif

inline void distinct_labels_into(const int* data, std::size_t from, std::size_t to,
                                 std::set<int>& seen, bool widest_blocks) {
  std::array<int, 64> cache;  // cache[v & 63] == v: v is in `seen` (or 0)
  cache.fill(0);
  int last = 0;
  const std::size_t n = to;
  constexpr std::size_t kBlock = 16;
#if defined(HAIR25D_SCAN_AVX512)
  const bool widest = widest_blocks && __builtin_cpu_supports("avx512f");
  if (widest) {
    distinct_changes_avx512(data, from, to, seen, cache);
    return;
  }
#else
  constexpr bool widest = false;
  (void)widest_blocks;
#endif
  for (std::size_t i = from; i < n;) {
#if defined(__SSE2__)
    const __m128i same = _mm_set1_epi32(last);
    auto equal = [&](std::size_t at) {
      return _mm_cmpeq_epi32(_mm_loadu_si128(reinterpret_cast<const __m128i*>(data + at)), same);
    };
    for (; !widest && i + kBlock <= n; i += kBlock) {
      const __m128i all = _mm_and_si128(_mm_and_si128(equal(i), equal(i + 4)),
                                        _mm_and_si128(equal(i + 8), equal(i + 12)));
      if (_mm_movemask_epi8(all) != 0xFFFF) break;
    }
#else
    (void)widest;
    for (; i + kBlock <= n; i += kBlock) {
      int differs = 0;
      for (std::size_t k = 0; k < kBlock; ++k) differs |= data[i + k] ^ last;
      if (differs != 0) break;
    }
#endif
    for (const std::size_t end = std::min(n, i + kBlock); i < end; ++i) {
      const int v = data[i];
      if (v == last) continue;
      last = v;
      int& slot = cache[static_cast<unsigned>(v) & 63];
      if (v == 0 || slot == v) continue;
      slot = v;
      seen.insert(v);
    }
  }
}

// The distinct non-zero labels of `map`, sorted (LabelMap::labels sorts
// every pixel). The pass reads the whole map, so a large map is read in two
// halves on two cores (`pool`'s helper where one is given). With
// `widest_blocks` false, blocks are compared four labels at a time even
// where the processor has AVX-512F (the same labels, for tests).
class DistinctLabels {
 public:
  // Starts the scan: its halves go to `pool`'s helper (queued behind the
  // pool's earlier jobs) while the caller does other work.
  DistinctLabels(const LabelMap& map, Pool* pool, bool widest_blocks = true)
      : loop_(pool, map.size() >= kSplit ? 2 : 1, Part{&map, &seen_, widest_blocks}, 2, 1) {}
  // The labels, sorted; the halves no helper has taken are scanned here.
  std::vector<int> get() {
    loop_.finish();
    seen_[0].insert(seen_[1].begin(), seen_[1].end());
    return {seen_[0].begin(), seen_[0].end()};
  }

 private:
  static constexpr std::size_t kSplit = std::size_t{1}
                                        << 18;  // pixels below which one pass is quicker
  struct Part {
    const LabelMap* map;
    std::array<std::set<int>, 2>* seen;
    bool widest_blocks;
    void operator()(int p) const {
      const std::size_t n = map->size();
      const int parts = n >= kSplit ? 2 : 1;
      distinct_labels_into(map->data(), n * p / parts, n * (p + 1) / parts, (*seen)[p],
                           widest_blocks);
    }
  };
  std::array<std::set<int>, 2> seen_;  // before loop_: its items write here
  ParallelLoop<Part> loop_;
};

inline std::vector<int> distinct_labels(const LabelMap& map, Pool* pool = nullptr,
                                        bool widest_blocks = true) {
  return DistinctLabels(map, pool, widest_blocks).get();
}

// A fixed-size set of bits: an eighth of the memory of a byte a flag, so the
// per-corner and per-edge marks of a large image stay in cache.
class Bits {
 public:
  explicit Bits(std::size_t n) : words_((n + 63) / 64, 0) {}
  void set(std::size_t i) { words_[i >> 6] |= std::uint64_t{1} << (i & 63); }
  bool test(std::size_t i) const { return (words_[i >> 6] >> (i & 63)) & 1; }
  // Sets bit i; whether it was clear before.
  bool test_and_set(std::size_t i) {
    std::uint64_t& word = words_[i >> 6];
    const std::uint64_t bit = std::uint64_t{1} << (i & 63);
    const bool was_clear = (word & bit) == 0;
    word |= bit;
    return was_clear;
  }

 private:
  std::vector<std::uint64_t> words_;
};

}  // namespace hair25d::layering::detail
