#include "hair25d/pipeline/hair_check.h"

#include <gtest/gtest.h>

namespace hair25d::pipeline {
namespace {

TEST(HairCheck, StrandsInsideTheDrawingPassQuietly) {
  LabelMap m(60, 40);
  for (int y = 5; y < 35; ++y)
    for (int x = 0; x < 20; ++x) m.at(x, y) = 1;  // touches the left side only
  for (int y = 0; y < 40; ++y) m.at(30, y) = 2;   // top to bottom, thin
  EXPECT_TRUE(hair_region_warnings(m, "the strokes").empty());
}

TEST(HairCheck, ThePaperIsCalledOut) {
  LabelMap m(60, 40, 3);  // everything one region: the paper
  for (int y = 10; y < 20; ++y)
    for (int x = 10; x < 20; ++x) m.at(x, y) = 1;
  const std::vector<std::string> w = hair_region_warnings(m, "--hair-colour #d8d8dc");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_NE(w[0].find("region 3 covers 96%"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("all four"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("--hair-colour #d8d8dc"), std::string::npos) << w[0];
}

TEST(HairCheck, FourSidesOrMostOfTheDrawingEachSuffice) {
  // A thin frame round the drawing: small, but on all four sides.
  LabelMap frame(50, 30);
  for (int x = 0; x < 50; ++x) frame.at(x, 0) = frame.at(x, 29) = 4;
  for (int y = 0; y < 30; ++y) frame.at(0, y) = frame.at(49, y) = 4;
  ASSERT_EQ(hair_region_warnings(frame, "s").size(), 1u);
  // Three quarters of the drawing, three sides.
  LabelMap big(40, 40);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) big.at(x, y) = 7;
  const std::vector<std::string> w = hair_region_warnings(big, "s");
  ASSERT_EQ(w.size(), 1u);
  EXPECT_EQ(w[0].find("four"), std::string::npos) << w[0];
  EXPECT_NE(w[0].find("75%"), std::string::npos) << w[0];
}

}  // namespace
}  // namespace hair25d::pipeline
