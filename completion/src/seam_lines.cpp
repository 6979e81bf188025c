// Ink along the seams of the background's flat fill: where two fill colours
// meet inside the hole and the drawing keeps those two colours apart with an
// ink line (a face against the paper), the seam is drawn as a line too; where
// the drawing lets them touch (cel shading on skin), it is left as it is.
#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <unordered_map>

#include "background_internal.h"

namespace hair25d::completion::detail {
namespace {

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

std::uint32_t pair_key(int a, int b) {
  return static_cast<std::uint32_t>(std::min(a, b)) << 13 |
         static_cast<std::uint32_t>(std::max(a, b));
}

struct PairCount {
  int direct = 0, inked = 0;
};

constexpr double kMinContrast = 40.0;  // RGB distance of colours that need a border at all

// Along every row and column of the known pixels: consecutive stable colours
// (two pixels alike) within 12 px, and whether ink lay between them.
std::unordered_map<std::uint32_t, PairCount> count_pairs(const Image& image, const Mask& hole,
                                                         const Mask& near_ink) {
  const int w = image.width(), h = image.height();
  std::unordered_map<std::uint32_t, PairCount> pairs;
  auto scan = [&](int length, auto index) {
    int stable = -1, stable_at = -100, run_key = -1, run = 0;
    bool ink_between = false;
    for (int t = 0; t < length; ++t) {
      const std::size_t i = index(t);
      if (hole[i]) {
        stable = -1, run_key = -1, run = 0;
        continue;
      }
      if (near_ink[i]) {
        ink_between = true;
        run_key = -1, run = 0;
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
      }
      stable = key, stable_at = t, ink_between = false;
    }
  };
  for (int y = 0; y < h; ++y) scan(w, [&](int x) { return static_cast<std::size_t>(y) * w + x; });
  for (int x = 0; x < w; ++x) scan(h, [&](int y) { return static_cast<std::size_t>(y) * w + x; });
  return pairs;
}

}  // namespace

int ink_seams(Image& filled, const Image& original, const Mask& hole, const Mask& ink,
              const Mask& barrier, const Rgba& colour, double width) {
  const int w = filled.width(), h = filled.height();
  const std::size_t n = static_cast<std::size_t>(w) * h;
  cv::Mat ink_m(h, w, CV_8U, const_cast<std::uint8_t*>(ink.data())), near_m;
  cv::dilate(ink_m, near_m, cv::getStructuringElement(cv::MORPH_RECT, {3, 3}));
  const Mask near_ink(near_m.datastart, near_m.dataend);
  const auto pairs = count_pairs(original, hole, near_ink);
  auto inked = [&](int a, int b) {
    if (a == b || key_distance(a, b) < kMinContrast) return false;
    auto it = pairs.find(pair_key(a, b));
    return it != pairs.end() && it->second.inked >= 10 && it->second.inked > 2 * it->second.direct;
  };
  // Seam pixels: 0 in `away` (distance transform input), hole pixels whose
  // right or lower neighbour has a colour the drawing separates by ink.
  cv::Mat away(h, w, CV_8U, cv::Scalar(255));
  int seams = 0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (!hole[i] || barrier[i]) continue;
      const int a = colour_key(filled.data()[i]);
      for (const std::size_t j : {x + 1 < w ? i + 1 : i, y + 1 < h ? i + w : i}) {
        if (j == i || !hole[j] || barrier[j]) continue;
        if (inked(a, colour_key(filled.data()[j]))) {
          away.at<std::uint8_t>(y, x) = 0;
          ++seams;
          break;
        }
      }
    }
  if (seams == 0) return 0;
  cv::Mat dist;
  cv::distanceTransform(away, dist, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  // The seam pixels lie on one side of the true border: centre the line half
  // a pixel over and give it an anti-aliased edge.
  const double half = 0.5 * width;
  for (std::size_t i = 0; i < n; ++i) {
    if (!hole[i]) continue;
    const double d = dist.at<float>(static_cast<int>(i / w), static_cast<int>(i % w));
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
