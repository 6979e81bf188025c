#include "hair25d/core/model_io.h"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "common/temp_dir.h"
#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;
using nlohmann::json;

HairModel small_model() {
  HairModel m;
  m.width = 7;
  m.height = 5;
  m.image = Image(7, 5, {10, 20, 30, 255});
  m.background = Image(7, 5, {1, 2, 3, 255});
  m.head_center = Vec2(3.5, 1.25);
  Strand s;
  s.id = 4;
  s.name = "left bang";
  s.regions = {2, 9};
  s.depth = 1;
  s.outline = {{1, 1}, {5, 1}, {5, 4}, {1, 4}};
  s.texture = Image(3, 2, {100, 150, 200, 128});
  s.texture_origin = {2, 3};
  s.mesh.V.resize(4, 2);
  s.mesh.V << 1, 1, 5, 1, 5, 4, 1, 4;
  s.mesh.F.resize(2, 3);
  s.mesh.F << 0, 1, 2, 0, 2, 3;
  s.mesh.on_curve.resize(2, 3);
  s.mesh.on_curve << true, false, false, false, true, true;
  s.skeleton.nodes = {{3, 1}, {3, 2.5}, {3, 4}};
  s.skeleton.parent = {-1, 0, 1};
  s.skeleton.tips = {2};
  s.physics.stiffness = 2.5;
  m.strands.push_back(s);
  Strand t;
  t.id = 5;
  t.regions = {3};
  m.strands.push_back(t);
  m.relations.push_back({2, 3, Relation::kAbove, 0.75, true, false});
  m.relations.push_back({9, 3, Relation::kEqual, 0.0, false, true});
  m.relations.back().equal_evidence = EqualEvidence{-1.25, true, 0.8};
  return m;
}

TEST(ModelIo, RoundTripKeepsEverything) {
  testing::TempDir dir;
  const HairModel m = small_model();
  write_model(dir / "model", m);
  const HairModel back = read_model(dir / "model");
  EXPECT_EQ(back.width, 7);
  EXPECT_EQ(back.image, m.image);
  EXPECT_EQ(back.background, m.background);
  EXPECT_TRUE(back.head_center->isApprox(*m.head_center));
  ASSERT_EQ(back.strands.size(), 2u);
  const Strand& s = back.strands[0];
  EXPECT_EQ(s.id, 4);
  EXPECT_EQ(s.name, "left bang");
  EXPECT_EQ(s.regions, (std::vector<int>{2, 9}));
  EXPECT_EQ(s.depth, 1);
  EXPECT_EQ(s.outline.size(), 4u);
  EXPECT_EQ(s.texture, m.strands[0].texture);
  EXPECT_EQ(s.texture_origin, m.strands[0].texture_origin);
  EXPECT_EQ(s.mesh.V, m.strands[0].mesh.V);
  EXPECT_EQ(s.mesh.F, m.strands[0].mesh.F);
  EXPECT_EQ(s.mesh.on_curve, m.strands[0].mesh.on_curve);
  EXPECT_EQ(s.skeleton.parent, m.strands[0].skeleton.parent);
  EXPECT_EQ(s.skeleton.tips, m.strands[0].skeleton.tips);
  EXPECT_DOUBLE_EQ(s.physics.stiffness, 2.5);
  EXPECT_TRUE(back.strands[1].texture.empty());
  ASSERT_EQ(back.relations.size(), 2u);
  EXPECT_EQ(back.relations[0].relation, Relation::kAbove);
  EXPECT_DOUBLE_EQ(back.relations[0].score, 0.75);
  EXPECT_TRUE(back.relations[0].user_fixed);
  EXPECT_TRUE(back.relations[1].overridden);
  EXPECT_FALSE(back.relations[0].equal_evidence);
  ASSERT_TRUE(back.relations[1].equal_evidence);
  EXPECT_DOUBLE_EQ(back.relations[1].equal_evidence->log_odds, -1.25);
  EXPECT_TRUE(back.relations[1].equal_evidence->open);
  EXPECT_DOUBLE_EQ(back.relations[1].equal_evidence->open_fraction, 0.8);
}

class EditedModel : public ::testing::Test {
 protected:
  void SetUp() override {
    write_model(dir_ / "m", small_model());
    doc_ = json::parse(read_text_file(dir_ / "m" / "model.json"));
  }
  std::string error_after(const json& doc) {
    write_text_atomically(dir_ / "m" / "model.json", doc.dump());
    try {
      read_model(dir_ / "m");
    } catch (const Error& e) {
      return e.what();
    }
    return "";
  }
  testing::TempDir dir_;
  json doc_;
};

TEST_F(EditedModel, PathsLeavingTheFolderAreRefused) {
  for (const char* bad : {"../image.png", "/etc/passwd", "strands/../../x.png"}) {
    json doc = doc_;
    doc["strands"][0]["texture"] = bad;
    const std::string e = error_after(doc);
    EXPECT_NE(e.find("strands[0].texture"), std::string::npos) << bad << ": " << e;
    EXPECT_NE(e.find("inside the model folder"), std::string::npos) << e;
  }
  json doc = doc_;
  doc["background"] = "../../background.png";
  EXPECT_NE(error_after(doc).find("'background'"), std::string::npos);
}

TEST_F(EditedModel, WrongTypesAndUnknownIdsAreNamed) {
  json doc = doc_;
  doc["strands"][0]["depth"] = "deep";
  EXPECT_NE(error_after(doc).find("strands[0].depth"), std::string::npos);
  doc = doc_;
  doc["relations"][0]["a"] = 77;
  EXPECT_NE(error_after(doc).find("relations[0].a"), std::string::npos);
  doc = doc_;
  doc["relations"][1]["equal_evidence"]["log_odds"] = "sure";
  EXPECT_NE(error_after(doc).find("relations[1].equal_evidence.log_odds"), std::string::npos);
  doc = doc_;
  doc["strands"][0]["mesh"]["triangles"][1][2] = 40;
  EXPECT_NE(error_after(doc).find("strands[0].mesh.triangles[1][2]"), std::string::npos);
  doc = doc_;
  doc["strands"][0]["skeleton"]["parent"][2] = 9;
  EXPECT_NE(error_after(doc).find("skeleton.parent[2]"), std::string::npos);
  doc = doc_;
  doc["strands"][1]["id"] = 4;
  EXPECT_NE(error_after(doc).find("strands[1].id"), std::string::npos);
  doc = doc_;
  doc["version"] = kModelFormatVersion + 1;
  EXPECT_NE(error_after(doc).find("'version'"), std::string::npos);
  doc = doc_;
  doc["format"] = "something-else";
  EXPECT_NE(error_after(doc).find("hair25d-model"), std::string::npos);
  doc = doc_;
  doc["width"] = 8;  // the images are 7 wide
  EXPECT_NE(error_after(doc).find("differs"), std::string::npos);
}

// The skeleton is a tree stored root first and textures lie near the
// drawing: a cycle or an absurd origin is named, not taken.
TEST_F(EditedModel, CyclicSkeletonsAndFarTexturesAreRefused) {
  json doc = doc_;
  doc["strands"][0]["skeleton"]["parent"][0] = 1;  // 0 -> 1 -> 0: a cycle
  std::string e = error_after(doc);
  EXPECT_NE(e.find("model.json"), std::string::npos) << e;
  EXPECT_NE(e.find("strands[0].skeleton.parent[0]"), std::string::npos) << e;
  EXPECT_NE(e.find("node 0 is the root"), std::string::npos) << e;
  doc = doc_;
  doc["strands"][0]["skeleton"]["parent"][1] = 2;  // a child before its parent
  e = error_after(doc);
  EXPECT_NE(e.find("strands[0].skeleton.parent[1]"), std::string::npos) << e;
  EXPECT_NE(e.find("parent[i] < i"), std::string::npos) << e;
  doc = doc_;
  doc["strands"][0]["skeleton"]["parent"][2] = -1;  // a second root
  EXPECT_NE(error_after(doc).find("strands[0].skeleton.parent[2]"), std::string::npos);
  doc = doc_;
  doc["strands"][0]["skeleton"]["tips"][0] = 3;
  EXPECT_NE(error_after(doc).find("strands[0].skeleton.tips[0]"), std::string::npos);
  for (const json& origin : {json::array({1e12, -5}), json::array({2, -6}), json::array({8, 0})}) {
    doc = doc_;
    doc["strands"][0]["texture_origin"] = origin;
    e = error_after(doc);
    EXPECT_NE(e.find("strands[0].texture_origin"), std::string::npos) << origin << ": " << e;
    EXPECT_NE(e.find("x in -7..7, y in -5..5"), std::string::npos) << e;
  }
  doc = doc_;
  doc["strands"][0]["texture_origin"] = json::array({-7, 5});  // at the bound: taken
  EXPECT_EQ(error_after(doc), "");
}

// A forged model.json must not fill memory: size, strand count, texture
// size and all textures together are bounded.
TEST_F(EditedModel, ModelsBeyondTheLimitsAreRefused) {
  json doc = doc_;
  doc.erase("image");
  doc.erase("background");
  doc["width"] = 16000;
  doc["height"] = 16000;
  EXPECT_NE(error_after(doc).find("width x height = 256000000 pixels; at most 64000000"),
            std::string::npos)
      << error_after(doc);
  doc = doc_;
  doc["strands"][0]["texture_origin"] = {0, 0};
  write_model(dir_ / "big", [] {
    HairModel big = small_model();
    big.strands[0].texture = Image(8, 2);  // wider than the 7-pixel model
    big.strands[0].texture_origin = {0, 0};
    return big;
  }());
  std::string e;
  try {
    read_model(dir_ / "big");
  } catch (const Error& error) {
    e = error.what();
  }
  EXPECT_NE(e.find("strands[0].texture': texture 8x2 is larger than the model's 7x5"),
            std::string::npos)
      << e;
  // 30 strands sharing one 3x2 texture: 180 pixels, over 4 x 35 allowed.
  doc = doc_;
  for (int i = 0; i < 30; ++i) {
    json copy = doc_["strands"][0];
    copy["id"] = 100 + i;
    doc["strands"].push_back(copy);
  }
  write_text_atomically(dir_ / "m" / "model.json", doc.dump());
  ImageLimits small;
  small.max_pixels = 35;
  try {
    read_model(dir_ / "m", small);
    ADD_FAILURE() << "30 textures beyond the budget were read";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("textures hold more than 140 pixels together"),
              std::string::npos)
        << error.what();
  }
  small = {};
  small.max_regions = 31;  // 32 strands now
  try {
    read_model(dir_ / "m", small);
    ADD_FAILURE() << "32 strands read with max_regions 31";
  } catch (const Error& error) {
    EXPECT_NE(std::string(error.what()).find("'strands': expected at most 31 strands"),
              std::string::npos)
        << error.what();
  }
}

TEST(ModelIo, RewritingReplacesTheFolderWhole) {
  testing::TempDir dir;
  HairModel m = small_model();
  write_model(dir / "m", m);
  m.strands.pop_back();
  m.relations.clear();
  m.strands[0].texture = Image();
  write_model(dir / "m", m);
  EXPECT_FALSE(fs::exists(dir / "m" / "strands" / "4.png"));  // stale files do not survive
  EXPECT_EQ(read_model(dir / "m").strands.size(), 1u);
  // Nothing but the model folder is left behind.
  int entries = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir.path())) ++entries;
  EXPECT_EQ(entries, 1);
}

TEST(ModelIo, FailedWriteKeepsTheOldModel) {
  testing::TempDir dir;
  write_model(dir / "m", small_model());
  HairModel broken = small_model();
  broken.width = 0;
  EXPECT_THROW(write_model(dir / "m", broken), Error);
  // A failure half way (an empty texture cannot be saved) must not either.
  HairModel half = small_model();
  half.strands[1].texture = Image(0, 0);
  half.strands[1].mesh.F.resize(1, 3);
  half.strands[1].mesh.F << 0, 0, 0;
  EXPECT_THROW(write_model(dir / "m", half), Error);
  EXPECT_EQ(read_model(dir / "m").strands.size(), 2u);
  EXPECT_THROW(read_model(dir / "missing"), Error);
}

}  // namespace
}  // namespace hair25d
