// The six annotated cases: case-1 joins against the annotated strands, with
// the relations taken from the annotation's pairs. Ground truth is used only
// to score here.
#include <gtest/gtest.h>

#include <cstdio>

#include "annotated_eval.h"
#include "hair25d/core/annotation.h"

namespace hair25d::completion {
namespace {

TEST(AnnotatedCases, JoinsMatchTheAnnotatedStrands) {
  const auto folders = find_annotated_cases(HAIR25D_TEST_DATA_DIR "/annotated");
  ASSERT_EQ(folders.size(), 6u);
  test::PairScore total;
  double iou_sum = 0;
  int iou_count = 0;
  for (const auto& folder : folders) {
    const AnnotatedCase c = read_annotated_case(folder);
    const Input in = test::input_from_case(c);
    Options o;
    o.inpaint_strands = false;  // colours are not scored here
    o.inpaint_background = false;
    const Result r = complete_strands(in, o);
    const test::PairScore s = test::score_pairs(c, r);
    const std::vector<double> ious = test::strand_ious(c, r);
    double mean = 0;
    for (double v : ious) mean += v;
    mean /= std::max<std::size_t>(1, ious.size());
    std::printf(
        "%s: pairs predicted %d, annotated %d, correct %d: precision %.3f recall %.3f; "
        "mean strand IoU %.3f over %zu strands\n",
        c.name.c_str(), s.predicted, s.truth, s.correct, s.precision(), s.recall(), mean,
        ious.size());
    std::printf("  strand IoUs:");
    for (double v : ious) std::printf(" %.2f", v);
    std::printf("\n");
    total.predicted += s.predicted;
    total.truth += s.truth;
    total.correct += s.correct;
    for (double v : ious) iou_sum += v, ++iou_count;
  }
  std::printf("all: precision %.3f recall %.3f, mean strand IoU %.3f\n", total.precision(),
              total.recall(), iou_sum / std::max(1, iou_count));
  // Floors just under the measured level (0.982 / 0.931 / 0.754 with the
  // joins across the face and the grown edges without visible outline beside
  // an end; see docs/completion.md for the targets).
  EXPECT_GE(total.precision(), 0.975);
  EXPECT_GE(total.recall(), 0.92);
  EXPECT_GE(iou_sum / iou_count, 0.75);
}

}  // namespace
}  // namespace hair25d::completion
