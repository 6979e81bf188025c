#include "hair25d/core/annotation.h"

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>

#include "common/temp_dir.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;
const fs::path kCases = fs::path(HAIR25D_TEST_DATA_DIR) / "annotated";

TEST(Annotation, ReadsTheBundledCases) {
  const auto cases = find_annotated_cases(kCases);
  ASSERT_EQ(cases.size(), 6u);
  const AnnotatedCase c = read_annotated_case(cases[0]);
  EXPECT_EQ(c.name, "case0");
  EXPECT_EQ(c.image.width(), 1024);
  EXPECT_EQ(c.image.height(), 1289);
  EXPECT_EQ(c.regions.width(), 1024);
  EXPECT_EQ(c.region_list.size(), 27u);
  EXPECT_EQ(c.pairs.size(), 56u);
  ASSERT_TRUE(c.strokes.has_value());
  EXPECT_FALSE(c.strand_masks.empty());
  // Every listed region id appears in regions.png and nothing else does.
  std::vector<int> listed;
  for (const auto& r : c.region_list) listed.push_back(r.id);
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(c.regions.labels(), listed);
}

TEST(Annotation, RelationsParseAndReverse) {
  EXPECT_EQ(parse_relation("above"), Relation::kAbove);
  EXPECT_EQ(parse_relation("sideways"), std::nullopt);
  EXPECT_EQ(reversed(Relation::kAbove), Relation::kBelow);
  EXPECT_EQ(reversed(Relation::kEqual), Relation::kEqual);
  EXPECT_STREQ(to_string(Relation::kBelow), "below");
}

class BrokenCase : public ::testing::Test {
 protected:
  void SetUp() override {
    folder_ = dir_ / "c";
    AnnotatedCase c;
    c.image = Image(6, 4, {200, 200, 200, 255});
    c.regions = LabelMap(6, 4);
    for (int y = 0; y < 4; ++y) {
      for (int x = 0; x < 6; ++x) c.regions.at(x, y) = x < 3 ? 1 : 2;
    }
    c.region_list = {{1, 1, "a"}, {2, 2, "b"}};
    c.pairs = {{1, 2, Relation::kBelow}};
    c.head_center = Vec2(3, 1);
    write_annotated_case(folder_, c);
    doc_ = nlohmann::json::parse(read_text_file(folder_ / "layering.json"));
  }
  std::string error_after(const nlohmann::json& doc) {
    write_text_atomically(folder_ / "layering.json", doc.dump());
    try {
      read_annotated_case(folder_);
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  testing::TempDir dir_;
  fs::path folder_;
  nlohmann::json doc_;
};

TEST_F(BrokenCase, WrittenCaseReadsBack) {
  const AnnotatedCase c = read_annotated_case(folder_);
  EXPECT_EQ(c.regions.at(4, 2), 2);
  ASSERT_EQ(c.pairs.size(), 1u);
  EXPECT_EQ(c.pairs[0].relation, Relation::kBelow);
  EXPECT_TRUE(c.head_center->isApprox(Vec2(3, 1)));
}

TEST_F(BrokenCase, UnknownRegionInPairIsNamed) {
  auto doc = doc_;
  doc["pairs"][0]["b"] = 9;
  const std::string e = error_after(doc);
  EXPECT_NE(e.find("pairs[0].b"), std::string::npos) << e;
  EXPECT_NE(e.find("layering.json"), std::string::npos) << e;
}

TEST_F(BrokenCase, BadRelationDuplicateIdAndEscapingPathAreErrors) {
  auto bad_rel = doc_;
  bad_rel["pairs"][0]["relation"] = "beside";
  EXPECT_NE(error_after(bad_rel).find("pairs[0].relation"), std::string::npos);
  auto dup = doc_;
  dup["regions"][1]["id"] = 1;
  EXPECT_NE(error_after(dup).find("regions[1].id"), std::string::npos);
  auto escape = doc_;
  escape["image"] = "../../etc/passwd";
  EXPECT_NE(error_after(escape).find("inside the case folder"), std::string::npos);
  auto self = doc_;
  self["pairs"][0]["b"] = 1;
  EXPECT_NE(error_after(self).find("two different regions"), std::string::npos);
}

TEST_F(BrokenCase, RepeatedPairsAreRefused) {
  // The same pair again, and the same relation written the other way round:
  // either would count twice in the accuracy.
  for (const nlohmann::json& repeat : {nlohmann::json{{"a", 1}, {"b", 2}, {"relation", "below"}},
                                       nlohmann::json{{"a", 2}, {"b", 1}, {"relation", "above"}}}) {
    auto doc = doc_;
    doc["pairs"].push_back(repeat);
    const std::string e = error_after(doc);
    EXPECT_NE(e.find("layering.json"), std::string::npos) << e;
    EXPECT_NE(e.find("'pairs[1]'"), std::string::npos) << e;
    EXPECT_NE(e.find("listed once; pairs[0] lists it already"), std::string::npos) << e;
  }
}

TEST_F(BrokenCase, ContradictingPairsAreRefused) {
  // pairs[0] says 1 below 2; these say 2 below 1 and 1 equal to 2.
  for (const nlohmann::json& other : {nlohmann::json{{"a", 2}, {"b", 1}, {"relation", "below"}},
                                      nlohmann::json{{"a", 1}, {"b", 2}, {"relation", "equal"}}}) {
    auto doc = doc_;
    doc["pairs"].push_back(other);
    const std::string e = error_after(doc);
    EXPECT_NE(e.find("layering.json"), std::string::npos) << e;
    EXPECT_NE(e.find("'pairs[1]'"), std::string::npos) << e;
    EXPECT_NE(e.find("agrees with pairs[0]"), std::string::npos) << e;
  }
}

TEST_F(BrokenCase, PairNamingARegionNotDrawnIsRefused) {
  // Region 3 is listed but no pixel of regions.png carries it.
  auto doc = doc_;
  doc["regions"].push_back({{"id", 3}, {"strand", 3}, {"name", "ghost"}});
  EXPECT_EQ(error_after(doc), "");  // listing it alone is fine
  doc["pairs"].push_back({{"a", 3}, {"b", 2}, {"relation", "above"}});
  const std::string e = error_after(doc);
  EXPECT_NE(e.find("layering.json"), std::string::npos) << e;
  EXPECT_NE(e.find("'pairs[1].a'"), std::string::npos) << e;
  EXPECT_NE(e.find("drawn in regions.png"), std::string::npos) << e;
}

TEST_F(BrokenCase, RegionsOfTheWrongSizeAreRefused) {
  save_label_map(folder_ / "regions.png", LabelMap(5, 4, 1));
  try {
    read_annotated_case(folder_);
    FAIL();
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("5x4"), std::string::npos) << e.what();
  }
}

TEST(Annotation, NotAFolderOfCases) {
  EXPECT_THROW(find_annotated_cases("/nonexistent/cases"), Error);
  testing::TempDir dir;
  EXPECT_TRUE(find_annotated_cases(dir.path()).empty());
  EXPECT_THROW(read_annotated_case(dir.path()), Error);
}

}  // namespace
}  // namespace hair25d
