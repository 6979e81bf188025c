// The rules of hole_rules.h: each reads the drawing the way one kind of
// drawing needed (the real drawings and generated seeds named below).
#include "hole_rules.h"

#include <algorithm>
#include <opencv2/imgproc.hpp>

#include "raster.h"

namespace hair25d::completion::detail {

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

}  // namespace hair25d::completion::detail
