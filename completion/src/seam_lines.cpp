// Ink along the seams of the background's flat fill: where two fill colours
// meet inside the hole and the drawing keeps those two colours apart with an
// ink line (a face against the paper), the seam is drawn as a line too; where
// the drawing lets them touch (cel shading on skin), it is left as it is.
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <unordered_map>
#include <vector>

#include "background_internal.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// Keys this near (RGB, in 16-level steps) count as one colour in the pair
// counts: two steps in one channel, or one in each of three.
constexpr double kNearKey = 40.0;

// 4 bits a channel: anti-aliasing and compression noise fall into one key;
// every mostly transparent pixel is one key (a transparent sheet).
constexpr int kTransparent = 1 << 12;
int colour_key(const Rgba& c) {
  return c.a < 128 ? kTransparent : (c.r >> 4) << 8 | (c.g >> 4) << 4 | (c.b >> 4);
}

double key_distance(int a, int b) {
  if (a == kTransparent || b == kTransparent) return a == b ? 0.0 : 255.0;
  const double dr = ((a >> 8) & 15) - ((b >> 8) & 15), dg = ((a >> 4) & 15) - ((b >> 4) & 15),
               db = (a & 15) - (b & 15);
  return 16.0 * std::sqrt(dr * dr + dg * dg + db * db);
}

// key_distance(a, b) <= kNearKey without the square root.
bool near_key(int a, int b) {
  if (a == kTransparent || b == kTransparent) return a == b;
  const int dr = ((a >> 8) & 15) - ((b >> 8) & 15), dg = ((a >> 4) & 15) - ((b >> 4) & 15),
            db = (a & 15) - (b & 15);
  return 256 * (dr * dr + dg * dg + db * db) <= static_cast<int>(kNearKey * kNearKey);
}

std::uint32_t pair_key(int a, int b) {
  return static_cast<std::uint32_t>(std::min(a, b)) << 13 |
         static_cast<std::uint32_t>(std::max(a, b));
}

struct PairCount {
  int direct = 0, inked = 0;
  // Over the inked crossings: the darkest pixel's colour and the ink's
  // length along the scan, summed.
  long r = 0, g = 0, b = 0, a = 0, ink_px = 0, crossings = 0;
};

constexpr double kMinContrast = 40.0;  // RGB distance of colours that need a border at all

// Along rows and columns of the known pixels: consecutive stable colours
// (two pixels alike) within 12 px, and whether ink lay between them.
std::unordered_map<std::uint32_t, PairCount> count_pairs(const Image& image, const Mask& hole,
                                                         const Mask& ink, const Mask& near_ink) {
  const int w = image.width(), h = image.height();
  std::unordered_map<std::uint32_t, PairCount> pairs;
  auto scan = [&](int length, auto index) {
    int stable = -1, stable_at = -100, run_key = -1, run = 0, ink_px = 0, darkest = 256;
    Rgba dark{};
    bool ink_between = false;
    for (int t = 0; t < length; ++t) {
      const std::size_t i = index(t);
      if (hole[i]) {
        stable = -1, run_key = -1, run = 0;
        continue;
      }
      if (near_ink[i]) {
        if (!ink_between) ink_px = 0, darkest = 256;
        ink_between = true;
        run_key = -1, run = 0;
        if (ink[i]) {
          ++ink_px;
          if (luma(image.data()[i]) < darkest)
            darkest = luma(image.data()[i]), dark = image.data()[i];
        }
        continue;
      }
      const int key = colour_key(image.data()[i]);
      run = key == run_key ? run + 1 : 1;
      run_key = key;
      if (run > 2 && key == stable) stable_at = t;
      if (run != 2) continue;
      if (stable >= 0 && key != stable && t - stable_at <= 12 &&
          key_distance(key, stable) >= kMinContrast) {
        PairCount& c = pairs[pair_key(key, stable)];
        (ink_between ? c.inked : c.direct) += 1;
        if (ink_between && ink_px > 0) {
          c.r += dark.r, c.g += dark.g, c.b += dark.b, c.a += dark.a, c.ink_px += ink_px;
          ++c.crossings;
        }
      }
      stable = key, stable_at = t, ink_between = false;
    }
  };
  // Every other row and column: a border crosses many of them.
  for (int y = 0; y < h; y += 2)
    scan(w, [&](int x) { return static_cast<std::size_t>(y) * w + x; });
  for (int x = 0; x < w; x += 2)
    scan(h, [&](int y) { return static_cast<std::size_t>(y) * w + x; });
  return pairs;
}

}  // namespace

int ink_seams(Image& filled, const Image& original, const Mask& hole, const Mask& ink,
              const Mask& barrier, const Rgba& fallback_colour, double fallback_width) {
  const int w = filled.width(), h = filled.height();
  // Candidates first (most neighbours in a flat fill are equal): hole pixels
  // whose right or lower neighbour has a clearly different colour.
  struct Candidate {
    int x, y;
    int a, b;  // colour keys
  };
  std::vector<Candidate> candidates;
  auto same = [](const Rgba& p, const Rgba& q) {
    return p.r == q.r && p.g == q.g && p.b == q.b && p.a == q.a;
  };
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!hole[i] || barrier[i]) continue;
      for (const std::size_t j : {x + 1 < w ? i + 1 : i, y + 1 < h ? i + w : i}) {
        if (j == i || !hole[j] || barrier[j] || same(filled.data()[i], filled.data()[j])) continue;
        const int a = colour_key(filled.data()[i]), b = colour_key(filled.data()[j]);
        if (a != b && key_distance(a, b) >= kMinContrast) candidates.push_back({x, y, a, b});
      }
    }
  if (candidates.empty()) return 0;
  cv::Mat ink_m(h, w, CV_8U, const_cast<std::uint8_t*>(ink.data())), near_m;
  cv::dilate(ink_m, near_m, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  const Mask near_ink(near_m.datastart, near_m.dataend);
  const auto pairs = count_pairs(original, hole, ink, near_ink);
  // Seam pixels: 0 in `away` (distance transform input), on the box of the seams.
  int x0 = w, y0 = h, x1 = -1, y1 = -1, seams = 0;
  std::vector<cv::Point> marks;
  PairCount ink_sum;
  // A fill colour is counted together with the drawing's colours near it: a
  // shirt's soft shading spreads its border with the paper over many keys,
  // each seen only a few times along the visible outline (sylvie's shoulder
  // got no line where its lighter blue met the paper).
  std::unordered_map<std::uint32_t, PairCount> near_pairs;
  auto counts = [&](int a, int b) -> const PairCount& {
    const std::uint32_t key = pair_key(a, b);
    auto it = near_pairs.find(key);
    if (it != near_pairs.end()) return it->second;
    PairCount sum;
    for (const auto& [k, c] : pairs) {
      const int p = static_cast<int>(k >> 13), q = static_cast<int>(k & 0x1fff);
      if ((near_key(a, p) && near_key(b, q)) || (near_key(a, q) && near_key(b, p)))
        sum.inked += c.inked, sum.direct += c.direct, sum.r += c.r, sum.g += c.g, sum.b += c.b,
            sum.a += c.a, sum.ink_px += c.ink_px, sum.crossings += c.crossings;
    }
    return near_pairs.emplace(key, sum).first->second;
  };
  for (const Candidate& c : candidates) {
    const PairCount& count = counts(c.a, c.b);
    if (count.inked < 5 || count.inked <= 2 * count.direct) continue;
    marks.emplace_back(c.x, c.y);
    ink_sum.crossings += count.crossings, ink_sum.r += count.r, ink_sum.g += count.g,
        ink_sum.b += count.b, ink_sum.a += count.a, ink_sum.ink_px += count.ink_px;
    x0 = std::min(x0, c.x), y0 = std::min(y0, c.y), x1 = std::max(x1, c.x), y1 = std::max(y1, c.y);
  }
  if (marks.empty()) return 0;
  // The line the drawing puts between those colours: its darkest pixels'
  // colour and its width along the scans (a slanted line is crossed longer,
  // hence 0.8). Lucy's dress met the paper along a thick black line, the
  // colour of the black hair's line ends, where her own lines are thin.
  Rgba colour = fallback_colour;
  double width = fallback_width;
  if (ink_sum.crossings > 0) {
    const long k = ink_sum.crossings;
    colour = {static_cast<std::uint8_t>(ink_sum.r / k), static_cast<std::uint8_t>(ink_sum.g / k),
              static_cast<std::uint8_t>(ink_sum.b / k), static_cast<std::uint8_t>(ink_sum.a / k)};
    width =
        std::clamp(0.8 * static_cast<double>(ink_sum.ink_px) / static_cast<double>(k), 1.0, 4.0);
  }
  // Distance to the nearest seam pixel, only as far as the line reaches
  // (a distance transform of the seams' whole box costs more).
  const int reach = static_cast<int>(std::ceil(0.5 * width)) + 2;
  const cv::Rect box =
      cv::Rect(cv::Point(x0 - reach, y0 - reach), cv::Point(x1 + reach + 1, y1 + reach + 1)) &
      cv::Rect(0, 0, w, h);
  cv::Mat dist(box.size(), CV_32F, cv::Scalar(1e9f));
  for (const cv::Point& m : marks) {
    float& here = dist.at<float>(m.y - box.y, m.x - box.x);
    seams += here != 0.0f;
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const int x = m.x - box.x + dx, y = m.y - box.y + dy;
        if (x < 0 || y < 0 || x >= box.width || y >= box.height) continue;
        float& d = dist.at<float>(y, x);
        d = std::min(d, std::sqrt(static_cast<float>(dx * dx + dy * dy)));
      }
  }
  // The seam pixels lie on one side of the true border: centre the line half
  // a pixel over and give it an anti-aliased edge.
  const double half = 0.5 * width;
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y + box.y) * w + (x + box.x);
      if (!hole[i]) continue;
      const double d = dist.at<float>(y, x);
      const double cover = std::clamp(half + 0.5 - std::abs(d - 0.5), 0.0, 1.0) * colour.a / 255.0;
      if (cover <= 0) continue;
      Rgba& p = filled.data()[i];
      const double da = p.a / 255.0, oa = cover + da * (1 - cover);
      auto mix = [&](double line, double under) {
        return static_cast<std::uint8_t>(std::clamp(
            std::lround((line * cover + under * da * (1 - cover)) / std::max(oa, 1e-9)), 0L, 255L));
      };
      p = {mix(colour.r, p.r), mix(colour.g, p.g), mix(colour.b, p.b),
           static_cast<std::uint8_t>(std::lround(oa * 255))};
    }
  return seams;
}

}  // namespace hair25d::completion::detail
