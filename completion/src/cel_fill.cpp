// Flat fills for cel art: the coarse fill of inpaint_cel (every hole pixel
// continues the flat region nearest to it, so the exemplar pass only has to
// add texture) and the full-resolution geodesic fill of the background.
#include <algorithm>
#include <array>
#include <climits>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "background_internal.h"
#include "inpaint_internal.h"
#include "raster.h"

namespace hair25d::completion::detail {

bool CommonColours::common(const Rgba& c) const {
  if (common_.empty()) {
    // The 3×3×3 box sum of the histogram, one axis at a time.
    std::vector<long> sum = count_, next(sum.size());
    for (const int stride : {1, kSide, kSide * kSide}) {
      for (std::size_t i = 0; i < sum.size(); ++i) {
        const int along = static_cast<int>(i / static_cast<std::size_t>(stride)) % kSide;
        long v = sum[i];
        if (along > 0) v += sum[i - static_cast<std::size_t>(stride)];
        if (along + 1 < kSide) v += sum[i + static_cast<std::size_t>(stride)];
        next[i] = v;
      }
      sum.swap(next);
    }
    common_.assign(sum.size(), 0);
    for (std::size_t i = 0; i < sum.size(); ++i)
      common_[i] =
          total_ > 0 && static_cast<double>(sum[i]) >= share_ * static_cast<double>(total_);
  }
  return common_[bin(c)] != 0;
}

namespace {

bool usable_source(const LabelMap& fill, const LabelMap& source, int x, int y) {
  return fill.at(x, y) == 0 && (source.empty() || source.at(x, y) != 0);
}

}  // namespace

InpaintOptions source_ink_options(const Image& image, const LabelMap& fill, const LabelMap& source,
                                  const InpaintOptions& options) {
  std::vector<int> lumas;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (usable_source(fill, source, x, y) && image.at(x, y).a >= 128)
        lumas.push_back(luma(image.at(x, y)));
  InpaintOptions o = options;
  if (lumas.empty()) return o;
  std::nth_element(lumas.begin(), lumas.begin() + lumas.size() / 2, lumas.end());
  o.ink_luma = std::min(o.ink_luma, lumas[lumas.size() / 2] / 2);
  return o;
}

Image coarse_fill(const Image& image, const LabelMap& fill, const LabelMap& source,
                  const std::vector<std::uint8_t>& ink) {
  // A source colour is a flat one when at least this share of the sources
  // is painted in it (hair a segmentation gave a few pixels of the face,
  // the dress or a highlight's rim does not fill its hidden part with them).
  constexpr double kCommonShare = 0.01;
  const int w = image.width(), h = image.height();
  auto idx = [w](int x, int y) { return static_cast<std::size_t>(y) * w + x; };
  auto usable = [&](int x, int y) { return usable_source(fill, source, x, y); };
  CommonColours colours(kCommonShare);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (usable(x, y) && !ink[idx(x, y)]) colours.add(image.at(x, y));
  // Flat pixels: usable, not ink and not next to ink (the anti-aliased rim of
  // a line is neither line nor region colour). distanceTransform measures the
  // distance to the nearest zero, so flat pixels are the zeros.
  cv::Mat not_flat(h, w, CV_8U, cv::Scalar(255)), near_ink;
  cv::dilate(cv::Mat(h, w, CV_8U, const_cast<std::uint8_t*>(ink.data())), near_ink,
             cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  int flat_count = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (usable(x, y) && !near_ink.at<std::uint8_t>(y, x) && colours.common(image.at(x, y)))
        not_flat.at<std::uint8_t>(y, x) = 0, ++flat_count;
  if (flat_count == 0) {
    // No flat pixel: fall back to every usable pixel.
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (usable(x, y)) not_flat.at<std::uint8_t>(y, x) = 0, ++flat_count;
  }
  Image guide = image;
  if (flat_count == 0) return guide;
  cv::Mat dist, labels;
  cv::distanceTransform(not_flat, dist, labels, cv::DIST_L2, cv::DIST_MASK_5, cv::DIST_LABEL_PIXEL);
  // Label → colour of that zero pixel.
  std::vector<Rgba> colour_of(static_cast<std::size_t>(flat_count) + 1);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (not_flat.at<std::uint8_t>(y, x) == 0) {
        const int l = labels.at<int>(y, x);
        if (l >= 0 && static_cast<std::size_t>(l) < colour_of.size())
          colour_of[static_cast<std::size_t>(l)] = image.at(x, y);
      }
  // The median below reads the hole pixels' neighbours too: pixels that are
  // no source (the paper or a face round a strand's texture, transparent
  // there) take their nearest flat colour as well, or they would bleed into
  // the hole's rim (completed hair turned transparent or face-coloured).
  Image nearest = image;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (!usable(x, y)) {
        const int l = labels.at<int>(y, x);
        if (l >= 0 && static_cast<std::size_t>(l) < colour_of.size())
          nearest.at(x, y) = colour_of[static_cast<std::size_t>(l)];
      }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (fill.at(x, y) != 0) guide.at(x, y) = nearest.at(x, y);
  // Nearest-pixel fill leaves ragged Voronoi seams; a median keeps the flat
  // colours and straightens the seams. Only hole pixels take it, so it runs
  // on their box (the 5×5 window of a hole pixel lies 2 px inside a box
  // grown by 4 px, or at the image's edge, replicated either way).
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (fill.at(x, y) != 0)
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  if (x1 < 0) return guide;
  const cv::Rect box =
      cv::Rect(cv::Point(x0 - 4, y0 - 4), cv::Point(x1 + 5, y1 + 5)) & cv::Rect(0, 0, w, h);
  cv::Mat smooth;
  cv::medianBlur(view(nearest)(box), smooth, 5);
  for (int y = box.y; y < box.y + box.height; ++y)
    for (int x = box.x; x < box.x + box.width; ++x)
      if (fill.at(x, y) != 0) {
        const cv::Vec4b& v = smooth.at<cv::Vec4b>(y - box.y, x - box.x);
        guide.at(x, y) = {v[0], v[1], v[2], v[3]};
      }
  return guide;
}

}  // namespace hair25d::completion::detail

// ---------------------------------------------------------------------------
// Full-resolution flat fill of the background (background.cpp).

namespace hair25d::completion::detail {
namespace {

// Steps beyond a material's reach into the hole cost this many times more.
constexpr int kBeyondReach = 16;
// Alpha at or under this is a transparent sheet's paper, not a colour.
constexpr std::uint8_t kFaintAlpha = 15;

// The known materials around the hole (connected known, non-ink areas) and
// how far (chamfer units) each plausibly continues behind the hair.
struct Materials {
  std::vector<int> label;  // per pixel, 0 = none
  std::vector<int> reach;  // per material
};

// Multi-source geodesic propagation (Dial's bucket queue, chamfer weights 5
// orthogonal and 7 diagonal ≈ 5√2): each pixel reachable through `pass`
// takes the origin of its nearest seed. A seed starts at its `start`
// distance (same units; empty = all 0). With `materials`, a step beyond the
// reach of the origin's material costs kBeyondReach times more. Pixels never
// reached keep −1.
void propagate(int w, int h, const Mask& pass, const std::vector<int>& seeds,
               const std::vector<int>& start, std::vector<int>& origin,
               const Materials* materials = nullptr) {
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<int> dist(n, INT_MAX);
  // Distance from the origin (unweighted), only needed with materials.
  std::vector<int> travelled(materials == nullptr ? 0 : n, 0);
  int max_start = 0;
  for (std::size_t k = 0; k < start.size(); ++k) max_start = std::max(max_start, start[k]);
  // Every pending distance lies within [d, d + max_start + longest step]: a
  // ring of that many buckets never wraps onto the one being emptied.
  const int longest = materials == nullptr ? 7 : 7 * kBeyondReach;
  const std::size_t ring = static_cast<std::size_t>(max_start + longest) + 1;
  std::vector<std::vector<int>> bucket(ring);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const int s = seeds[k], d0 = start.empty() ? 0 : start[k];
    if (d0 >= dist[static_cast<std::size_t>(s)]) continue;
    dist[static_cast<std::size_t>(s)] = d0;
    bucket[static_cast<std::size_t>(d0) % ring].push_back(s);
  }
  std::size_t pending = 0;
  for (const auto& b : bucket) pending += b.size();
  const int dx[8] = {1, -1, 0, 0, 1, 1, -1, -1};
  const int dy[8] = {0, 0, 1, -1, 1, -1, 1, -1};
  for (int d = 0; pending > 0; ++d) {
    std::vector<int>& list = bucket[static_cast<std::size_t>(d) % ring];
    // Relaxing adds to other buckets only (weights 5 and 7 < ring).
    for (std::size_t k = 0; k < list.size(); ++k) {
      const int i = list[k];
      --pending;
      if (dist[static_cast<std::size_t>(i)] != d) continue;
      const int x = i % w, y = i / w;
      for (int m = 0; m < 8; ++m) {
        const int nx = x + dx[m], ny = y + dy[m];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const int j = ny * w + nx;
        if (!pass[static_cast<std::size_t>(j)]) continue;
        // No diagonal step between two blocked pixels (through a thin line).
        if (m >= 4 && !pass[static_cast<std::size_t>(y * w + nx)] &&
            !pass[static_cast<std::size_t>(ny * w + x)])
          continue;
        const int step = m < 4 ? 5 : 7;
        int nd = d + step, nt = 0;
        if (materials != nullptr) {
          nt = travelled[static_cast<std::size_t>(i)] + step;
          const int o = origin[static_cast<std::size_t>(i)];
          const int mat = o >= 0 ? materials->label[static_cast<std::size_t>(o)] : 0;
          if (mat > 0 && nt > materials->reach[static_cast<std::size_t>(mat)])
            nd = d + step * kBeyondReach;
        }
        if (nd >= dist[static_cast<std::size_t>(j)]) continue;
        dist[static_cast<std::size_t>(j)] = nd;
        if (materials != nullptr) travelled[static_cast<std::size_t>(j)] = nt;
        origin[static_cast<std::size_t>(j)] = origin[static_cast<std::size_t>(i)];
        bucket[static_cast<std::size_t>(nd) % ring].push_back(j);
        ++pending;
      }
    }
    list.clear();
  }
}

// 255 where a known pixel is neither ink nor on a colour border of the
// drawing (a step of more than 24 in a channel to its right or lower
// neighbour; all transparent pixels one colour), and on the hole.
cv::Mat colour_free(const Image& image, const Mask& hole, const Mask& ink) {
  const int w = image.width(), h = image.height();
  cv::Mat free(h, w, CV_8U, cv::Scalar(255));
  auto differ = [](const Rgba& a, const Rgba& b) {
    if ((a.a < 128) != (b.a < 128)) return true;
    if (a.a < 128) return false;
    return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)}) > 24;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (hole[i]) continue;
      bool border = ink[i] != 0;
      if (!border && x + 1 < w && !hole[i + 1])
        border = differ(image.data()[i], image.data()[i + 1]);
      if (!border && y + 1 < h && !hole[i + w])
        border = differ(image.data()[i], image.data()[i + w]);
      if (border) free.at<std::uint8_t>(y, x) = 0;
    }
  return free;
}

// How far each known pixel is from the nearest ink or colour border of the
// drawing (not counting the hole's rim), in pixels.
cv::Mat region_depth(const cv::Mat& free) {
  cv::Mat depth;
  cv::distanceTransform(free, depth, cv::DIST_L1, cv::DIST_MASK_3);  // only compared to 10 px
  return depth;
}

// The known materials around the hole: connected known areas of one colour
// (4-connected, bounded by ink and by colour borders, so a line or a step
// of colour closes them; soft shading stays one). One that lies on the hair
// (most of its rim within a line's width of the hole: a headband or a clip
// lying on the hair, a highlight the segmentation left) is no part of what
// is behind the hair: it continues only as far as it is thick (its largest
// inscribed radius). The face, the skin and the paper, cut by the hair,
// reach on. (Bounded by ink only, lucy's dress, collar, sleeves, skin and
// paper were one material: their soft lines are no ink. The grey inside
// of her collar then filled the hair's place from the neck to the sleeve.)
Materials find_materials(const Image& image, const Mask& hole, const Mask& ink, const cv::Mat& free,
                         int drawing_edges) {
  constexpr int kRimReach = 6;       // px: a rim pixel this near the hole borders it
  constexpr double kOnHair = 0.6;    // share of the rim bordering the hole
  constexpr float kMinReach = 3.0f;  // px
  // A material smaller than this share of the hole (a hair clip, an ear, a
  // collar's tip) cannot be what lies behind much of it: it too continues
  // only as far as it is thick. On wikipe-tan a clip's grey filled the hair
  // beside the head; the paper and the body, large, reach on.
  constexpr double kSmall = 0.25;
  const int w = image.width(), h = image.height();
  const std::size_t n = static_cast<std::size_t>(w) * h;
  cv::Mat known(h, w, CV_8U);
  for (std::size_t i = 0; i < n; ++i) known.data[i] = !hole[i] && free.data[i] ? 255 : 0;
  cv::Mat labels;
  const int count = cv::connectedComponents(known, labels, 4, CV_32S);
  int* lab = labels.ptr<int>();
  // A pixel on a colour border belongs to the neighbour of the nearest
  // colour (one pass down, one up, so that borders 2 px wide are reached).
  auto adopt = [&](std::size_t i, int x, int y) {
    if (lab[i] != 0 || hole[i] || ink[i]) return;
    const Rgba& c = image.data()[i];
    int best = INT_MAX;
    const int nx[4] = {x - 1, x + 1, x, x}, ny[4] = {y, y, y - 1, y + 1};
    for (int k = 0; k < 4; ++k) {
      if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
      const std::size_t j = static_cast<std::size_t>(ny[k]) * w + nx[k];
      if (lab[j] == 0) continue;
      const Rgba& d = image.data()[j];
      const int diff =
          std::abs(c.r - d.r) + std::abs(c.g - d.g) + std::abs(c.b - d.b) + std::abs(c.a - d.a);
      if (diff < best) best = diff, lab[i] = lab[j];
    }
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) adopt(static_cast<std::size_t>(y) * w + x, x, y);
  for (int y = h - 1; y >= 0; --y)
    for (int x = w - 1; x >= 0; --x) adopt(static_cast<std::size_t>(y) * w + x, x, y);
  cv::Mat hole_m(h, w, CV_8U, const_cast<std::uint8_t*>(hole.data())), near_hole;
  cv::dilate(hole_m, near_hole,
             cv::getStructuringElement(cv::MORPH_RECT, {2 * kRimReach + 1, 2 * kRimReach + 1}));
  cv::Mat inside;
  cv::distanceTransform(known, inside, cv::DIST_L2, cv::DIST_MASK_3);
  const std::size_t k_count = static_cast<std::size_t>(count);
  std::vector<int> rim(k_count, 0), rim_near(k_count, 0);
  std::vector<float> thick(k_count, 0.0f);
  // A material running off the drawing is larger than it shows (the body
  // below its lower edge): never small. (Off a crop's side it is not: a
  // hair clip cut by the hole's box.)
  std::vector<std::uint8_t> cut(k_count, 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const int c = lab[i];
      if (c == 0) continue;
      const std::size_t k = static_cast<std::size_t>(c);
      thick[k] = std::max(thick[k], inside.ptr<float>(y)[x]);
      const bool side = x == 0 || y == 0 || x + 1 == w || y + 1 == h;
      cut[k] |= (x == 0 && (drawing_edges & kLeftEdge)) || (y == 0 && (drawing_edges & kTopEdge)) ||
                (x + 1 == w && (drawing_edges & kRightEdge)) ||
                (y + 1 == h && (drawing_edges & kBottomEdge));
      const bool edge =
          side || lab[i - 1] != c || lab[i + 1] != c || lab[i - w] != c || lab[i + w] != c;
      if (!edge) continue;
      ++rim[k];
      if (near_hole.data[i]) ++rim_near[k];
    }
  std::vector<long> area(k_count, 0);
  long holes = 0;
  for (std::size_t i = 0; i < n; ++i) {
    ++area[static_cast<std::size_t>(lab[i])];
    holes += hole[i] != 0;
  }
  Materials m;
  m.label.assign(lab, lab + n);
  m.reach.assign(k_count, INT_MAX);
  for (std::size_t k = 1; k < k_count; ++k)
    if ((rim[k] > 0 && rim_near[k] >= kOnHair * rim[k]) ||
        (rim_near[k] > 0 && !cut[k] &&
         static_cast<double>(area[k]) < kSmall * static_cast<double>(holes)))
      m.reach[k] = static_cast<int>(std::lround(5.0f * std::max(kMinReach, thick[k])));
  return m;
}

// The geodesic fill's borders between materials are bisectors between
// scattered seeds: stairs, and spikes where a sliver of one colour seen
// between two strands reached into the paper (sylvie's shoulder). A
// majority vote over a disc, repeated (a discrete curvature flow), rounds
// them off: a hole pixel on a border takes the material most of the disc
// holds, from a neighbour of that material (so it never jumps a drawn
// line); known pixels vote and stay. `origin` of a changed pixel becomes
// its neighbour's.
void smooth_borders(const Image& image, const Mask& hole, const Mask& barrier, const Materials& m,
                    std::vector<int>& origin) {
  const int w = image.width(), h = image.height();
  constexpr int kRadius = 5;  // px: spikes and steps thinner than the disc go
  constexpr int kRounds = 6;
  const std::size_t n = static_cast<std::size_t>(w) * h;
  std::vector<int> cls(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    if (!hole[i])
      cls[i] = m.label[i];
    else if (!barrier[i] && origin[i] >= 0)
      cls[i] = m.label[static_cast<std::size_t>(origin[i])];
  }
  std::vector<std::pair<int, int>> disc;
  for (int dy = -kRadius; dy <= kRadius; ++dy)
    for (int dx = -kRadius; dx <= kRadius; ++dx)
      if (dx * dx + dy * dy <= kRadius * kRadius + kRadius) disc.emplace_back(dx, dy);
  std::vector<std::ptrdiff_t> offset;
  for (const auto& [dx, dy] : disc) offset.push_back(static_cast<std::ptrdiff_t>(dy) * w + dx);
  auto movable = [&](std::size_t i) { return hole[i] && !barrier[i] && cls[i] > 0; };
  // A pixel with an 8-neighbour of another material.
  auto on_border = [&](int x, int y) {
    const int c = cls[static_cast<std::size_t>(y) * w + x];
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int nx = x + dx, ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const int d = cls[static_cast<std::size_t>(ny) * w + nx];
        if (d > 0 && d != c) return true;
      }
    return false;
  };
  // The first borders: pairs of 8-neighbours of two materials of clearly
  // different colours (a border within soft shading is not seen), each pair
  // looked at once (right, lower left, lower, lower right).
  auto colour_of = [&](std::size_t i) -> const Rgba& {
    return image.data()[hole[i] ? static_cast<std::size_t>(origin[i]) : i];
  };
  auto contrast = [&](std::size_t i, std::size_t j) {
    const Rgba &a = colour_of(i), &b = colour_of(j);
    if ((a.a < 128) != (b.a < 128)) return true;
    return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) > 48;
  };
  Mask border(n, 0);
  for (int y = 0; y < h; ++y) {
    const int* row = cls.data() + static_cast<std::size_t>(y) * w;
    const int* below = y + 1 < h ? row + w : nullptr;
    for (int x = 0; x < w; ++x) {
      const int c = row[x];
      if (c <= 0) continue;
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      auto differ = [&](int d, std::size_t j) {
        if (d > 0 && d != c && (hole[i] || hole[j]) && contrast(i, j)) border[i] = border[j] = 1;
      };
      if (x + 1 < w) differ(row[x + 1], i + 1);
      if (below != nullptr) {
        if (x > 0) differ(below[x - 1], i + w - 1);
        differ(below[x], i + w);
        if (x + 1 < w) differ(below[x + 1], i + w + 1);
      }
    }
  }
  std::vector<int> stamp(n, -1), pending, next;
  for (std::size_t i = 0; i < n; ++i)
    if (border[i] && movable(i)) pending.push_back(static_cast<int>(i));
  std::vector<int> changes;
  std::vector<std::pair<int, int>> votes;
  for (int round = 0; round < kRounds && !pending.empty(); ++round) {
    changes.clear();
    for (const int i : pending) {
      const int x = i % w, y = i / w, own = cls[static_cast<std::size_t>(i)];
      const bool inside = x >= kRadius && y >= kRadius && x + kRadius < w && y + kRadius < h;
      // Most border pixels hold half their disc or more: they stay.
      int mine = 0, all = 0;
      for (std::size_t k = 0; k < disc.size(); ++k) {
        const auto [dx, dy] = disc[k];
        if (!inside && (x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h)) continue;
        const int c = cls[static_cast<std::size_t>(i + offset[k])];
        all += c > 0;
        mine += c == own;
      }
      if (2 * mine >= all) continue;
      votes.clear();
      for (std::size_t k = 0; k < disc.size(); ++k) {
        const auto [dx, dy] = disc[k];
        if (!inside && (x + dx < 0 || y + dy < 0 || x + dx >= w || y + dy >= h)) continue;
        const int c = cls[static_cast<std::size_t>(i + offset[k])];
        if (c <= 0) continue;
        auto it = std::find_if(votes.begin(), votes.end(), [c](auto& v) { return v.first == c; });
        if (it == votes.end())
          votes.emplace_back(c, 1);
        else
          ++it->second;
      }
      int best = own, best_count = 0, own_count = 0;
      for (const auto& [c, k] : votes) {
        if (c == own) own_count = k;
        if (k > best_count) best = c, best_count = k;
      }
      if (best == own || best_count <= own_count) continue;
      // Take it from a neighbour of that material (4-neighbours first).
      int from = -1;
      const int nx[8] = {x - 1, x + 1, x, x, x - 1, x + 1, x - 1, x + 1};
      const int ny[8] = {y, y, y - 1, y + 1, y - 1, y - 1, y + 1, y + 1};
      for (int pass = 0; pass < 2 && from < 0; ++pass)
        for (int k = 0; k < 8 && from < 0; ++k) {
          if (nx[k] < 0 || ny[k] < 0 || nx[k] >= w || ny[k] >= h) continue;
          const std::size_t j = static_cast<std::size_t>(ny[k]) * w + nx[k];
          if (cls[j] != best) continue;
          if (pass == 0 && hole[j] && origin[j] >= 0 && !barrier[j])
            from = origin[j];
          else if (pass == 1 && !hole[j])
            from = static_cast<int>(j);
        }
      if (from < 0) continue;
      // In place: the border moves on within the round, and a pixel cannot
      // flip back and forth with its neighbour.
      cls[static_cast<std::size_t>(i)] = best;
      origin[static_cast<std::size_t>(i)] = from;
      changes.push_back(i);
    }
    next.clear();
    for (const int i : changes) {
      const int x = i % w, y = i / w;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
          const std::size_t j = static_cast<std::size_t>(qy) * w + qx;
          if (stamp[j] == round || !movable(j) || !on_border(qx, qy)) continue;
          stamp[j] = round;
          next.push_back(static_cast<int>(j));
        }
    }
    pending.swap(next);
  }
}

}  // namespace

int flat_fill(Image& image, const Mask& hole, const Mask& ink, const Mask& barrier, int seam_radius,
              std::vector<int>* seed, int drawing_edges) {
  const int w = image.width(), h = image.height();
  const std::size_t n = static_cast<std::size_t>(w) * h;
  cv::Mat hole_m(h, w, CV_8U, const_cast<std::uint8_t*>(hole.data()));
  cv::Mat ink_m(h, w, CV_8U, const_cast<std::uint8_t*>(ink.data()));
  // Known pixels within a few pixels of the hole may carry the wave to the
  // hole pixels behind an ink rim; flat ones there are the seeds.
  constexpr int kBand = 4;
  constexpr float kThinDepth = 10.0f;    // px: regions thinner than twice this are "thin"
  constexpr float kThinPenalty = 10.0f;  // chamfer units (5 = 1 px) a px short of kThinDepth
  cv::Mat band, near_ink;
  cv::dilate(hole_m, band,
             cv::getStructuringElement(cv::MORPH_RECT, {2 * kBand + 1, 2 * kBand + 1}));
  cv::dilate(ink_m, near_ink, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  Mask pass(n, 0);
  std::vector<int> origin(n, -1), seeds;
  for (std::size_t i = 0; i < n; ++i) {
    if (!band.data[i] || barrier[i]) continue;
    if (hole[i]) {
      pass[i] = 1;
    } else if (!ink[i]) {
      pass[i] = 1;
      // Half-transparent pixels are the anti-aliased rim of a drawing on a
      // transparent sheet, not a colour of it.
      const std::uint8_t a = image.data()[i].a;
      if (!near_ink.data[i] && (a >= 240 || a <= kFaintAlpha)) {
        origin[i] = static_cast<int>(i);
        seeds.push_back(static_cast<int>(i));
      }
    }
  }
  if (seeds.empty())  // everything near the hole is ink: take any known pixel
    for (std::size_t i = 0; i < n; ++i)
      if (band.data[i] && !hole[i]) {
        pass[i] = 1;
        origin[i] = static_cast<int>(i);
        seeds.push_back(static_cast<int>(i));
      }
  // Thin bands along the hole (a shadow the hair casts, a highlight on a
  // clip's rim) start behind: they continue a little way, thick regions win.
  std::vector<int> start(seeds.size(), 0);
  const cv::Mat free = colour_free(image, hole, ink);
  const cv::Mat depth = region_depth(free);
  for (std::size_t k = 0; k < seeds.size(); ++k) {
    const float t = depth.at<float>(seeds[k] / w, seeds[k] % w);
    start[k] = static_cast<int>(std::lround(kThinPenalty * std::max(0.0f, kThinDepth - t)));
  }
  const Materials materials = find_materials(image, hole, ink, free, drawing_edges);
  propagate(w, h, pass, seeds, start, origin, &materials);
  // Pockets closed off by barriers or ink (and the barrier pixels
  // themselves) take the nearest colour across them.
  bool cut_off = false;
  for (std::size_t i = 0; i < n && !cut_off; ++i) cut_off = hole[i] && origin[i] < 0;
  if (cut_off) {
    std::vector<int> reached;
    Mask all(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      // Through ink too: a hole ringed by a line takes the colours beyond it.
      if (hole[i] || band.data[i]) all[i] = 1;
      if (origin[i] >= 0 && all[i]) reached.push_back(static_cast<int>(i));
    }
    propagate(w, h, all, reached, {}, origin, &materials);
  }
  smooth_borders(image, hole, barrier, materials, origin);
  int unreached = 0;
  Image filled = image;
  for (std::size_t i = 0; i < n; ++i)
    if (hole[i]) {
      if (origin[i] >= 0) {
        Rgba c = image.data()[static_cast<std::size_t>(origin[i])];
        // A seed this faint is a transparent sheet's paper under the last
        // step of an anti-aliased rim: it fills with the sheet. Spread with
        // its alpha of 1-15 it left faint grey squares on lucy's paper.
        if (c.a <= kFaintAlpha) c.a = 0;
        filled.data()[i] = c;
      } else
        ++unreached;
    }
  // A median straightens the Voronoi seams between colours and removes the
  // streaks of anti-aliased seed colours; not next to barriers, where the
  // window would mix the two sides of a drawn line.
  if (seam_radius > 0) {
    cv::Mat smooth, keep_out;
    cv::medianBlur(view(filled), smooth, 2 * seam_radius + 1);
    cv::Mat barrier_m(h, w, CV_8U, const_cast<std::uint8_t*>(barrier.data()));
    cv::dilate(
        barrier_m, keep_out,
        cv::getStructuringElement(cv::MORPH_RECT, {2 * seam_radius + 1, 2 * seam_radius + 1}));
    for (std::size_t i = 0; i < n; ++i)
      if (hole[i] && origin[i] >= 0 && !keep_out.data[i]) {
        const cv::Vec4b& v = smooth.at<cv::Vec4b>(static_cast<int>(i / w), static_cast<int>(i % w));
        filled.data()[i] = {v[0], v[1], v[2], v[3]};
      }
  }
  for (std::size_t i = 0; i < n; ++i)
    if (hole[i]) image.data()[i] = filled.data()[i];
  if (seed != nullptr) {
    seed->assign(n, -1);
    for (std::size_t i = 0; i < n; ++i)
      if (hole[i]) (*seed)[i] = origin[i];
  }
  return unreached;
}

}  // namespace hair25d::completion::detail
