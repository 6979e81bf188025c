// segmentation.json: round trip and strict reading; the overlay.
#include <gtest/gtest.h>

#include <filesystem>

#include "common/temp_dir.h"
#include "drawing.h"
#include "hair25d/core/error.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/overlay.h"
#include "hair25d/segment/segmentation_io.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::segment {
namespace {

Segmentation sample() {
  Strokes s;
  s.strokes = {{1, 3.0, {{10, 30}}}, {2, 3.0, {{90, 30}}}};
  Image img = testing::split_rectangle(110, 60, 50.0);
  testing::draw_line(img, {50, 30}, {80, 30}, 3.0);  // a T-junction
  return segment_image(img, &s).segmentation;
}

TEST(SegmentationJson, RoundTripIsExact) {
  const Segmentation a = sample();
  ASSERT_FALSE(a.curves.empty());
  const Segmentation b = segmentation_from_json(segmentation_to_json(a), "test");
  EXPECT_EQ(b.width, a.width);
  EXPECT_EQ(b.height, a.height);
  ASSERT_EQ(b.curves.size(), a.curves.size());
  for (std::size_t i = 0; i < a.curves.size(); ++i) {
    EXPECT_EQ(b.curves[i].points, a.curves[i].points);
    EXPECT_EQ(b.curves[i].ends, a.curves[i].ends);
    EXPECT_EQ(b.curves[i].closed, a.curves[i].closed);
  }
  EXPECT_EQ(b.mesh.V, a.mesh.V);
  EXPECT_EQ(b.mesh.F, a.mesh.F);
  EXPECT_EQ(b.mesh.on_curve, a.mesh.on_curve);
  EXPECT_EQ(b.triangle_region, a.triangle_region);
  EXPECT_EQ(b.adjacency, a.adjacency);

  const hair25d::testing::TempDir dir;
  write_segmentation(dir / "s.json", a);
  EXPECT_EQ(read_segmentation(dir / "s.json").triangle_region, a.triangle_region);
}

TEST(SegmentationJson, MalformedFilesNameTheKey) {
  const std::string good = segmentation_to_json(sample());
  auto expect_error = [](const std::string& text, const std::string& key) {
    try {
      segmentation_from_json(text, "seg.json");
      ADD_FAILURE() << "accepted: " << key;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("seg.json"), std::string::npos) << e.what();
    }
  };
  expect_error("{", "JSON");
  expect_error("[]", "format");
  expect_error(R"({"format": "hair25d-strokes/1"})", "format");
  auto edit = [&](const std::string& from, const std::string& to) {
    std::string s = good;
    const auto at = s.find(from);
    EXPECT_NE(at, std::string::npos) << from;
    return s.replace(at, from.size(), to);
  };
  expect_error(edit("\"triangle_region\":[", "\"triangle_region\":[1,"), "triangle_region");
  expect_error(edit("\"ends\":[\"", "\"ends\":[\"middle"), "ends");
  expect_error(edit("\"triangles\":[[", "\"triangles\":[[100000,"), "triangles");
  expect_error(edit("\"width\":", "\"wide\":"), "width");
  EXPECT_THROW(read_segmentation("/no/such/segmentation.json"), Error);
}

TEST(Overlay, SameSizeTintedAndChecked) {
  Strokes s;
  s.strokes = {{1, 3.0, {{10, 30}}}};
  const Image img = testing::split_rectangle(90, 50, 45.0);
  const SegmentResult r = segment_image(img, &s);
  const LabelMap l =
      rasterize_triangle_values(r.segmentation.mesh, r.segmentation.triangle_region, 90, 50);
  const Image o = draw_overlay(img, r.segmentation, l);
  EXPECT_EQ(o.width(), 90);
  EXPECT_EQ(o.height(), 50);
  EXPECT_NE(o.at(20, 10), img.at(20, 10));  // tinted region
  EXPECT_NE(label_colour(1), label_colour(2));
  EXPECT_THROW(draw_overlay(img, r.segmentation, LabelMap(50, 90)), Error);
}

}  // namespace
}  // namespace hair25d::segment
