// The layering's relations revised with completion's strands
// (ui/pipeline joint_layering.h): a weak relation between two strands that
// disagrees with their summed evidence is turned, unless it is firm, the sum
// is small, or the rest of the order contradicts it.
#include <gtest/gtest.h>

#include <map>
#include <vector>

#include "hair25d/pipeline/joint_layering.h"

namespace hair25d::pipeline {
namespace {

const RegionRelation& find(const std::vector<RegionRelation>& rs, int a, int b) {
  for (const RegionRelation& r : rs)
    if (r.a == a && r.b == b) return r;
  ADD_FAILURE() << "no relation " << a << "-" << b;
  return rs.front();
}

// Pieces 1 and 2 of one strand; region 3 of another lies above 1 (score
// −3, firm) and, by a weak reading, below 2 (score 0.5).
std::vector<RegionRelation> crossing(double firm, double weak) {
  return {{1, 3, Relation::kBelow, firm, false, false},
          {2, 3, Relation::kAbove, weak, false, false}};
}

TEST(JointLayering, AWeakRelationToAPieceTurnsWithTheStrand) {
  std::vector<RegionRelation> rs = crossing(-3.0, 0.5);
  std::map<int, int> depth;
  const JointRevision rev = revise_with_strands({1, 2, 3}, {{1, 2}}, {}, &rs, &depth);
  EXPECT_EQ(rev.flipped, 1);
  EXPECT_EQ(rev.undone, 0);
  const RegionRelation& r = find(rs, 2, 3);
  EXPECT_EQ(r.relation, Relation::kBelow);
  EXPECT_TRUE(r.overridden);
  EXPECT_DOUBLE_EQ(r.score, 0.5);  // keeps the layering's reading
  EXPECT_EQ(find(rs, 1, 3).relation, Relation::kBelow);
  EXPECT_GT(depth.at(3), depth.at(1));
  EXPECT_GT(depth.at(3), depth.at(2));
}

TEST(JointLayering, FirmRelationsSmallSumsAndTheUsersStay) {
  // Firm: |score| 2.5 ≥ weak_score.
  std::vector<RegionRelation> firm = crossing(-6.0, 2.5);
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1, 2}}, {}, &firm).flipped, 0);
  EXPECT_EQ(find(firm, 2, 3).relation, Relation::kAbove);
  // The strands' summed evidence, −1.5 + 0.5, is under agree_min_sum.
  std::vector<RegionRelation> small = crossing(-1.5, 0.5);
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1, 2}}, {}, &small).flipped, 0);
  EXPECT_EQ(find(small, 2, 3).relation, Relation::kAbove);
  // The user's relation is never turned.
  std::vector<RegionRelation> user = crossing(-3.0, 0.5);
  user[1].user_fixed = true;
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1, 2}}, {}, &user).flipped, 0);
  EXPECT_EQ(find(user, 2, 3).relation, Relation::kAbove);
  // Not one strand: nothing to agree with.
  std::vector<RegionRelation> apart = crossing(-3.0, 0.5);
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1}, {2}}, {}, &apart).flipped, 0);
  EXPECT_EQ(find(apart, 2, 3).relation, Relation::kAbove);
}

TEST(JointLayering, TheUsersRelationToAPieceDecidesForTheStrand) {
  // The user put 3 above piece 1 (no score); 2 above 3 is weak.
  std::vector<RegionRelation> rs = crossing(0.0, 0.5);
  rs[0].user_fixed = true;
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1, 2}}, {}, &rs).flipped, 1);
  EXPECT_EQ(find(rs, 2, 3).relation, Relation::kBelow);
  EXPECT_TRUE(find(rs, 1, 3).user_fixed);
}

TEST(JointLayering, ARevisionTheOrderContradictsIsUndone) {
  // 2 above 4 above 3, both firm: 2 lies above 3 whatever the strand says.
  std::vector<RegionRelation> rs = crossing(-3.0, 0.5);
  rs.push_back({2, 4, Relation::kAbove, 3.0, false, false});
  rs.push_back({3, 4, Relation::kBelow, -3.0, false, false});
  std::map<int, int> depth;
  const JointRevision rev = revise_with_strands({1, 2, 3, 4}, {{1, 2}}, {}, &rs, &depth);
  EXPECT_EQ(rev.flipped, 0);
  EXPECT_EQ(rev.undone, 1);
  const RegionRelation& r = find(rs, 2, 3);
  EXPECT_EQ(r.relation, Relation::kAbove);
  EXPECT_FALSE(r.overridden);
  EXPECT_GT(depth.at(2), depth.at(4));
  EXPECT_GT(depth.at(4), depth.at(3));
}

TEST(JointLayering, WeakOrdersWithinAStrandBecomeEqualWhenAsked) {
  std::vector<RegionRelation> rs = {{1, 2, Relation::kAbove, 0.8, false, false},
                                    {2, 3, Relation::kBelow, -1.0, false, false}};
  std::vector<RegionRelation> off = rs;
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1, 2}}, {}, &off).to_equal, 0);
  EXPECT_EQ(find(off, 1, 2).relation, Relation::kAbove);
  JointOptions same;
  same.same_depth = true;
  std::map<int, int> depth;
  EXPECT_EQ(revise_with_strands({1, 2, 3}, {{1, 2}}, same, &rs, &depth).to_equal, 1);
  EXPECT_EQ(find(rs, 1, 2).relation, Relation::kEqual);
  EXPECT_EQ(depth.at(1), depth.at(2));
}

}  // namespace
}  // namespace hair25d::pipeline
