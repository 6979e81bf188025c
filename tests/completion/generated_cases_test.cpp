// Properties of completion over generated drawings (fixed seeds, non-square).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <initializer_list>
#include <map>
#include <set>
#include <tuple>
#include <vector>

#include "annotated_eval.h"
#include "generated_case.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/join_scorer.h"
#include "hair25d/generator/generator.h"

namespace hair25d::completion {
namespace {

// The generator's strand of every region of `c`.
std::map<int, int> true_strands(const AnnotatedCase& c) {
  std::map<int, int> truth;
  for (const AnnotatedRegion& reg : c.region_list) truth[reg.id] = reg.strand;
  return truth;
}

// The regions of the strand completion (without inpainting, the case's
// relations) makes of `region`; empty when no strand holds it.
std::vector<int> completed_strand_of(const AnnotatedCase& c, int region) {
  Options o;
  o.inpaint_strands = false;
  o.inpaint_background = false;
  const Result r = complete_strands(test::input_from_case(c), o);
  for (const CompletedStrand& s : r.strands)
    if (std::count(s.regions.begin(), s.regions.end(), region) > 0) return s.regions;
  return {};
}

TEST(GeneratedCases, CompletedPixelsLieUnderOccludersAndRegionsAreKept) {
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const AnnotatedCase c = test::generated_case(
        seed, seed == 2 ? generator::Shading::kTwoTone : generator::Shading::kFlat, 600, 440, 14);
    const Input in = test::input_from_case(c);
    Options o;
    o.inpaint_background = false;
    const Result r = complete_strands(in, o);
    SCOPED_TRACE(seed);
    // Which regions lie above which, through any chain of relations: a
    // completed pixel must show one of those above one of its pieces.
    std::map<int, std::set<int>> direct, above;
    for (const RegionRelation& rel : in.relations) {
      if (rel.relation == Relation::kBelow) direct[rel.a].insert(rel.b);
      if (rel.relation == Relation::kAbove) direct[rel.b].insert(rel.a);
    }
    for (const auto& [id, ups] : direct) {
      std::vector<int> stack(ups.begin(), ups.end());
      while (!stack.empty()) {
        const int r = stack.back();
        stack.pop_back();
        if (!above[id].insert(r).second) continue;
        auto it = direct.find(r);
        if (it != direct.end()) stack.insert(stack.end(), it->second.begin(), it->second.end());
      }
    }
    // Back hair (no piece above any region) may also be completed behind
    // the face, which hides it as a strand does, but never over the paper.
    std::set<int> front;
    for (const auto& [id, ups] : above) front.insert(ups.begin(), ups.end());
    const Rgba paper = c.image.at(0, 0);
    auto is_paper = [&](int x, int y) {
      const Rgba& p = c.image.at(x, y);
      return std::abs(p.r - paper.r) + std::abs(p.g - paper.g) + std::abs(p.b - paper.b) <= 12;
    };
    std::set<int> seen;
    for (const CompletedStrand& s : r.strands) {
      bool back_hair = true;
      for (int id : s.regions) back_hair = back_hair && !front.count(id);
      for (int id : s.regions) EXPECT_TRUE(seen.insert(id).second);
      EXPECT_GE(s.outline.size(), 3u);
      EXPECT_EQ(s.texture.width(), s.mask.width());
      for (int y = 0; y < s.mask.height(); ++y)
        for (int x = 0; x < s.mask.width(); ++x) {
          if (s.mask.at(x, y) != 2) continue;
          const int gx = x + s.origin.x(), gy = y + s.origin.y();
          const int l = r.regions.at(gx, gy);
          bool under = false;
          for (int id : s.regions) under = under || above[id].count(l) > 0;
          const bool behind_face = !under && back_hair && l == 0 && !is_paper(gx, gy);
          EXPECT_TRUE(under || behind_face) << "completed pixel " << gx << ", " << gy;
          // Under a strand the completed part is opaque; behind the face,
          // which the background draws below every strand, it shows nothing.
          EXPECT_EQ(s.texture.at(x, y).a, behind_face ? 0 : 255) << "at " << gx << ", " << gy;
        }
    }
    for (int id : c.regions.labels()) EXPECT_TRUE(seen.count(id)) << "region " << id;
    // Only slivers with no 3×3 patch of their own fall back to their mean colour.
    const test::PairScore score = test::score_pairs(c, r);
    std::printf(
        "generated seed %d: same-strand pairs predicted %d, true %d, correct %d: "
        "precision %.3f recall %.3f\n",
        static_cast<int>(seed), score.predicted, score.truth, score.correct, score.precision(),
        score.recall());
    EXPECT_LE(r.strand_inpaint.unfilled, 0.02 * r.strand_inpaint.filled)
        << r.strand_inpaint.unfilled << " of " << r.strand_inpaint.filled;
  }
}

// Same-strand pair scores summed over 800 × 640 drawings of 20 strands,
// relations from the generator's pairs, no inpainting (joins only).
test::PairScore score_generated(std::initializer_list<generator::Shading> shadings,
                                std::uint64_t first_seed, std::uint64_t last_seed,
                                bool face_joins) {
  test::PairScore total;
  for (generator::Shading shading : shadings)
    for (std::uint64_t seed = first_seed; seed <= last_seed; ++seed) {
      const AnnotatedCase c = test::generated_case(seed, shading);
      Options o;
      o.face_joins = face_joins;
      o.inpaint_strands = false;
      o.inpaint_background = false;
      const test::PairScore s = test::score_pairs(c, complete_strands(test::input_from_case(c), o));
      total.predicted += s.predicted;
      total.truth += s.truth;
      total.correct += s.correct;
    }
  return total;
}

// Prints a set's pair score and holds it to its floors.
void expect_at_least(const char* set, const test::PairScore& total, double precision,
                     double recall) {
  std::printf(
      "generated (%s): pairs predicted %d, true %d, correct %d: precision %.3f recall %.3f\n", set,
      total.predicted, total.truth, total.correct, total.precision(), total.recall());
  EXPECT_GE(total.precision(), precision) << set;
  EXPECT_GE(total.recall(), recall) << set;
}

// Case-1 joins against the generator's strands, relations from its pairs:
// flat and cel-shaded drawings, four seeds each. Floors at the measured
// level (docs/completion.md); the targets (precision 0.95, recall 0.85) are
// not met on these crowded drawings.
// With joins across the face the generated drawings lose precision (0.850
// -> 0.773, recall 0.507 both; 0.739 before tails were kept out of the face
// joins): their side and under strands lie along the face, above nothing,
// in the back hair's colour, and are joined to it; both are checked. Before the strand joins'
// colour-step term: 0.773 / 0.680, so the precision floors fail without it.
TEST(GeneratedCases, JoinsMatchTheGeneratedStrands) {
  for (const bool face_joins : {false, true}) {
    const test::PairScore total = score_generated(
        {generator::Shading::kFlat, generator::Shading::kTwoTone}, 1, 4, face_joins);
    expect_at_least(face_joins ? "flat and two-tone, seeds 1-4, face joins on"
                               : "flat and two-tone, seeds 1-4, face joins off",
                    total, face_joins ? 0.75 : 0.82, 0.49);
  }
}

// Back hair cut into pieces by strands and by the face (mass joins across
// fans of strands, bank joins, face joins): flat and gradient drawings,
// seeds 101-104, relations from the generator's pairs. Measured 0.960 /
// 0.654 (119 right of 182 pairs, 5 wrong); with the mass joins' old rules
// (6 rays, 0.5 widths deep, rays stopped by any unlabelled pixel) 0.926 /
// 0.412, so the recall floor fails if the back hair's slivers stay apart
// again.
TEST(GeneratedCases, BackHairPiecesAreJoined) {
  const test::PairScore total =
      score_generated({generator::Shading::kFlat, generator::Shading::kGradient}, 101, 104, true);
  expect_at_least("flat and gradient, seeds 101-104", total, 0.9, 0.6);
}

// The generator hangs tails under the back hair, so the back hair's pieces
// over them lie above a region; flat and two-tone seeds 112-115 (the seeds
// with such pieces among 101-116) measured 0.881 / 0.607 (74 right of 122
// pairs, 10 wrong); 0.875 / 0.574 while a lock lying on another lock kept
// the back hair over it from being back hair (session 6, stacked locks:
// the recall floor fails without them), 0.681 / 0.508 when back hair over
// tails is no mass-join source or target, so both floors fail without it.
TEST(GeneratedCases, BackHairOverTailsIsJoined) {
  const test::PairScore total =
      score_generated({generator::Shading::kFlat, generator::Shading::kTwoTone}, 112, 115, true);
  expect_at_least("flat and two-tone, seeds 112-115", total, 0.86, 0.59);
}

// Screentone drawings, seeds 1-4: the tone's dots move an 11 x 11 window's
// mean by 10-35 RGB between the two sides of a strand, so the mass joins'
// colour step is allowed to grow with the windows' texture spread.
// Measured 0.805 / 0.458 (33 right of 72 pairs, 8 wrong); with the plain
// 10 RGB limit 0.778 / 0.292, so the recall floor fails without it.
TEST(GeneratedCases, ScreentonePiecesAreJoined) {
  const test::PairScore total = score_generated({generator::Shading::kScreentone}, 1, 4, true);
  expect_at_least("screentone, seeds 1-4", total, 0.78, 0.44);
}

// A tail hanging beside the back hair in its tone is no back hair: on
// screentone seed 104 the tail (region 5) was strand-joined behind the face
// to back piece 27 across piece 25 of another tone, and a guard keeping body
// joins off such strands cost seed 207 its back hair across the neck.
// Measured 21 pairs, 17 right (104: 8 / 4, 207: 13 / 13); with the join
// across the other tone and the guard 17 pairs, 12 right (0.706 / 0.240),
// so both floors fail.
TEST(GeneratedCases, ScreentoneTailIsNoBackHair) {
  test::PairScore total = score_generated({generator::Shading::kScreentone}, 104, 104, true);
  const test::PairScore held = score_generated({generator::Shading::kScreentone}, 207, 207, true);
  total.predicted += held.predicted;
  total.truth += held.truth;
  total.correct += held.correct;
  expect_at_least("screentone, seeds 104 and 207", total, 0.8, 0.33);
}

// The strands are grown and assembled on two workers, a strand as soon as the
// edges of its regions have grown (beside the growing of the others), and
// the strand-join candidates' rasters are measured on two (session 40): the
// result is that of one worker, growing every edge and then assembling,
// each raster measured where the matching reaches it. Seed 6 is a gradient
// drawing, whose cover refusals measure the arm shares' shapes; every
// candidate's trace is compared too.
TEST(GeneratedCases, TwoWorkersGiveTheResultOfOne) {
  for (std::uint64_t seed : {4u, 5u, 6u}) {
    const generator::Shading shading = seed == 4   ? generator::Shading::kFlat
                                       : seed == 5 ? generator::Shading::kScreentone
                                                   : generator::Shading::kGradient;
    const AnnotatedCase c = test::generated_case(seed, shading, 560, 420, 16);
    const Input in = test::input_from_case(c);
    Options one;
    one.threads = 1;
    one.trace_joins = true;
    Options two = one;
    two.threads = 2;
    const Result a = complete_strands(in, one);
    const Result b = complete_strands(in, two);
    SCOPED_TRACE(seed);
    ASSERT_EQ(a.strands.size(), b.strands.size());
    for (std::size_t i = 0; i < a.strands.size(); ++i) {
      const CompletedStrand& x = a.strands[i];
      const CompletedStrand& y = b.strands[i];
      EXPECT_EQ(x.regions, y.regions);
      EXPECT_EQ(x.origin, y.origin);
      EXPECT_TRUE(x.mask == y.mask) << "strand " << i;
      EXPECT_TRUE(x.texture == y.texture) << "strand " << i;
      EXPECT_EQ(x.outline, y.outline);
      EXPECT_EQ(x.body, y.body);
      EXPECT_EQ(x.root_hint.has_value(), y.root_hint.has_value());
      if (x.root_hint && y.root_hint) {
        EXPECT_EQ(*x.root_hint, *y.root_hint);
      }
      EXPECT_EQ(x.completed_pixels, y.completed_pixels);
    }
    ASSERT_EQ(a.edges.size(), b.edges.size());
    for (std::size_t i = 0; i < a.edges.size(); ++i) {
      EXPECT_EQ(a.edges[i].region, b.edges[i].region);
      EXPECT_EQ(a.edges[i].completion, b.edges[i].completion);
      EXPECT_EQ(a.edges[i].stop, b.edges[i].stop);
      EXPECT_EQ(a.edges[i].hidden_pixels, b.edges[i].hidden_pixels);
    }
    EXPECT_TRUE(a.background == b.background);
    ASSERT_EQ(a.join_trace.size(), b.join_trace.size());
    int measured = 0;
    for (std::size_t i = 0; i < a.join_trace.size(); ++i) {
      const JoinTrace& x = a.join_trace[i];
      const JoinTrace& y = b.join_trace[i];
      EXPECT_EQ(x.region_a, y.region_a);
      EXPECT_EQ(x.region_b, y.region_b);
      EXPECT_EQ(x.stage, y.stage) << "pair " << i;
      EXPECT_EQ(x.hand_cost, y.hand_cost) << "pair " << i;
      EXPECT_EQ(x.probability, y.probability) << "pair " << i;
      EXPECT_EQ(x.cover, y.cover) << "pair " << i;
      EXPECT_EQ(x.hole_background, y.hole_background) << "pair " << i;
      EXPECT_EQ(x.hole_below, y.hole_below) << "pair " << i;
      EXPECT_EQ(x.hole_sibling, y.hole_sibling) << "pair " << i;
      EXPECT_EQ(x.hole_other, y.hole_other) << "pair " << i;
      measured += x.cover >= 0;
    }
    EXPECT_GE(measured, 3);  // candidates whose patches were measured (4: 3, 5: 11, 6: 34)
    EXPECT_EQ(a.joins, b.joins);
    EXPECT_EQ(a.roots, b.roots);
    EXPECT_EQ(a.tips, b.tips);
    EXPECT_EQ(a.strand_inpaint.filled, b.strand_inpaint.filled);
    EXPECT_EQ(a.summary, b.summary);
  }
}

// Screentone drawings rescue strand candidates over the cost limit at their
// own threshold (JoinScorerOptions::screentone_threshold, session 21), the
// other drawings at `threshold`, or with `retrained` (session 29) by the
// retrained net at retrained_threshold: with one threshold low (0.05) and
// the other high (0.999), the candidates of the band are rescued by the one
// of their drawing only, and judged by their drawing's net (session 30: on
// screentone the screentone net, or with screentone_band off the default
// one).
TEST(GeneratedCases, ScreentoneDrawingsRescueJoinsAtTheirOwnThreshold) {
  auto run = [](const AnnotatedCase& c, double threshold, double screentone_threshold,
                bool retrained) {
    Options o;
    o.inpaint_strands = false;
    o.inpaint_background = false;
    o.join_scorer.record = true;
    // `retrained` also stands for screentone_band off on screentone.
    o.join_scorer.retrained = retrained;
    o.join_scorer.screentone_band = !retrained;
    (retrained ? o.join_scorer.retrained_threshold : o.join_scorer.threshold) = threshold;
    o.join_scorer.screentone_threshold = screentone_threshold;
    // The nets' thresholds alone: the ensembles' rescues are
    // join_scorer_ensemble_test.cpp's, the side tangents' bar
    // side_tangent_test.cpp's, the second opinion's join_scorer_second_test.cpp's.
    o.join_scorer.ensemble = JoinScorerOptions::Ensemble::kNone;
    o.join_scorer.side_threshold = 1.0;
    o.join_scorer.second_threshold = 1.0;
    // Angle refusals' second chances have their own net (angle_refusal_test.cpp).
    o.join_scorer.angle_refusal_threshold = 1.0;
    // So have flat drawings' cover refusals' (cover_plain_test.cpp).
    o.join_scorer.cover_flat_threshold = 1.0;
    return complete_strands(test::input_from_case(c), o);
  };
  const JoinScorerOptions s;
  const double limit = Options{}.max_join_cost;
  for (const generator::Shading shading :
       {generator::Shading::kScreentone, generator::Shading::kFlat}) {
    const bool screentone = shading == generator::Shading::kScreentone;
    const AnnotatedCase c = test::generated_case(2004, shading);
    for (const bool retrained : {false, true}) {
      const JoinScorerNet& net = !screentone
                                     ? (retrained ? retrained_join_scorer() : default_join_scorer())
                                 : !retrained ? screentone_join_scorer()
                                              : default_join_scorer();
      for (const auto& [threshold, screentone_threshold] :
           {std::pair{0.05, 0.999}, {0.999, 0.05}}) {
        SCOPED_TRACE(testing::Message() << "screentone " << screentone << " retrained " << retrained
                                        << " threshold " << threshold);
        const Result r = run(c, threshold, screentone_threshold, retrained);
        const double t = screentone ? screentone_threshold : threshold;
        int rescued = 0, asked = 0;
        for (const JoinCandidate& j : r.join_candidates) {
          if (j.hand_cost < s.band_low || j.hand_cost > s.band_high || j.probability < 0) continue;
          ++asked;
          EXPECT_DOUBLE_EQ(j.probability, join_probability(net, j.features));
          if (j.probability >= t) {
            EXPECT_DOUBLE_EQ(j.cost, std::min(j.hand_cost, limit + (t - j.probability) *
                                                                       (s.band_high - s.band_low)));
            rescued += j.hand_cost > limit;
          } else {
            EXPECT_EQ(j.cost, j.hand_cost);
          }
        }
        EXPECT_GT(asked, 0);
        // The low threshold rescues some candidate over the limit, the high none.
        if (t < 0.5) {
          EXPECT_GT(rescued, 0);
        } else {
          EXPECT_EQ(rescued, 0);
        }
      }
    }
  }
}

// Session 32: the veto reaches lower on screentone drawings
// (screentone_veto_low 0.6 against veto_low 1.4): there a candidate of hand
// cost 0.6-1.4 is asked, elsewhere it is not.
TEST(GeneratedCases, ScreentoneVetoReachesLower) {
  const JoinScorerOptions s;
  ASSERT_LT(s.screentone_veto_low, s.veto_low);
  for (const generator::Shading shading :
       {generator::Shading::kFlat, generator::Shading::kScreentone}) {
    const bool screentone = shading == generator::Shading::kScreentone;
    SCOPED_TRACE(testing::Message() << "screentone " << screentone);
    Options o;
    o.inpaint_strands = false;
    o.inpaint_background = false;
    o.join_scorer.record = true;
    o.trace_joins = true;
    // Angle refusals' second chances have their own net (angle_refusal_test.cpp).
    o.join_scorer.angle_refusal_threshold = 1.0;
    // So have flat drawings' cover refusals' (cover_plain_test.cpp).
    o.join_scorer.cover_flat_threshold = 1.0;
    int between = 0, vetoed = 0;
    for (int seed : {2000, 2001, 2004}) {
      const Result r =
          complete_strands(test::input_from_case(test::generated_case(seed, shading)), o);
      for (const JoinCandidate& j : r.join_candidates) {
        if (!screentone || j.hand_cost < s.screentone_veto_low || j.hand_cost >= s.veto_low)
          continue;
        ++between;
        EXPECT_DOUBLE_EQ(j.probability, join_probability(screentone_join_scorer(), j.features));
        EXPECT_EQ(std::isinf(j.cost), j.probability < s.screentone_veto_below);
      }
      for (const JoinTrace& x : r.join_trace)
        if (x.stage == JoinStage::kVetoed && x.hand_cost < s.veto_low) {
          EXPECT_GE(x.hand_cost, s.screentone_veto_low);
          ++vetoed;
        }
    }
    if (screentone) {
      EXPECT_GT(between, 0);  // each asked, and refused exactly under the bar
    } else {
      EXPECT_EQ(vetoed, 0) << "under veto_low only on screentone";
    }
  }
}

// Session 29: on drawings without screentone the retrained net refuses
// candidates under the limit with hand cost in [veto_low, band_low) at
// p < veto_below, and joins candidates over the band up to rescue_high at
// p >= rescue_threshold, whichever net judges the band (`retrained` or
// not). Session 30: on screentone drawings the screentone net does the
// same at screentone_veto_below and screentone_rescue_threshold. With the
// bars set so that most candidates fall on their side (veto 0.999, rescue
// 0.05), a refused candidate is never chosen and a rescued one is ranked
// under the limit; with only the other drawings' bars set, a screentone
// drawing keeps both edges as they were, and the other drawings do with
// only the screentone bars set.
TEST(GeneratedCases, RetrainedNetJudgesTheBandsEdges) {
  // `edges`: which drawings' bars are set (none, the others', screentone's).
  enum class Edges { kNone, kOthers, kScreentone };
  auto run = [](const AnnotatedCase& c, Edges edges, bool retrained) {
    Options o;
    o.inpaint_strands = false;
    o.inpaint_background = false;
    o.join_scorer.record = true;
    o.trace_joins = true;
    o.join_scorer.retrained = retrained;
    o.join_scorer.ensemble = JoinScorerOptions::Ensemble::kNone;
    // Angle refusals' second chances have their own net (angle_refusal_test.cpp).
    o.join_scorer.angle_refusal_threshold = 1.0;
    // So have flat drawings' cover refusals' (cover_plain_test.cpp).
    o.join_scorer.cover_flat_threshold = 1.0;
    o.join_scorer.veto_low = 0.0;
    o.join_scorer.screentone_veto_low = 0.0;
    o.join_scorer.rescue_high = 5.0;
    o.join_scorer.veto_below = edges == Edges::kOthers ? 0.999 : 0.0;
    o.join_scorer.rescue_threshold = edges == Edges::kOthers ? 0.05 : 0.999999;
    o.join_scorer.screentone_veto_below = edges == Edges::kScreentone ? 0.999 : 0.0;
    o.join_scorer.screentone_rescue_threshold = edges == Edges::kScreentone ? 0.05 : 1.0;
    if (edges == Edges::kNone) o.join_scorer.rescue_high = o.join_scorer.band_high;
    return complete_strands(test::input_from_case(c), o);
  };
  const JoinScorerOptions s;
  const double limit = Options{}.max_join_cost, t = 0.05;
  const Result off =
      run(test::generated_case(2004, generator::Shading::kFlat), Edges::kNone, false);
  // Off, no candidate under the band is asked, none over it recorded.
  int chosen_low = 0;
  for (const JoinCandidate& j : off.join_candidates) {
    EXPECT_LE(j.hand_cost, s.band_high);
    if (j.hand_cost < s.band_low) {
      EXPECT_EQ(j.probability, -1.0);
    }
    chosen_low += j.chosen && j.hand_cost >= 0 && j.hand_cost < s.band_low;
  }
  EXPECT_GT(chosen_low, 0);
  for (const JoinTrace& x : off.join_trace) EXPECT_NE(x.stage, JoinStage::kVetoed);
  for (const generator::Shading shading :
       {generator::Shading::kFlat, generator::Shading::kScreentone}) {
    const bool screentone = shading == generator::Shading::kScreentone;
    SCOPED_TRACE(testing::Message() << "screentone " << screentone);
    const AnnotatedCase c = test::generated_case(2004, shading);
    const JoinScorerNet& net = screentone ? screentone_join_scorer() : retrained_join_scorer();
    for (const Edges edges : {Edges::kOthers, Edges::kScreentone}) {
      // Whether this drawing's bars are the ones set.
      const bool judged = screentone == (edges == Edges::kScreentone);
      for (const bool retrained : {false, true}) {
        // The band's net does not matter on a screentone drawing.
        if (screentone && retrained) continue;
        SCOPED_TRACE(testing::Message()
                     << "edges " << static_cast<int>(edges) << " retrained " << retrained);
        const Result on = run(c, edges, retrained);
        int vetoed = 0, over = 0, rescued = 0;
        for (const JoinCandidate& j : on.join_candidates) {
          // Session 37: a cut's second partner's own row (recorded with the
          // scorer on, input 64 `second_cut`), judged by its own net.
          if (j.features[64] > 0.5f) continue;
          if (j.hand_cost >= 0 && j.hand_cost < s.band_low) {
            if (!judged) {
              EXPECT_EQ(j.probability, -1.0);
              continue;
            }
            EXPECT_DOUBLE_EQ(j.probability, join_probability(net, j.features));
            if (j.probability < 0.999) {
              EXPECT_TRUE(std::isinf(j.cost));
              EXPECT_FALSE(j.chosen);
              ++vetoed;
            } else {
              EXPECT_EQ(j.cost, j.hand_cost);
            }
          } else if (j.hand_cost > s.band_high) {
            EXPECT_LE(j.hand_cost, 5.0);
            ++over;
            // Unjudged: not asked on a screentone drawing; on the others
            // asked, as rescue_high is shared, but at a bar none reaches.
            if (!judged && screentone) {
              EXPECT_EQ(j.probability, -1.0);
            }
            if (!judged || j.probability < 0) {
              if (j.probability < 0.999999) {
                EXPECT_EQ(j.cost, j.hand_cost);
              }
              continue;
            }
            EXPECT_DOUBLE_EQ(j.probability, join_probability(net, j.features));
            if (j.probability >= t) {
              EXPECT_DOUBLE_EQ(j.cost, limit + (t - j.probability) * (s.band_high - s.band_low));
              ++rescued;
            } else {
              EXPECT_EQ(j.cost, j.hand_cost);
            }
          }
        }
        // The trace (eval_joins --census) names a vetoed pair's stage.
        int traced_vetoes = 0;
        for (const JoinTrace& x : on.join_trace) {
          if (x.stage != JoinStage::kVetoed) continue;
          ++traced_vetoes;
          EXPECT_LT(x.hand_cost, s.band_low);
          EXPECT_GE(x.probability, 0.0);
          EXPECT_LT(x.probability, 0.999);
        }
        EXPECT_EQ(traced_vetoes > 0, judged);
        if (judged) {
          EXPECT_GT(vetoed, 0);
          EXPECT_GT(over, 0);
          EXPECT_GT(rescued, 0);
        } else {
          EXPECT_EQ(vetoed, 0);
          EXPECT_EQ(rescued, 0);
        }
      }
    }
  }
}

// Tone path joins of two pieces under one common occluder whose paths cross
// a piece's long axis are two strands side by side (session 21,
// mass_paths.cpp kMinToneAxisCos): dev screentone 2004's bang 13's piece 7
// and side lock 9's piece 16, one tone, linked under one strand across
// 16's axis, were joined (axis cosines 0.52 and 0.44); each keeps its own
// strand.
TEST(GeneratedCases, ScreentoneStrandsSideBySideAreNotJoinedAcrossAPiece) {
  const AnnotatedCase c = test::generated_case(2004, generator::Shading::kScreentone);
  const std::map<int, int> truth = true_strands(c);
  ASSERT_NE(truth.at(7), truth.at(16));
  const std::vector<int> with = completed_strand_of(c, 7);
  ASSERT_FALSE(with.empty());
  EXPECT_EQ(std::count(with.begin(), with.end(), 16), 0);
  for (int id : with) EXPECT_EQ(truth.at(id), truth.at(7)) << id;
}

// Screentone pieces whose dots say two tones are two strands, whatever
// their outlines say (session 23, bank_crossings.h two_tones_by_dots): on
// dev screentone 2046 the cap (region 2, dark share 0.33) was edge-joined
// under a bang to a strand of a lighter tone (14, 0.22), and on 4079 the
// back hair (1, 0.37) across the face to a tail (9, 0.23). Neither pair is
// one strand now (both fail without the rule, checked).
TEST(GeneratedCases, ScreentonePiecesOfTwoTonesAreNotJoined) {
  for (const auto& [seed, a, b] : {std::tuple{2046u, 2, 14}, std::tuple{4079u, 1, 9}}) {
    SCOPED_TRACE(seed);
    const AnnotatedCase c = test::generated_case(seed, generator::Shading::kScreentone);
    const std::map<int, int> truth = true_strands(c);
    ASSERT_NE(truth.at(a), truth.at(b));
    const std::vector<int> with = completed_strand_of(c, a);
    ASSERT_FALSE(with.empty());
    EXPECT_EQ(std::count(with.begin(), with.end(), b), 0);
  }
}

}  // namespace
}  // namespace hair25d::completion
