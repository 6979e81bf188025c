// The trace of case-1 edge pairs (Options::trace_joins) and the census of
// lost links built on it (join_census.h, eval_joins --census): tracing
// changes no output, chosen pairs are joined, pairs kept apart are ordered,
// and the lost links account for every missed true pair.
#include <gtest/gtest.h>

#include <map>
#include <set>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/generator/generator.h"
#include "join_census.h"

namespace hair25d::completion {
namespace {

Options plain() {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  return o;
}

TEST(JoinCensus, TracingChangesNothingAndLostLinksCoverEveryMissedPair) {
  int links = 0;
  for (std::uint64_t seed : {3u, 6u}) {
    const AnnotatedCase c = test::generated_case(
        seed, seed == 3 ? generator::Shading::kFlat : generator::Shading::kTwoTone, 560, 420, 14);
    const Input in = test::input_from_case(c);
    const Result untraced = complete_strands(in, plain());
    Options o = plain();
    o.trace_joins = true;
    const Result r = complete_strands(in, o);
    ASSERT_EQ(r.strands.size(), untraced.strands.size()) << "seed " << seed;
    for (std::size_t s = 0; s < r.strands.size(); ++s)
      EXPECT_EQ(r.strands[s].regions, untraced.strands[s].regions) << "seed " << seed;
    ASSERT_FALSE(r.join_trace.empty());
    EXPECT_TRUE(untraced.join_trace.empty());

    std::map<int, int> strand_of;
    for (std::size_t s = 0; s < r.strands.size(); ++s)
      for (int id : r.strands[s].regions) strand_of[id] = static_cast<int>(s);
    std::set<std::pair<int, int>> ordered;
    for (const RegionRelation& rel : in.relations)
      if (rel.relation != Relation::kEqual) ordered.insert(std::minmax(rel.a, rel.b));
    int chosen = 0;
    for (const JoinTrace& t : r.join_trace) {
      EXPECT_NE(t.region_a, t.region_b);
      if (t.stage == JoinStage::kChosen) {
        ++chosen;
        EXPECT_EQ(strand_of.at(t.region_a), strand_of.at(t.region_b))
            << "seed " << seed << ": " << t.region_a << "-" << t.region_b;
      }
      if (t.stage == JoinStage::kKeptApart) {
        EXPECT_TRUE(ordered.count(std::minmax(t.region_a, t.region_b)))
            << "seed " << seed << ": " << t.region_a << "-" << t.region_b;
      }
      // Only pairs that reached the cover test carry its holes, within it.
      if (t.cover >= 0) {
        EXPECT_NEAR(t.cover + t.hole_background + t.hole_below + t.hole_sibling + t.hole_other, 1.0,
                    1e-9);
      }
    }
    EXPECT_GT(chosen, 0);

    const test::PairScore score = test::score_pairs(c, r);
    int lost_pairs = 0;
    for (const test::LostLink& l : test::lost_links(c, r)) {
      lost_pairs += l.pairs;
      ++links;
      EXPECT_GT(l.pairs, 0);
      if (l.best) {
        EXPECT_NE(l.best->stage, JoinStage::kChosen);
      }
      EXPECT_FALSE(test::census_class(l).empty());
    }
    EXPECT_EQ(lost_pairs, score.truth - score.correct) << "seed " << seed;
  }
  EXPECT_GT(links, 0);  // the drawings lose some links, or the test says nothing
}

// The census's Kruskal on a hand-made result: a strand of three regions
// left in three groups needs two links, the pair that got furthest first.
TEST(JoinCensus, LinksTakeTheFurthestStageFirstAndCountPairs) {
  AnnotatedCase c;
  for (int id : {1, 2, 3}) c.region_list.push_back({id, 7});
  c.region_list.push_back({4, 8});
  Result r;
  r.strands.resize(3);
  r.strands[0].regions = {1, 4};  // a wrong join: 1 with 4
  r.strands[1].regions = {2};
  r.strands[2].regions = {3};
  r.edge_regions = {1, 2, 4};
  JoinTrace angle{1, 2, JoinStage::kAngle};
  JoinTrace band{1, 2, JoinStage::kBandRefused};
  band.hand_cost = 3.0;
  JoinTrace taken{2, 1, JoinStage::kAtomTaken};
  taken.rival_a = 1, taken.rival_b = 4;
  r.join_trace = {angle, band, taken};
  const std::vector<test::LostLink> links = test::lost_links(c, r);
  ASSERT_EQ(links.size(), 2u);  // strand 7 in three parts; strand 8 is one region
  EXPECT_EQ(links[0].strand, 7);
  ASSERT_TRUE(links[0].best);
  EXPECT_EQ(links[0].best->stage, JoinStage::kAtomTaken);
  EXPECT_EQ(test::census_class(links[0]), "atom taken: wrong rival");
  EXPECT_EQ(links[0].pairs, 1);
  // Region 3 has no traced pair and no edge: one link from the first group.
  EXPECT_FALSE(links[1].best);
  EXPECT_EQ(test::census_class(links[1]), "a side without edges");
  EXPECT_EQ(links[1].pairs, 2);
}

}  // namespace
}  // namespace hair25d::completion
