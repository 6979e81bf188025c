// What the background takes for hair (paper §5.4, `background_hole`): the
// regions, their drawn outline and rim, what the segmentation left along
// them, and what the hair encloses; and the head behind it. Each stage below
// adds to or reads the shared rasters in turn; the rules of single kinds of
// dark pieces are in hole_rules.cpp.
#include <algorithm>
#include <opencv2/imgproc.hpp>
#include <vector>

#include "front_outlines.h"
#include "head_fill.h"
#include "hole_rules.h"
#include "raster.h"
#include "strand_assembly.h"

namespace hair25d::completion::detail {
namespace {

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

// The rasters the stages share: CV_8U, the drawing's size, 255 where set.
struct Rasters {
  cv::Mat dark;           // opaque pixels darker than Options::dark_luma
  cv::Mat hair;           // what goes with the hair so far
  cv::Mat hair_coloured;  // dark pixels of a hair region's colour
  cv::Mat band;           // the strands' outline band
  cv::Mat line_coloured;  // dark pixels of the hair's outline colour
  // The same on a drawing with a head, else all 0.
  cv::Mat outline_coloured;
  cv::Mat features;  // the face's thick dark features (empty without a head)
};

// Hair the segmentation left along the hair's edge (dark locks, the
// shaded rim of black hair) goes with it: dark areas of a hair region's
// colour, at least 5 px thick, that touch the hair. Lines are thinner and
// stay (the face's, glasses); so do dark clothes of another colour (a
// sailor collar and its tie under light blue twin tails).
// Inside the head the colour must also be one the hair is painted in:
// an iris or a blush as dark as the hair is no hair.
void take_dark_hair(const Context& ctx, const Head& head, const CommonColours& painted,
                    Rasters& r) {
  const Options& o = *ctx.options;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  const cv::Mat& dark = r.dark;
  cv::Mat& hair = r.hair;
  cv::Mat& hair_coloured = r.hair_coloured;
  cv::Mat& band = r.band;
  hair_coloured = cv::Mat(h, w, CV_8U, cv::Scalar(0));
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
      off.at<std::uint8_t>(y, x) = thick.at<std::uint8_t>(y, x) && !band.at<std::uint8_t>(y, x) &&
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
cv::Mat light_tips(const Image& image, const Head& head, const CommonColours& painted, int reach,
                   const Rasters& r) {
  const int w = image.width(), h = image.height();
  const cv::Mat& dark = r.dark;
  const cv::Mat& hair = r.hair;
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
    for (int k = 0; k < reach; ++k) {
      cv::dilate(tips, grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3)));
      tips = grown & light;
    }
  }
  return tips;
}

// The colour of the hair's drawn outline: the median by luma of the dark
// pixels the outline assignment gave the regions. Where a strand's point
// lies on the face its two outlines converge into a thick wedge of that
// colour beyond the labelled pixels (generated seed 50: black wedges
// along a diagonal lock stayed on the face as if they were eyes).
// The same off the head too: what may hang along the hair (spurs below).
void outline_colours(const Context& ctx, const Head& head, Rasters& r) {
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  const cv::Mat& dark = r.dark;
  r.outline_coloured = cv::Mat(h, w, CV_8U, cv::Scalar(0));
  r.line_coloured = cv::Mat(h, w, CV_8U, cv::Scalar(0));
  cv::Mat& line_coloured = r.line_coloured;
  cv::Mat& outline_coloured = r.outline_coloured;
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
void thick_features(const Context& ctx, const Head& head, Rasters& r) {
  if (head.mask.empty()) return;
  const int w = ctx.image->width(), h = ctx.image->height();
  const cv::Mat& dark = r.dark;
  const cv::Mat& hair_coloured = r.hair_coloured;
  const cv::Mat& outline_coloured = r.outline_coloured;
  cv::Mat& features = r.features;
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
cv::Mat grow_outline(const Head& head, const cv::Mat& front, int reach, const Rasters& r) {
  const cv::Mat& dark = r.dark;
  const cv::Mat& hair = r.hair;
  const cv::Mat& band = r.band;
  const cv::Mat& hair_coloured = r.hair_coloured;
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
    reachable &= ~face_lines(dark & ~hair, hair_coloured, hair, head.mask, 2 * reach);
  }
  reachable &= ~front;
  for (int k = 0; k < 2 * reach; ++k) {
    cv::Mat grown;
    cv::dilate(outline, grown, step);
    outline = grown & reachable;
  }
  // ... with its anti-aliased rim, too light to be dark.
  cv::dilate(outline, outline, step);
  return outline;
}

// How far from the hair a dark piece may reach and still go with it.
struct Reaches {
  cv::Mat near;        // 8 px round the labelled hair
  cv::Mat near_grown;  // 8 px round the grown hair (on the head)
  cv::Mat near_wedge;  // kWedgeReach px round it (on the head)
  cv::Mat near_tip;    // kTipReach px round it (when a lock's tip is found)
};

// The dark pieces (8-connected) beside the grown hair and what each is.
struct DarkPieces {
  cv::Mat pieces;                    // CV_32S labels, 0 where not dark
  std::vector<std::uint8_t> beyond;  // reaches beyond its reach: stays drawn
  std::vector<std::uint8_t> mixed;   // holds a pixel of neither hair colour
  std::vector<std::uint8_t> tip;     // a lock's tip off the head
};

// Where outlines converge (sharp tips) the drawn line is wider than the
// outline reach: dark specks close to the hair are hair too. Dark pieces
// reaching farther are other things' lines (a hair clip's, the face's) and
// stay, so that their colours stay closed off from the hole. On the face,
// a piece holding a thick feature stays however near (an eye under the
// bangs, its lashes with it); thin pieces of another colour near the hair
// are its outlines converging at a tip and go. `r.dark` holds no hair pixel.
DarkPieces dark_pieces(const Head& head, const Rasters& r, Reaches& nears) {
  const int w = r.dark.cols, h = r.dark.rows;
  const cv::Mat& dark = r.dark;
  const cv::Mat& hair = r.hair;
  const cv::Mat& hair_coloured = r.hair_coloured;
  const cv::Mat& line_coloured = r.line_coloured;
  const cv::Mat& outline_coloured = r.outline_coloured;
  const cv::Mat& features = r.features;
  const cv::Mat& near = nears.near;
  const cv::Mat& near_grown = nears.near_grown;
  const cv::Mat& near_wedge = nears.near_wedge;
  cv::Mat& near_tip = nears.near_tip;
  const cv::Mat step = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
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
      const cv::Rect around = cv::Rect(box[k].x - kAlone, box[k].y - kAlone,
                                       box[k].width + 2 * kAlone, box[k].height + 2 * kAlone) &
                              cv::Rect(0, 0, w, h);
      seen.clear();
      for (int y = around.y; y < around.y + around.height; ++y)
        for (int x = around.x; x < around.x + around.width; ++x) {
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
  return {std::move(pieces), std::move(beyond), std::move(mixed), std::move(tip)};
}

// Wedges of lock points on the face and points over face lines.
struct Wedges {
  cv::Mat parts;                   // CV_32S labels of the own-coloured dark pieces on the head
  std::vector<std::uint8_t> goes;  // per part: a wedge that goes with the hair
  cv::Mat points;                  // points_over_lines'
};

// A lock's point lying on the face beside an eye: its wedge touches the
// iris, so the dark piece holds a pixel of another colour and stayed whole
// (generated seed 50's third wedge, left of its left eye). The wedge
// itself — the piece's pixels of the outline's or the hair's colour,
// joined through such pixels, all within the wedge reach, no thick
// feature — goes; the iris stays with the rest of the piece. A wedge has
// at least kMinWedge pixels: smaller bits are blends along a face line
// drawn in the outline's colour (sylvie's chin), not a point's two
// converging lines.
Wedges lock_wedges(const Head& head, const Rasters& r, const DarkPieces& p,
                   const cv::Mat& near_wedge) {
  if (head.mask.empty()) return {};
  constexpr int kMinWedge = 20;
  Wedges out;
  const cv::Mat own_colour = r.dark & (r.outline_coloured | r.hair_coloured) & (head.mask != 0);
  const int parts = cv::connectedComponents(own_colour, out.parts, 8, CV_32S);
  out.goes.assign(static_cast<std::size_t>(parts), 1);
  out.goes[0] = 0;
  std::vector<std::uint8_t> fill(static_cast<std::size_t>(parts), 0);
  std::vector<int> size(static_cast<std::size_t>(parts), 0), line(size);
  for (int y = 0; y < r.dark.rows; ++y)
    for (int x = 0; x < r.dark.cols; ++x) {
      const auto k = static_cast<std::size_t>(out.parts.at<int>(y, x));
      if (k == 0) continue;
      ++size[k];
      line[k] += r.outline_coloured.at<std::uint8_t>(y, x) != 0;
      if (r.hair_coloured.at<std::uint8_t>(y, x)) fill[k] = 1;
      if (!p.mixed[static_cast<std::size_t>(p.pieces.at<int>(y, x))] ||
          !near_wedge.at<std::uint8_t>(y, x) || r.features.at<std::uint8_t>(y, x))
        out.goes[k] = 0;
    }
  // Between a point's converging outlines lies the lock's own fill: a
  // piece of the outline's colour with none of it is a face line of that
  // colour (wikipe-tan's black upper lashes under her bangs), not a wedge.
  // And a wedge is mostly the outline's colour: a dark body mostly of the
  // hair's (sylvie's hair beside her chin) keeps the old rules.
  for (std::size_t k = 0; k < fill.size(); ++k)
    out.goes[k] &= fill[k] && 2 * line[k] >= size[k] && size[k] >= kMinWedge;
  out.points = points_over_lines(own_colour, r.hair, near_wedge, r.features, p.pieces, p.mixed,
                                 r.hair_coloured, r.outline_coloured);
  return out;
}

}  // namespace

BackgroundHole background_hole(const Context& ctx, const Face& face) {
  const Options& o = *ctx.options;
  const Image& image = *ctx.image;
  const int w = image.width(), h = image.height();
  Rasters r;
  cv::Mat& dark = r.dark;
  cv::Mat& hair = r.hair;
  // Hair plus a 2-pixel margin: the anti-aliased rim of the outline is not
  // dark enough to be assigned to a region but is still hair.
  hair = view(ctx.labels) != 0;
  dark = cv::Mat(h, w, CV_8U, cv::Scalar(0));
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
  const CommonColours painted = hair_colours(ctx);
  take_dark_hair(ctx, head, painted, r);
  const cv::Mat tips = light_tips(image, head, painted, o.outline_reach, r);
  outline_colours(ctx, head, r);
  thick_features(ctx, head, r);
  const cv::Mat outline = grow_outline(head, front, o.outline_reach, r);
  Reaches nears;
  cv::Mat& near = nears.near;
  cv::Mat& near_grown = nears.near_grown;
  cv::Mat& near_wedge = nears.near_wedge;
  cv::dilate(hair, near, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(17, 17)));
  cv::dilate(hair, hair, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(5, 5)));
  hair |= outline;
  // The points go with the hair but do not lead the outline's growth on
  // (the growth from them ran into sylvie's iris).
  hair |= tips;
  // On the face, a lock's point beyond the outline growth (the growth there
  // follows the hair's colour only) is measured from the grown hair.
  if (!head.mask.empty())
    cv::dilate(hair, near_grown, cv::getStructuringElement(cv::MORPH_RECT, cv::Size(17, 17)));
  // A wedge of the outline's colour reaches farther from the labelled
  // pixels than a lock's point of the hair's colour.
  if (!head.mask.empty())
    cv::dilate(hair, near_wedge,
               cv::getStructuringElement(cv::MORPH_RECT,
                                         cv::Size(2 * kWedgeReach + 1, 2 * kWedgeReach + 1)));
  dark &= ~hair;
  const DarkPieces dark_parts = dark_pieces(head, r, nears);
  const Wedges wedges = lock_wedges(head, r, dark_parts, near_wedge);
  const cv::Mat& pieces = dark_parts.pieces;
  const std::vector<std::uint8_t>& beyond = dark_parts.beyond;
  const std::vector<std::uint8_t>& tip = dark_parts.tip;
  const cv::Mat& wedge_parts = wedges.parts;
  const std::vector<std::uint8_t>& wedge_goes = wedges.goes;
  const cv::Mat& points = wedges.points;
  const cv::Mat& features = r.features;
  const cv::Mat& line_coloured = r.line_coloured;
  const cv::Mat& hair_coloured = r.hair_coloured;
  const cv::Mat step = cv::getStructuringElement(cv::MORPH_RECT, cv::Size(3, 3));
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

}  // namespace hair25d::completion::detail
