// Layering accuracy on annotated cases (paper §7, Table 1): the six cases in
// tests/data/annotated and generated cases when the generator is built.
//
// The issue asks for >= 95% of judged pairs (the paper reached 93.6%). The
// floors asserted here are what this implementation measurably reaches, so
// that a regression fails; the gap to 95% is reported, not hidden.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <map>

#include "hair25d/core/annotation.h"
#include "hair25d/layering/evaluation.h"
#ifdef HAIR25D_HAVE_GENERATOR
#include "hair25d/generator/generator.h"
#endif

namespace hair25d::layering {
namespace {

constexpr double kTarget = 0.95;

struct Totals {
  int pairs = 0, correct = 0;
  double accuracy() const { return pairs ? static_cast<double>(correct) / pairs : 0.0; }
};

void add(Totals& t, const CaseScore& s) {
  t.pairs += s.pairs;
  t.correct += s.correct;
  std::printf("  %-10s regions %3d  pairs %3d  correct %3d  accuracy %5.1f%%  %.3f s\n",
              s.name.c_str(), s.regions, s.pairs, s.correct, 100 * s.accuracy(), s.seconds);
}

Totals six_cases(const Options& options, double per_case_floor) {
  const auto folders =
      find_annotated_cases(std::filesystem::path(HAIR25D_TEST_DATA_DIR) / "annotated");
  EXPECT_EQ(folders.size(), 6u);
  Totals t;
  for (const auto& folder : folders) {
    const AnnotatedCase c = read_annotated_case(folder);
    const CaseScore s = evaluate_case(c, options);
    EXPECT_EQ(s.pairs, static_cast<int>(c.pairs.size()));
    EXPECT_GE(s.accuracy(), per_case_floor) << c.name;
    add(t, s);
  }
  std::printf("  total %d/%d = %.1f%% (target %.0f%%)\n", t.correct, t.pairs, 100 * t.accuracy(),
              100 * kTarget);
  return t;
}

// The learned metric was trained on generated drawings only: these six cases
// are a validation it never saw. Measured 292/305 = 95.7% (session 19; 290
// before the open pairs were ordered), 291/305 = 95.4% with the junction
// patches (session 8's networks, which also read the grey levels, and
// session 7's; session 6's: 292/305; without patches:
// 287/305 = 94.1%; before the label-map sectors and the same-depth model's
// new cues: 279/305).
TEST(Accuracy, SixAnnotatedCases) {
  // case0, the lowest: 89.3% since session 19's open pairs ordered
  // (Options::open_order_log_odds; its 8 = 9, whose open boundary reads
  // -10.6 same-depth log-odds, is ordered), 91.1% before.
  const Totals t = six_cases({}, 0.88);
  RecordProperty("accuracy_percent", std::to_string(100 * t.accuracy()));
  EXPECT_GE(t.accuracy(), 0.95);
}

// Without the junction patches (Options::junction_patches = false).
// Measured 287/305 = 94.1%.
TEST(Accuracy, SixAnnotatedCasesWithoutPatches) {
  Options options;
  options.junction_patches = false;
  const Totals t = six_cases(options, 0.85);  // case1: 88.4%
  EXPECT_GE(t.accuracy(), 0.93);
}

// The paper's own Φ (Eq. 1) as the unary term. Measured 271/305 = 88.9%.
TEST(Accuracy, SixAnnotatedCasesPaperMetric) {
  Options options;
  options.metric = Metric::kPaper;
  const Totals t = six_cases(options, 0.75);  // case1: 78.3%
  RecordProperty("accuracy_percent", std::to_string(100 * t.accuracy()));
  EXPECT_GE(t.accuracy(), 0.88);
}

#ifdef HAIR25D_HAVE_GENERATOR
TEST(Accuracy, GeneratedCasesInSeveralStyles) {
  Totals t;
  const generator::Shading styles[] = {generator::Shading::kFlat, generator::Shading::kTwoTone,
                                       generator::Shading::kGradient,
                                       generator::Shading::kScreentone};
  for (int i = 0; i < 8; ++i) {
    generator::Options o;
    o.width = 640;
    o.height = 480;
    o.seed = 500 + i;
    o.shading = styles[i % 4];
    o.line_width = i % 3 == 0 ? 1.5 : 3.0;
    o.jpeg_quality = i % 2 ? 70 : 0;
    AnnotatedCase c = generator::generate_case(o);
    c.name = "gen" + std::to_string(i);
    const CaseScore s = evaluate_case(c);
    add(t, s);
  }
  std::printf("  total %d/%d = %.1f%% (target %.0f%%)\n", t.correct, t.pairs, 100 * t.accuracy(),
              100 * kTarget);
  RecordProperty("accuracy_percent", std::to_string(100 * t.accuracy()));
  // Measured 190/197 = 96.4% (sessions 7 and 8; the patch networks of session 6: 183/197 =
  // 92.9%; without the junction patches 178/197 = 90.4%, the paper's Φ:
  // 161/197 = 81.7%).
  EXPECT_GE(t.accuracy(), 0.95);
}

// Forks whose dividing line fades out inside the strand (generator option
// fading_forks): the halves are "equal" although most of their boundary is
// on a drawn line. Measured 177/183 = 96.7%, 7 of the 8 equal pairs right
// (session 8's networks, which also read the grey levels; session 7's:
// 171/183, 6 of 8; session 6's: 169/183, 5 of 8).
TEST(Accuracy, GeneratedFadingForks) {
  Totals t;
  int equal = 0, equal_right = 0;
  for (int i = 0; i < 6; ++i) {
    generator::Options o;
    o.width = 640;
    o.height = 480;
    o.seed = 700 + i;
    o.strand_count = 16;
    o.shading = i % 2 ? generator::Shading::kTwoTone : generator::Shading::kScreentone;
    o.line_width = i % 3 == 0 ? 1.5 : 2.5;
    o.fading_forks = true;
    o.strand_masks = false;
    AnnotatedCase c = generator::generate_case(o);
    c.name = "fork" + std::to_string(i);
    const CaseScore s = evaluate_case(c);
    add(t, s);
    for (const PairOutcome& p : s.outcomes) {
      equal += p.truth == Relation::kEqual;
      equal_right += p.truth == Relation::kEqual && p.correct;
    }
  }
  std::printf("  total %d/%d = %.1f%%; equal pairs right %d/%d\n", t.correct, t.pairs,
              100 * t.accuracy(), equal_right, equal);
  RecordProperty("accuracy_percent", std::to_string(100 * t.accuracy()));
  EXPECT_GE(t.accuracy(), 0.96);
  EXPECT_GE(equal_right, 7);
}

// Styles of the unseen drawings the project is judged on: lines 1.2 px
// wide, and grey screentone through JPEG q40 with noise.
TEST(Accuracy, GeneratedThinLinesAndGreyJpeg) {
  Totals t;
  for (int i = 0; i < 8; ++i) {
    generator::Options o;
    o.width = i % 2 ? 640 : 560;
    o.height = 480;
    o.seed = 900 + i;
    o.strand_masks = false;
    if (i < 4) {
      o.shading = i % 2 ? generator::Shading::kGradient : generator::Shading::kFlat;
      o.line_width = 1.2;
    } else {
      o.shading = generator::Shading::kScreentone;
      o.jpeg_quality = 40;
      o.noise_sigma = 3.0;
    }
    AnnotatedCase c = generator::generate_case(o);
    c.name = "style" + std::to_string(i);
    add(t, evaluate_case(c));
  }
  std::printf("  total %d/%d = %.1f%% (target %.0f%%)\n", t.correct, t.pairs, 100 * t.accuracy(),
              100 * kTarget);
  RecordProperty("accuracy_percent", std::to_string(100 * t.accuracy()));
  // Measured 189/204 = 92.6% (sessions 7 and 8; session 6's patch networks 184/204 = 90.2%,
  // without the junction patches 182/204 = 89.2%).
  EXPECT_GE(t.accuracy(), 0.92);
}

TEST(Accuracy, GeneratedOrderDoesNotDependOnRegionNumbers) {
  for (std::uint64_t seed : {31u, 32u, 33u}) {
    generator::Options o;
    o.width = 480;
    o.height = 360;
    o.strand_count = 10;
    o.seed = seed;
    const AnnotatedCase c = generator::generate_case(o);
    const Result r = layer_regions(c.image, c.regions);
    // Renumber: reverse the order of ids and spread them out.
    const std::vector<int> ids = c.regions.labels();
    std::map<int, int> perm;
    for (std::size_t i = 0; i < ids.size(); ++i) perm[ids[i]] = 1000 - 7 * static_cast<int>(i);
    LabelMap moved = c.regions;
    for (std::size_t i = 0; i < moved.size(); ++i)
      if (moved.data()[i] != 0) moved.data()[i] = perm.at(moved.data()[i]);
    const Result p = layer_regions(c.image, moved);
    ASSERT_EQ(r.depth.size(), p.depth.size());
    for (const auto& [id, depth] : r.depth) EXPECT_EQ(p.depth.at(perm.at(id)), depth) << seed;
    // And the order is acyclic: every relation holds in it.
    for (const RegionRelation& x : p.relations) {
      if (x.relation == Relation::kAbove) {
        EXPECT_GT(p.depth.at(x.a), p.depth.at(x.b));
      }
      if (x.relation == Relation::kBelow) {
        EXPECT_LT(p.depth.at(x.a), p.depth.at(x.b));
      }
      if (x.relation == Relation::kEqual) {
        EXPECT_EQ(p.depth.at(x.a), p.depth.at(x.b));
      }
    }
  }
}
#endif

}  // namespace
}  // namespace hair25d::layering
