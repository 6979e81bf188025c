// Options::cover_fringe (session 31): the cover test reads the outlines'
// light fringe, which lies in no region of the map, as the nearest
// region's, on screentone drawings, under the user's orders or (session 32)
// the layering's at a low hand cost.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "annotated_eval.h"
#include "cover_labels.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/core/error.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "strand_of.h"

namespace hair25d::completion {
namespace {

// Regions 1 (x < 10) and 2 (x >= 15) with a 5-px band of label 0 between
// them, and paper (label 0) below y 20.
LabelMap two_regions() {
  LabelMap m(30, 30, 0);
  for (int y = 0; y < 20; ++y)
    for (int x = 0; x < 30; ++x) m.at(x, y) = x < 10 ? 1 : x >= 15 ? 2 : 0;
  return m;
}

TEST(CoverFringe, FringeGoesToTheNearestRegionWithinReach) {
  const LabelMap m = two_regions();
  const LabelMap f = detail::fringe_labels(m, 2);
  for (int y = 0; y < 18; ++y) {
    EXPECT_EQ(f.at(10, y), 1);
    EXPECT_EQ(f.at(11, y), 1);
    EXPECT_EQ(f.at(12, y), 0) << "3 px from both regions";
    EXPECT_EQ(f.at(13, y), 2);
    EXPECT_EQ(f.at(14, y), 2);
    EXPECT_EQ(f.at(5, y), 1);  // labelled pixels keep their label
    EXPECT_EQ(f.at(20, y), 2);
  }
  EXPECT_EQ(f.at(5, 21), 1);
  EXPECT_EQ(f.at(5, 22), 0) << "paper 3 px below region 1";
  EXPECT_EQ(f.at(5, 29), 0);
  // Reach 0 changes nothing.
  const LabelMap same = detail::fringe_labels(m, 0);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 30; ++x) EXPECT_EQ(same.at(x, y), m.at(x, y));
}

Result run(const AnnotatedCase& c, int fringe, bool users, double layering_cost = 0.0) {
  Options o = test::joins_only();
  o.cover_fringe = fringe;
  o.cover_fringe_layering_cost = layering_cost;
  Input in = test::input_from_case(c);
  // The same orders as the layering's (firm, not the user's).
  if (!users)
    for (RegionRelation& r : in.relations)
      r.user_fixed = false, r.score = r.score >= 0 ? 3.0 : -3.0;
  return complete_strands(in, o);
}

// Dev screentone 2006: piece 13 runs under strand 11 and shows again as the
// sliver 25 (one strand in the annotation); the straight patch between them
// lies on 11 and the white fringe of its outlines, which the map leaves at
// label 0 (cover 0.81 without the fringe).
TEST(CoverFringe, ScreentoneJoinUnderTheUsersOrders) {
  const AnnotatedCase c = test::generated_case(2006, generator::Shading::kScreentone);
  {
    const std::map<int, int> s = test::strand_of(run(c, 0, true));
    EXPECT_NE(s.at(13), s.at(25)) << "refused by the cover without the fringe";
  }
  {
    const std::map<int, int> s = test::strand_of(run(c, 2, true));
    EXPECT_EQ(s.at(13), s.at(25));
  }
  // Not the user's orders and no cost for the layering's: the fringe is not
  // read, the strands are main's.
  EXPECT_EQ(test::strand_of(run(c, 2, false)), test::strand_of(run(c, 0, false)));
}

// Without the user's orders the fringe is read under the layering's at a
// low hand cost only: dev screentone 2006's 13-25 (one strand) is that
// cheap; dev screentone 2018's 17 and 25 (two strands) would be joined
// through the fringe at a higher cost, and stay apart under the cap.
TEST(CoverFringe, LayeringsOrdersAtALowCost) {
  {
    const AnnotatedCase c = test::generated_case(2006, generator::Shading::kScreentone);
    const std::map<int, int> s = test::strand_of(run(c, 2, false, 1.5));
    EXPECT_EQ(s.at(13), s.at(25));
  }
  const AnnotatedCase c = test::generated_case(2018, generator::Shading::kScreentone);
  const std::map<int, int> capped = test::strand_of(run(c, 2, false, 1.5));
  EXPECT_NE(capped.at(17), capped.at(25));
  const std::map<int, int> any = test::strand_of(run(c, 2, false, 99.0));
  EXPECT_EQ(any.at(17), any.at(25)) << "the cap, not the cover, keeps them apart";
}

// Flat drawings do not read the fringe.
TEST(CoverFringe, NotOnFlatDrawings) {
  const AnnotatedCase c = test::generated_case(2006, generator::Shading::kFlat);
  EXPECT_EQ(test::strand_of(run(c, 2, true)), test::strand_of(run(c, 0, true)));
}

TEST(CoverFringe, BadReachIsRefused) {
  const AnnotatedCase c = test::generated_case(2006, generator::Shading::kScreentone);
  Options o;
  o.cover_fringe = -1;
  test::expect_invalid(o, "cover_fringe = -1");
  EXPECT_THROW(complete_strands(test::input_from_case(c), o), Error);
  Options cost;
  cost.cover_fringe_layering_cost = -0.5;
  test::expect_invalid(cost, "cover_fringe_layering_cost = -0.5");
  cost.cover_fringe_layering_cost = std::nan("");
  test::expect_invalid(cost, "cover_fringe_layering_cost = nan");
}

}  // namespace
}  // namespace hair25d::completion
