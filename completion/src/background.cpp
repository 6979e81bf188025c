// The background behind the hair (paper §5.4): the drawing with the hair
// removed and the hole filled at full resolution so that moving hair uncovers
// face, skin or paper. Cel drawings are flat colours bounded by ink, so: ink
// lines that enter the hole are continued, flat colours fill up to them, and
// the exemplar pass of Criminisi et al. runs only where the surroundings are
// textured.
#include "hair25d/completion/background.h"

#include <algorithm>
#include <cmath>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "background_internal.h"
#include "front_outlines.h"
#include "hair25d/core/error.h"
#include "head_fill.h"
#include "inpaint_internal.h"
#include "raster.h"
#include "strand_assembly.h"

namespace hair25d::completion {

bool BackgroundOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "completion::BackgroundOptions::" + m;
    return false;
  };
  auto num = [](double v) { return std::to_string(v); };
  if (!(max_join_angle_deg > 0 && max_join_angle_deg <= 90))
    return fail("max_join_angle_deg = " + num(max_join_angle_deg) + "; must be in (0, 90]");
  if (!(max_join_length >= 1))
    return fail("max_join_length = " + num(max_join_length) + "; must be >= 1");
  if (!(min_width_ratio >= 0 && min_width_ratio <= 1))
    return fail("min_width_ratio = " + num(min_width_ratio) + "; must be in [0, 1]");
  if (!(max_colour_distance > 0))
    return fail("max_colour_distance = " + num(max_colour_distance) + "; must be > 0");
  if (!(min_inside_share >= 0 && min_inside_share <= 1))
    return fail("min_inside_share = " + num(min_inside_share) + "; must be in [0, 1]");
  if (!(tangent_arm >= 4 && tangent_arm <= 64))
    return fail("tangent_arm = " + num(tangent_arm) + "; must be in [4, 64]");
  if (!(max_extension >= 0))
    return fail("max_extension = " + num(max_extension) + "; must be >= 0");
  if (seam_radius < 0 || seam_radius > 8)
    return fail("seam_radius = " + std::to_string(seam_radius) + "; must be in [0, 8]");
  if (!(texture_threshold >= 0))
    return fail("texture_threshold = " + num(texture_threshold) + "; must be >= 0");
  std::string inner;
  if (!inpaint.is_valid(&inner)) return fail("inpaint: " + inner);
  return true;
}

namespace {

using detail::Mask;

// Mean |luma − its 3×3 median| over the known ink-free pixels of a 9×9
// window: 0 on flat cel regions and along straight borders between them,
// large on hatching, noise or painted texture.
cv::Mat texture_measure(const Image& crop, const Mask& hole, const Mask& ink) {
  const int w = crop.width(), h = crop.height();
  cv::Mat grey(h, w, CV_8U), med, resid(h, w, CV_32F), valid(h, w, CV_32F);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) grey.at<std::uint8_t>(y, x) = detail::luma(crop.at(x, y));
  cv::medianBlur(grey, med, 3);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const bool ok = !hole[i] && !ink[i];
      valid.at<float>(y, x) = ok ? 1.0f : 0.0f;
      resid.at<float>(y, x) = ok ? std::abs(static_cast<float>(grey.at<std::uint8_t>(y, x)) -
                                            med.at<std::uint8_t>(y, x))
                                 : 0.0f;
    }
  cv::boxFilter(resid, resid, CV_32F, {9, 9}, {-1, -1}, false);
  cv::boxFilter(valid, valid, CV_32F, {9, 9}, {-1, -1}, false);
  return resid / cv::max(valid, 1.0f);
}

// The exemplar pass on the hole pixels whose colour came from a textured
// place, guided by the flat fill.
InpaintResult add_texture(Image& crop, const Mask& hole, const Mask& ink,
                          const std::vector<int>& seed, const BackgroundOptions& o) {
  const int w = crop.width(), h = crop.height();
  const cv::Mat texture = texture_measure(crop, hole, ink);
  cv::Rect box;
  Mask textured(hole.size(), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const int s = seed[i];
      if (!hole[i] || s < 0 || texture.at<float>(s / w, s % w) <= o.texture_threshold) continue;
      textured[i] = 1;
      box = box.area() == 0 ? cv::Rect(x, y, 1, 1) : box | cv::Rect(x, y, 1, 1);
    }
  if (box.area() == 0) return {};
  const int pad = o.inpaint.patch_radius + o.inpaint.search_radius;
  box = cv::Rect(box.x - pad, box.y - pad, box.width + 2 * pad, box.height + 2 * pad) &
        cv::Rect(0, 0, w, h);
  Image sub(box.width, box.height);
  LabelMap fill(box.width, box.height), source(box.width, box.height);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const std::size_t i = static_cast<std::size_t>(y + box.y) * w + (x + box.x);
      sub.at(x, y) = crop.data()[i];
      fill.at(x, y) = textured[i];
      source.at(x, y) = hole[i] ? 0 : 1;
    }
  const Image guide = sub;
  const InpaintResult r = detail::run_exemplar(sub, fill, source, o.inpaint, &guide);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x)
      if (fill.at(x, y)) crop.at(x + box.x, y + box.y) = sub.at(x, y);
  return r;
}

}  // namespace

BackgroundResult fill_background(const Image& image, const LabelMap& hole,
                                 const BackgroundOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  detail::require_image_size("completion::fill_background", "hole mask is", hole, image);
  BackgroundResult result;
  result.image = image;
  const int w = image.width(), h = image.height();
  int x0 = w, y0 = h, x1 = -1, y1 = -1;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (hole.at(x, y) != 0)
        x0 = std::min(x0, x), y0 = std::min(y0, y), x1 = std::max(x1, x), y1 = std::max(y1, y);
  if (x1 < 0) return result;
  // Work on the hole's box plus what the tangents and seeds look at.
  const int pad = static_cast<int>(std::ceil(options.tangent_arm)) + 12;
  const cv::Rect box =
      cv::Rect(cv::Point(x0 - pad, y0 - pad), cv::Point(x1 + pad + 1, y1 + pad + 1)) &
      cv::Rect(0, 0, w, h);
  const int cw = box.width, ch = box.height;
  const std::size_t n = static_cast<std::size_t>(cw) * ch;
  Image crop(cw, ch);
  Mask in_hole(n, 0);
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x) {
      crop.at(x, y) = image.at(x + box.x, y + box.y);
      in_hole[static_cast<std::size_t>(y) * cw + x] = hole.at(x + box.x, y + box.y) != 0;
    }
  Mask ink = detail::ink_mask(crop, options.inpaint);
  for (std::size_t i = 0; i < n; ++i)
    if (in_hole[i]) ink[i] = 0;

  std::vector<detail::Stroke> strokes;
  std::vector<detail::LineEnd> ends;
  if (options.continue_lines || options.ink_seams)
    ends = detail::find_line_ends(crop, in_hole, ink, options);
  if (options.continue_lines) {
    result.line_ends = static_cast<int>(ends.size());
    strokes = detail::continue_lines(ends, in_hole, ink, cw, ch, options, &result.joined_lines,
                                     &result.extended_lines);
  }
  Mask barrier = detail::stroke_barrier(strokes, cw, ch);
  for (std::size_t i = 0; i < n; ++i) barrier[i] &= in_hole[i];
  std::vector<int> seed;
  const Image original = crop;
  const int edges = (box.x == 0 ? detail::kLeftEdge : 0) | (box.y == 0 ? detail::kTopEdge : 0) |
                    (box.x + cw == w ? detail::kRightEdge : 0) |
                    (box.y + ch == h ? detail::kBottomEdge : 0);
  result.unreached =
      detail::flat_fill(crop, in_hole, ink, barrier, options.seam_radius, &seed, edges);
  if (options.ink_seams) {
    // The seam line looks like the lines that enter the hole.
    Rgba colour{40, 30, 30, 255};
    double width = 2.0;
    if (!ends.empty()) {
      std::vector<const detail::LineEnd*> sorted;
      for (const detail::LineEnd& e : ends) sorted.push_back(&e);
      std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->width < b->width; });
      width = std::clamp(sorted[sorted.size() / 2]->width, 1.0, 4.0);
      std::sort(sorted.begin(), sorted.end(),
                [](auto* a, auto* b) { return detail::luma(a->colour) < detail::luma(b->colour); });
      colour = sorted[sorted.size() / 2]->colour;
    }
    result.seam_pixels = detail::ink_seams(crop, original, in_hole, ink, barrier, colour, width);
  }
  result.texture = add_texture(crop, in_hole, ink, seed, options);
  detail::draw_strokes(crop, in_hole, strokes);
  for (int y = 0; y < ch; ++y)
    for (int x = 0; x < cw; ++x)
      if (in_hole[static_cast<std::size_t>(y) * cw + x]) {
        result.image.at(x + box.x, y + box.y) = crop.at(x, y);
        ++result.filled;
      }
  result.filled -= result.unreached;
  return result;
}

namespace detail {
namespace {

// Pixels less opaque than this are the sheet (or its anti-aliased rim), not
// a dark colour of the drawing.
constexpr int kOpaque = 128;
// RGB distance from a hair region's mean colour of hair the segmentation left.
constexpr double kHairColour = 60.0;
// RGB distance from the skin's median within which a colour is skin (a
// shadow or a blush on it), never hair.
constexpr double kSkinColour = 48.0;
// RGB distance from the hair's outline colour of a dark pixel of that line.
constexpr double kLineColour = 24.0;
// How far (px, chessboard) from the grown hair a wedge of the outline's
// colour where a lock's point lies on the face may reach.
constexpr int kWedgeReach = 24;
// How far (px, chessboard) from the grown hair a lock's tip hanging off it
// off the head may reach (generated drawings' tips: up to ~45 px).
constexpr int kTipReach = 48;
// A dark piece of the hair's colour hanging off the hair beyond its outline
// band is a lock the strokes missed when it is at most this share of the
// labelled hair it touches.
constexpr double kMissedLock = 0.25;

// The colour of the head's outline: the median by luma of the ink just
// outside the hole along the head's rim, or of all the ink just outside the
// hole when none lies there (the face's outline, the clothes'). The ink
// round the whole hole mixes in what the hair's loose ends touch (the lock
// tips on generated drawings: taken with the hair, the median became an
// iris's green-grey).
Rgba head_line_colour(const Image& image, const LabelMap& regions, const cv::Mat& holes,
                      const cv::Mat& head, const Options& o) {
  cv::Mat around, rim;
  cv::dilate(holes, around, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(7, 7)));
  {
    cv::Mat inner, outer;
    const cv::Mat k = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(9, 9));
    cv::dilate(head, outer, k);
    cv::erode(head, inner, k);
    rim = outer & ~inner;
  }
  std::vector<Rgba> ink, on_rim, under_rim;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const Rgba& c = image.at(x, y);
      if (c.a < 240 || luma(c) >= o.background.inpaint.ink_luma) continue;
      const bool hidden = holes.at<std::uint8_t>(y, x) != 0;
      if (around.at<std::uint8_t>(y, x) && !hidden) ink.push_back(c);
      if (!rim.at<std::uint8_t>(y, x)) continue;
      if (!hidden)
        on_rim.push_back(c);
      else if (regions.at(x, y) == 0)
        under_rim.push_back(c);
    }
  // A few pixels are anti-aliased ends, not the line. Where the hair hides
  // the whole rim, its line was drawn there: the ink no region holds (not
  // the dark purple of the hair, which then outlined the head).
  constexpr std::size_t kMinRim = 20;
  if (on_rim.size() >= kMinRim)
    ink.swap(on_rim);
  else if (under_rim.size() >= kMinRim)
    ink.swap(under_rim);
  if (ink.empty()) return {40, 30, 30, 255};
  std::nth_element(ink.begin(), ink.begin() + ink.size() / 2, ink.end(),
                   [](const Rgba& a, const Rgba& b) { return luma(a) < luma(b); });
  return ink[ink.size() / 2];
}

// The colours the hair regions are painted in (their own pixels, not the
// outline pixels given to them): black on black hair, not the dark red of an
// iris that is as far from the hair's mean colour as the black of its tips.
CommonColours hair_colours(const Context& ctx) {
  constexpr double kTypicalShare = 0.005;
  CommonColours colours(kTypicalShare);
  const LabelMap& regions = *ctx.original;
  for (int y = 0; y < regions.height(); ++y)
    for (int x = 0; x < regions.width(); ++x)
      if (regions.at(x, y) != 0) colours.add(ctx.image->at(x, y));
  return colours;
}

// Small pieces of the drawing the hole encloses (a headband's fragments or
// a highlight the segmentation left between hair regions: on lucy, white
// specks floated on the bald head) lie on the hair and go with it. What is
// behind the hair always reaches out of it (the face to the neck, the
// paper to the image's edge), and the face's features are joined to it.
void take_islands(cv::Mat& holes) {
  // An island holds at most this share of the hole's pixels.
  constexpr double kIslandShare = 0.02;
  cv::Mat known = holes == 0, parts;
  const int n = cv::connectedComponents(known, parts, 8, CV_32S);
  std::vector<long> area(static_cast<std::size_t>(n), 0);
  std::vector<std::uint8_t> edge(static_cast<std::size_t>(n), 0);
  const int w = holes.cols, h = holes.rows;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto k = static_cast<std::size_t>(parts.at<int>(y, x));
      ++area[k];
      if (x == 0 || y == 0 || x == w - 1 || y == h - 1) edge[k] = 1;
    }
  const double limit = kIslandShare * cv::countNonZero(holes);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const auto k = static_cast<std::size_t>(parts.at<int>(y, x));
      if (k != 0 && !edge[k] && static_cast<double>(area[k]) <= limit)
        holes.at<std::uint8_t>(y, x) = 255;
    }
}

// The pixels on the head of the pieces (8-connected) of `dark` that hold a
// pixel not `own` (the hair's colour) more than `reach` px (chessboard) from
// `hair`.
cv::Mat face_lines(const cv::Mat& dark, const cv::Mat& own, const cv::Mat& hair,
                   const cv::Mat& head, int reach) {
  cv::Mat near, parts;
  cv::dilate(hair, near,
             cv::getStructuringElement(cv::MORPH_RECT, cv::Size(2 * reach + 1, 2 * reach + 1)));
  const int n = cv::connectedComponents(dark, parts, 8, CV_32S);
  std::vector<std::uint8_t> far(static_cast<std::size_t>(n), 0);
  for (int y = 0; y < dark.rows; ++y)
    for (int x = 0; x < dark.cols; ++x)
      if (dark.at<std::uint8_t>(y, x) && !near.at<std::uint8_t>(y, x) &&
          !own.at<std::uint8_t>(y, x))
        far[static_cast<std::size_t>(parts.at<int>(y, x))] = 1;
  cv::Mat lines(dark.size(), CV_8U, cv::Scalar(0));
  for (int y = 0; y < dark.rows; ++y)
    for (int x = 0; x < dark.cols; ++x)
      if (head.at<std::uint8_t>(y, x) && far[static_cast<std::size_t>(parts.at<int>(y, x))])
        lines.at<std::uint8_t>(y, x) = 255;
  return lines;
}

// Dark pixels hanging along the hair off the head (`head` may be empty):
// within the hair's outline band (`near`) but farther than kSpur px,
// through dark pixels, from any dark pixel beyond the band. A line of the
// drawing crosses the band to reach the hair; what runs along it is the
// hair's (a thin lock the segmentation missed, the converging outlines at
// a lock's tips) even when it touches such a line: whole pieces within the
// band go with the hair already, and these stayed (a red fleck on sylvie's
// shirt; dark dashes on wikipe-tan's collar stripes, beside which the paper
// reached in between her shirt and collar). With their anti-aliased rim
// (1 px, not dark).
cv::Mat hanging_spurs(const cv::Mat& dark, const cv::Mat& own, const cv::Mat& near,
                      const cv::Mat& head) {
  constexpr int kSpur = 10;
  const int w = dark.cols, h = dark.rows;
  cv::Mat dist(h, w, CV_32S, cv::Scalar(-1));
  // Distance 0: dark pixels beyond the band, or on the head; only those
  // next to a dark pixel in the band (not on the head) lead on.
  auto seed = [&](int x, int y) {
    return !near.at<std::uint8_t>(y, x) || (!head.empty() && head.at<std::uint8_t>(y, x));
  };
  std::vector<cv::Point> queue;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!dark.at<std::uint8_t>(y, x) || !seed(x, y)) continue;
      dist.at<int>(y, x) = 0;
      bool leads = false;
      for (int dy = -1; dy <= 1 && !leads; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < w && v < h && dark.at<std::uint8_t>(v, u) && !seed(u, v)) {
            leads = true;
            break;
          }
        }
      if (leads) queue.emplace_back(x, y);
    }
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const cv::Point p = queue[k];
    const int d = dist.at<int>(p);
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int x = p.x + dx, y = p.y + dy;
        if (x < 0 || y < 0 || x >= w || y >= h || !dark.at<std::uint8_t>(y, x) ||
            dist.at<int>(y, x) >= 0)
          continue;
        dist.at<int>(y, x) = d + 1;
        queue.emplace_back(x, y);
      }
  }
  // Pieces wholly within the band (never reached) are left to the rules
  // for whole pieces. Only lines of the hair's colour or of its outline's
  // (`own`) go, not thick dark areas nor lines of another colour (the navy
  // sailor collar lying along wikipe-tan's twin tails, 2-4 px wide between
  // its white stripes, lost strips of itself).
  cv::Mat spurs(h, w, CV_8U, cv::Scalar(0));
  bool any = false;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (dist.at<int>(y, x) > kSpur && own.at<std::uint8_t>(y, x))
        spurs.at<std::uint8_t>(y, x) = 255, any = true;
  if (!any) return spurs;
  // A piece whose feet (its pixels' neighbours at the limit) lie in two
  // places or more joins two lines beyond the band: a drawn shape's
  // outline running along the hair between them (wikipe-tan's collar along
  // her twin tail: trimmed, its end lost its join across the tail and the
  // shirt rose over the collar), not a line hanging off one.
  cv::Mat parts;
  const int n = cv::connectedComponents(spurs, parts, 8, CV_32S);
  cv::Mat feet(h, w, CV_32S, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int k = parts.at<int>(y, x);
      if (k == 0 || dist.at<int>(y, x) != kSpur + 1) continue;
      for (int dy = -1; dy <= 1; ++dy)
        for (int dx = -1; dx <= 1; ++dx) {
          const int u = x + dx, v = y + dy;
          if (u >= 0 && v >= 0 && u < w && v < h && dist.at<int>(v, u) == kSpur)
            feet.at<int>(v, u) = k;
        }
    }
  cv::Mat places;
  cv::connectedComponents(feet != 0, places, 8, CV_32S);
  std::vector<int> first(static_cast<std::size_t>(n), 0);
  std::vector<std::uint8_t> bridge(static_cast<std::size_t>(n), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      const int k = feet.at<int>(y, x), place = places.at<int>(y, x);
      if (k == 0) continue;
      auto& f = first[static_cast<std::size_t>(k)];
      if (f == 0)
        f = place;
      else if (f != place)
        bridge[static_cast<std::size_t>(k)] = 1;
    }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (bridge[static_cast<std::size_t>(parts.at<int>(y, x))]) spurs.at<std::uint8_t>(y, x) = 0;
  cv::Mat rim;
  cv::dilate(spurs, rim, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)));
  return spurs | (rim & ~dark & near);
}

// A lock's point lying over a thin face line of its own colour (lucy's
// black fringe points cross her brows, 1-2 px lines that run on into her
// glasses' frame and lashes): the own-coloured pixels joined to the point
// reach beyond the wedge reach through the line, so the wedge rule kept it
// whole. The point's thick part (a 3x3 opening: the lines are thinner) is
// measured alone. It goes when it touches the hair, lies wholly within
// `near` (the wedge reach), holds no thick feature, lies in dark `pieces`
// that are `mixed` (pieces of the hair's and outline's colours only are
// left to the rules for whole pieces), holds a pixel of the hair's colour
// (`fill`), is at least a third of the outline's colour (`line`: a point is
// drawn by its two converging outlines; on lucy 44 % of her largest point,
// the rest black fill), has at least kMinPoint pixels (a 3x3 block), and
// points away from the hair: no wider on average than kPointWidth px over
// its reach (lucy's points: 3.2-6.9). A lash or a brow of the hair's colour
// under the bangs runs along them: far wider than that over its few pixels
// of reach (lucy's lashes: ~40 px long, 4 px thick, within ~10 px of the
// hair).
cv::Mat points_over_lines(const cv::Mat& own, const cv::Mat& hair, const cv::Mat& near,
                          const cv::Mat& features, const cv::Mat& pieces,
                          const std::vector<std::uint8_t>& mixed, const cv::Mat& fill_coloured,
                          const cv::Mat& line) {
  constexpr double kPointWidth = 8.0;
  constexpr int kMinPoint = 9;
  // Touching: within this many px of the hair (lucy's largest point's thick
  // part starts 2.9 px from it; its root is thinner than the opening).
  constexpr float kTouch = 3.0f;
  cv::Mat thick, parts;
  cv::morphologyEx(own, thick, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)));
  cv::Mat points(own.size(), CV_8U, cv::Scalar(0));
  const int n = cv::connectedComponents(thick, parts, 8, CV_32S);
  if (n <= 1) return points;
  // Distance to the hair, only over the thick pixels' box, widened so
  // that hair beyond its edge is seen (the reach wanted is within `near`).
  constexpr int kMargin = 32;
  const cv::Rect inner = cv::boundingRect(thick);
  const cv::Rect box(inner.x - kMargin, inner.y - kMargin, inner.width + 2 * kMargin,
                     inner.height + 2 * kMargin);
  const cv::Rect seen = box & cv::Rect(0, 0, own.cols, own.rows);
  cv::Mat reach;
  cv::distanceTransform(hair(seen) == 0, reach, cv::DIST_L2, cv::DIST_MASK_PRECISE);
  const auto m = static_cast<std::size_t>(n);
  std::vector<std::uint8_t> ok(m, 1), fill(m, 0);
  std::vector<int> size(m, 0), lined(m, 0);
  std::vector<float> nearest(m, 1e9f), farthest(m, 0.f);
  for (int y = inner.y; y < inner.y + inner.height; ++y)
    for (int x = inner.x; x < inner.x + inner.width; ++x) {
      const auto k = static_cast<std::size_t>(parts.at<int>(y, x));
      if (k == 0) continue;
      ++size[k];
      lined[k] += line.at<std::uint8_t>(y, x) != 0;
      if (!near.at<std::uint8_t>(y, x) || features.at<std::uint8_t>(y, x) ||
          !mixed[static_cast<std::size_t>(pieces.at<int>(y, x))])
        ok[k] = 0;
      fill[k] |= fill_coloured.at<std::uint8_t>(y, x) != 0;
      const float d = reach.at<float>(y - seen.y, x - seen.x);
      nearest[k] = std::min(nearest[k], d);
      farthest[k] = std::max(farthest[k], d);
    }
  std::vector<std::uint8_t> goes(m, 0);
  for (std::size_t k = 1; k < m; ++k)
    goes[k] = ok[k] && fill[k] && 3 * lined[k] >= size[k] && size[k] >= kMinPoint &&
              nearest[k] <= kTouch && size[k] <= kPointWidth * farthest[k];
  for (int y = inner.y; y < inner.y + inner.height; ++y)
    for (int x = inner.x; x < inner.x + inner.width; ++x)
      if (goes[static_cast<std::size_t>(parts.at<int>(y, x))]) points.at<std::uint8_t>(y, x) = 255;
  return points;
}

// Skin seen in thin slivers between the bangs' locks, darker than the
// head's skin: the locks' cast shadow (lucy: 3-5 px wide, 20 px tall, pink
// against the filled forehead's light skin, which the head's fill takes from
// the face's median). Known pixels on the head, not dark, that a
// kSliver-wide disc does not fit into and lie beside the hole, within
// kShadeColour of the skin's median colour and darker than it: they go with
// the hair, and the head's fill gives them the skin of the rest of the
// forehead (at rest the strand beside them carries them, carry_rims). Lines
// stay (dark), and so do the eyes' whites (lighter) and irises (another
// colour). kShadeColour is wide enough for the rim between a black lock and
// the skin (lucy's sliver kept a pink-grey line at 80).
cv::Mat shaded_slivers(const Image& image, const cv::Mat& holes, const cv::Mat& dark,
                       const Head& head) {
  constexpr int kSliver = 7;
  constexpr double kShadeColour = 120.0;
  constexpr int kShade = 8;  // luma below the skin's
  cv::Mat slivers(holes.size(), CV_8U, cv::Scalar(0));
  // Only over the head's box (with room for the structuring elements).
  const cv::Rect inner = cv::boundingRect(head.mask);
  const cv::Rect box = cv::Rect(inner.x - kSliver, inner.y - kSliver, inner.width + 2 * kSliver,
                                inner.height + 2 * kSliver) &
                       cv::Rect(0, 0, holes.cols, holes.rows);
  if (box.empty()) return slivers;
  cv::Mat known = (head.mask(box) != 0) & (holes(box) == 0) & (dark(box) == 0), wide, beside;
  cv::morphologyEx(known, wide, cv::MORPH_OPEN,
                   cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(kSliver, kSliver)));
  cv::dilate(holes(box), beside, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(7, 7)));
  cv::Mat thin = known & ~wide & beside;
  const int skin_luma = luma(head.colour);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      if (!thin.at<std::uint8_t>(y, x)) continue;
      const Rgba& c = image.at(box.x + x, box.y + y);
      if (c.a >= kOpaque && colour_distance(c, head.colour) <= kShadeColour &&
          luma(c) < skin_luma - kShade)
        slivers.at<std::uint8_t>(box.y + y, box.x + x) = 255;
    }
  return slivers;
}

}  // namespace

BackgroundHole background_hole(const Context& ctx, const Face& face) {
  const Options& o = *ctx.options;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  // Hair plus a 2-pixel margin: the anti-aliased rim of the outline is not
  // dark enough to be assigned to a region but is still hair.
  cv::Mat hair = view(ctx.labels) != 0;
  cv::Mat dark(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      dark.at<std::uint8_t>(y, x) =
          image.at(x, y).a >= kOpaque && luma(image.at(x, y)) < o.dark_luma ? 255 : 0;
  // The face's eyes and brows are no hair even where they are thick and
  // touch the bangs: inside the head nothing is taken for hair but regions.
  Head head = find_head(ctx, face, o.background.inpaint);
  // The outlines of shapes lying on the hair (a clip over a twin tail, a
  // shirt over the back hair) are theirs, not the hair's, though the outline
  // assignment gave them to it: left out of the hair and of its growth.
  const cv::Mat front =
      front_outlines(image, *ctx.original, ctx.labels, dark, head.mask, face.mask);
  hair &= ~front;
  // Hair the segmentation left along the hair's edge (dark locks, the
  // shaded rim of black hair) goes with it: dark areas of a hair region's
  // colour, at least 5 px thick, that touch the hair. Lines are thinner and
  // stay (the face's, glasses); so do dark clothes of another colour (a
  // sailor collar and its tie under light blue twin tails).
  // Inside the head the colour must also be one the hair is painted in:
  // an iris or a blush as dark as the hair is no hair.
  cv::Mat hair_coloured(h, w, CV_8U, cv::Scalar(0)), band;
  const CommonColours painted = hair_colours(ctx);
  {
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!dark.at<std::uint8_t>(y, x)) continue;
        const Rgba& c = image.at(x, y);
        const Eigen::Vector3d v(c.r, c.g, c.b);
        bool near_mean = false;
        for (const auto& [id, info] : ctx.regions)
          if ((v - info.colour).norm() <= kHairColour) {
            near_mean = true;
            break;
          }
        if (near_mean &&
            (head.mask.empty() || !head.mask.at<std::uint8_t>(y, x) || painted.common(c)))
          hair_coloured.at<std::uint8_t>(y, x) = 255;
      }
    cv::Mat thick, grown, parts;
    cv::morphologyEx(hair_coloured, thick, cv::MORPH_OPEN,
                     cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
    // The band along the strands goes, and beyond it only a lock small
    // beside the hair it hangs from (below): what the hole takes no region
    // holds is carried by the strand reached first (carry_rims), so it
    // moves with it. A dark body of the hair's colour as large as the hair
    // (dark clothes, a black disk beside one labelled pixel) stays drawn in
    // the background; carried by one strand it would move with the hair.
    const int band_reach = o.outline_reach;
    cv::dilate(hair, band,
               cv::getStructuringElement(cv::MORPH_ELLIPSE,
                                         cv::Size(2 * band_reach + 1, 2 * band_reach + 1)));
    cv::dilate(hair, grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
    const int n = cv::connectedComponents(thick | grown, parts, 8, CV_32S);
    std::vector<long> labelled(static_cast<std::size_t>(n), 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (hair.at<std::uint8_t>(y, x)) ++labelled[static_cast<std::size_t>(parts.at<int>(y, x))];
    // Beyond the band, off the head: a lock the strokes missed hanging off
    // the hair (lucy's black points at her shoulders, 30-40 px long). A
    // piece of it that touches the hair goes when it is small beside the
    // labelled hair it hangs from; dark clothes of the hair's colour are not.
    cv::Mat off(h, w, CV_8U, cv::Scalar(0)), lock_parts;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        off.at<std::uint8_t>(y, x) =
            thick.at<std::uint8_t>(y, x) && !band.at<std::uint8_t>(y, x) &&
                    (head.mask.empty() || !head.mask.at<std::uint8_t>(y, x))
                ? 255
                : 0;
    const int locks = cv::connectedComponents(off, lock_parts, 8, CV_32S);
    std::vector<long> lock_area(static_cast<std::size_t>(locks), 0);
    std::vector<int> lock_of(static_cast<std::size_t>(locks), 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const auto k = static_cast<std::size_t>(lock_parts.at<int>(y, x));
        if (k == 0) continue;
        ++lock_area[k];
        const int p = parts.at<int>(y, x);
        if (labelled[static_cast<std::size_t>(p)] > 0) lock_of[k] = p;
      }
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const auto k = static_cast<std::size_t>(parts.at<int>(y, x));
        if (!thick.at<std::uint8_t>(y, x) || labelled[k] == 0) continue;
        bool goes = band.at<std::uint8_t>(y, x) != 0;
        if (!goes) {
          const auto l = static_cast<std::size_t>(lock_parts.at<int>(y, x));
          goes = l != 0 && lock_of[l] > 0 &&
                 static_cast<double>(lock_area[l]) <=
                     kMissedLock * labelled[static_cast<std::size_t>(lock_of[l])];
        }
        if (goes) hair.at<std::uint8_t>(y, x) = 255;
      }
  }
  // On the head the bangs' points are drawn lighter than the regions the
  // segmentation gave them (a highlight, the anti-aliased taper): they are
  // no dark outline, and left in the background they were orange and pink
  // flecks on sylvie's brows. Hair grows there through pixels of a colour
  // the hair is painted in that is no skin colour, within the outline's
  // reach.
  cv::Mat tips = hair.clone();
  if (!head.mask.empty()) {
    cv::Mat light(h, w, CV_8U, cv::Scalar(0)), grown;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const Rgba& c = image.at(x, y);
        if (head.mask.at<std::uint8_t>(y, x) && !dark.at<std::uint8_t>(y, x) && c.a >= kOpaque &&
            colour_distance(c, head.colour) > kSkinColour && painted.common(c))
          light.at<std::uint8_t>(y, x) = 255;
      }
    light |= hair;
    for (int k = 0; k < o.outline_reach; ++k) {
      cv::dilate(tips, grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)));
      tips = grown & light;
    }
  }
  // The colour of the hair's drawn outline: the median by luma of the dark
  // pixels the outline assignment gave the regions. Where a strand's point
  // lies on the face its two outlines converge into a thick wedge of that
  // colour beyond the labelled pixels (generated seed 50: black wedges
  // along a diagonal lock stayed on the face as if they were eyes).
  cv::Mat outline_coloured(h, w, CV_8U, cv::Scalar(0));
  // The same off the head too: what may hang along the hair (spurs below).
  cv::Mat line_coloured(h, w, CV_8U, cv::Scalar(0));
  {
    std::vector<Rgba> assigned;
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (dark.at<std::uint8_t>(y, x) && ctx.labels.at(x, y) != 0 && ctx.original->at(x, y) == 0)
          assigned.push_back(image.at(x, y));
    if (!assigned.empty()) {
      std::nth_element(assigned.begin(), assigned.begin() + assigned.size() / 2, assigned.end(),
                       [](const Rgba& a, const Rgba& b) { return luma(a) < luma(b); });
      const Rgba line = assigned[assigned.size() / 2];
      for (int y = 0; y < h; ++y)
        for (int x = 0; x < w; ++x)
          if (dark.at<std::uint8_t>(y, x) && colour_distance(image.at(x, y), line) <= kLineColour)
            line_coloured.at<std::uint8_t>(y, x) = 255;
    }
    if (!head.mask.empty()) outline_coloured = line_coloured.clone();
  }
  // The face's thick dark features that the hair's outline pixels took
  // where the bangs touch them (an eye's upper lash line: thick, dark, not
  // of the hair's colour) stay: the hair's outline is thinner.
  cv::Mat features;
  if (!head.mask.empty()) {
    cv::Mat candidate(h, w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        candidate.at<std::uint8_t>(y, x) =
            dark.at<std::uint8_t>(y, x) && !hair_coloured.at<std::uint8_t>(y, x) &&
                    !outline_coloured.at<std::uint8_t>(y, x) && head.mask.at<std::uint8_t>(y, x) &&
                    ctx.original->at(x, y) == 0
                ? 255
                : 0;
    cv::morphologyEx(candidate, features, cv::MORPH_OPEN,
                     cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
    // Where strand tips lying on the face converge, their outlines make
    // small thick wedges: a feature is larger than that.
    constexpr int kMinFeature = 50;
    cv::Mat parts, stats, centroids;
    const int n = cv::connectedComponentsWithStats(features, parts, stats, centroids, 8, CV_32S);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int k = parts.at<int>(y, x);
        if (k > 0 && k < n && stats.at<int>(k, cv::CC_STAT_AREA) < kMinFeature)
          features.at<std::uint8_t>(y, x) = 0;
      }
  }
  // The hair's drawn outline goes with the hair: the dark pixels reached
  // from it through dark pixels within a line's width (wider where outlines
  // converge at tips, and the hair's own dark strokes along its edge).
  const cv::Mat step = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
  cv::Mat outline = hair.clone();
  // Inside the head the face's own lines (lashes, brows, an iris darker
  // than dark_luma) touch the bangs: there it grows only through pixels of
  // the hair's colour (the bangs' tips and outline, not a blue eye).
  cv::Mat reachable = dark | hair;
  // Nor does it eat into a thick dark area beyond the strands' band (dark
  // clothes beside the hair, a black disk): no strand's texture covers that
  // at rest, so what the growth took there vanished from the model. The
  // outline is thinner than the opening.
  {
    cv::Mat thick_dark;
    cv::morphologyEx(dark & ~hair, thick_dark, cv::MORPH_OPEN,
                     cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(5, 5)));
    reachable &= ~(thick_dark & ~band);
  }
  if (!head.mask.empty()) {
    reachable &= (head.mask == 0) | hair | hair_coloured;
    // Lashes and a glasses' frame as dark as the hair run along the bangs'
    // edge, within the growth's reach, but they are joined to the rest of
    // the eye, whose iris, of another colour, lies farther; a lock's point
    // of the hair's colour may reach farther, but in the hair's colour. On
    // the head the growth does not enter dark pieces holding a pixel of
    // another colour beyond its reach (sylvie's upper lashes and with them
    // her irises' tops, lucy's lash and glasses' frame went with the bangs).
    reachable &= ~face_lines(dark & ~hair, hair_coloured, hair, head.mask, 2 * o.outline_reach);
  }
  reachable &= ~front;
  for (int k = 0; k < 2 * o.outline_reach; ++k) {
    cv::Mat grown;
    cv::dilate(outline, grown, step);
    outline = grown & reachable;
  }
  // ... with its anti-aliased rim, too light to be dark.
  cv::dilate(outline, outline, step);
  cv::Mat near;
  cv::dilate(hair, near, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(17, 17)));
  cv::dilate(hair, hair, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  hair |= outline;
  // The points go with the hair but do not lead the outline's growth on
  // (the growth from them ran into sylvie's iris).
  hair |= tips;
  // On the face, a lock's point beyond the outline growth (the growth there
  // follows the hair's colour only) is measured from the grown hair.
  cv::Mat near_grown;
  if (!head.mask.empty())
    cv::dilate(hair, near_grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(17, 17)));
  // A wedge of the outline's colour reaches farther from the labelled
  // pixels than a lock's point of the hair's colour.
  cv::Mat near_wedge, near_tip;
  if (!head.mask.empty())
    cv::dilate(hair, near_wedge,
               cv::getStructuringElement(cv::MORPH_RECT,
                                         cv::Size(2 * kWedgeReach + 1, 2 * kWedgeReach + 1)));
  // Where outlines converge (sharp tips) the drawn line is wider than the
  // outline reach: dark specks close to the hair are hair too. Dark pieces
  // reaching farther are other things' lines (a hair clip's, the face's) and
  // stay, so that their colours stay closed off from the hole. On the face,
  // a piece holding a thick feature stays however near (an eye under the
  // bangs, its lashes with it); thin pieces of another colour near the hair
  // are its outlines converging at a tip and go.
  dark &= ~hair;
  cv::Mat pieces;
  const int count = cv::connectedComponents(dark, pieces, 8, CV_32S);
  std::vector<std::uint8_t> beyond(static_cast<std::size_t>(count), 0);
  // A wedge is all of the outline's or the hair's colour: one holding an
  // eye's pixel is the eye's lash line.
  std::vector<std::uint8_t> mixed(static_cast<std::size_t>(count), 0);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (dark.at<std::uint8_t>(y, x) && !outline_coloured.at<std::uint8_t>(y, x) &&
          !hair_coloured.at<std::uint8_t>(y, x))
        mixed[static_cast<std::size_t>(pieces.at<int>(y, x))] = 1;
  // A lock's tip off the head, beyond the outline's growth: where a strand
  // ends in a point its two outlines converge into a dark wedge that the
  // segmentation leaves unlabelled, 10-20 px long (black ticks under the
  // hair of generated drawings; on lucy the black point along her left
  // shoulder). A piece of the hair's or its outline's colour, off the
  // head, touching the hair in one place only (a line of the drawing
  // running on from the hair meets it at both ends or reaches farther),
  // reaches as far as a wedge on the face.
  std::vector<std::uint8_t> tip(static_cast<std::size_t>(count), 1);
  {
    cv::Mat touch, places;
    cv::dilate(hair, touch, step);
    touch &= dark;
    cv::connectedComponents(touch, places, 8, CV_32S);
    std::vector<int> place(static_cast<std::size_t>(count), 0), size(place), other(place);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (!dark.at<std::uint8_t>(y, x)) continue;
        const auto k = static_cast<std::size_t>(pieces.at<int>(y, x));
        // Nor does a tip run off the drawing (a line reaching its edge runs on).
        if ((!head.mask.empty() && head.mask.at<std::uint8_t>(y, x)) || x == 0 || y == 0 ||
            x == w - 1 || y == h - 1)
          tip[k] = 0;
        ++size[k];
        other[k] += !(line_coloured.at<std::uint8_t>(y, x) || hair_coloured.at<std::uint8_t>(y, x));
        const int at = places.at<int>(y, x);
        if (at == 0) continue;
        if (place[k] == 0)
          place[k] = at;
        else if (place[k] != at)
          tip[k] = 0;
      }
    // Its dark anti-aliased rim over a light colour is of neither colour.
    constexpr double kRimShare = 0.25;
    for (std::size_t k = 0; k < tip.size(); ++k)
      tip[k] &= place[k] != 0 && other[k] <= kRimShare * size[k];
    // A tip hangs alone; a screentone's dots, touching each other in twos
    // and threes beside the hair, have others like them round them (a
    // generated screentone body lost its dots along the hair). At most this
    // many other dark pieces within kAlone px of its box.
    constexpr int kAlone = 6, kMaxOthers = 2;
    std::vector<cv::Rect> box(tip.size());
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const auto k = static_cast<std::size_t>(pieces.at<int>(y, x));
        if (k != 0 && tip[k]) box[k] |= cv::Rect(x, y, 1, 1);
      }
    std::vector<int> seen;
    for (std::size_t k = 1; k < tip.size(); ++k) {
      if (!tip[k]) continue;
      const cv::Rect r = cv::Rect(box[k].x - kAlone, box[k].y - kAlone, box[k].width + 2 * kAlone,
                                  box[k].height + 2 * kAlone) &
                         cv::Rect(0, 0, w, h);
      seen.clear();
      for (int y = r.y; y < r.y + r.height; ++y)
        for (int x = r.x; x < r.x + r.width; ++x) {
          const int l = pieces.at<int>(y, x);
          if (l != 0 && static_cast<std::size_t>(l) != k &&
              std::find(seen.begin(), seen.end(), l) == seen.end())
            seen.push_back(l);
        }
      if (static_cast<int>(seen.size()) > kMaxOthers) tip[k] = 0;
    }
    // Only when a tip is found (a chessboard distance transform instead
    // cost 35 M instructions more on a 1024² drawing).
    if (std::find(tip.begin() + 1, tip.end(), 1) != tip.end())
      cv::dilate(hair, near_tip,
                 cv::getStructuringElement(cv::MORPH_RECT,
                                           cv::Size(2 * kTipReach + 1, 2 * kTipReach + 1)));
  }
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if (dark.at<std::uint8_t>(y, x)) {
        const bool on_head = !head.mask.empty() && head.mask.at<std::uint8_t>(y, x);
        const bool own = hair_coloured.at<std::uint8_t>(y, x);
        const bool thick_feature = on_head && features.at<std::uint8_t>(y, x);
        const bool wedge = on_head && outline_coloured.at<std::uint8_t>(y, x) &&
                           !mixed[static_cast<std::size_t>(pieces.at<int>(y, x))];
        const cv::Mat& reach = tip[static_cast<std::size_t>(pieces.at<int>(y, x))] ? near_tip
                               : wedge                                             ? near_wedge
                               : on_head && own                                    ? near_grown
                                                                                   : near;
        if (thick_feature || !reach.at<std::uint8_t>(y, x))
          beyond[static_cast<std::size_t>(pieces.at<int>(y, x))] = 1;
      }
  // A lock's point lying on the face beside an eye: its wedge touches the
  // iris, so the dark piece holds a pixel of another colour and stayed whole
  // (generated seed 50's third wedge, left of its left eye). The wedge
  // itself — the piece's pixels of the outline's or the hair's colour,
  // joined through such pixels, all within the wedge reach, no thick
  // feature — goes; the iris stays with the rest of the piece. A wedge has
  // at least kMinWedge pixels: smaller bits are blends along a face line
  // drawn in the outline's colour (sylvie's chin), not a point's two
  // converging lines.
  constexpr int kMinWedge = 20;
  cv::Mat wedge_parts, points;
  std::vector<std::uint8_t> wedge_goes;
  if (!head.mask.empty()) {
    const cv::Mat own_colour = dark & (outline_coloured | hair_coloured) & (head.mask != 0);
    const int parts = cv::connectedComponents(own_colour, wedge_parts, 8, CV_32S);
    wedge_goes.assign(static_cast<std::size_t>(parts), 1);
    wedge_goes[0] = 0;
    std::vector<std::uint8_t> fill(static_cast<std::size_t>(parts), 0);
    std::vector<int> size(static_cast<std::size_t>(parts), 0), line(size);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const int k = wedge_parts.at<int>(y, x);
        if (k == 0) continue;
        ++size[static_cast<std::size_t>(k)];
        line[static_cast<std::size_t>(k)] += outline_coloured.at<std::uint8_t>(y, x) != 0;
        if (hair_coloured.at<std::uint8_t>(y, x)) fill[static_cast<std::size_t>(k)] = 1;
        if (!mixed[static_cast<std::size_t>(pieces.at<int>(y, x))] ||
            !near_wedge.at<std::uint8_t>(y, x) || features.at<std::uint8_t>(y, x))
          wedge_goes[static_cast<std::size_t>(k)] = 0;
      }
    // Between a point's converging outlines lies the lock's own fill: a
    // piece of the outline's colour with none of it is a face line of that
    // colour (wikipe-tan's black upper lashes under her bangs), not a wedge.
    // And a wedge is mostly the outline's colour: a dark body mostly of the
    // hair's (sylvie's hair beside her chin) keeps the old rules.
    for (std::size_t k = 0; k < fill.size(); ++k)
      wedge_goes[k] &= fill[k] && 2 * line[k] >= size[k] && size[k] >= kMinWedge;
    points = points_over_lines(own_colour, hair, near_wedge, features, pieces, mixed, hair_coloured,
                               outline_coloured);
  }
  const cv::Mat spurs = hanging_spurs(dark, line_coloured | hair_coloured, near, head.mask);
  cv::Mat holes(h, w, CV_8U, cv::Scalar(0));
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      holes.at<std::uint8_t>(y, x) =
          hair.at<std::uint8_t>(y, x) ||
          (dark.at<std::uint8_t>(y, x) &&
           (!beyond[static_cast<std::size_t>(pieces.at<int>(y, x))] ||
            (!wedge_parts.empty() &&
             wedge_goes[static_cast<std::size_t>(wedge_parts.at<int>(y, x))])));
  {
    // A tip goes with its anti-aliased rim (1 px, not dark).
    cv::Mat gone(h, w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        const auto k = static_cast<std::size_t>(pieces.at<int>(y, x));
        if (dark.at<std::uint8_t>(y, x) && tip[k] && !beyond[k]) gone.at<std::uint8_t>(y, x) = 255;
      }
    cv::dilate(gone, gone, step);
    holes |= gone;
  }
  if (!wedge_parts.empty()) {
    // ... with its rim two pixels wide: its anti-aliased blends with the
    // skin, some dark but of neither colour (grey ticks of it stayed on the
    // face). A thick feature (the iris) keeps its pixels.
    cv::Mat gone(h, w, CV_8U, cv::Scalar(0));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (wedge_goes[static_cast<std::size_t>(wedge_parts.at<int>(y, x))] ||
            points.at<std::uint8_t>(y, x))
          gone.at<std::uint8_t>(y, x) = 255;
    cv::dilate(gone, gone, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
    holes |= gone & ~features;
  }
  if (!features.empty()) holes &= ~features;
  if (!head.mask.empty()) {
    const cv::Mat slivers = shaded_slivers(image, holes, dark, head);
    holes |= slivers;
    // Nor are they the skin the head's fill copies (each copied itself).
    if (!head.skin.empty()) head.skin.setTo(0, slivers);
  }
  take_islands(holes);
  // After the islands: a spur gone leaves what it bordered known (a collar's
  // stripes along wikipe-tan's twin tail were enclosed by the hole and went).
  holes |= spurs;
  holes &= ~front;
  return {std::move(holes), head};
}

Image fill_background(const Context& ctx, const BackgroundHole& taken, InpaintResult* inpainted) {
  const Options& o = *ctx.options;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  const Head& head = taken.head;
  cv::Mat holes = taken.holes.clone();
  // The head: under the hair it is skin, filled from the face first; the
  // rest of the hole is filled around it, the head's outline drawn where it
  // meets the rest, so that no other colour runs into the head and the skin
  // does not run out of it.
  Image work = image;
  InpaintResult skin;
  if (!head.mask.empty()) {
    skin = fill_head(work, holes, head, o.background.inpaint, o.background.texture_threshold);
    cv::Mat rest = holes & (head.mask == 0);
    cv::Mat rim;
    cv::dilate(head.mask, rim, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
    rim &= rest;
    const Rgba line = head_line_colour(image, *ctx.original, holes, head.mask, o);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        if (rim.at<std::uint8_t>(y, x)) work.at(x, y) = line;
    holes = rest & ~rim;
  }
  LabelMap hole(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) hole.at(x, y) = holes.at<std::uint8_t>(y, x) != 0;
  BackgroundResult r = completion::fill_background(work, hole, o.background);
  inpainted->filled = r.filled + skin.filled;
  inpainted->patches = r.texture.patches + skin.patches;
  inpainted->unfilled = r.unreached + skin.unfilled;
  return std::move(r.image);
}

}  // namespace detail
}  // namespace hair25d::completion
