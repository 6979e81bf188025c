// Outline pixels are 0 in an annotation's regions.png; giving each to its
// nearest region puts the boundary between two regions in the middle of the
// drawn line, which is where the junction geometry of §4.2 is measured.
#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <set>
#include <string>
#include <vector>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR25D_FILL_AVX2 1
#endif
#if defined(__SSE2__)
#include <emmintrin.h>
#define HAIR25D_FILL_SSE2 1
#endif

#include "hair25d/core/error.h"
#include "hair25d/layering/boundary_graph.h"
#include "outline_fill.h"
#include "parallel.h"
#include "raster_scan.h"

namespace hair25d::layering {
namespace {

// Chamfer steps in fifths of a pixel: 5 across an edge, 7 across a corner.
constexpr int kOrtho = 5;
constexpr int kDiag = 7;
constexpr int kUnit = 5;
constexpr double kMaxReach = 7.0;  // pixels grown at most: outlines up to ~14 px wide
// Growth limits (fifths of a pixel) up to which the filled box is kept per
// distance reached (a box per distance and band).
constexpr int kBoxedLimit = 1000;

// The part of the image a growth runs on: columns of the box of all regions
// grown by the growth limit, rows of one band of it, with a one-pixel frame so
// that neighbours need no bounds checks. Indices are row-major in the framed
// window, which keeps the raster order of the image and so the order in which
// fronts are seeded and expanded.
struct Window {
  int x0 = 0, y0 = 0;  // image position of the first pixel inside the frame
  int w = 0, h = 0;    // pixels inside the frame
  int stride() const { return w + 2; }
  int at(int x, int y) const { return (y - y0 + 1) * stride() + (x - x0 + 1); }
  int x_of(int i) const { return i % stride() - 1 + x0; }
  int y_of(int i) const { return i / stride() - 1 + y0; }
};

constexpr std::uint16_t kUnreached = std::numeric_limits<std::uint16_t>::max();

// A pixel (index in the window) put into a bucket of the growth, and the
// region that reached it there.
struct Front {
  int at;
  int owner;
};

// A bucket of the growth's ring: fronts in the order they were put there,
// with room for four more past its end after reserve(), which the AVX-512
// relaxation writes whole (an entry's improved neighbours compressed into
// one store, the count moved on by those improved).
class Bucket {
 public:
  std::size_t size() const { return static_cast<std::size_t>(end_ - data_.get()); }
  const Front& operator[](std::size_t k) const { return data_[k]; }
  const Front* data() const { return data_.get(); }
  void clear() { end_ = data_.get(); }
  // Room for n fronts and four more.
  void reserve(std::size_t n) {
    if (n + 4 > capacity_) [[unlikely]]
      regrow(n);
  }
  void push_back(const Front& f) {
    if (end_ + 4 >= room_) [[unlikely]]
      regrow(2 * size() + 16);
    *end_++ = f;
  }
  // The end, where up to four fronts may be written (after reserve(size() + 4)),
  // and how many of them to keep.
  Front* end() { return end_; }
  void grow_by(std::size_t n) { end_ += n; }

 private:
  __attribute__((noinline)) void regrow(std::size_t n) {
    const std::size_t grown = std::max(n + 4, 2 * capacity_), kept = size();
    auto more = std::make_unique_for_overwrite<Front[]>(grown);
    std::copy(data_.get(), end_, more.get());
    data_ = std::move(more);
    capacity_ = grown;
    end_ = data_.get() + kept;
    room_ = data_.get() + capacity_;
  }
  std::unique_ptr<Front[]> data_;
  Front* end_ = nullptr;   // past the last front
  Front* room_ = nullptr;  // past the room
  std::size_t capacity_ = 0;
};

struct Growth {
  Window box;
  // Chamfer distance (fifths of a pixel) to the nearest region: 0 on region
  // pixels and on the frame (so nothing grows into them), kUnreached on label-0
  // pixels not reached. 16 bits halve the memory traffic of the relaxation; the
  // growth limit keeps real distances far below kUnreached.
  std::unique_ptr<std::uint16_t[]> dist;
  // The region that reached a label-0 pixel; set only where dist was
  // lowered, so it needs no clearing.
  std::unique_ptr<int[]> owner;
  // Every label-0 pixel reached in the band's own rows, once, in the order
  // reached (not with `widest`, where the passes after the growth scan the
  // own rows for them instead).
  std::vector<int> reached;
  // The same pixels with their image position, final distance and owner,
  // listed on the band's core after its growth, so that the serial pass
  // which writes them into the map reads one array in order rather than
  // the band's distance and owner maps at scattered places.
  struct Given {
    int x, y, owner;
    std::uint16_t dist;
  };
  std::vector<Given> given;
};

#if defined(HAIR25D_FILL_AVX2)
// start_row and seed_row sixteen pixels at a time; they return how many
// pixels they did.
__attribute__((target("avx2"))) int start_row_avx2(const int* row, int n, std::uint16_t* out,
                                                   int x) {
  const __m256i zero = _mm256_setzero_si256();
  for (; x + 16 <= n; x += 16) {
    // −1 (kUnreached) where the label is 0; packs keeps −1 and 0, in lanes
    // ordered per 128-bit half, which the permute puts back in order.
    const __m256i a =
        _mm256_cmpeq_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + x)), zero);
    const __m256i b =
        _mm256_cmpeq_epi32(_mm256_loadu_si256(reinterpret_cast<const __m256i*>(row + x + 8)), zero);
    const __m256i packed = _mm256_permute4x64_epi64(_mm256_packs_epi32(a, b), 0xD8);
    _mm256_storeu_si256(reinterpret_cast<__m256i*>(out + x), packed);
  }
  return x;
}

__attribute__((target("avx2"))) inline __m256i at(const std::uint16_t* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

__attribute__((target("avx2"))) int seed_row_avx2(const std::uint16_t* mid, int stride, int n,
                                                  std::vector<int>& seeds, int x) {
  const __m256i zero = _mm256_setzero_si256();
  for (; x + 16 <= n; x += 16) {
    const std::uint16_t* u = mid - stride + x;
    const std::uint16_t* m = mid + x;
    const std::uint16_t* d = mid + stride + x;
    const __m256i around = _mm256_or_si256(
        _mm256_or_si256(_mm256_or_si256(at(u - 1), at(u)), _mm256_or_si256(at(u + 1), at(m - 1))),
        _mm256_or_si256(_mm256_or_si256(at(m + 1), at(d - 1)), _mm256_or_si256(at(d), at(d + 1))));
    const __m256i region = _mm256_cmpeq_epi16(at(m), zero);
    // Two bits per pixel, both set for a seed (around is 0 or all ones).
    auto bits = static_cast<std::uint32_t>(_mm256_movemask_epi8(_mm256_and_si256(region, around)));
    while (bits != 0) {
      const int b = std::countr_zero(bits);
      seeds.push_back(x + b / 2);
      bits &= ~(3u << b);
    }
  }
  return x;
}

// start_row and seed_row thirty-two pixels at a time (AVX-512F and BW), from
// x = 0; they return how many pixels they did.
__attribute__((target("avx2,avx512f,avx512bw"))) int start_row_avx512(const int* row, int n,
                                                                      std::uint16_t* out) {
  const __m512i zero = _mm512_setzero_si512();
  int x = 0;
  for (; x + 32 <= n; x += 32) {
    const std::uint32_t low = _mm512_cmpeq_epi32_mask(_mm512_loadu_si512(row + x), zero);
    const std::uint32_t high = _mm512_cmpeq_epi32_mask(_mm512_loadu_si512(row + x + 16), zero);
    // All ones (kUnreached) in the lanes of label 0.
    _mm512_storeu_si512(out + x, _mm512_movm_epi16(low | high << 16));
  }
  return x;
}

__attribute__((target("avx2,avx512f"))) inline __m512i at512(const std::uint16_t* p) {
  return _mm512_loadu_si512(p);
}

__attribute__((target("avx2,avx512f,avx512bw"))) int seed_row_avx512(const std::uint16_t* mid,
                                                                     int stride, int n,
                                                                     std::vector<int>& seeds) {
  int x = 0;
  for (; x + 32 <= n; x += 32) {
    const std::uint16_t* u = mid - stride + x;
    const std::uint16_t* m = mid + x;
    const std::uint16_t* d = mid + stride + x;
    const __m512i around =
        _mm512_or_si512(_mm512_or_si512(_mm512_or_si512(at512(u - 1), at512(u)),
                                        _mm512_or_si512(at512(u + 1), at512(m - 1))),
                        _mm512_or_si512(_mm512_or_si512(at512(m + 1), at512(d - 1)),
                                        _mm512_or_si512(at512(d), at512(d + 1))));
    // One bit per pixel: a region pixel with a label-0 neighbour.
    std::uint32_t bits = _mm512_cmpeq_epi16_mask(at512(m), _mm512_setzero_si512()) &
                         _mm512_test_epi16_mask(around, around);
    for (; bits != 0; bits &= bits - 1) seeds.push_back(x + std::countr_zero(bits));
  }
  return x;
}
#endif

// A row of the distance map before the growth: kUnreached on label 0, else
// 0 (out[x] from row[x], x in [0, n)).
void start_row(const int* row, int n, std::uint16_t* out, bool wide, bool widest) {
  int x = 0;
#if defined(HAIR25D_FILL_AVX2)
  if (widest) x = start_row_avx512(row, n, out);
  if (wide) x = start_row_avx2(row, n, out, x);
#else
  (void)wide, (void)widest;
#endif
  for (; x < n; ++x) out[x] = row[x] == 0 ? kUnreached : 0;
}

// The seeds of a row (`mid`, with the rows above and below at ∓stride),
// appended to `seeds` in increasing x: region pixels (0) with a label-0
// neighbour (kUnreached). Every distance is 0 or kUnreached yet, so "a
// label-0 neighbour" is an OR of the eight.
void seed_row(const std::uint16_t* mid, int stride, int n, std::vector<int>& seeds, bool wide,
              bool widest) {
  const std::uint16_t* up = mid - stride;
  const std::uint16_t* down = mid + stride;
  int x = 0;
#if defined(HAIR25D_FILL_AVX2)
  if (widest) x = seed_row_avx512(mid, stride, n, seeds);
  if (wide) x = seed_row_avx2(mid, stride, n, seeds, x);
#else
  (void)wide, (void)widest;
#endif
  for (; x < n; ++x) {
    const std::uint16_t around = up[x - 1] | up[x] | up[x + 1] | mid[x - 1] | mid[x + 1] |
                                 down[x - 1] | down[x] | down[x + 1];
    if (mid[x] == 0 && around != 0) seeds.push_back(x);
  }
}

#if defined(HAIR25D_FILL_AVX2)
__attribute__((target("avx2,avx512f,avx512bw"))) int reached_masks_avx512(const std::uint16_t* row,
                                                                          int n,
                                                                          std::uint32_t* masks) {
  const __m512i none = _mm512_set1_epi16(static_cast<short>(kUnreached));
  int x = 0;
  for (; x + 32 <= n; x += 32) {
    const __m512i v = _mm512_loadu_si512(row + x);
    masks[x / 32] = _mm512_test_epi16_mask(v, v) & _mm512_cmpneq_epi16_mask(v, none);
  }
  return x;
}
#endif

// Bit k % 32 of masks[k / 32]: whether row[k] (k in [0, n)) is a distance
// reached, neither 0 (a region or the frame) nor kUnreached; thirty-two a
// compare with `widest` (AVX-512F and BW).
void reached_masks(const std::uint16_t* row, int n, std::uint32_t* masks, bool widest) {
  int x = 0;
#if defined(HAIR25D_FILL_AVX2)
  if (widest) x = reached_masks_avx512(row, n, masks);
#else
  (void)widest;
#endif
  for (; x < n; x += 32) {
    std::uint32_t bits = 0;
    for (int k = 0; k < 32 && x + k < n; ++k)
      bits |= static_cast<std::uint32_t>(row[x + k] != 0 && row[x + k] != kUnreached) << k;
    masks[x / 32] = bits;
  }
}

// Whether start_row and seed_row may use AVX2, and AVX-512 (F, BW and VL:
// the growth's masked relaxation too).
bool wide_rows_available() {
#if defined(HAIR25D_FILL_AVX2)
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}
bool widest_rows_available() {
#if defined(HAIR25D_FILL_AVX2)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") &&
         __builtin_cpu_supports("avx512bw") && __builtin_cpu_supports("avx512vl");
#else
  return false;
#endif
}

#if defined(HAIR25D_FILL_SSE2)
// The distances a pixel's neighbours are offered, as compared by
// improved_neighbours: lanes of the rows above and of its own row (four
// each, from its left), and of the row below. Offsets are xor 0x8000 (an
// unsigned compare by a signed one); 0x7FFF never improves anything (the
// pixel itself, the fourth lanes, corners past the limit).
struct NeighbourLimits {
  __m128i above_mid;
  __m128i below;
};

inline NeighbourLimits neighbour_limits(int edge, int corner) {
  const auto e = static_cast<short>(edge ^ 0x8000);
  const auto c = static_cast<short>(corner < 0 ? 0x7FFF : corner ^ 0x8000);
  constexpr short kNever = 0x7FFF;
  return {_mm_setr_epi16(c, e, c, kNever, e, kNever, e, kNever),
          _mm_setr_epi16(c, e, c, kNever, kNever, kNever, kNever, kNever)};
}

// Bit b of the result: the distance of (ordinal) neighbour b is lowered by
// the offer, neighbours in relax order: right, left, down, up, then down
// right, up right, down left, up left. From movemask's bits (above: 0-2,
// own row: 4 and 6, below: 8-10).
constexpr std::array<std::uint8_t, 256> kAboveMidOrder = [] {
  std::array<std::uint8_t, 256> t{};
  for (int m = 0; m < 256; ++m)
    t[m] =
        static_cast<std::uint8_t>(((m >> 0 & 1) << 7) | ((m >> 1 & 1) << 3) | ((m >> 2 & 1) << 5) |
                                  ((m >> 4 & 1) << 1) | ((m >> 6 & 1) << 0));
  return t;
}();
constexpr std::array<std::uint8_t, 8> kBelowOrder = {
    0,      1 << 6,          1 << 2,          1 << 6 | 1 << 2,
    1 << 4, 1 << 6 | 1 << 4, 1 << 2 | 1 << 4, 1 << 6 | 1 << 2 | 1 << 4};

// Which of the eight neighbours of the pixel at `at` the offer lowers.
inline unsigned improved_neighbours(const std::uint16_t* at, int stride,
                                    const NeighbourLimits& lim) {
  auto four = [](const std::uint16_t* p) {
    return _mm_loadl_epi64(reinterpret_cast<const __m128i*>(p));
  };
  const __m128i bias = _mm_set1_epi16(static_cast<short>(0x8000));
  const __m128i above_mid =
      _mm_xor_si128(_mm_unpacklo_epi64(four(at - stride - 1), four(at - 1)), bias);
  const __m128i below = _mm_xor_si128(four(at + stride - 1), bias);
  const __m128i lower =
      _mm_packs_epi16(_mm_cmpgt_epi16(above_mid, lim.above_mid), _mm_cmpgt_epi16(below, lim.below));
  const auto m = static_cast<unsigned>(_mm_movemask_epi8(lower));
  return kAboveMidOrder[m & 0xFF] | kBelowOrder[(m >> 8) & 7];
}
#endif

#if defined(HAIR25D_FILL_AVX2)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#pragma GCC diagnostic ignored "-Wuninitialized"
// The fronts of bucket d (`count` of them from `fronts`) relaxed without a
// branch per neighbour (AVX-512F, BW and VL): a front's eight compares as in
// improved_neighbours (none for a stale entry), then the improved
// neighbours' distances and owners written by masked stores of the three
// rows, and their fronts compressed in relax order (right, left, down, up;
// then down right, up right, down left, up left) and stored whole at the
// ends of the edge bucket (d + kOrtho) and the corner bucket (d + kDiag),
// which are moved on by the counts improved. The same distances, owners and
// bucket order as the relaxations one neighbour after another, since a
// relaxation changes only its own neighbour. `corner` is d + kDiag, or −1
// past the limit.
__attribute__((target("avx2,avx512f,avx512bw,avx512vl"))) void relax_bucket_avx512(
    const Front* fronts, std::size_t count, int d, int corner, std::uint16_t* dist, int* owner,
    int stride, Bucket& edges, Bucket& corners) {
  edges.reserve(edges.size() + 4 * count);
  corners.reserve(corners.size() + 4 * count);
  const int edge = d + kOrtho;
  const auto e = static_cast<short>(edge ^ 0x8000);
  const auto c = static_cast<short>(corner < 0 ? 0x7FFF : corner ^ 0x8000);
  constexpr short kNever = 0x7FFF;
  const __m128i above_mid_limit = _mm_setr_epi16(c, e, c, kNever, e, kNever, e, kNever);
  const __m128i below_limit = _mm_setr_epi16(c, e, c, kNever, kNever, kNever, kNever, kNever);
  const __m128i bias = _mm_set1_epi16(static_cast<short>(0x8000));
  // The distances written: a row above or below (corner, edge, corner), the
  // own row (edge at the left and right lanes).
  const auto cd = static_cast<short>(corner), ed = static_cast<short>(edge);
  const __m128i row_values = _mm_setr_epi16(cd, ed, cd, 0, 0, 0, 0, 0);
  const __m128i mid_values = _mm_setr_epi16(ed, 0, ed, 0, 0, 0, 0, 0);
  const __m256i edge_offsets = _mm256_setr_epi64x(1, -1, stride, -stride);
  const __m256i corner_offsets =
      _mm256_setr_epi64x(stride + 1, -stride + 1, stride - 1, -stride - 1);
  Front* edge_end = edges.end();
  Front* corner_end = corners.end();
  for (std::size_t k = 0; k < count; ++k) {
    const int i = fronts[k].at;
    const int own = fronts[k].owner;
    // A stale entry (its pixel since lowered) relaxes nothing.
    const unsigned live = -static_cast<unsigned>(dist[i] == d);
    const std::uint16_t* at = dist + i;
    const __m128i above_mid = _mm_xor_si128(
        _mm_unpacklo_epi64(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(at - stride - 1)),
                           _mm_loadl_epi64(reinterpret_cast<const __m128i*>(at - 1))),
        bias);
    const __m128i below =
        _mm_xor_si128(_mm_loadl_epi64(reinterpret_cast<const __m128i*>(at + stride - 1)), bias);
    const unsigned am = _mm_cmpgt_epi16_mask(above_mid, above_mid_limit) & live;
    const unsigned bm = _mm_cmpgt_epi16_mask(below, below_limit) & live;
    const __mmask8 up_row = am & 7, mid_row = (am >> 4) & 5, down_row = bm & 7;
    _mm_mask_storeu_epi16(dist + i - stride - 1, up_row, row_values);
    _mm_mask_storeu_epi16(dist + i - 1, mid_row, mid_values);
    _mm_mask_storeu_epi16(dist + i + stride - 1, down_row, row_values);
    const __m128i owners = _mm_set1_epi32(own);
    _mm_mask_storeu_epi32(owner + i - stride - 1, up_row, owners);
    _mm_mask_storeu_epi32(owner + i - 1, mid_row, owners);
    _mm_mask_storeu_epi32(owner + i + stride - 1, down_row, owners);
    const unsigned order = kAboveMidOrder[am & 0xFF] | kBelowOrder[bm & 7];
    const __m256i front = _mm256_set1_epi64x(
        static_cast<long long>(static_cast<std::uint64_t>(static_cast<std::uint32_t>(i)) |
                               static_cast<std::uint64_t>(static_cast<std::uint32_t>(own)) << 32));
    // Neighbours lie inside the window (the frame), so i + offset ≥ 0 and
    // the 64-bit sum keeps the owner in the high half.
    const __mmask8 edge_bits = order & 0xF, corner_bits = order >> 4;
    _mm256_storeu_si256(
        reinterpret_cast<__m256i*>(edge_end),
        _mm256_maskz_compress_epi64(edge_bits, _mm256_add_epi64(front, edge_offsets)));
    edge_end += std::popcount(static_cast<unsigned>(edge_bits));
    _mm256_storeu_si256(
        reinterpret_cast<__m256i*>(corner_end),
        _mm256_maskz_compress_epi64(corner_bits, _mm256_add_epi64(front, corner_offsets)));
    corner_end += std::popcount(static_cast<unsigned>(corner_bits));
  }
  edges.grow_by(static_cast<std::size_t>(edge_end - edges.end()));
  corners.grow_by(static_cast<std::size_t>(corner_end - corners.end()));
}
#pragma GCC diagnostic pop
#endif

// Dial's algorithm: a multi-source shortest path on the 8-neighbour grid with a
// ring of buckets, linear in the pixel count. Fronts start from region pixels
// next to label 0, in raster order; where two fronts reach a pixel at the same
// distance the one expanded first keeps it. Runs on the rows [y0, y1) of
// `box` (the box's columns), keeping in `reached` the pixels of rows
// [own0, own1).
//
// Why a band gives the whole map's answer on its own rows: a pixel at
// distance d is decided by the pixels its fronts came through, all within
// d / kOrtho ≤ limit / kOrtho pixels of it (every step lowers the distance by
// at least kOrtho), and by which of them was expanded first. Within a bucket
// pixels are expanded in the order they were put there, that is in the order
// of (the expansion of the neighbour that first gave them that distance, the
// direction from it): a key made of pixels equally near, down to the seeds'
// raster order. So when the band reaches limit / kOrtho + 2 rows beyond its
// own (the +2: seeds are found from their neighbours), its own rows get the
// distances, owners and ties of one growth over the whole box.
Growth grow(const LabelMap& labels, const Window& box, int y0, int y1, int own0, int own1,
            int limit, bool wide, bool widest) {
  const int w = labels.width();
  Growth g;
  Window& win = g.box;
  win.x0 = box.x0;
  win.w = box.w;
  win.y0 = y0;
  win.h = y1 - y0;
  const int stride = win.stride();
  const std::size_t n = static_cast<std::size_t>(stride) * (win.h + 2);
  // Four more entries: the growth reads neighbours four at a time from a
  // pixel's left (improved_neighbours), up to two past the last corner.
  g.dist = std::make_unique_for_overwrite<std::uint16_t[]>(n + 4);
  std::fill(g.dist.get() + n, g.dist.get() + n + 4, 0);
  g.owner = std::make_unique_for_overwrite<int[]>(n);
  std::uint16_t* dist = g.dist.get();
  int* owner = g.owner.get();
  // The frame: rows above and below, and a column each side of every row.
  std::fill(dist, dist + stride, 0);
  std::fill(dist + n - stride, dist + n, 0);
  for (int y = 0; y < win.h; ++y) {
    const int* row = labels.data() + static_cast<std::size_t>(win.y0 + y) * w + win.x0;
    std::uint16_t* out = dist + win.at(win.x0, win.y0 + y);
    out[-1] = 0;
    out[win.w] = 0;
    start_row(row, win.w, out, wide, widest);
  }
  // Only region pixels on the edge of label 0 start a front, found a row at
  // a time (seed_row), in raster order. A front carries its owner, so a
  // pixel's owner is read from the bucket, not from the map (a cache miss);
  // the map keeps the owners of the label-0 pixels reached, for the passes
  // after the growth.
  std::array<Bucket, kDiag + 1> ring;
  std::vector<int> seeds;
  for (int y = 0; y < win.h; ++y) {
    const int base = win.at(win.x0, win.y0 + y);
    seeds.clear();
    seed_row(dist + base, stride, win.w, seeds, wide, widest);
    const int* row = labels.data() + static_cast<std::size_t>(win.y0 + y) * w + win.x0;
    for (int x : seeds) ring[0].push_back({base + x, row[x]});
  }
  // Every bucket holds about as many fronts as there are seeds (one ring
  // of pixels per step): reserving spares most regrowth and its copies.
  for (std::size_t k = 1; k < ring.size(); ++k) ring[k].reserve(ring[0].size());
  // Neighbour offsets: right, left, down, up, then the diagonals.
  const std::array<int, 4> ortho = {1, -1, stride, -stride};
  const std::array<int, 4> diag = {stride + 1, -stride + 1, stride - 1, -stride - 1};
  const int first = win.at(win.x0, own0), last = win.at(win.x0, own1);  // own rows' indices
  auto relax = [&](int j, int nd, int own) {
    // Region pixels and the frame hold 0, so they are never grown into.
    if (nd >= dist[j]) return;
    if (dist[j] == kUnreached && j >= first && j < last) g.reached.push_back(j);
    dist[j] = static_cast<std::uint16_t>(nd);
    owner[j] = own;
    ring[nd % ring.size()].push_back({j, own});
  };
  // Each seed reaches a few pixels; reserving avoids most regrowth.
  if (!widest) g.reached.reserve(4 * ring[0].size());
  std::size_t pending = ring[0].size();
#if defined(HAIR25D_FILL_SSE2)
  // The neighbours in relax order (the bits of improved_neighbours).
  const std::array<int, 8> around = {1,          -1,          stride,     -stride,
                                     stride + 1, -stride + 1, stride - 1, -stride - 1};
#endif
  for (int d = 0; pending > 0; ++d) {
    auto& bucket = ring[d % ring.size()];
    // Entries may be added to this bucket while it is processed only with
    // weight 0, which never happens, so iterating by index is safe.
#if defined(HAIR25D_FILL_SSE2)
    // With `wide`, the eight compares of a pixel at once; then only the
    // neighbours they improve are relaxed, in the same order (a relaxation
    // changes only its own neighbour, so the compares do not depend on each
    // other): the same distances, owners and bucket order.
#if defined(HAIR25D_FILL_AVX2)
    if (widest) {
      if (d + kOrtho <= limit)
        relax_bucket_avx512(bucket.data(), bucket.size(), d, d + kDiag <= limit ? d + kDiag : -1,
                            dist, owner, stride, ring[(d + kOrtho) % ring.size()],
                            ring[(d + kDiag) % ring.size()]);
    } else
#endif
        if (wide) {
      if (d + kOrtho <= limit) {
        const NeighbourLimits lim =
            neighbour_limits(d + kOrtho, d + kDiag <= limit ? d + kDiag : -1);
        for (std::size_t k = 0; k < bucket.size(); ++k) {
          const auto [i, own] = bucket[k];
          if (dist[i] != d) continue;  // a stale entry
          for (unsigned bits = improved_neighbours(dist + i, stride, lim); bits != 0;
               bits &= bits - 1) {
            const int b = std::countr_zero(bits);
            const int j = i + around[b];
            const int nd = b < 4 ? d + kOrtho : d + kDiag;
            if (dist[j] == kUnreached && j >= first && j < last) g.reached.push_back(j);
            dist[j] = static_cast<std::uint16_t>(nd);
            owner[j] = own;
            ring[nd % ring.size()].push_back({j, own});
          }
        }
      }
    } else
#endif
    {
      for (std::size_t k = 0; k < bucket.size(); ++k) {
        const auto [i, own] = bucket[k];
        if (dist[i] != d) continue;  // a stale entry
        if (d + kOrtho > limit) continue;
        for (int s : ortho) relax(i + s, d + kOrtho, own);
        if (d + kDiag > limit) continue;
        for (int s : diag) relax(i + s, d + kDiag, own);
      }
    }
    bucket.clear();
    pending = 0;  // entries still waiting in any bucket
    for (const auto& r : ring) pending += r.size();
  }
  return g;
}

}  // namespace

namespace detail {

OutlineFill fill_outlines_in_bands(const LabelMap& labels, const OutlineFillOptions& options,
                                   int max_bands, int min_band_rows, bool wide_rows, Pool* pool,
                                   LabelBox* filled_box, bool widest_rows, std::vector<int>* ids,
                                   const BeforeWrites& before_writes) {
  std::string why;
  if (!options.is_valid(&why)) throw Error("layering: " + why);
  if (labels.empty()) throw Error("layering: label map is empty; need at least one pixel");
  // Lines wider than this are not outlines but background gaps; growing no
  // farther keeps the cost to a band around the regions.
  const double reach = options.max_distance > 0 ? options.max_distance : kMaxReach;
  const int limit = static_cast<int>(std::ceil(std::min(reach * kUnit, 60000.0)));
  OutlineFill out;
  int bx0, by0, bx1, by1;
  if (filled_box != nullptr) *filled_box = LabelBox{};
  if (ids != nullptr) ids->clear();
  // The copy of the map the pixels are written into starts on the pool's
  // helper at once (on a large map, where bands run on two cores), while
  // this thread looks for the label box: the helper, busy from the start,
  // then goes on to the bands. Small maps are copied here.
  const bool copy_early = pool != nullptr && pool->helpers() > 0 &&
                          labels.height() >= 2 * min_band_rows && max_bands > 1;
  auto copy_map = [&out, &labels] { out.labels = labels; };
  BackgroundTask copy_task(copy_early ? pool : nullptr, copy_map);
  if (!detail::label_box(labels, &bx0, &by0, &bx1, &by1)) {
    copy_task.finish();  // no non-zero label: no ids
    out.radius = options.max_distance > 0 ? options.max_distance : 0.0;
    out.radius = std::min(out.radius, static_cast<double>(limit) / kUnit);
    return out;
  }
  // A pixel c steps (Chebyshev) from every region is at least c · kOrtho away.
  const int margin = limit / kOrtho + 1;
  Window box;
  box.x0 = std::max(0, bx0 - margin);
  box.y0 = std::max(0, by0 - margin);
  box.w = std::min(labels.width(), bx1 + margin + 1) - box.x0;
  box.h = std::min(labels.height(), by1 + margin + 1) - box.y0;
  // Bands of the box's rows, each grown on its own core over its rows and
  // the rows within reach (grow()), to the same result as one growth.
  const int reach_rows = limit / kOrtho + 2;
  const bool wide = wide_rows && wide_rows_available();
  const bool widest = wide && widest_rows && widest_rows_available();
  const int bands = std::clamp(std::min(max_bands, box.h / std::max(1, min_band_rows)), 1, 64);
  std::vector<Growth> growth(bands);
  std::vector<std::vector<int>> meets(bands);
  std::vector<std::size_t> one_pixel(bands, 0);  // crossings of lines one pixel wide
  // Per band, the box of the pixels reached at each distance (up to a limit
  // of kBoxedLimit): the filled map's box is known from them once the
  // radius is, before the pixels are written.
  const bool boxed = limit <= kBoxedLimit;
  std::vector<std::vector<LabelBox>> by_distance(bands);
  // The ids are two more items (halves of the label box's rows: outside it
  // the map is 0), on whichever core is free (here on small maps).
  constexpr int kIdParts = 2;
  std::array<std::set<int>, kIdParts> seen;
  auto read_ids = [&](int part) {
    const std::size_t w = static_cast<std::size_t>(labels.width());
    const int rows = by1 + 1 - by0;
    const int y0 = by0 + static_cast<int>(static_cast<long long>(rows) * part / kIdParts);
    const int y1 = by0 + static_cast<int>(static_cast<long long>(rows) * (part + 1) / kIdParts);
    for (int y = y0; y < y1; ++y)
      distinct_labels_into(labels.data(), y * w + bx0, y * w + bx1 + 1, seen[part]);
  };
  const int id_items = ids != nullptr ? kIdParts : 0;
  if (bands == 1) {
    copy_task.finish();
    for (int part = 0; part < id_items; ++part) read_ids(part);
  }
  // Without the early copy (no pool: the threads started for the call
  // start late), the copy is the item after the bands, then the ids.
  const int copy_items = bands > 1 && !copy_early ? 1 : 0;
  detail::parallel_for(
      pool, bands == 1 ? 1 : bands + copy_items + id_items,
      [&](int b) {
        if (b >= bands) {
          if (b < bands + copy_items)
            copy_task.finish();
          else
            read_ids(b - bands - copy_items);
          return;
        }
        const int own0 = box.y0 + static_cast<int>(static_cast<long long>(box.h) * b / bands);
        const int own1 = box.y0 + static_cast<int>(static_cast<long long>(box.h) * (b + 1) / bands);
        growth[b] =
            grow(labels, box, std::max(box.y0, own0 - reach_rows),
                 std::min(box.y0 + box.h, own1 + reach_rows), own0, own1, limit, wide, widest);
        // Where fronts of two regions meet inside label-0 pixels, each side
        // has come about half a line width: the typical meeting distance
        // measures the lines. Each pair of 4-neighbours is counted once, from
        // its left or upper pixel (the one below may be in the next band's
        // rows, which this band's growth also holds as they are).
        const Growth& g = growth[b];
        const std::uint16_t* dist = g.dist.get();
        const int* owner = g.owner.get();
        const int stride = g.box.stride();
        std::vector<int>& meet = meets[b];
        Growth::Given* given = nullptr;  // the next to write
        const int* map = labels.data();
        const std::size_t map_w = static_cast<std::size_t>(labels.width());
        std::vector<LabelBox>& boxes = by_distance[b];
        const LabelBox none{false, std::numeric_limits<int>::max(), std::numeric_limits<int>::max(),
                            -1, -1};
        if (boxed) boxes.assign(limit + 1, none);
        auto visit = [&](int i, int x, int y) __attribute__((always_inline)) {
          *given++ = {x, y, owner[i], dist[i]};
          if (boxed) {
            LabelBox& r = boxes[dist[i]];
            r.x0 = std::min(r.x0, x), r.x1 = std::max(r.x1, x);
            r.y0 = std::min(r.y0, y), r.y1 = std::max(r.y1, y);
          }
          for (int j : {i + 1, i + stride}) {
            // The frame and region pixels hold 0, unreached pixels kUnreached.
            if (dist[j] == 0 || dist[j] == kUnreached || owner[j] == owner[i]) continue;
            meet.push_back(std::max(dist[i], dist[j]));
          }
          // A line one pixel wide has no two fronts meeting inside it: the
          // front of one region steps straight onto the other region's own
          // pixels. Such crossings — a label-0 pixel between the pixels of
          // two regions across it, along a row or a column — are counted
          // apart (the frame, also 0 in `dist`, lies outside the map's
          // regions).
          if (dist[i] != kOrtho) return;
          auto label_at = [&](int nx, int ny) {
            if (nx < g.box.x0 || nx >= g.box.x0 + g.box.w || ny < 0 || ny >= labels.height())
              return 0;
            return map[static_cast<std::size_t>(ny) * map_w + nx];
          };
          if (dist[i - 1] == 0 && dist[i + 1] == 0) {
            const int l = label_at(x - 1, y), r = label_at(x + 1, y);
            if (l != 0 && r != 0 && l != r) {
              ++one_pixel[b];
              return;
            }
          }
          if (dist[i - stride] == 0 && dist[i + stride] == 0) {
            const int u = label_at(x, y - 1), d = label_at(x, y + 1);
            if (u != 0 && d != 0 && u != d) ++one_pixel[b];
          }
        };
        // The pixels reached in the own rows: in the order reached (the
        // growth's list), or with `widest` in raster order, found by a scan
        // of the distances thirty-two at a time (every pass below adds up or
        // takes the median of what it finds, and writes each pixel once, so
        // the order changes nothing); the scan needs no division for a
        // pixel's place and reads the maps in order.
        if (!widest) {
          growth[b].given.resize(g.reached.size());
          given = growth[b].given.data();
          for (int i : g.reached) visit(i, g.box.x_of(i), g.box.y_of(i));
        } else {
          const std::size_t words = (g.box.w + 31) / 32;
          std::vector<std::uint32_t> masks(words * (own1 - own0));
          std::size_t count = 0;
          for (int y = own0; y < own1; ++y) {
            std::uint32_t* row = masks.data() + words * (y - own0);
            reached_masks(dist + g.box.at(g.box.x0, y), g.box.w, row, widest);
            for (std::size_t m = 0; m < words; ++m) count += std::popcount(row[m]);
          }
          growth[b].given.resize(count);
          given = growth[b].given.data();
          for (int y = own0; y < own1; ++y) {
            const int base = g.box.at(g.box.x0, y);
            const std::uint32_t* row = masks.data() + words * (y - own0);
            for (std::size_t m = 0; m < words; ++m)
              for (std::uint32_t bits = row[m]; bits != 0; bits &= bits - 1) {
                const int k = static_cast<int>(32 * m) + std::countr_zero(bits);
                visit(base + k, g.box.x0 + k, y);
              }
          }
        }
      },
      0, 1);
  std::vector<int> meet;
  for (const auto& m : meets) meet.insert(meet.end(), m.begin(), m.end());
  // Where most crossings of the lines are one pixel wide (drawings with
  // lines of 1–1.5 px), the lines are that wide: the fronts that do meet
  // there are the blots where lines pile up, and their median read such
  // drawings as 1 to 5 px wide, drawing by drawing. Where most are wider,
  // the one-pixel crossings are the pinches where two regions nearly touch
  // (a wedge's tip), and the meeting fronts alone measure the lines.
  std::size_t thin = 0;
  for (const std::size_t n : one_pixel) thin += n;
  const auto at_one = thin + static_cast<std::size_t>(std::count(meet.begin(), meet.end(), kOrtho));
  if (at_one > (meet.size() + thin) / 2) {
    out.line_width = std::max(1.0, 2.0 * kOrtho / kUnit - 1.0);
  } else if (!meet.empty()) {
    auto mid = meet.begin() + static_cast<std::ptrdiff_t>(meet.size() / 2);
    std::nth_element(meet.begin(), mid, meet.end());
    // A line w pixels wide is met at about w/2 from each side.
    out.line_width = std::max(1.0, 2.0 * (*mid) / kUnit - 1.0);
  }
  out.radius = options.max_distance > 0 ? options.max_distance
                                        : (out.line_width > 0 ? out.line_width + 1.5 : 0.0);
  out.radius = std::min(out.radius, static_cast<double>(limit) / kUnit);
  const int radius = static_cast<int>(std::floor(out.radius * kUnit));
  copy_task.finish();
  // The filled map's non-zero labels: the regions' and the pixels given to them.
  LabelBox filled{true, bx0, by0, bx1, by1};
  auto add = [&filled](int x0, int y0, int x1, int y1) {
    filled.x0 = std::min(filled.x0, x0), filled.x1 = std::max(filled.x1, x1);
    filled.y0 = std::min(filled.y0, y0), filled.y1 = std::max(filled.y1, y1);
  };
  if (boxed) {
    for (const std::vector<LabelBox>& boxes : by_distance)
      for (int d = 0; d <= std::min(radius, limit); ++d)
        if (boxes[d].x1 >= 0) add(boxes[d].x0, boxes[d].y0, boxes[d].x1, boxes[d].y1);
    if (before_writes) before_writes(out.line_width, filled);
  }
  int* map = out.labels.data();
  const std::size_t map_w = static_cast<std::size_t>(out.labels.width());
  for (const Growth& g : growth) {
    for (const Growth::Given& p : g.given) {
      if (p.dist > radius) continue;
      map[static_cast<std::size_t>(p.y) * map_w + p.x] = p.owner;
      if (!boxed) add(p.x, p.y, p.x, p.y);
    }
  }
  if (filled_box != nullptr) *filled_box = filled;
  if (ids != nullptr) {
    for (int part = 1; part < kIdParts; ++part)
      seen[0].insert(seen[part].begin(), seen[part].end());
    ids->assign(seen[0].begin(), seen[0].end());
  }
  return out;
}

}  // namespace detail

bool OutlineFillOptions::is_valid(std::string* error) const {
  if (!std::isfinite(max_distance)) {
    if (error)
      *error =
          "OutlineFillOptions::max_distance = " + std::to_string(max_distance) + "; must be finite";
    return false;
  }
  return true;
}

OutlineFill fill_outlines(const LabelMap& labels, const OutlineFillOptions& options) {
  return detail::fill_outlines_in_bands(labels, options, detail::kFillBands,
                                        detail::kMinFillBandRows);
}

}  // namespace hair25d::layering
