// score_relations: counting judged pairs against predicted relations, and
// refusing a pair judged twice (it would count twice).
#include "hair25d/layering/evaluation.h"

#include <gtest/gtest.h>

#include "hair25d/core/error.h"

namespace hair25d::layering {
namespace {

AnnotatedCase two_pairs() {
  AnnotatedCase c;
  c.name = "tiny";
  c.regions = LabelMap(5, 3);
  for (int x = 0; x < 5; ++x)
    c.regions.at(x, 0) = 1, c.regions.at(x, 1) = 2, c.regions.at(x, 2) = 3;
  c.pairs = {{1, 2, Relation::kBelow}, {3, 2, Relation::kAbove}};
  return c;
}

TEST(ScoreRelations, CountsPairsJudgedEitherWayRound) {
  const AnnotatedCase c = two_pairs();
  // 2 above 1 (so 1 below 2: right); 2 above 3 (so 3 below 2: wrong).
  const std::vector<RegionRelation> predicted = {{2, 1, Relation::kAbove},
                                                 {2, 3, Relation::kAbove}};
  const CaseScore s = score_relations(c, predicted);
  EXPECT_EQ(s.pairs, 2);
  EXPECT_EQ(s.correct, 1);
  EXPECT_EQ(s.regions, 3);
  ASSERT_EQ(s.outcomes.size(), 2u);
  EXPECT_TRUE(s.outcomes[0].correct);
  EXPECT_EQ(s.outcomes[1].predicted, Relation::kBelow);
  EXPECT_EQ(score_relations(c, {}).correct, 0);  // unrelated pairs count as wrong
}

TEST(ScoreRelations, APairJudgedTwiceIsRefused) {
  const std::vector<RegionRelation> predicted = {{1, 2, Relation::kBelow}};
  for (const AnnotatedPair& again :
       {AnnotatedPair{1, 2, Relation::kBelow}, AnnotatedPair{2, 1, Relation::kAbove}}) {
    AnnotatedCase c = two_pairs();
    c.pairs.push_back(again);
    try {
      score_relations(c, predicted);
      ADD_FAILURE() << "a repeated pair was scored";
    } catch (const Error& e) {
      const std::string m = e.what();
      EXPECT_NE(m.find("tiny: pairs[2]"), std::string::npos) << m;
      EXPECT_NE(m.find("pairs[0] did"), std::string::npos) << m;
    }
  }
}

}  // namespace
}  // namespace hair25d::layering
