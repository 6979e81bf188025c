#include "cover_retry.h"

#include <algorithm>
#include <cmath>

#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// An uncovered pixel this near a cut (the wider cut's width times this, at
// least kMinCutReach px) is "at the cut": the drawn outline and its light
// fringe lie there, where a right patch often leaves the occluder's region
// for a pixel or two (joins72, joins75); a wrong one misses in its middle.
constexpr double kCutReachShare = 0.15;
constexpr double kMinCutReach = 3.0;

double segment_distance(const Vec2& x, const Vec2& p, const Vec2& q) {
  const Vec2 d = q - p;
  const double n = d.squaredNorm();
  const double s = n > 0 ? std::clamp((x - p).dot(d) / n, 0.0, 1.0) : 0.0;
  return (x - (p + s * d)).norm();
}

}  // namespace

void add_cover_terms(const Context& ctx, const Polyline& patch, const Edge& a, const Edge& b,
                     const cv::Mat& face, const cv::Mat& cover_face, bool ink, double shape_cover,
                     JoinTerms* t) {
  t->cover_retried = true;
  t->shape_cover = shape_cover;
  const cv::Rect box = polygon_box(patch);
  if (box.empty()) return;
  const cv::Point origin = box.tl();
  const int w = box.width, h = box.height;
  cv::Mat mask(h, w, CV_8U, cv::Scalar(0));
  fill_polygon(mask, patch, origin, 255);
  const int ra = a.region, rb = b.region;
  const double wide = std::max({a.width, b.width, 1.0});
  const double reach = std::max(kMinCutReach, kCutReachShare * wide);
  AboveEither above(ctx, ra, rb);
  // A region's class, asked once per label: a patch crosses few of them.
  std::vector<std::pair<int, HoleKind>> kinds;
  auto kind_of = [&](int l) {
    for (const auto& [label, k] : kinds)
      if (label == l) return k;
    kinds.push_back({l, hole_kind(ctx, ra, rb, l)});
    return kinds.back().second;
  };
  int total = 0, missed = 0, at_cuts = 0;
  double paper = 0, on_face = 0, on_ink = 0, below = 0, sibling = 0, other = 0;
  for (int y = 0; y < h; ++y) {
    const std::uint8_t* row = mask.ptr<std::uint8_t>(y);
    for (int x = 0; x < w; ++x) {
      if (!row[x]) continue;
      const int gx = x + origin.x, gy = y + origin.y;
      const bool inside = ctx.labels.contains(gx, gy);
      const int l = inside ? ctx.labels.at(gx, gy) : 0;
      if (inside && (l == ra || l == rb)) continue;
      ++total;
      if (inside && above.hides(l, gx, gy, cover_face, ink)) continue;
      ++missed;
      // Label 0 is no hair region: the face, a drawn line, or the paper
      // (the background); a hair region's pixel that was outline in the
      // map as given is ink assigned to it.
      if (!inside)
        ++paper;
      else if (l == 0 && !face.empty() && face.at<std::uint8_t>(gy, gx))
        ++on_face;
      else if (l == 0)
        ++(luma(ctx.image->at(gx, gy)) < ctx.options->dark_luma ? on_ink : paper);
      else if (ctx.original->at(gx, gy) == 0)
        ++on_ink;
      else
        switch (kind_of(l)) {
          case HoleKind::kBelow:
            ++below;
            break;
          case HoleKind::kSibling:
            ++sibling;
            break;
          case HoleKind::kOther:
            ++other;
            break;
        }
      const Vec2 c(gx + 0.5, gy + 0.5);
      if (std::min(segment_distance(c, a.p, a.q), segment_distance(c, b.p, b.q)) <= reach)
        ++at_cuts;
    }
  }
  if (total == 0) return;
  t->miss_paper = paper / total;
  t->miss_face = on_face / total;
  t->miss_ink = on_ink / total;
  t->miss_below = below / total;
  t->miss_sibling = sibling / total;
  t->miss_other = other / total;
  t->miss_per_width = missed / (wide * wide);
  t->miss_at_cuts = missed > 0 ? static_cast<double>(at_cuts) / missed : 0.0;
}

}  // namespace hair25d::completion::detail
