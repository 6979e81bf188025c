#include "join_shapes.h"

#include <algorithm>
#include <climits>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <utility>
#include <vector>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include "hair25d/completion/bezier.h"
#include "raster.h"

namespace hair25d::completion::detail {

namespace {

// Over `n` pixels of a mask (0 or 255) and their classes (0, 1 counted, 3
// counted and under cover), adds the masked pixels counted to `total` and
// those under cover to `hidden`. Sixteen at a time where SSE2 is (the
// masks of a call's shapes are megabytes: session 40).
void count_classes(const std::uint8_t* mask, const std::uint8_t* classes, int n, int* total,
                   int* hidden) {
  int x = 0;
#if defined(__SSE2__)
  const __m128i one = _mm_set1_epi8(1), zero = _mm_setzero_si128();
  while (n - x >= 16) {
    // Each byte lane adds at most 255 ones before the lanes are summed.
    const int blocks = std::min((n - x) / 16, 255);
    __m128i t = zero, h = zero;
    for (int k = 0; k < blocks; ++k, x += 16) {
      const __m128i v =
          _mm_and_si128(_mm_loadu_si128(reinterpret_cast<const __m128i*>(mask + x)),
                        _mm_loadu_si128(reinterpret_cast<const __m128i*>(classes + x)));
      t = _mm_add_epi8(t, _mm_and_si128(v, one));
      h = _mm_add_epi8(h, _mm_and_si128(_mm_srli_epi16(v, 1), one));
    }
    t = _mm_sad_epu8(t, zero);
    h = _mm_sad_epu8(h, zero);
    *total += _mm_cvtsi128_si32(t) + _mm_extract_epi16(t, 4);
    *hidden += _mm_cvtsi128_si32(h) + _mm_extract_epi16(h, 4);
  }
#endif
  for (; x < n; ++x) {
    const int v = mask[x] & classes[x];
    *total += v & 1;
    *hidden += v >> 1;
  }
}

}  // namespace

Polyline join_patch(const Edge& a, const Edge& b, double share_a, double share_b) {
  const CubicBezier first = join_bezier_arms(a.p, a.tangent_p, b.q, -b.tangent_q, share_a, share_b);
  const CubicBezier second =
      join_bezier_arms(b.p, b.tangent_p, a.q, -a.tangent_q, share_b, share_a);
  const int s1 = std::max(4, static_cast<int>((a.p - b.q).norm() / 2));
  const int s2 = std::max(4, static_cast<int>((b.p - a.q).norm() / 2));
  Polyline patch = first.sample(s1);
  for (auto it = b.points.rbegin() + 1; it != b.points.rend(); ++it) patch.push_back(*it);
  const Polyline second_points = second.sample(s2);
  patch.insert(patch.end(), second_points.begin() + 1, second_points.end());
  for (auto it = a.points.rbegin() + 1; it != a.points.rend(); ++it) patch.push_back(*it);
  return patch;
}

JoinShape best_join_shape(const Context& ctx, const Edge& a, const Edge& b, const cv::Mat& face,
                          bool ink, const std::vector<double>& shares,
                          const std::optional<JoinShape>& known) {
  JoinShape best;
  struct Shape {
    double share_a, share_b;
    Polyline patch;
    cv::Rect box;  // polygon_box
    cv::Mat mask;  // the patch filled in its box, once (empty: `known`'s)
  };
  const auto is_known = [&](const Shape& shape) {
    return known && shape.share_a == known->share_a && shape.share_b == known->share_b;
  };
  std::vector<Shape> patches;
  int x0 = INT_MAX, y0 = INT_MAX, x1 = INT_MIN, y1 = INT_MIN;  // the boxes' union
  std::size_t mask_bytes = 0;
  for (double sa : shares)
    for (double sb : shares) {
      Polyline patch = join_patch(a, b, sa, sb);
      const cv::Rect box = polygon_box(patch);
      if (box.empty()) return best;
      x0 = std::min(x0, box.x), y0 = std::min(y0, box.y);
      x1 = std::max(x1, box.x + box.width), y1 = std::max(y1, box.y + box.height);
      patches.push_back({sa, sb, std::move(patch), box, cv::Mat()});
      if (!is_known(patches.back())) mask_bytes += static_cast<std::size_t>(box.area());
    }
  if (patches.empty()) return best;
  const cv::Point origin(x0, y0);
  const int w = x1 - x0, h = y1 - y0;
  if (static_cast<double>(w) * h > kMaxPolygonBoxPixels) return best;
  // The masks and the union's classes live in one buffer.
  thread_local std::vector<std::uint8_t> kept;
  const std::size_t union_bytes = static_cast<std::size_t>(w) * h;
  ScratchBytes scratch(kept, mask_bytes + 2 * union_bytes);
  std::uint8_t* next = scratch.data();
  cv::Mat any(h, w, CV_8U, next);
  next += union_bytes;
  // Per pixel of the union outside both pieces: 1 counted, 3 counted and
  // under cover (0: a piece's or no patch's).
  cv::Mat classes(h, w, CV_8U, next);
  next += union_bytes;
  for (Shape& shape : patches) {
    if (is_known(shape)) continue;
    shape.mask = cv::Mat(shape.box.size(), CV_8U, next);
    next += static_cast<std::size_t>(shape.box.area());
    fill_polygon(shape.mask, shape.patch, shape.box.tl(), 255);
    cv::Mat in_union = any(shape.box - origin);
    cv::bitwise_or(in_union, shape.mask, in_union);
  }
  // Counted: a pixel outside both pieces; under: one of those under cover.
  // What the relations say of a label is asked once (a box holds few), and
  // labels come in runs along a row. Only pixels some patch covers are
  // asked: the box of long slanted patches is mostly outside them (session
  // 36: the cover refusals' inputs ask this for every such candidate).
  AboveEither above(ctx, a.region, b.region);
  int last_label = INT_MIN;
  bool last_above = false;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* in = any.ptr<std::uint8_t>(y);
    std::uint8_t* c = classes.ptr<std::uint8_t>(y);
    const int gy = y + origin.y;
    if (gy < 0 || gy >= ctx.labels.height()) {  // off the map: counted, never under
      for (int x = 0; x < w; ++x) c[x] = in[x] ? 1 : 0;
      continue;
    }
    const int* labels = ctx.labels.data() + static_cast<std::size_t>(gy) * ctx.labels.width();
    const HiddenRow hides(ctx, face, ink, gy);
    const int map_end = std::min(w, ctx.labels.width() - origin.x);  // x past the map's right
    for (int x = 0; x < w; ++x) {
      if (!in[x]) continue;
      const int gx = x + origin.x;
      if (gx < 0 || gx >= ctx.labels.width()) {
        c[x] = 1;
        continue;
      }
      const int l = labels[gx];
      // The run of this label in the union along the row, classed at once
      // unless each pixel may tell (the face, the ink).
      int end = x + 1;
      while (end < map_end && in[end] && labels[end + origin.x] == l) ++end;
      if (l != a.region && l != b.region) {
        if (l != last_label) last_label = l, last_above = above(l);
        if (last_above || !hides.per_pixel(l)) {
          std::fill(c + x, c + end, last_above ? 3 : 1);
        } else {
          for (int k = x; k < end; ++k) c[k] = hides.hidden(false, l, k + origin.x) ? 3 : 1;
        }
      }
      x = end - 1;
    }
  }
  // Each patch is counted within its own box, not the union's.
  for (const Shape& shape : patches) {
    double cover = known ? known->cover : -1.0;
    if (!is_known(shape)) {
      const cv::Rect box = shape.box - origin;
      int total = 0, hidden = 0;
      for (int y = 0; y < box.height; ++y)
        count_classes(shape.mask.ptr<std::uint8_t>(y), classes.ptr<std::uint8_t>(y + box.y) + box.x,
                      box.width, &total, &hidden);
      cover = total > 0 ? static_cast<double>(hidden) / total : 1.0;
    }
    if (cover > best.cover) best = {shape.share_a, shape.share_b, cover};
  }
  return best;
}

}  // namespace hair25d::completion::detail
