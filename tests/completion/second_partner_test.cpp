// Options::second_partner_p (session 33): a candidate the scorer is sure of
// joins though one of its cuts already joins another piece.
#include <gtest/gtest.h>

#include <map>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/core/error.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "strand_of.h"
#include "trace_of.h"

namespace hair25d::completion {
namespace {

Result run(const AnnotatedCase& c, double second_partner_p) {
  Options o = test::joins_only();
  o.trace_joins = true;
  o.second_partner_p = second_partner_p;
  return complete_strands(test::input_from_case(c), o);
}

// Dev screentone 2037: piece 27's cut faces 23 and 25, all three one strand
// in the annotation; 23-27 is cheaper and takes 27's cut, and 25-27 (the
// scorer's p 1.0) is refused by the one-to-one matching unless a cut may
// take a second partner.
TEST(SecondPartner, ACutJoinsTwoPiecesOfOneStrand) {
  const AnnotatedCase c = test::generated_case(2037, generator::Shading::kScreentone);
  const Result off = run(c, 0.0);
  const JoinTrace* refused = test::trace_of(off, 25, 27, JoinStage::kAtomTaken);
  ASSERT_NE(refused, nullptr);
  EXPECT_GE(refused->probability, 0.95);
  EXPECT_EQ(test::trace_of(off, 25, 27, JoinStage::kChosen), nullptr);
  std::map<int, int> s = test::strand_of(off);
  EXPECT_EQ(s.at(23), s.at(27));
  EXPECT_NE(s.at(25), s.at(27));

  const Result on = run(c, 0.95);
  EXPECT_NE(test::trace_of(on, 25, 27, JoinStage::kChosen), nullptr);
  s = test::strand_of(on);
  EXPECT_EQ(s.at(23), s.at(27));
  EXPECT_EQ(s.at(25), s.at(27));
}

// A bar above the scorer's p keeps the one-to-one matching.
TEST(SecondPartner, NotUnderTheBar) {
  const AnnotatedCase c = test::generated_case(2037, generator::Shading::kScreentone);
  EXPECT_EQ(test::strand_of(run(c, 1.0)), test::strand_of(run(c, 0.0)));
}

TEST(SecondPartner, BadBarIsRefused) {
  const AnnotatedCase c = test::generated_case(2037, generator::Shading::kScreentone);
  Options o;
  o.second_partner_p = 0.3;
  test::expect_invalid(o, "second_partner_p = 0.3");
  EXPECT_THROW(complete_strands(test::input_from_case(c), o), Error);
  o.second_partner_p = 1.5;
  test::expect_invalid(o, "second_partner_p = 1.5");
  o.second_partner_p = -0.0;  // never: valid
  std::string why;
  EXPECT_TRUE(o.is_valid(&why)) << why;
}

}  // namespace
}  // namespace hair25d::completion
