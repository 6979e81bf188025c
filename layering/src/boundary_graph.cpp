// Crack-grid tracing: every boundary is a chain of unit edges between pixel
// corners, so lengths, areas and junction positions are exact and the cost is
// one pass over the corners.
#include "hair25d/layering/boundary_graph.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cstdint>
#include <string>

#if defined(__x86_64__) && defined(__GNUC__)
#include <immintrin.h>
#define HAIR25D_TRACE_AVX2 1
#endif

#include "boundary_trace.h"
#include "hair25d/core/error.h"
#include "raster_scan.h"

namespace hair25d::layering {
namespace {

using detail::Bits;
using detail::for_each_set;

// Directions of travel on the screen: right, down, left, up.
constexpr std::array<int, 4> kDx = {1, 0, -1, 0};
constexpr std::array<int, 4> kDy = {0, 1, 0, -1};
int opposite(int d) { return (d + 2) & 3; }

class CrackGrid {
 public:
  explicit CrackGrid(const LabelMap& labels)
      : labels_(labels), w_(labels.width()), h_(labels.height()) {}

  int label(int x, int y) const {
    return (x < 0 || y < 0 || x >= w_ || y >= h_) ? kOutsideLabel : labels_.at(x, y);
  }
  // The four pixels around corner (x, y): top-left, top-right, bottom-left, bottom-right.
  std::array<int, 4> around(int x, int y) const {
    if (x > 0 && y > 0 && x < w_ && y < h_) {  // inside: no bounds to check
      const int* p = labels_.data() + static_cast<std::size_t>(y - 1) * w_ + (x - 1);
      return {p[0], p[1], p[w_], p[w_ + 1]};
    }
    return {label(x - 1, y - 1), label(x, y - 1), label(x - 1, y), label(x, y)};
  }
  // Whether the crack edge leaving corner (x, y) in direction d exists.
  static bool has_edge(const std::array<int, 4>& q, int d) {
    switch (d) {
      case 0:
        return q[1] != q[3];  // right: between top-right and bottom-right
      case 1:
        return q[2] != q[3];  // down: between bottom-left and bottom-right
      case 2:
        return q[0] != q[2];  // left: between top-left and bottom-left
      default:
        return q[0] != q[1];  // up: between top-left and top-right
    }
  }
  // Undirected index of the crack edge leaving corner (x, y) in direction d.
  std::size_t edge_index(int x, int y, int d) const {
    const std::size_t horizontal = static_cast<std::size_t>(h_ + 1) * w_;
    switch (d) {
      case 0:
        return static_cast<std::size_t>(y) * w_ + x;
      case 2:
        return static_cast<std::size_t>(y) * w_ + (x - 1);
      case 1:
        return horizontal + static_cast<std::size_t>(y) * (w_ + 1) + x;
      default:
        return horizontal + static_cast<std::size_t>(y - 1) * (w_ + 1) + x;
    }
  }
  std::size_t edge_count() const {
    return static_cast<std::size_t>(h_ + 1) * w_ + static_cast<std::size_t>(w_ + 1) * h_;
  }
  // Labels on the left and right of travel from corner (x, y) in direction d
  // (screen orientation: y grows downwards).
  void sides(int x, int y, int d, int* left, int* right) const {
    switch (d) {
      case 0:
        *left = label(x, y - 1);
        *right = label(x, y);
        break;
      case 1:
        *left = label(x, y);
        *right = label(x - 1, y);
        break;
      case 2:
        *left = label(x - 1, y);
        *right = label(x - 1, y - 1);
        break;
      default:
        *left = label(x - 1, y - 1);
        *right = label(x, y - 1);
        break;
    }
  }
  int width() const { return w_; }
  int height() const { return h_; }

 private:
  const LabelMap& labels_;
  int w_, h_;
};

bool is_junction(const std::array<int, 4>& q) {
  int distinct = 1;
  for (int i = 1; i < 4; ++i) {
    bool seen = false;
    for (int j = 0; j < i; ++j) seen = seen || q[j] == q[i];
    if (!seen) ++distinct;
  }
  return distinct >= 3;
}

// At a non-junction corner reached by travelling in direction `arrived`, the
// direction to leave in. Degree-2 corners have one choice; at a saddle (two
// labels meeting diagonally) the pixels of the smaller label are joined.
int continue_direction(const std::array<int, 4>& q, int arrived) {
  const int back = opposite(arrived);
  // Bit d: the edge in direction d exists (has_edge).
  const unsigned edges = (q[1] != q[3] ? 1u : 0u) | (q[2] != q[3] ? 2u : 0u) |
                         (q[0] != q[2] ? 4u : 0u) | (q[0] != q[1] ? 8u : 0u);
  // Edges per mask (a table: without -mpopcnt std::popcount is a call).
  static constexpr std::array<int, 16> kDegree = {0, 1, 1, 2, 1, 2, 2, 3, 1, 2, 2, 3, 2, 3, 3, 4};
  if (kDegree[edges] == 2) return std::countr_zero(edges & ~(1u << back));
  // Saddle: q = {A, B, B, A}. Joining the A diagonal (top-left with
  // bottom-right) leaves top-right enclosed by up+right and bottom-left by
  // down+left; joining B pairs up+left and right+down.
  const bool join_main_diagonal = q[0] < q[1];
  static constexpr std::array<int, 4> kPairMain = {3, 2, 1, 0};   // right<->up, down<->left
  static constexpr std::array<int, 4> kPairOther = {1, 0, 3, 2};  // right<->down, left<->up
  return join_main_diagonal ? kPairMain[back] : kPairOther[back];
}

#if defined(HAIR25D_TRACE_AVX2)
// One row of inner corners eight at a time: calls visit(x) for every x in
// [1, n) where the row above or the row below changes label from x − 1 to x
// (in increasing x), and returns how many of x in [1, n) have above[x] !=
// below[x] (crack edges between the rows). Returns the first x not done.
__attribute__((target("avx2"))) inline __m256i at(const int* p) {
  return _mm256_loadu_si256(reinterpret_cast<const __m256i*>(p));
}

template <class F>
__attribute__((target("avx2,popcnt"))) int corner_row_avx2(const int* above, const int* below,
                                                           int n, F&& visit, long long* crossing,
                                                           int x = 1) {
  long long count = 0;
  for (; x + 8 <= n; x += 8) {
    const __m256i a = at(above + x), b = at(below + x);
    const __m256i same = _mm256_and_si256(_mm256_cmpeq_epi32(at(above + x - 1), a),
                                          _mm256_cmpeq_epi32(at(below + x - 1), b));
    unsigned changes =
        ~static_cast<unsigned>(_mm256_movemask_ps(_mm256_castsi256_ps(same))) & 0xFFu;
    count += 8 - __builtin_popcount(static_cast<unsigned>(
                     _mm256_movemask_ps(_mm256_castsi256_ps(_mm256_cmpeq_epi32(a, b)))));
    for (; changes != 0; changes &= changes - 1) visit(x + std::countr_zero(changes));
  }
  *crossing += count;
  return x;
}
#endif

// corner_row_avx2 sixteen labels at a time (AVX-512F), from x = 1; returns
// the first x not done.
template <class F>
__attribute__((target("avx2,avx512f,popcnt"))) int corner_row_avx512(const int* above,
                                                                     const int* below, int n,
                                                                     F&& visit,
                                                                     long long* crossing) {
  int x = 1;
  long long count = 0;
  for (; x + 16 <= n; x += 16) {
    const __m512i a = _mm512_loadu_si512(above + x), b = _mm512_loadu_si512(below + x);
    const unsigned same = _mm512_cmpeq_epi32_mask(_mm512_loadu_si512(above + x - 1), a) &
                          _mm512_cmpeq_epi32_mask(_mm512_loadu_si512(below + x - 1), b);
    unsigned changes = ~same & 0xFFFFu;
    count += 16 - __builtin_popcount(static_cast<unsigned>(_mm512_cmpeq_epi32_mask(a, b)));
    for (; changes != 0; changes &= changes - 1) visit(x + std::countr_zero(changes));
  }
  *crossing += count;
  return x;
}

bool trace_avx512_available() {
#if defined(HAIR25D_TRACE_AVX2)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("avx512f") &&
         __builtin_cpu_supports("popcnt");
#else
  return false;
#endif
}

bool trace_avx2_available() {
#if defined(HAIR25D_TRACE_AVX2)
  return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("popcnt");
#else
  return false;
#endif
}

}  // namespace

double Boundary::length() const {
  // Crack edges have unit length, so the count of segments is the length.
  if (points.empty()) return 0.0;
  return closed() ? static_cast<double>(points.size()) : static_cast<double>(points.size() - 1);
}

BoundaryGraph build_boundary_graph(const LabelMap& labels) {
  return detail::build_boundary_graph(labels, true);
}

namespace detail {

BoundaryGraph build_boundary_graph(const LabelMap& labels, bool wide_rows, bool widest_rows,
                                   const LabelBox* box) {
  if (labels.empty())
    throw Error("layering: label map is empty (" + std::to_string(labels.width()) + "x" +
                std::to_string(labels.height()) + "); need at least one pixel");
  const CrackGrid grid(labels);
  const int w = grid.width();
  const int h = grid.height();
  BoundaryGraph graph;
  graph.width = w;
  graph.height = h;

  // Junctions in raster order of their corners, so a corner's junction id is
  // found by binary search among `junction_corner` once its bit says it is one.
  const std::size_t corners = static_cast<std::size_t>(w + 1) * (h + 1);
  Bits is_junction_corner(corners);
  std::vector<std::size_t> junction_corner;
  auto visit_corner = [&](int x, int y) {
    if (!is_junction(grid.around(x, y))) return;
    const std::size_t c = static_cast<std::size_t>(y) * (w + 1) + x;
    is_junction_corner.set(c);
    junction_corner.push_back(c);
    graph.junctions.push_back({Vec2(x, y), {}});
  };
  // Inside the image a corner where neither row changes label holds at most
  // two labels, so is no junction (almost all corners): flags from two rows
  // at once, which vectorises.
  std::vector<std::uint8_t> differs(static_cast<std::size_t>(w) + 1, 0);
  // Where each row changes label from pixel x − 1 to x (at index x), for the
  // rows above and below the corners: each row is compared once.
  std::vector<std::uint8_t> changes_above(static_cast<std::size_t>(w) + 1, 0);
  std::vector<std::uint8_t> changes_below(static_cast<std::size_t>(w) + 1, 0);
  if (h > 0 && w > 1) detail::not_equal(labels.data(), labels.data() + 1, w - 1, &changes_below[1]);
  // With AVX2 the rows are compared eight labels at a time, and the crack
  // edges between rows are counted on the way: when the traces from the
  // junctions have walked all of them, there is no closed loop left to look
  // for (every loop has one), and the second scan below is skipped.
  const bool wide = wide_rows && trace_avx2_available();
  const bool widest = wide && widest_rows && trace_avx512_available();
  long long horizontal = 0;
  // Outside the box of the non-zero labels every label is 0: a row pair
  // there changes nowhere, and within the box's rows the labels change only
  // at corners x0 <= x <= x1 + 1 (the corners at x = 0 and x = w are
  // visited apart). Without a box, the whole row.
  const bool boxed = box != nullptr && box->any;
  const int row0 = boxed ? box->y0 : 0, row1 = boxed ? box->y1 + 1 : h;  // rows y of corners
  const int xs = boxed ? std::max(1, box->x0) : 1, xe = boxed ? std::min(w, box->x1 + 2) : w;
  for (int y = 0; y <= h; ++y) {
    if (y == 0 || y == h) {
      for (int x = 0; x <= w; ++x) visit_corner(x, y);
      const int* row = labels.data() + static_cast<std::size_t>(y == 0 ? 0 : h - 1) * w;
      for (int x = 0; x < w; ++x) horizontal += row[x] != kOutsideLabel;
      continue;
    }
    const int* below = labels.data() + static_cast<std::size_t>(y) * w;
    visit_corner(0, y);
#if defined(HAIR25D_TRACE_AVX2)
    if (wide) {
      const int* above = below - w;
      if (y >= row0 && y <= row1 && xs < xe) {
        // The scans run over x in [1, n) of rows starting at xs − 1.
        const int* a = above + (xs - 1);
        const int* b = below + (xs - 1);
        const int n = xe - xs + 1;
        auto visit = [&](int x) { visit_corner(x + xs - 1, y); };
        int x = widest ? corner_row_avx512(a, b, n, visit, &horizontal) : 1;
        x = corner_row_avx2(a, b, n, visit, &horizontal, x);
        for (; x < n; ++x) {
          if (a[x - 1] != a[x] || b[x - 1] != b[x]) visit_corner(x + xs - 1, y);
          horizontal += a[x] != b[x];
        }
      }
      horizontal += above[0] != below[0];
      visit_corner(w, y);
      continue;
    }
#endif
    changes_above.swap(changes_below);
    if (w > 1) detail::not_equal(below, below + 1, w - 1, &changes_below[1]);
    for (int x = 1; x < w; ++x) differs[x] = changes_above[x] | changes_below[x];
    for_each_set(differs, 1, w, [&](int x) { visit_corner(x, y); });
    visit_corner(w, y);
  }
  auto junction_at = [&](int x, int y) {
    const std::size_t c = static_cast<std::size_t>(y) * (w + 1) + x;
    if (!is_junction_corner.test(c)) return -1;
    return static_cast<int>(std::lower_bound(junction_corner.begin(), junction_corner.end(), c) -
                            junction_corner.begin());
  };

  Bits visited(grid.edge_count());
  long long walked_horizontal = 0;  // crack edges walked between rows
  const std::size_t edge_limit = grid.edge_count();
  // A chain's corners are gathered here, then copied into its boundary at
  // their final size (growing each boundary's own vector cost more).
  Polyline chain;
  auto trace = [&](int x0, int y0, int d0) {
    Boundary b;
    grid.sides(x0, y0, d0, &b.left, &b.right);
    b.start = junction_at(x0, y0);
    chain.clear();
    chain.emplace_back(x0, y0);
    int x = x0, y = y0, d = d0;
    for (;;) {
      // Counted only when first set, so the count never passes the edges
      // there are, whatever the walk does.
      if (visited.test_and_set(grid.edge_index(x, y, d))) walked_horizontal += (d & 1) == 0;
      x += kDx[d];
      y += kDy[d];
      // A walk down or up reads a new row of the map at each step (the
      // next corner's pixels), from the cache's far levels once the map is
      // larger than the near ones: the rows two and three steps ahead are
      // asked for now (the walk mostly keeps its direction), so that the
      // reads of the steps meanwhile overlap with their fetch.
      if ((d & 1) != 0) {
        const int ahead = d == 1 ? y + 1 : y - 3;
        for (const int r : {ahead, ahead + 1})
          if (r >= 0 && r < h && x > 0)
            __builtin_prefetch(labels.data() + static_cast<std::size_t>(r) * w + (x - 1));
      }
      const int j = junction_at(x, y);
      if (j >= 0) {
        chain.emplace_back(x, y);
        b.end = j;
        break;
      }
      d = continue_direction(grid.around(x, y), d);
      if (x == x0 && y == y0 && visited.test(grid.edge_index(x, y, d))) break;  // closed loop
      // Each edge is walked once, so a chain is never longer than the grid
      // has edges: a guard that turns a broken invariant into an error
      // instead of a vector growing until memory runs out.
      if (chain.size() > edge_limit)
        throw Error("layering: boundary trace from corner (" + std::to_string(x0) + ", " +
                    std::to_string(y0) + ") exceeded " + std::to_string(edge_limit) +
                    " edges without closing; the crack-grid walk is inconsistent");
      chain.emplace_back(x, y);
    }
    b.points.assign(chain.begin(), chain.end());
    const int id = static_cast<int>(graph.boundaries.size());
    if (b.start >= 0) {
      graph.junctions[b.start].boundaries.push_back(id);
      graph.junctions[b.end].boundaries.push_back(id);
    }
    graph.boundaries.push_back(std::move(b));
  };

  // Tracing adds boundary ids to junctions but never junctions.
  for (std::size_t k = 0; k < graph.junctions.size(); ++k) {
    const int x = static_cast<int>(graph.junctions[k].position.x());
    const int y = static_cast<int>(graph.junctions[k].position.y());
    const auto q = grid.around(x, y);
    for (int d = 0; d < 4; ++d)
      if (CrackGrid::has_edge(q, d) && !visited.test(grid.edge_index(x, y, d))) trace(x, y, d);
  }
  // What is left are closed loops with no junction (a region inside another).
  // A loop is found at its first horizontal crack edge in raster order: an
  // edge rightwards from corner (x, y) lies between pixels (x, y-1) and (x, y).
  if (wide && walked_horizontal == horizontal) return graph;
  std::vector<int> outside(static_cast<std::size_t>(w), kOutsideLabel);
  for (int y = 0; y <= h; ++y) {
    const int* above = y > 0 ? labels.data() + static_cast<std::size_t>(y - 1) * w : outside.data();
    const int* below = y < h ? labels.data() + static_cast<std::size_t>(y) * w : outside.data();
    detail::not_equal(above, below, w, differs.data());
    for_each_set(differs, 0, w, [&](int x) {
      if (!visited.test(grid.edge_index(x, y, 0))) trace(x, y, 0);
    });
  }
  return graph;
}

}  // namespace detail

}  // namespace hair25d::layering
