// Options::face_piece_mass_step (session 33): on screentone the back-hair
// passes (path, back paint, face and body joins) leave apart two pieces
// whose dots step more than the limit when one of them runs along the face
// for most of its outline (a strand lying on the face, not back hair).
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

Result run(const AnnotatedCase& c, double step) {
  Options o = test::joins_only();
  o.face_piece_mass_step = step;
  o.join_scorer.record = true;
  return complete_strands(test::input_from_case(c), o);
}

// Dev screentone 2009: strand 22 lies on the face (0.79 of its outline
// along it), its dots 3.1 % off the back hair's (RegionTones's one tone
// reaches 4 %); a back-piece path join made it back hair 1's. Dev
// screentone 2003: sliver 7 (0.99 along the face, 3.9 % and 3.0 % off the
// back pieces 1 and 24) went to the back hair by a path join, then (the
// path joins refusing it) by the back-paint and body joins.
TEST(FacePiece, StrandOnTheFaceIsNoBackHair) {
  const AnnotatedCase c2009 = test::generated_case(2009, generator::Shading::kScreentone);
  const std::map<int, int> off2009 = test::strand_of(run(c2009, 0));
  EXPECT_EQ(off2009.at(1), off2009.at(22));
  const std::map<int, int> s2009 = test::strand_of(run(c2009, 0.025));
  EXPECT_NE(s2009.at(1), s2009.at(22));
  const AnnotatedCase c2003 = test::generated_case(2003, generator::Shading::kScreentone);
  const std::map<int, int> off2003 = test::strand_of(run(c2003, 0));
  EXPECT_EQ(off2003.at(1), off2003.at(7));
  const std::map<int, int> s2003 = test::strand_of(run(c2003, 0.025));
  EXPECT_NE(s2003.at(1), s2003.at(7));
  EXPECT_NE(s2003.at(24), s2003.at(7));
  EXPECT_EQ(s2003.at(1), s2003.at(24)) << "the back hair's own pieces stay one";
  // A looser limit lets the 3.0 % step to back piece 24 through.
  const std::map<int, int> loose = test::strand_of(run(c2003, 0.035));
  EXPECT_EQ(loose.at(24), loose.at(7));
}

// Off screentone the option does nothing.
TEST(FacePiece, NotOffScreentone) {
  for (generator::Shading shading : {generator::Shading::kFlat, generator::Shading::kTwoTone}) {
    const AnnotatedCase c = test::generated_case(2009, shading);
    test::expect_same_joins(run(c, 0), run(c, 0.025));
  }
}

TEST(FacePiece, BadLimitIsRefused) {
  Options o;
  o.face_piece_mass_step = -0.1;
  test::expect_invalid(o, "face_piece_mass_step = -0.1");
  o.face_piece_mass_step = std::nan("");
  test::expect_invalid(o, "face_piece_mass_step");
  const AnnotatedCase c = test::generated_case(2009, generator::Shading::kScreentone);
  EXPECT_THROW(complete_strands(test::input_from_case(c), o), Error);
}

}  // namespace
}  // namespace hair25d::completion
