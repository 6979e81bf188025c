// A drawn line seen in colour where its grey level equals the paint's
// (layering/src/colour_line.h, paper §4.1): a black outline between a purple
// strand and a darker purple one is a line, a tone step or a blend of the two
// paints is not, and the layering calls such a boundary occluding.
#include "colour_line.h"

#include <gtest/gtest.h>

#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"
#include "line_response.h"

namespace hair25d::layering {
namespace {

constexpr Rgba kPurple{60, 24, 95, 255};  // grey level 44
constexpr Rgba kDark{33, 13, 53, 255};    // grey level 23.5
constexpr Rgba kInk{23, 23, 23, 255};     // grey level 23: the dark paint's

// 61 × 43: region 1 (purple) left of x = 30, region 2 (dark purple) right of
// it; with `line`, pixels 29 and 30 are ink, else the paints meet (with
// `blend`, pixel 30 is half of each, as anti-aliasing or a JPEG's chroma
// makes a step).
struct TwoPaints {
  Image image{61, 43};
  LabelMap labels{61, 43};
  TwoPaints(bool line, bool blend) {
    for (int y = 0; y < 43; ++y)
      for (int x = 0; x < 61; ++x) {
        image.at(x, y) = x < 30 ? kPurple : kDark;
        labels.at(x, y) = x < 30 ? 1 : 2;
        if (line && (x == 29 || x == 30)) image.at(x, y) = kInk;
        if (!line && blend && x == 30)
          image.at(x, y) = Rgba{(60 + 33) / 2, (24 + 13) / 2, (95 + 53) / 2, 255};
      }
  }
  Polyline boundary() const {
    for (const Boundary& b : build_boundary_graph(labels).boundaries)
      if ((b.left == 1 && b.right == 2) || (b.left == 2 && b.right == 1)) return b.points;
    return {};
  }
  detail::BoundaryLine colour(int left, int right) const {
    return detail::colour_line(image, 2.0, boundary(), 3.0, labels, left, right);
  }
};

int left_of(const TwoPaints& d) {
  for (const Boundary& b : build_boundary_graph(d.labels).boundaries)
    if ((b.left == 1 && b.right == 2) || (b.left == 2 && b.right == 1)) return b.left;
  return 0;
}

// The grey levels see almost nothing of the ink (under 1 level); in colour
// it lies off the segment between the paints, at its distance to the dark
// paint, (10, −10, 30)/√3 ≈ 19.1. Returns the left region (0 if none).
int expect_ink_seen_in_colour_only(const TwoPaints& d, detail::BoundaryLine* out) {
  const int l = left_of(d);
  if (l == 0) return 0;
  const detail::LineResponse grey(d.image, 2.0, 0, 0, 61, 43);
  EXPECT_LT(grey.measure(d.boundary(), 3.0, d.labels, l, 3 - l).contrast, 1.0);
  const detail::BoundaryLine c = d.colour(l, 3 - l);
  EXPECT_NEAR(c.contrast, std::sqrt(1100.0 / 3.0), 0.5);
  EXPECT_NEAR(c.contrast_low, c.contrast, 0.5);
  *out = c;
  return l;
}

TEST(ColourLine, InkOnPaintAsDarkAsItIsALine) {
  const TwoPaints d(true, false);
  // Grey: 44 − 23 on one side, 0.5 on the other.
  detail::BoundaryLine c;
  const int l = expect_ink_seen_in_colour_only(d, &c);
  ASSERT_NE(l, 0);
  EXPECT_EQ(c.colour_difference, 0.0);
  // Walked the other way (sides exchanged): the same.
  const Polyline forth = d.boundary();
  const Polyline back(forth.rbegin(), forth.rend());
  EXPECT_NEAR(detail::colour_line(d.image, 2.0, back, 3.0, d.labels, 3 - l, l).contrast, c.contrast,
              1e-9);
}

// Black hair: two strands of one dark paint with ink of its grey level
// between them. Neither side sees the line in grey (0.5 levels both), so
// the other side's grey contrast cannot cap the colour: the paper is too
// dark for any ink to show much in grey, and the ink's colour distance to
// the paint, (10, −10, 30)/√3 ≈ 19.1, is the line.
TEST(ColourLine, InkBetweenTwoStrandsOfOneDarkPaintIsALine) {
  TwoPaints d(true, false);
  for (int y = 0; y < 43; ++y)
    for (int x = 0; x < 61; ++x) d.image.at(x, y) = x == 29 || x == 30 ? kInk : kDark;
  detail::BoundaryLine c;
  ASSERT_NE(expect_ink_seen_in_colour_only(d, &c), 0);
}

// Black-purple paint under grey ink that is brighter than it (grey 28
// against 15.5): the brightest point beside the boundary is the line's own
// rim, so the paper is read beyond the line's cross-section. The ink lies
// (3, 23, −17)/√3 ≈ 16.6 off the paint; on paper this dark the lift is
// capped at the paper's grey level, 15.5.
TEST(ColourLine, InkBrighterThanBlackPaintIsALine) {
  TwoPaints d(true, false);
  for (int y = 0; y < 43; ++y)
    for (int x = 0; x < 61; ++x)
      d.image.at(x, y) = x == 29 || x == 30 ? Rgba{28, 28, 28, 255} : Rgba{25, 5, 45, 255};
  const int l = left_of(d);
  ASSERT_NE(l, 0);
  const detail::BoundaryLine c = d.colour(l, 3 - l);
  EXPECT_NEAR(c.contrast, 0.299 * 25 + 0.587 * 5 + 0.114 * 45, 0.5);
  EXPECT_NEAR(c.contrast_low, c.contrast, 0.5);
}

// The same on a thin strand: 5 px right of the line runs the strand's
// other outline, within the reach of the paper, brighter than the paint.
// The paper is the paint just beyond the line, not that outline.
TEST(ColourLine, InkBrighterThanBlackPaintOnAThinStrandIsALine) {
  TwoPaints d(true, false);
  for (int y = 0; y < 43; ++y)
    for (int x = 0; x < 61; ++x)
      d.image.at(x, y) =
          x == 29 || x == 30 || x == 36 || x == 37 ? Rgba{28, 28, 28, 255} : Rgba{25, 5, 45, 255};
  const int l = left_of(d);
  ASSERT_NE(l, 0);
  EXPECT_NEAR(d.colour(l, 3 - l).contrast, 0.299 * 25 + 0.587 * 5 + 0.114 * 45, 0.5);
}

// The same on light paint: ink of the paint's grey level but another hue
// is no line the colour may lift past what the grey levels see (0 here).
TEST(ColourLine, InkOfTheGreyOfOneLightPaintIsCappedByTheGrey) {
  TwoPaints d(true, false);
  for (int y = 0; y < 43; ++y)
    for (int x = 0; x < 61; ++x)
      d.image.at(x, y) = x == 29 || x == 30 ? Rgba{150, 160, 100, 255}   // grey 150.2
                                            : Rgba{180, 140, 150, 255};  // grey 153.3
  const int l = left_of(d);
  ASSERT_NE(l, 0);
  EXPECT_LT(d.colour(l, 3 - l).contrast, 4.0);
}

TEST(ColourLine, ToneStepAndBlendAreNoLine) {
  for (const bool blend : {false, true}) {
    const TwoPaints d(false, blend);
    const int l = left_of(d);
    ASSERT_NE(l, 0);
    EXPECT_LT(d.colour(l, 3 - l).contrast, 0.5) << "blend " << blend;
  }
}

// A faint line of another hue that the grey levels see on both sides (a
// fork line fading out): its colour does not make it a stronger line.
TEST(ColourLine, HueOfALineBothSidesSeeAddsNothing) {
  TwoPaints d(true, false);
  for (int y = 0; y < 43; ++y)
    for (int x = 0; x < 61; ++x)
      d.image.at(x, y) = x == 29 || x == 30 ? Rgba{150, 110, 200, 255}  // grey 132.3
                         : x < 30           ? Rgba{180, 150, 140, 255}  // grey 157.9
                                            : Rgba{170, 150, 160, 255};           // grey 157.1
  const int l = left_of(d);
  ASSERT_NE(l, 0);
  EXPECT_EQ(d.colour(l, 3 - l).contrast, 0.0);
}

TEST(ColourLine, NoPaperOnASideGivesZero) {
  const TwoPaints d(true, false);
  const int l = left_of(d);
  // Region 3 is nowhere: no sample has paper on that side.
  EXPECT_EQ(detail::colour_line(d.image, 2.0, d.boundary(), 3.0, d.labels, l, 3).contrast, 0.0);
  EXPECT_EQ(detail::colour_line(d.image, 2.0, Polyline{}, 3.0, d.labels, l, 3 - l).contrast, 0.0);
}

// The whole layering: three strands of dark paints under ink of their own
// grey level, on a backdrop as dark, so the grey levels find no line
// anywhere (the threshold is its floor). Before colour_line, every boundary
// was non-occluding and every pair "equal".
TEST(ColourLine, LayeringCallsTheInkedBoundaryOccluding) {
  const int w = 90, h = 61;
  Image image(w, h, kDark);
  LabelMap labels(w, h, 0);
  auto strand = [&](int x0, int x1, int y0, int y1, int id, Rgba paint) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const bool edge = x < x0 + 2 || x >= x1 - 2 || y < y0 + 2 || y >= y1 - 2;
        image.at(x, y) = edge ? kInk : paint;
        labels.at(x, y) = edge ? 0 : id;
      }
  };
  strand(8, 50, 6, 55, 1, kPurple);
  strand(48, 82, 6, 55, 2, kDark);
  strand(30, 70, 20, 40, 3, Rgba{52, 20, 80, 255});
  const Result r = layer_regions(image, labels);
  int inked = 0;
  for (const BoundaryReport& b : r.boundaries) {
    if (b.left <= 0 || b.right <= 0) continue;
    ++inked;
    EXPECT_TRUE(b.occluding) << b.left << "|" << b.right << " contrast " << b.line_contrast
                             << " threshold " << r.line_threshold;
    EXPECT_GE(b.line_contrast, r.line_threshold);
  }
  EXPECT_GE(inked, 3);
  for (const RegionRelation& rel : r.relations)
    EXPECT_NE(rel.relation, Relation::kEqual) << rel.a << "|" << rel.b;
}

// Black hair drawn in near-neutral paint with ink a little darker: a plain
// outline between strands reads only 4–6 grey levels, as no ink shows more
// than the paint's grey level. On dark paper (64 or less) the threshold is
// 4, not the drawing's floor of 6, so the outlines are occluding (before,
// every pair came out "equal"); two regions of one paint meeting without
// ink stay non-occluding.
TEST(ColourLine, FaintInkOnBlackPaintIsOccludingUnderTheFloor) {
  const int w = 90, h = 61;
  constexpr Rgba kBlack{30, 28, 34, 255};  // grey level 29.3
  constexpr Rgba kFaint{24, 22, 28, 255};  // grey level 23.3
  Image image(w, h, kBlack);
  LabelMap labels(w, h, 0);
  auto strand = [&](int x0, int x1, int y0, int y1, int id) {
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) {
        const bool edge = x < x0 + 2 || x >= x1 - 2 || y < y0 + 2 || y >= y1 - 2;
        image.at(x, y) = edge ? kFaint : kBlack;
        labels.at(x, y) = edge ? 0 : id;
      }
  };
  strand(8, 50, 6, 55, 1);
  strand(48, 82, 6, 55, 2);
  strand(30, 70, 20, 40, 3);
  // Region 4: the lower part of strand 1 with no ink between them.
  for (int y = 45; y < 53; ++y)
    for (int x = 10; x < 30; ++x) labels.at(x, y) = 4;
  const Result r = layer_regions(image, labels);
  EXPECT_NEAR(r.line_threshold, 6.0, 0.5);
  int inked = 0;
  for (const BoundaryReport& b : r.boundaries) {
    if (b.left <= 0 || b.right <= 0) continue;
    const bool split = b.left == 4 || b.right == 4;
    if (!split) ++inked;
    EXPECT_EQ(b.occluding, !split) << b.left << "|" << b.right << " contrast " << b.line_contrast
                                   << " threshold " << r.line_threshold;
  }
  EXPECT_GE(inked, 3);
}

}  // namespace
}  // namespace hair25d::layering
