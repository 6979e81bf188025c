// layer_regions on small drawings painted here with exact answers, user
// overrides, invariance to region numbering, and bad input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numbers>

#include "hair25d/core/error.h"
#include "hair25d/layering/layering.h"
#include "hair25d/layering/overlay.h"
#include "layering/relation_lookup.h"

namespace hair25d::layering {
namespace {

using test::relation_of;

struct Rect {
  int x0, y0, x1, y1;  // inclusive pixel bounds
  int region;          // its region id where visible
  Rgba fill;
};

struct Scene {
  Image image;
  LabelMap regions;
};

// Paints rectangles back to front with a `line`-pixel black outline inside
// each; region ids are those of the topmost rectangle, 0 on outlines and
// outside every rectangle. `split_y` > 0 gives the part of region 2 below it
// id 4 (a strand cut in two by the one painted over it).
Scene paint(int w, int h, const std::vector<Rect>& rects, int line, int split_y) {
  Scene s{Image(w, h, Rgba{230, 240, 250, 255}), LabelMap(w, h, 0)};
  for (const Rect& r : rects) {
    for (int y = std::max(0, r.y0); y <= std::min(h - 1, r.y1); ++y) {
      for (int x = std::max(0, r.x0); x <= std::min(w - 1, r.x1); ++x) {
        const bool edge = x - r.x0 < line || r.x1 - x < line || y - r.y0 < line || r.y1 - y < line;
        s.image.at(x, y) = edge ? Rgba{20, 15, 15, 255} : r.fill;
        s.regions.at(x, y) =
            edge ? 0 : (r.region == 2 && split_y > 0 && y > split_y ? 4 : r.region);
      }
    }
  }
  return s;
}

// Back hair (1), a vertical strand (2) over it, a horizontal strand (3) over
// both that cuts the vertical one into 2 (top) and 4 (bottom). 180 × 130.
Scene crossing() {
  return paint(180, 130,
               {{20, 15, 160, 120, 1, {200, 170, 120, 255}},
                {70, 2, 100, 105, 2, {190, 150, 110, 255}},
                {40, 60, 140, 80, 3, {210, 180, 130, 255}}},
               3, 70);
}

TEST(LayerRegions, CrossingStrands) {
  for (Metric metric : {Metric::kLearned, Metric::kPaper}) {
    SCOPED_TRACE(metric == Metric::kPaper ? "paper" : "learned");
    Options options;
    options.metric = metric;
    const Scene s = crossing();
    const Result r = layer_regions(s.image, s.regions, options);
    EXPECT_EQ(relation_of(r, 1, 2), Relation::kBelow);
    EXPECT_EQ(relation_of(r, 1, 3), Relation::kBelow);
    EXPECT_EQ(relation_of(r, 1, 4), Relation::kBelow);
    EXPECT_EQ(relation_of(r, 2, 3), Relation::kBelow);
    EXPECT_EQ(relation_of(r, 4, 3), Relation::kBelow);
    EXPECT_TRUE(r.overridden.empty());
    EXPECT_EQ(r.depth.at(1), 0);
    EXPECT_GT(r.depth.at(3), r.depth.at(2));
    EXPECT_GT(r.depth.at(3), r.depth.at(4));
    EXPECT_NEAR(r.line_width, 3.0, 1.0);
    EXPECT_EQ(r.anchors.size(), r.relations.size());
    EXPECT_FALSE(r.summary.empty());
    // Every reported relation is between hair regions, smaller id first.
    for (const RegionRelation& x : r.relations) {
      EXPECT_GT(x.a, 0);
      EXPECT_LT(x.a, x.b);
    }
  }
}

TEST(LayerRegions, JunctionSectorsOnTheLabelMapAndFromCurvedFits) {
  // Where the horizontal strand 3 lies over the lower piece 4 of the vertical
  // one, both ends of their boundary are T-junctions: 3 is the bar (π) and 4
  // the stem's side (π/2), whichever way the sectors are measured.
  const Scene s = crossing();
  const Result r = layer_regions(s.image, s.regions);
  int seen = 0;
  for (const BoundaryReport& b : r.boundaries) {
    if (!((b.left == 3 && b.right == 4) || (b.left == 4 && b.right == 3))) continue;
    for (const EndAngles& e : {b.cues.start, b.cues.end}) {
      ASSERT_TRUE(e.used);
      const double bar = b.left == 3 ? e.circle_left : e.circle_right;
      const double stem = b.left == 3 ? e.circle_right : e.circle_left;
      EXPECT_NEAR(bar, std::numbers::pi, 0.35);
      EXPECT_NEAR(stem, std::numbers::pi / 2, 0.35);
      EXPECT_NEAR(b.left == 3 ? e.curved_left : e.curved_right, std::numbers::pi, 0.2);
      EXPECT_NEAR(b.left == 3 ? e.curved_right : e.curved_left, std::numbers::pi / 2, 0.2);
      ++seen;
    }
    EXPECT_GT(b.left == 3 ? b.learned : -b.learned, 0.0);
  }
  EXPECT_EQ(seen, 2);
}

TEST(LayerRegions, RegionsAcrossASliverStrandAreNeighbours) {
  // A strand only 2 pixels wide inside its outline (2) lies over the back
  // hair and splits it into 1 (left) and 5 (right), which never touch but
  // are judged neighbours by a reader. 190 × 140.
  Scene s = paint(
      190, 140,
      {{20, 15, 170, 125, 1, {200, 170, 120, 255}}, {80, 3, 87, 137, 2, {190, 150, 110, 255}}}, 3,
      0);
  for (int y = 0; y < s.image.height(); ++y)
    for (int x = 88; x < s.image.width(); ++x)
      if (s.regions.at(x, y) == 1) s.regions.at(x, y) = 5;
  const Result r = layer_regions(s.image, s.regions);
  EXPECT_EQ(relation_of(r, 1, 2), Relation::kBelow);
  EXPECT_EQ(relation_of(r, 5, 2), Relation::kBelow);
  // Related, and in agreement with the drawing order.
  const Relation across = relation_of(r, 1, 5);
  const int d1 = r.depth.at(1), d5 = r.depth.at(5);
  EXPECT_EQ(across, d1 > d5 ? Relation::kAbove : d1 < d5 ? Relation::kBelow : Relation::kEqual);
  EXPECT_EQ(r.anchors.size(), r.relations.size());
}

TEST(LayerRegions, BoundaryWithoutALineIsEqual) {
  // Two tones of one strand meet without a drawn line: the same depth.
  Scene s = crossing();
  for (int y = 0; y < s.image.height(); ++y)
    for (int x = 0; x < s.image.width(); ++x)
      if (s.regions.at(x, y) == 1 && x > 120) {
        s.regions.at(x, y) = 5;
        s.image.at(x, y) = Rgba{170, 140, 100, 255};  // a darker cel tone
      }
  const Result r = layer_regions(s.image, s.regions);
  EXPECT_EQ(relation_of(r, 1, 5), Relation::kEqual);
  EXPECT_EQ(r.depth.at(1), r.depth.at(5));
  EXPECT_EQ(relation_of(r, 3, 5), Relation::kAbove);
}

// Eq. (1) on every boundary: Φ = w Φ̂_J + Φ_R/‖L‖², Φ̂_J the sum of its two
// junction terms, for the paper's w and another.
TEST(LayerRegions, PhiIsEquationOneOfItsParts) {
  const Scene s = crossing();
  for (const double w : {0.25, 0.7}) {
    Options o;
    o.junction_weight = w;
    const Result r = layer_regions(s.image, s.regions, o);
    int with_junction_term = 0;
    for (const BoundaryReport& b : r.boundaries) {
      EXPECT_NEAR(b.phi_j, b.phi_j_start + b.phi_j_end, 1e-12);
      EXPECT_NEAR(b.phi, w * b.phi_j + b.phi_r, 1e-12);
      with_junction_term += std::abs(b.phi_j) > 0.05;
    }
    EXPECT_GT(with_junction_term, 2);  // the T-junctions of the crossing say something
  }
}

TEST(LayerRegions, UserOverrideIsKeptAndTheRestReSolved) {
  const Scene s = crossing();
  Options o;
  RegionRelation fix;
  fix.a = 3;
  fix.b = 2;
  fix.relation = Relation::kBelow;  // the user says 3 is under 2
  o.fixed.push_back(fix);
  const Result r = layer_regions(s.image, s.regions, o);
  EXPECT_EQ(relation_of(r, 2, 3), Relation::kAbove);
  EXPECT_GT(r.depth.at(2), r.depth.at(3));
  bool marked = false;
  for (const RegionRelation& x : r.relations)
    if (x.a == 2 && x.b == 3) marked = x.user_fixed && !x.overridden;
  EXPECT_TRUE(marked);
  EXPECT_EQ(relation_of(r, 1, 3), Relation::kBelow);  // the rest still solved
}

TEST(LayerRegions, RenumberingRegionsGivesTheSameOrder) {
  const Scene s = crossing();
  const Result r = layer_regions(s.image, s.regions);
  const std::map<int, int> perm = {{1, 9}, {2, 3}, {3, 1}, {4, 20}};
  LabelMap moved = s.regions;
  for (std::size_t i = 0; i < moved.size(); ++i)
    if (moved.data()[i] != 0) moved.data()[i] = perm.at(moved.data()[i]);
  const Result p = layer_regions(s.image, moved);
  for (const auto& [from, to] : perm) EXPECT_EQ(r.depth.at(from), p.depth.at(to));
  for (const RegionRelation& x : r.relations)
    EXPECT_EQ(relation_of(p, perm.at(x.a), perm.at(x.b)), x.relation);
}

TEST(LayerRegions, OverlayHasTheImageSize) {
  const Scene s = crossing();
  const Result r = layer_regions(s.image, s.regions);
  const Image o = render_overlay(s.image, r, {{2, 3}});
  EXPECT_EQ(o.width(), s.image.width());
  EXPECT_EQ(o.height(), s.image.height());
  EXPECT_NE(o, s.image);
  EXPECT_THROW(render_overlay(Image(5, 4), r), Error);
}

int red_pixels_near(const Image& img, int cx, int cy, int radius) {
  int n = 0;
  for (int y = cy - radius; y <= cy + radius; ++y)
    for (int x = cx - radius; x <= cx + radius; ++x) {
      const Rgba& p = img.at(x, y);
      n += p.r > 200 && p.g < 80 && p.b < 80;
    }
  return n;
}

TEST(LayerRegions, OverlayMarksPairsWithoutABoundaryWhereTheRegionsMeet) {
  // 2 and 4 are the two pieces of the vertical strand either side of 3: they
  // share no boundary, so a relation between them carries no anchor of its own.
  const Scene s = crossing();
  Options o;
  o.fixed.push_back({2, 4, Relation::kAbove, 0.0, true, false});
  const Result r = layer_regions(s.image, s.regions, o);
  Result bare = r;
  bare.relations.clear();
  bare.anchors.clear();
  const Image plain = render_overlay(s.image, bare);
  const Image marked = render_overlay(s.image, r, {{4, 2}});
  // Drawn between the pieces (they come closest about (85, 70)), not at the
  // image corner.
  EXPECT_GT(red_pixels_near(marked, 85, 70, 14), 10);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 12; ++x) EXPECT_EQ(marked.at(x, y), plain.at(x, y)) << x << "," << y;
  // A wrong pair the result does not relate at all is still shown there.
  Result missing = r;
  for (std::size_t k = missing.relations.size(); k-- > 0;)
    if (std::min(missing.relations[k].a, missing.relations[k].b) == 2 &&
        std::max(missing.relations[k].a, missing.relations[k].b) == 4) {
      missing.relations.erase(missing.relations.begin() + k);
      missing.anchors.erase(missing.anchors.begin() + k);
    }
  EXPECT_GT(red_pixels_near(render_overlay(s.image, missing, {{2, 4}}), 85, 70, 14), 10);
  EXPECT_EQ(red_pixels_near(render_overlay(s.image, missing), 85, 70, 14), 0);
}

TEST(LayerRegions, RejectsASingleRegion) {
  const Scene s = paint(60, 40, {{5, 5, 50, 30, 1, {200, 170, 120, 255}}}, 2, 0);
  try {
    layer_regions(s.image, s.regions);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("at least two"), std::string::npos) << e.what();
  }
}

TEST(LayerRegions, RejectsRegionsWithoutJunctions) {
  // One region fills the image, another is an island in it: no junction.
  LabelMap m(50, 30, 1);
  for (int y = 10; y < 20; ++y)
    for (int x = 20; x < 30; ++x) m.at(x, y) = 2;
  try {
    layer_regions(Image(50, 30, Rgba{255, 255, 255, 255}), m);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("junction"), std::string::npos) << e.what();
  }
}

TEST(LayerRegions, RejectsAMapOfTheWrongSize) {
  const Scene s = crossing();
  try {
    layer_regions(s.image, LabelMap(s.image.width() + 1, s.image.height(), 1));
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("same size"), std::string::npos) << e.what();
  }
  EXPECT_THROW(layer_regions(s.image, LabelMap()), Error);
}

TEST(LayerRegions, RejectsBadOptions) {
  const Scene s = crossing();
  Options o;
  o.coupling_cap = -1;
  EXPECT_THROW(layer_regions(s.image, s.regions, o), Error);
  o = {};
  o.learned_scale = 0;
  EXPECT_THROW(layer_regions(s.image, s.regions, o), Error);
  o = {};
  o.equal_fraction = 2;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("equal_fraction"), std::string::npos);
  for (double bad : {0.0, -3.0, std::numeric_limits<double>::infinity()}) {
    o = {};
    o.fit_reach_min = bad;
    EXPECT_FALSE(o.is_valid(&why));
    EXPECT_NE(why.find("fit_reach_min"), std::string::npos);
    EXPECT_THROW(layer_regions(s.image, s.regions, o), Error);
  }
  o = {};
  RegionRelation fix;
  fix.a = 2;
  fix.b = 77;  // not in the map
  o.fixed.push_back(fix);
  EXPECT_THROW(layer_regions(s.image, s.regions, o), Error);
}

}  // namespace
}  // namespace hair25d::layering
