// Regions without strokes: faces enclosed by curves, picking by colour,
// turning picks into strokes, merge and relabel helpers.
#include <gtest/gtest.h>

#include <set>

#include "drawing.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/graph_cut.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/regions.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::segment {
namespace {

LabelMap raster(const SegmentResult& r, const std::vector<int>& v) {
  return rasterize_triangle_values(r.segmentation.mesh, v, r.segmentation.width,
                                   r.segmentation.height);
}

TEST(AutomaticRegions, OneLineSplitsTheRectangleInTwo) {
  const SegmentResult r = segment_image(testing::split_rectangle(120, 80, 45.0), nullptr);
  EXPECT_FALSE(r.from_strokes);
  const auto& ids = r.segmentation.triangle_region;
  EXPECT_EQ(std::set<int>(ids.begin(), ids.end()), (std::set<int>{1, 2}));
  const LabelMap l = raster(r, ids);
  EXPECT_NE(l.at(10, 40), l.at(100, 40));
  EXPECT_EQ(l.at(10, 5), l.at(30, 75));
  EXPECT_EQ(l.at(60, 5), l.at(110, 75));
  EXPECT_EQ(r.segmentation.adjacency, (std::vector<std::array<int, 2>>{{1, 2}}));
}

TEST(AutomaticRegions, CircleAndBlankImages) {
  Image img(110, 90, {240, 240, 240, 255});
  testing::draw_polyline(img, testing::circle(Vec2(55, 45), 30), 3.0, {20, 20, 20, 255}, true);
  const SegmentResult r = segment_image(img, nullptr);
  const auto& ids = r.segmentation.triangle_region;
  EXPECT_EQ(std::set<int>(ids.begin(), ids.end()).size(), 2u);
  const LabelMap l = raster(r, ids);
  EXPECT_NE(l.at(55, 45), l.at(5, 5));
  EXPECT_EQ(l.at(5, 5), l.at(105, 85));

  const SegmentResult blank = segment_image(Image(40, 25, {9, 9, 9, 255}), nullptr);
  const auto& b = blank.segmentation.triangle_region;
  EXPECT_EQ(std::set<int>(b.begin(), b.end()), (std::set<int>{1}));
  const SegmentResult tiny = segment_image(Image(1, 1, {9, 9, 9, 255}), nullptr);
  EXPECT_EQ(std::set<int>(tiny.segmentation.triangle_region.begin(),
                          tiny.segmentation.triangle_region.end()),
            (std::set<int>{1}));
}

TEST(LabelByColour, PicksTheRegionsOfThatColourOnly) {
  Image img(150, 80, {230, 60, 60, 255});                       // red left ...
  testing::fill_rect(img, 75, 0, 150, 80, {60, 60, 230, 255});  // ... blue right
  testing::draw_line(img, {75, -5}, {75, 85}, 3.0);
  testing::draw_line(img, {40, -5}, {40, 85}, 3.0);  // two red regions
  const SegmentResult r = segment_image(img, nullptr);
  ColourPick pick;
  pick.rgb = {225, 65, 60};
  pick.tolerance = 30.0;
  const auto labels = label_regions_by_colour(img, r.segmentation.mesh,
                                              r.segmentation.triangle_region, r.line_mask, pick);
  const LabelMap l = raster(r, labels);
  EXPECT_EQ(l.labels(), (std::vector<int>{1, 2}));  // one label per picked region
  EXPECT_GT(l.at(10, 40), 0);
  EXPECT_GT(l.at(60, 40), 0);
  EXPECT_NE(l.at(10, 40), l.at(60, 40));
  EXPECT_EQ(l.at(120, 40), 0);

  // The picked regions as strokes reproduce themselves through the graph cut.
  const Strokes s = strokes_from_labels(r.segmentation.mesh, labels);
  ASSERT_EQ(s.strokes.size(), 2u);
  const SegmentResult again = segment_image(img, &s);
  const LabelMap a = raster(again, again.segmentation.triangle_region);
  EXPECT_EQ(a.at(10, 40), l.at(10, 40));
  EXPECT_EQ(a.at(60, 40), l.at(60, 40));
  EXPECT_EQ(a.at(120, 40), 0);

  pick.tolerance = -1.0;
  EXPECT_THROW(label_regions_by_colour(img, r.segmentation.mesh, r.segmentation.triangle_region,
                                       r.line_mask, pick),
               Error);
  EXPECT_THROW(strokes_from_labels(r.segmentation.mesh, {1, 2}), Error);
  EXPECT_THROW(strokes_from_labels(r.segmentation.mesh, labels, 0.5), Error);
}

TEST(RegionStats, AreaCentroidAndColourOfEachRegion) {
  const SegmentResult r = segment_image(testing::split_rectangle(100, 40, 30.0), nullptr);
  const auto stats = region_stats(testing::split_rectangle(100, 40, 30.0), r.segmentation.mesh,
                                  r.segmentation.triangle_region, r.line_mask);
  ASSERT_EQ(stats.size(), 2u);
  double area = 0.0;
  for (const auto& s : stats) {
    area += s.area;
    EXPECT_NEAR(s.mean[0], 235.0, 1.0);  // the fill, lines left out
    EXPECT_NEAR(s.centroid.y(), 20.0, 1.0);
  }
  EXPECT_NEAR(area, 4000.0, 1e-6);
  EXPECT_THROW(region_stats(Image(100, 40), r.segmentation.mesh, {1}, {}), Error);
}

TEST(LabelHelpers, MergeRelabelCompactAdjacency) {
  std::vector<int> l{3, 3, 5, 0, 9};
  merge_labels(l, 5, 3);
  EXPECT_EQ(l, (std::vector<int>{3, 3, 3, 0, 9}));
  relabel(l, {{3, 7}, {9, 0}});
  EXPECT_EQ(l, (std::vector<int>{7, 7, 7, 0, 0}));
  std::vector<int> c{8, 0, 4, 8, 15};
  EXPECT_EQ(compact_labels(c), 3);
  EXPECT_EQ(c, (std::vector<int>{2, 0, 1, 2, 3}));
  EXPECT_THROW(merge_labels(l, -1, 2), Error);
  EXPECT_THROW(relabel(l, {{1, -2}}), Error);

  // Two triangles sharing the diagonal of a unit square.
  TriMesh2 m;
  m.V.resize(4, 2);
  m.V << 0, 0, 1, 0, 1, 1, 0, 1;
  m.F.resize(2, 3);
  m.F << 0, 1, 2, 0, 2, 3;
  EXPECT_EQ(label_adjacency(m, {4, 2}), (std::vector<std::array<int, 2>>{{2, 4}}));
  EXPECT_TRUE(label_adjacency(m, {4, 4}).empty());
  EXPECT_EQ(automatic_regions(m), (std::vector<int>{1, 1}));
  m.on_curve.resize(2, 3);
  m.on_curve << false, false, true, true, false, false;  // the diagonal is a curve
  EXPECT_EQ(automatic_regions(m), (std::vector<int>{1, 2}));
  EXPECT_THROW(label_adjacency(m, {1}), Error);
}

TEST(AutomaticRegions, BrokenMeshAndBadOptionsAreRejected) {
  TriMesh2 m;
  m.V.resize(3, 2);
  m.V << 0, 0, 1, 0, 0, 1;
  m.F.resize(1, 3);
  m.F << 0, 1, 7;  // no vertex 7
  EXPECT_THROW(automatic_regions(m), Error);
  SegmentOptions o;
  o.cut.max_cycles = 0;
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find("max_cycles"), std::string::npos);
  EXPECT_THROW(segment_image(Image(10, 10, {1, 1, 1, 255}), nullptr, o), Error);
}

}  // namespace
}  // namespace hair25d::segment
