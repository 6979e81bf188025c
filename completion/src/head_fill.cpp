#include "head_fill.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "face_joins.h"
#include "inpaint_internal.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// A face pixel is skin when within this RGB distance of the face's median.
constexpr double kSkinDistance = 48.0;
// Fewer skin pixels than this: no head (nothing to copy from).
constexpr int kMinSkin = 200;
// The face's width is taken at this quantile of its rows' widths (a few
// rows through a stray skin piece are not its width).
constexpr double kWidthQuantile = 0.95;
// The skull is a little wider than the face shows where hair along the
// face's sides hides its edge (hair within kSideReach px of the widest rows'
// ends); as wide where the face's own outline bounds it.
constexpr double kSkullScale = 1.2;
constexpr int kSideReach = 4;
// The face belongs to the head up to this many skull radii from the head
// centre (the chin lies within 1.3–1.7 on the samples).
constexpr double kFaceReach = 1.5;
// Sigma (px) of the smoothing of the coarse skin fill: it removes the
// seams between the nearest skin pixels, not the skin's own shading.
constexpr double kSmoothSigma = 5.0;
// The face's shading next to the hole fades into its median colour over
// this many px (a shadow under the bangs, a highlight, do not fill the skull).
constexpr double kShadingReach = 16.0;
// Skin beyond the face's mask within this many px of its skin (across a
// line) is the face's too.
constexpr int kLineGap = 6;
// Fewer skin pixels than this joined to the face is no cheek.
constexpr int kMinSkinPiece = 100;

// A piece of the face lying wholly below its largest piece, more than this
// many px under it, with no hair between them, is the neck or the chest seen
// below a collar or a scarf (sylvie), no part of the head. A piece cut off by
// a strand lying across the face has hair between.
constexpr int kChinGap = 6;
// Pieces with less skin than this share of the largest's are specks (a
// skin-coloured gap between locks beside the face).
constexpr double kMinPieceShare = 0.01;

// 1 on the face's pieces that belong to the head, with their outlines. The
// pieces are those of the face's ink-free pixels (find_face's mask holds the
// outlines up to `outline_reach` px, which bridges a scarf's band between its
// lines); a piece counts by its skin pixels (`skin`; paper or a scarf next to
// the face's outline has none). Kept: the piece with the most skin, and the
// others that are no speck and do not lie below it past kChinGap across
// something other than hair.
cv::Mat head_pieces(const Context& ctx, const cv::Mat& face_mask, const cv::Mat& skin,
                    const std::vector<std::uint8_t>& ink) {
  cv::Mat open = face_mask.clone();
  for (int y = 0; y < open.rows; ++y)
    for (int x = 0; x < open.cols; ++x)
      if (ink[static_cast<std::size_t>(y) * open.cols + x]) open.at<std::uint8_t>(y, x) = 0;
  cv::Mat parts, stats, centroids;
  const int n = cv::connectedComponentsWithStats(open, parts, stats, centroids, 4, CV_32S);
  std::vector<int> skin_of(static_cast<std::size_t>(n), 0);
  for (int y = 0; y < parts.rows; ++y)
    for (int x = 0; x < parts.cols; ++x)
      if (skin.at<std::uint8_t>(y, x)) ++skin_of[static_cast<std::size_t>(parts.at<int>(y, x))];
  auto stat = [&](int k, int which) { return stats.at<int>(k, which); };
  int largest = 0;
  for (int k = 1; k < n; ++k)
    if (skin_of[static_cast<std::size_t>(k)] > skin_of[static_cast<std::size_t>(largest)])
      largest = k;
  std::vector<std::uint8_t> keep(static_cast<std::size_t>(n), 0);
  const int bottom = stat(largest, cv::CC_STAT_TOP) + stat(largest, cv::CC_STAT_HEIGHT) - 1;
  for (int k = 1; largest > 0 && k < n; ++k) {
    const int s = skin_of[static_cast<std::size_t>(k)];
    if (s == 0 || s < kMinPieceShare * skin_of[static_cast<std::size_t>(largest)]) continue;
    const int top = stat(k, cv::CC_STAT_TOP);
    // What lies between it and the largest piece, over its columns.
    int between = 0, hair = 0;
    const int x0 = stat(k, cv::CC_STAT_LEFT), x1 = x0 + stat(k, cv::CC_STAT_WIDTH);
    for (int y = bottom + 1; y < top; ++y)
      for (int x = x0; x < x1; ++x) {
        ++between;
        hair += ctx.label(x, y) != 0;
      }
    keep[static_cast<std::size_t>(k)] = top <= bottom + kChinGap || 2 * hair >= between;
  }
  cv::Mat kept(face_mask.size(), CV_8U, cv::Scalar(0));
  for (int y = 0; y < parts.rows; ++y)
    for (int x = 0; x < parts.cols; ++x)
      kept.at<std::uint8_t>(y, x) = keep[static_cast<std::size_t>(parts.at<int>(y, x))];
  const int r = ctx.options->outline_reach;
  cv::dilate(kept, kept, cv::getStructuringElement(cv::MORPH_ELLIPSE, {2 * r + 1, 2 * r + 1}));
  return kept & face_mask;
}

// Mean |luma − its 3×3 median| over the skin pixels (0 on flat or softly
// shaded skin).
double skin_texture(const Image& image, const cv::Mat& skin) {
  cv::Mat grey(image.height(), image.width(), CV_8U), med;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) grey.at<std::uint8_t>(y, x) = luma(image.at(x, y));
  cv::medianBlur(grey, med, 3);
  double sum = 0.0;
  int count = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      if (skin.at<std::uint8_t>(y, x)) {
        sum += std::abs(grey.at<std::uint8_t>(y, x) - med.at<std::uint8_t>(y, x));
        ++count;
      }
  return count > 0 ? sum / count : 0.0;
}

}  // namespace

Head find_head(const Context& ctx, const Face& face, const InpaintOptions& options) {
  Head head;
  if (face.pixels == 0) return head;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  const std::vector<std::uint8_t> ink = ink_mask(image, options);
  // Median colour of the face's opaque, ink-free pixels.
  std::vector<int> r, g, b;
  std::vector<cv::Point> points;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!face.mask.at<std::uint8_t>(y, x)) continue;
      points.emplace_back(x, y);
      const Rgba& c = image.at(x, y);
      if (ink[static_cast<std::size_t>(y) * w + x] || c.a < 240) continue;
      r.push_back(c.r), g.push_back(c.g), b.push_back(c.b);
    }
  if (static_cast<int>(r.size()) < kMinSkin) return head;
  auto median = [](std::vector<int>& v) {
    std::nth_element(v.begin(), v.begin() + v.size() / 2, v.end());
    return static_cast<std::uint8_t>(v[v.size() / 2]);
  };
  head.colour = {median(r), median(g), median(b), 255};
  head.skin = cv::Mat(h, w, CV_8U, cv::Scalar(0));
  for (const cv::Point& p : points) {
    const Rgba& c = image.at(p.x, p.y);
    if (ink[static_cast<std::size_t>(p.y) * w + p.x] || c.a < 240) continue;
    if (colour_distance(c, head.colour) > kSkinDistance) continue;
    head.skin.at<std::uint8_t>(p) = 1;
    ++head.skin_pixels;
  }
  // Not the anti-aliased rims of lines and hair (blends of skin and ink
  // that pass the colour test): the skin at least 2 px inside.
  cv::Mat inner;
  cv::erode(head.skin, inner, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  head.skin_pixels = cv::countNonZero(inner);
  head.skin = inner;
  if (head.skin_pixels < kMinSkin) return head;
  // The skull: a disc round the head centre as wide as the face at its
  // widest (the cheeks; rows through the neck are narrower, and the face's
  // far side, the chin or the neck, lies well below the skull's rim). With
  // the face's own hull it is the head.
  std::vector<int> lo(h, w), hi(h, -1);
  for (const cv::Point& p : points)
    lo[p.y] = std::min(lo[p.y], p.x), hi[p.y] = std::max(hi[p.y], p.x);
  std::vector<int> widths;
  for (int y = 0; y < h; ++y)
    if (hi[y] >= lo[y]) widths.push_back(hi[y] - lo[y] + 1);
  if (widths.empty()) return head;
  std::sort(widths.begin(), widths.end());
  const int widest = widths[static_cast<std::size_t>(kWidthQuantile * (widths.size() - 1))];
  // Where hair lies along the face's sides at its widest rows, the skull
  // reaches under it: wider than the face shows.
  int ends = 0, under_hair = 0;
  for (int y = 0; y < h; ++y) {
    if (hi[y] < lo[y] || hi[y] - lo[y] + 1 < widest) continue;
    for (const int x : {lo[y] - kSideReach, hi[y] + kSideReach}) {
      ++ends;
      under_hair += ctx.label(x, y) != 0;
    }
  }
  const double share = ends > 0 ? static_cast<double>(under_hair) / ends : 0.0;
  const double radius = (1.0 + (kSkullScale - 1.0) * share) * 0.5 * widest;
  // The face's hull, without what runs on below the jaw (an open outline
  // lets the face run into the neck and the chest).
  // The face's skin runs on beyond find_face's mask: lucy's face is the
  // band of her eyes and glasses, her cheeks and jaw are skin joined to it.
  // Left out of the head, they bordered the rest of the hole and the flat
  // fill continued them sideways to the hair's outer edge. Known pixels of
  // the skin's colour joined to the face's skin count with the face.
  cv::Mat skin_like(h, w, CV_8U, cv::Scalar(0)), parts;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const Rgba& c = image.at(x, y);
      if (ctx.label(x, y) == 0 && !ink[static_cast<std::size_t>(y) * w + x] && c.a >= 240 &&
          colour_distance(c, head.colour) <= kSkinDistance)
        skin_like.at<std::uint8_t>(y, x) = 1;
    }
  // Joined across a line (her glasses' frame, the nose's line): within
  // kLineGap px of the face's skin.
  // Only the head's pieces of the face count: the chest's skin below a
  // scarf drew the head's hull down beside the neck to the shoulder, and the
  // skull's hidden side was filled with skin down to there.
  const cv::Mat pieces = head_pieces(ctx, face.mask, head.skin, ink);
  cv::Mat reach;
  cv::dilate(
      head.skin & pieces, reach,
      cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * kLineGap + 1, 2 * kLineGap + 1)));
  auto within = [&](int x, int y) {
    return std::hypot(x + 0.5 - ctx.head.x(), y + 0.5 - ctx.head.y()) <= kFaceReach * radius;
  };
  // A small piece is a gap between locks showing what is behind them, no
  // cheek.
  const int n = cv::connectedComponents(skin_like, parts, 8, CV_32S);
  std::vector<std::uint8_t> joined(static_cast<std::size_t>(n), 0);
  std::vector<int> area(static_cast<std::size_t>(n), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto k = static_cast<std::size_t>(parts.at<int>(y, x));
      if (reach.at<std::uint8_t>(y, x)) joined[k] = 1;
      ++area[k];
    }
  for (std::size_t k = 1; k < joined.size(); ++k)
    if (area[k] < kMinSkinPiece) joined[k] = 0;
  std::vector<cv::Point> near, hull;
  for (const cv::Point& p : points)
    if (within(p.x, p.y) && pieces.at<std::uint8_t>(p)) near.push_back(p);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int k = parts.at<int>(y, x);
      if (k > 0 && joined[static_cast<std::size_t>(k)] && skin_like.at<std::uint8_t>(y, x) &&
          !face.mask.at<std::uint8_t>(y, x) && within(x, y))
        near.emplace_back(x, y);
    }
  // The head is one convex shape, the skull and the face: its outline runs
  // from the jaw straight on to the skull (the disc and the face's hull
  // apart left a notch at the cheeks, which the rim line followed).
  const int disc_points = 64;
  for (int i = 0; i < disc_points; ++i) {
    const double a = 2.0 * std::numbers::pi * i / disc_points;
    near.emplace_back(static_cast<int>(std::lround(ctx.head.x() + radius * std::cos(a))),
                      static_cast<int>(std::lround(ctx.head.y() + radius * std::sin(a))));
  }
  cv::convexHull(near, hull);
  head.mask = cv::Mat(h, w, CV_8U, cv::Scalar(0));
  cv::fillConvexPoly(head.mask, hull, cv::Scalar(1));
  return head;
}

InpaintResult fill_head(Image& image, const cv::Mat& hole, const Head& head,
                        const InpaintOptions& options, double texture_threshold) {
  InpaintResult result;
  if (head.mask.empty()) return result;
  const int w = image.width(), h = image.height();
  cv::Mat target = hole & head.mask;
  const cv::Rect found = cv::boundingRect(target);
  if (found.area() == 0) return result;
  // Work on the target's box plus room for patches and nearby skin.
  const int pad = options.patch_radius + options.search_radius;
  const cv::Rect box =
      cv::Rect(found.x - pad, found.y - pad, found.width + 2 * pad, found.height + 2 * pad) &
      cv::Rect(0, 0, w, h);
  const cv::Mat t = target(box), skin = head.skin(box);
  // Coarse fill: the colour of the nearest skin pixel (anywhere on the face
  // within the box; with none there, the skin's median), then smoothed.
  cv::Mat not_skin = skin == 0, dist, labels;
  Image sub(box.width, box.height);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) sub.at(x, y) = image.at(x + box.x, y + box.y);
  Image guide = sub;
  if (cv::countNonZero(skin) > 0) {
    cv::distanceTransform(not_skin, dist, labels, cv::DIST_L2, cv::DIST_MASK_5,
                          cv::DIST_LABEL_PIXEL);
    std::vector<Rgba> colour_of(static_cast<std::size_t>(box.area()) + 1, head.colour);
    for (int y = 0; y < box.height; ++y)
      for (int x = 0; x < box.width; ++x)
        if (skin.at<std::uint8_t>(y, x)) colour_of[labels.at<int>(y, x)] = sub.at(x, y);
    // Near the face its shading continues; deeper in, the plain skin.
    for (int y = 0; y < box.height; ++y)
      for (int x = 0; x < box.width; ++x) {
        if (!t.at<std::uint8_t>(y, x)) continue;
        const Rgba& c = colour_of[labels.at<int>(y, x)];
        const double f = std::min(1.0, dist.at<float>(y, x) / kShadingReach);
        auto mix = [&](std::uint8_t a, std::uint8_t b) {
          return static_cast<std::uint8_t>(std::lround((1 - f) * a + f * b));
        };
        guide.at(x, y) = {mix(c.r, head.colour.r), mix(c.g, head.colour.g), mix(c.b, head.colour.b),
                          255};
      }
  } else {
    for (int y = 0; y < box.height; ++y)
      for (int x = 0; x < box.width; ++x)
        if (t.at<std::uint8_t>(y, x)) guide.at(x, y) = head.colour;
  }
  // Smooth over the target and the skin only (normalised: other colours
  // next to the head do not bleed in).
  cv::Mat weight(box.height, box.width, CV_32F), colour(box.height, box.width, CV_32FC3);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const bool use = t.at<std::uint8_t>(y, x) || skin.at<std::uint8_t>(y, x);
      const Rgba& c = guide.at(x, y);
      weight.at<float>(y, x) = use ? 1.0f : 0.0f;
      colour.at<cv::Vec3f>(y, x) = use ? cv::Vec3f(c.r, c.g, c.b) : cv::Vec3f(0, 0, 0);
    }
  cv::GaussianBlur(weight, weight, {0, 0}, kSmoothSigma);
  cv::GaussianBlur(colour, colour, {0, 0}, kSmoothSigma);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      if (!t.at<std::uint8_t>(y, x)) continue;
      const float wgt = std::max(weight.at<float>(y, x), 1e-6f);
      const cv::Vec3f c = colour.at<cv::Vec3f>(y, x) / wgt;
      guide.at(x, y) = {cv::saturate_cast<std::uint8_t>(c[0]),
                        cv::saturate_cast<std::uint8_t>(c[1]),
                        cv::saturate_cast<std::uint8_t>(c[2]), 255};
    }
  // Exemplar pass from skin only, guided by the smooth fill.
  LabelMap fill(box.width, box.height), source(box.width, box.height);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      fill.at(x, y) = t.at<std::uint8_t>(y, x);
      source.at(x, y) = skin.at<std::uint8_t>(y, x);
      if (fill.at(x, y)) sub.at(x, y) = guide.at(x, y);
    }
  // Exemplar patches from skin only where the skin is textured (screentone,
  // hatching, painted grain); soft cel shading takes the smooth fill, which
  // copied patches would only break into blotches.
  if (skin_texture(sub, skin) > texture_threshold)
    result = run_exemplar(sub, fill, source, options, &guide);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x)
      if (t.at<std::uint8_t>(y, x)) image.at(x + box.x, y + box.y) = sub.at(x, y);
  result.filled = cv::countNonZero(t);
  result.unfilled = 0;  // unmatched pixels keep the smooth fill
  return result;
}

}  // namespace hair25d::completion::detail
