// Options::tone_path_landing_share (session 38): on screentone a tone path
// join of two front pieces needs landings (pixels of one piece reached by
// the paths under the common occluders) in proportion to the square root of
// the smaller piece's pixels. Two strands meeting beside an occluder touch
// on a few pixels; a strand passing under it lands across its width.
#include <gtest/gtest.h>

#include <cmath>
#include <map>
#include <string>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/core/error.h"
#include "invalid_options.h"
#include "joins_only.h"
#include "same_joins.h"
#include "strand_of.h"

namespace hair25d::completion {
namespace {

Result run(const AnnotatedCase& c, double share) {
  Options o = test::joins_only();
  o.tone_path_landing_share = share;
  o.join_scorer.record = true;
  return complete_strands(test::input_from_case(c), o);
}

// Dev screentone 2013: strand 12 on the face and strand 21 below it were
// joined by tone paths under strand 7 landing on 11 pixels (0.22 per
// square root of 12's 2 433 pixels). Dev screentone 3000: pieces 9 and 19
// of one strand, 9 landings on 848 pixels (0.31), stay one at 0.3 and go
// apart at 0.4, so the measure is the one the limit reads.
TEST(ToneLanding, FewLandingsAreRefused) {
  const AnnotatedCase c2013 = test::generated_case(2013, generator::Shading::kScreentone);
  const std::map<int, int> off = test::strand_of(run(c2013, 0));
  EXPECT_EQ(off.at(12), off.at(21));
  const std::map<int, int> on = test::strand_of(run(c2013, 0.3));
  EXPECT_NE(on.at(12), on.at(21));
  const AnnotatedCase c3000 = test::generated_case(3000, generator::Shading::kScreentone);
  const std::map<int, int> kept = test::strand_of(run(c3000, 0.3));
  EXPECT_EQ(kept.at(9), kept.at(19)) << "a strand passing under keeps its tone path join";
  const std::map<int, int> strict = test::strand_of(run(c3000, 0.4));
  EXPECT_NE(strict.at(9), strict.at(19));
}

// Off screentone the tone path joins do not run: the option does nothing.
TEST(ToneLanding, NotOffScreentone) {
  for (generator::Shading shading : {generator::Shading::kFlat, generator::Shading::kTwoTone}) {
    const AnnotatedCase c = test::generated_case(2013, shading);
    test::expect_same_joins(run(c, 0), run(c, 0.65));
  }
}

TEST(ToneLanding, BadShareIsRefused) {
  Options o;
  o.tone_path_landing_share = -0.1;
  test::expect_invalid(o, "tone_path_landing_share = -0.1");
  o.tone_path_landing_share = std::nan("");
  test::expect_invalid(o, "tone_path_landing_share");
  const AnnotatedCase c = test::generated_case(2013, generator::Shading::kScreentone);
  EXPECT_THROW(complete_strands(test::input_from_case(c), o), Error);
}

}  // namespace
}  // namespace hair25d::completion
