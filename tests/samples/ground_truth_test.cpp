// Hand-built scenes with known answers for the generator's ground-truth pass
// (private to the generator; this test sees its src/ headers): a bar across a
// square splits it into two regions below the bar; an inner line splits one
// strand into two "equal" halves; noise-free rasters are exact.
#include <gtest/gtest.h>

#include <set>

#include "ground_truth.h"
#include "render.h"
#include "scene.h"

namespace hair25d::generator {
namespace {

Polyline rect(double x0, double y0, double x1, double y1) {
  return {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
}

Shape hair(int strand, Polyline outline) {
  Shape s;
  s.strand = strand;
  s.name = std::to_string(strand);
  s.outline = std::move(outline);
  return s;
}

Scene base() {
  Scene sc;
  sc.width = 130;  // not square
  sc.height = 90;
  sc.line_width = 2.0;
  sc.head_center = {65, 45};
  return sc;
}

std::set<int> labels_in(const LabelMap& m, int x0, int y0, int x1, int y1) {
  std::set<int> out;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) out.insert(m.at(x, y));
  }
  return out;
}

TEST(GroundTruth, BarAcrossSquareSplitsItIntoTwoRegionsBelowTheBar) {
  Scene sc = base();
  sc.shapes.push_back(hair(1, rect(10, 10, 90, 80)));
  sc.shapes.push_back(hair(2, rect(40, 2, 58, 88)));  // drawn later: above
  sc.strand_count = 2;
  const GroundTruth gt = make_ground_truth(sc, render_owner(sc));

  ASSERT_EQ(gt.region_list.size(), 3u);
  // Ids in scan order of the first pixel: the bar starts at the top.
  const int bar = gt.regions.at(49, 5);
  const int left = gt.regions.at(25, 45);
  const int right = gt.regions.at(75, 45);
  EXPECT_NE(bar, 0);
  EXPECT_NE(left, 0);
  EXPECT_NE(right, 0);
  EXPECT_EQ(std::set<int>({bar, left, right}).size(), 3u);
  EXPECT_EQ(gt.region_list[bar - 1].strand, 2);
  EXPECT_EQ(gt.region_list[left - 1].strand, 1);
  EXPECT_EQ(gt.region_list[right - 1].strand, 1);
  // Outlines are 0: the square's edge and both edges of the bar.
  EXPECT_EQ(gt.regions.at(10, 45), 0);
  EXPECT_EQ(gt.regions.at(40, 45), 0);
  EXPECT_EQ(gt.regions.at(58, 45), 0);
  EXPECT_EQ(gt.regions.at(5, 5), 0);  // paper

  // Exactly two pairs, both halves below the bar; the halves do not meet.
  ASSERT_EQ(gt.pairs.size(), 2u);
  for (const AnnotatedPair& p : gt.pairs) {
    const int other = p.a == bar ? p.b : p.a;
    ASSERT_TRUE(p.a == bar || p.b == bar);
    EXPECT_TRUE(other == left || other == right);
    EXPECT_EQ(p.relation, p.a == bar ? Relation::kAbove : Relation::kBelow);
  }

  // One stroke at least per region, inside it; background strokes on paper.
  std::set<int> stroked;
  for (const Stroke& s : gt.strokes.strokes) {
    stroked.insert(s.label);
    for (const Vec2& q : s.points) {
      const int x = static_cast<int>(q.x()), y = static_cast<int>(q.y());
      EXPECT_EQ(labels_in(gt.regions, x - 1, y - 1, x + 1, y + 1), std::set<int>{s.label});
    }
  }
  EXPECT_EQ(stroked, std::set<int>({0, 1, 2, 3}));
}

TEST(GroundTruth, InnerLineSplitsOneStrandIntoEqualHalves) {
  Scene sc = base();
  Shape s = hair(1, rect(10, 10, 110, 80));
  s.inner_lines.push_back({{60, 0}, {60, 90}});  // clipped to the shape
  sc.shapes.push_back(s);
  sc.strand_count = 1;
  const GroundTruth gt = make_ground_truth(sc, render_owner(sc));
  ASSERT_EQ(gt.region_list.size(), 2u);
  EXPECT_EQ(gt.regions.at(60, 45), 0);  // the inner line
  EXPECT_EQ(gt.regions.at(60, 5), 0);   // clipped: nothing drawn outside the shape...
  const cv::Mat owner = render_owner(sc);
  EXPECT_EQ(owner.at<int>(5, 60), 0);  // ...the paper above it stays paper
  ASSERT_EQ(gt.pairs.size(), 1u);
  EXPECT_EQ(gt.pairs[0].relation, Relation::kEqual);
}

TEST(GroundTruth, SliverThinnerThanAStrokeIsNoRegionAndBlocksContact) {
  // Strand 2 leaves a 4-pixel sliver of strand 1 between two bars of strand 3:
  // too thin for a stroke, so it is no region, and the regions on either side
  // of it only meet strand 3, not each other.
  Scene sc = base();
  sc.shapes.push_back(hair(1, rect(10, 10, 120, 80)));
  sc.shapes.push_back(hair(2, rect(40, 5, 60, 85)));
  sc.shapes.push_back(hair(3, rect(64, 5, 84, 85)));
  sc.strand_count = 3;
  const GroundTruth gt = make_ground_truth(sc, render_owner(sc));
  std::map<int, int> per_strand;
  for (const AnnotatedRegion& r : gt.region_list) ++per_strand[r.strand];
  EXPECT_EQ(per_strand[1], 2);  // left and right of the bars; the sliver is not a region
  EXPECT_EQ(per_strand[2], 1);
  EXPECT_EQ(per_strand[3], 1);
  EXPECT_EQ(gt.regions.at(62, 45), 0);
  for (const AnnotatedPair& p : gt.pairs) {
    const int sa = gt.region_list[p.a - 1].strand, sb = gt.region_list[p.b - 1].strand;
    EXPECT_FALSE(sa == 2 && sb == 3) << "the bars meet only across the sliver";
    EXPECT_FALSE(sa == 3 && sb == 2);
  }
}

}  // namespace
}  // namespace hair25d::generator
