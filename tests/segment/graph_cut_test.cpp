// The graph cut from strokes (paper §3): exact small cases, properties, and
// bad input.
#include <gtest/gtest.h>

#include <set>

#include "drawing.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/graph_cut.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::segment {
namespace {

using testing::stroke;

LabelMap labels_of(const SegmentResult& r, int w, int h) {
  return rasterize_triangle_values(r.segmentation.mesh, r.segmentation.triangle_region, w, h);
}

TEST(GraphCut, RectangleSplitByOneLineGivesTwoRegions) {
  const int W = 130, H = 70;
  const Image img = testing::split_rectangle(W, H, 50.0);
  Strokes s;
  s.strokes = {stroke(1, {{20, 30}, {25, 40}}), stroke(2, {{100, 10}, {90, 60}})};
  const SegmentResult r = segment_image(img, &s);
  const LabelMap l = labels_of(r, W, H);
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      if (std::abs(x + 0.5 - 50.0) < 3.0) continue;  // the line itself
      EXPECT_EQ(l.at(x, y), x < 50 ? 1 : 2) << x << "," << y;
    }
  }
  EXPECT_EQ(r.segmentation.adjacency, (std::vector<std::array<int, 2>>{{1, 2}}));
  EXPECT_TRUE(r.cut.converged);
}

TEST(GraphCut, EveryTriangleGetsOneStrokeLabelOrBackground) {
  const int W = 160, H = 110;
  Image img(W, H, {200, 230, 250, 255});  // sky-blue paper
  testing::fill_rect(img, 30, 20, 130, 95, {230, 180, 90, 255});
  testing::draw_polyline(img, {{30, 20}, {130, 20}, {130, 95}, {30, 95}}, 3.0, {20, 20, 20, 255},
                         true);
  testing::draw_line(img, {80, 20}, {80, 95}, 3.0);
  Strokes s;
  s.strokes = {stroke(4, {{50, 50}, {60, 60}}), stroke(9, {{100, 40}, {110, 70}}),
               stroke(0, {{5, 5}, {150, 5}})};
  const SegmentResult r = segment_image(img, &s);
  std::set<int> seen(r.segmentation.triangle_region.begin(), r.segmentation.triangle_region.end());
  EXPECT_EQ(seen, (std::set<int>{0, 4, 9}));
  const LabelMap l = labels_of(r, W, H);
  EXPECT_EQ(l.at(55, 40), 4);
  EXPECT_EQ(l.at(105, 80), 9);
  EXPECT_EQ(l.at(10, 100), 0);
  EXPECT_EQ(l.at(150, 60), 0);
}

TEST(GraphCut, UnmarkedFaceOfAnotherColourIsBackground) {
  const int W = 150, H = 100;
  Image img(W, H, {230, 180, 90, 255});                            // hair everywhere ...
  testing::fill_rect(img, 90, 30, 140, 90, {250, 225, 210, 255});  // ... but a skin patch
  testing::draw_polyline(img, {{90, 30}, {140, 30}, {140, 90}, {90, 90}}, 3.0, {20, 20, 20, 255},
                         true);
  Strokes s;
  s.strokes = {stroke(3, {{20, 20}, {40, 70}})};  // no background stroke at all
  const SegmentResult r = segment_image(img, &s);
  const LabelMap l = labels_of(r, W, H);
  EXPECT_EQ(l.at(115, 60), 0);
  EXPECT_EQ(l.at(60, 60), 3);
}

TEST(GraphCut, ImageWithoutLinesSplitsByColour) {
  const int W = 120, H = 60;
  Image img(W, H, {230, 180, 90, 255});
  testing::fill_rect(img, 60, 0, 120, 60, {90, 60, 160, 255});
  Strokes s;
  s.strokes = {stroke(1, {{10, 30}, {30, 30}}), stroke(2, {{90, 30}, {110, 30}})};
  const SegmentResult r = segment_image(img, &s);
  EXPECT_TRUE(r.segmentation.curves.empty());
  const LabelMap l = labels_of(r, W, H);
  for (int y = 0; y < H; ++y) {
    for (int x = 0; x < W; ++x) {
      if (std::abs(x - 60) < 8) continue;  // the cut follows triangles near the colour edge
      EXPECT_EQ(l.at(x, y), x < 60 ? 1 : 2) << x << "," << y;
    }
  }
}

TEST(GraphCut, PermutingLabelsPermutesTheResult) {
  const int W = 130, H = 70;
  const Image img = testing::split_rectangle(W, H, 70.0);
  Strokes a, b;
  a.strokes = {stroke(1, {{20, 30}}), stroke(2, {{100, 30}})};
  b.strokes = {stroke(5, {{20, 30}}), stroke(3, {{100, 30}})};
  const auto ra = segment_image(img, &a).segmentation.triangle_region;
  const auto rb = segment_image(img, &b).segmentation.triangle_region;
  ASSERT_EQ(ra.size(), rb.size());
  for (std::size_t t = 0; t < ra.size(); ++t)
    EXPECT_EQ(rb[t], ra[t] == 1 ? 5 : (ra[t] == 2 ? 3 : 0));
}

TEST(GraphCut, StrokesLeavingTheImageAreClipped) {
  const int W = 100, H = 60;
  const Image img = testing::split_rectangle(W, H, 50.0);
  Strokes s;
  s.strokes = {stroke(1, {{-40, 30}, {20, 30}}), stroke(2, {{80, 30}, {400, -200}}),
               stroke(7, {{-50, -50}, {-10, -20}})};  // wholly outside: ignored
  const SegmentResult r = segment_image(img, &s);
  const LabelMap l = labels_of(r, W, H);
  EXPECT_EQ(l.at(10, 10), 1);
  EXPECT_EQ(l.at(90, 50), 2);
  EXPECT_EQ(
      std::count(r.segmentation.triangle_region.begin(), r.segmentation.triangle_region.end(), 7),
      0);
}

TEST(GraphCut, TinyAndNonSquareImages) {
  Strokes s;
  s.strokes = {stroke(2, {{0, 0}})};
  for (const auto& [w, h] : {std::pair{1, 1}, std::pair{3, 2}, std::pair{2, 9}}) {
    const Image img(w, h, {100, 150, 200, 255});
    const SegmentResult r = segment_image(img, &s);
    const LabelMap l = labels_of(r, w, h);
    EXPECT_EQ(l.at(0, 0), 2) << w << "x" << h;
    for (int v : r.segmentation.triangle_region) EXPECT_TRUE(v == 0 || v == 2);
  }
}

TEST(GraphCut, BadInputIsRejected) {
  const Image img = testing::split_rectangle(60, 40, 30.0);
  Strokes none;
  EXPECT_THROW(segment_image(img, &none), Error);
  Strokes only_background;
  only_background.strokes = {stroke(0, {{5, 5}, {20, 20}})};
  try {
    segment_image(img, &only_background);
    FAIL() << "no hair stroke must be an error";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("no hair stroke"), std::string::npos) << e.what();
  }
  Strokes outside;
  outside.strokes = {stroke(1, {{-10, -10}, {-5, -30}})};
  EXPECT_THROW(segment_image(img, &outside), Error);
  EXPECT_THROW(segment_image(Image(), &outside), Error);

  const MeshResult m = build_mesh({}, 60, 40);
  Strokes one;
  one.strokes = {stroke(1, {{5, 5}})};
  EXPECT_THROW(graph_cut_labels(Image(30, 40, {}), m.mesh, one, {}), Error);  // mesh too wide
  EXPECT_THROW(graph_cut_labels(img, m.mesh, one, LabelMap(10, 10)), Error);  // mask size
  GraphCutOptions o;
  o.phi_other = -1.0;
  EXPECT_THROW(graph_cut_labels(img, m.mesh, one, {}, o), Error);
  TriMesh2 broken = m.mesh;
  broken.F(0, 0) = 1000;
  EXPECT_THROW(graph_cut_labels(img, broken, one, {}), Error);
}

}  // namespace
}  // namespace hair25d::segment
