#include "hair25d/core/strokes.h"

#include <gtest/gtest.h>

#include "common/temp_dir.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"

namespace hair25d {
namespace {

std::string error_of(const std::string& text) {
  try {
    parse_strokes(text, "s.json");
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(Strokes, ParsesTheDocumentedExample) {
  const Strokes s = parse_strokes(R"({
    "format": "hair25d-strokes/1", "head_center": [523.7, 663.7],
    "strokes": [
      {"label": 3, "width": 3, "points": [[471, 265], [413, 316], [333, 372]]},
      {"label": 0, "width": 5, "points": [[40, 40], [41, 41]]},
      {"label": 3, "width": 1.5, "points": [[1, 2]]}]})",
                                  "s.json");
  ASSERT_EQ(s.strokes.size(), 3u);
  EXPECT_EQ(s.strokes[0].label, 3);
  EXPECT_DOUBLE_EQ(s.strokes[0].width, 3.0);
  EXPECT_TRUE(s.strokes[0].points[2].isApprox(Vec2(333, 372)));
  ASSERT_TRUE(s.head_center.has_value());
  EXPECT_DOUBLE_EQ(s.head_center->y(), 663.7);
  EXPECT_EQ(s.labels(), std::vector<int>{3});
}

TEST(Strokes, MalformedFilesNameTheKeyAndTheRule) {
  EXPECT_NE(error_of("{").find("not valid JSON"), std::string::npos);
  EXPECT_NE(error_of("[]").find("expected an object"), std::string::npos);
  EXPECT_NE(error_of(R"({"strokes": []})").find("'format'"), std::string::npos);
  EXPECT_NE(error_of(R"({"format": "other/2", "strokes": []})").find("hair25d-strokes/1"),
            std::string::npos);
  EXPECT_NE(error_of(R"({"format": "hair25d-strokes/1"})").find("'strokes'"), std::string::npos);
  const std::string head = R"({"format": "hair25d-strokes/1", "strokes": [)";
  EXPECT_NE(
      error_of(head + R"({"label": -1, "width": 3, "points": [[1,2]]}]})").find("strokes[0].label"),
      std::string::npos);
  EXPECT_NE(
      error_of(head + R"({"label": 1.5, "width": 3, "points": [[1,2]]}]})").find("an integer"),
      std::string::npos);
  EXPECT_NE(error_of(head + R"({"label": 1, "width": 0.5, "points": [[1,2]]}]})").find(">= 1"),
            std::string::npos);
  EXPECT_NE(
      error_of(head + R"({"label": 1, "width": 2, "points": []}]})").find("at least one point"),
      std::string::npos);
  EXPECT_NE(error_of(head + R"({"label": 1, "width": 2, "points": [[1,2],[3]]}]})")
                .find("strokes[0].points[1]"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"({"label": 1, "width": 2, "points": [[1,"x"]]}]})").find("[x, y]"),
            std::string::npos);
  EXPECT_NE(error_of(head + R"(7]})").find("strokes[0]"), std::string::npos);
  EXPECT_NE(error_of(R"({"format": "hair25d-strokes/1", "head_center": [1], "strokes": []})")
                .find("head_center"),
            std::string::npos);
  // Every message names the file.
  EXPECT_EQ(error_of("{").rfind("s.json", 0), 0u);
}

TEST(Strokes, EmptyStrokeListIsValidMarkup) {
  const Strokes s = parse_strokes(R"({"format": "hair25d-strokes/1", "strokes": []})", "s.json");
  EXPECT_TRUE(s.strokes.empty());
  EXPECT_TRUE(s.labels().empty());
}

TEST(Strokes, RasterizeClipsOutsidePointsAndPaintsLaterOverEarlier) {
  Strokes s;
  s.strokes.push_back({1, 3.0, {{-50, 2}, {50, 2}}});  // crosses the whole image and beyond
  s.strokes.push_back({0, 1.0, {{4, 2}}});             // a dot over it
  s.strokes.push_back({2, 1.0, {{100, 100}}});         // wholly outside
  const LabelMap m = rasterize_strokes(s, 9, 5);
  EXPECT_EQ(m.at(0, 2), 1);
  EXPECT_EQ(m.at(8, 2), 1);
  EXPECT_EQ(m.at(8, 1), 1);  // width 3 covers the rows beside
  EXPECT_EQ(m.at(8, 4), kNoStroke);
  EXPECT_EQ(m.at(4, 2), 0);
  for (int y = 0; y < 5; ++y)
    for (int x = 0; x < 9; ++x) EXPECT_NE(m.at(x, y), 2);
}

TEST(Strokes, WriteThenReadRoundTrips) {
  testing::TempDir dir;
  Strokes s;
  s.head_center = Vec2(10.5, 20.25);
  s.strokes.push_back({4, 2.5, {{1, 2}, {3, 4}}});
  write_strokes(dir / "s.json", s);
  const Strokes back = read_strokes(dir / "s.json");
  ASSERT_EQ(back.strokes.size(), 1u);
  EXPECT_EQ(back.strokes[0].label, 4);
  EXPECT_DOUBLE_EQ(back.strokes[0].width, 2.5);
  EXPECT_TRUE(back.head_center->isApprox(*s.head_center));
  EXPECT_THROW(read_strokes(dir / "missing.json"), Error);
}

}  // namespace
}  // namespace hair25d
