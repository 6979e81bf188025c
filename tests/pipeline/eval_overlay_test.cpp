// The eval-layering overlay: label placement where many marks crowd (exact
// boxes), and the picture over an annotated case (size, caption, red marks).
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "../../ui/pipeline/src/label_layout.h"
#include "hair25d/core/annotation.h"
#include "hair25d/core/error.h"
#include "hair25d/layering/evaluation.h"
#include "hair25d/layering/layering.h"
#include "hair25d/pipeline/eval_overlay.h"

namespace hair25d::pipeline {
namespace {

using detail::Box;

const std::filesystem::path kCases = std::filesystem::path(HAIR25D_TEST_DATA_DIR) / "annotated";

// Twelve 40 x 16 labels whose marks lie within 12 px of one point (a dense
// junction): no label overlaps another label, any mark or the area's edge.
TEST(LabelLayout, CrowdedMarksGetDisjointLabels) {
  std::vector<detail::LabelRequest> requests;
  for (int i = 0; i < 12; ++i) {
    const double a = i * 0.52;
    requests.push_back(
        {Vec2(200 + 12 * std::cos(a), 150 + 12 * std::sin(a)), 3.0, 20.0, 8.0, i == 7});
  }
  const Box area{0, 0, 420, 300};
  const std::vector<Box> placed = detail::place_labels(requests, {}, area, 8.0);
  ASSERT_EQ(placed.size(), requests.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    EXPECT_NEAR(placed[i].x1 - placed[i].x0, 40.0, 1e-9);
    EXPECT_NEAR(placed[i].y1 - placed[i].y0, 16.0, 1e-9);
    EXPECT_GE(placed[i].x0, area.x0);
    EXPECT_LE(placed[i].y1, area.y1);
    for (std::size_t j = 0; j < placed.size(); ++j) {
      if (j != i) {
        EXPECT_EQ(placed[i].overlap(placed[j]), 0.0) << i << " and " << j;
      }
      EXPECT_EQ(placed[i].overlap(detail::box_around(requests[j].at, 3.0, 3.0)), 0.0)
          << "label " << i << " covers mark " << j;
    }
  }
  // The one placed first sits within two steps of its mark, past the
  // neighbouring marks (12 px from it at most).
  EXPECT_LT((placed[7].closest_to(requests[7].at) - requests[7].at).norm(), 16.0);
}

// A lone mark's label touches it nearly; an obstacle given is avoided.
TEST(LabelLayout, LoneLabelBesideItsMarkAvoidsObstacles) {
  const detail::LabelRequest r{Vec2(50, 40), 5.0, 15.0, 6.0, false};
  const Box area{0, 0, 100, 80};
  const Box free_spot = detail::place_labels({r}, {}, area, 4.0)[0];
  EXPECT_LT((free_spot.closest_to(r.at) - r.at).norm(), 5.0 + 4.0);
  const Box obstacle = free_spot;
  const Box moved = detail::place_labels({r}, {obstacle}, area, 4.0)[0];
  EXPECT_EQ(moved.overlap(obstacle), 0.0);
  EXPECT_EQ(moved.overlap(detail::box_around(r.at, 5.0, 5.0)), 0.0);
}

int count_red(const Image& img, int y0, int y1) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = 0; x < img.width(); ++x) {
      const Rgba& p = img.at(x, y);
      n += p.r > 180 && p.g < 60 && p.b < 60;
    }
  return n;
}

// case5 (896 x 1162) is drawn 1200 px tall with a caption band below; a pair
// scored wrong puts red in the drawing and in the caption, none without.
TEST(EvalOverlay, ScaledWithCaptionAndWrongPairsInRed) {
  const AnnotatedCase c = read_annotated_case(kCases / "case5");
  const layering::Result result = layering::layer_regions(c.image, c.regions);
  layering::CaseScore score = layering::score_relations(c, result.relations);
  for (layering::PairOutcome& o : score.outcomes) o.correct = true;
  score.correct = score.pairs;
  const Image right = render_eval_overlay(c.image, result, score);
  const int drawn_h = static_cast<int>(std::lround(c.image.height() * 1200.0 / 1162.0));
  EXPECT_EQ(right.width(), static_cast<int>(std::lround(c.image.width() * 1200.0 / 1162.0)));
  EXPECT_GT(right.height(), drawn_h + 40);  // the caption
  EXPECT_EQ(count_red(right, 0, right.height()), 0);

  score.outcomes.front().correct = false;
  --score.correct;
  const Image marked = render_eval_overlay(c.image, result, score);
  EXPECT_GT(count_red(marked, 0, drawn_h), 30);
  EXPECT_GT(count_red(marked, drawn_h, marked.height()), 30);
}

// A drawing too small for any label spot still gets its picture, caption wide
// enough to read; a drawing of another size than the labels is refused.
TEST(EvalOverlay, TinyDrawingAndSizeMismatch) {
  const AnnotatedCase c = read_annotated_case(kCases / "case5");
  const layering::Result result = layering::layer_regions(c.image, c.regions);
  const layering::CaseScore score = layering::score_relations(c, result.relations);
  EXPECT_THROW(render_eval_overlay(Image(5, 4), result, score), Error);
  layering::Result tiny;
  tiny.labels = LabelMap(3, 2, 1);
  const Image out = render_eval_overlay(Image(3, 2), tiny, {});
  EXPECT_GE(out.width(), 200);
  EXPECT_GT(out.height(), 8);
  // Two regions in 4 x 3 pixels, their pair related and scored wrong: the
  // label has no free spot in the drawing and is clipped, not a crash.
  layering::Result two;
  two.labels = LabelMap(4, 3, 1);
  for (int y = 0; y < 3; ++y) two.labels.at(2, y) = two.labels.at(3, y) = 2;
  RegionRelation r;
  r.a = 1, r.b = 2, r.relation = Relation::kAbove;
  two.relations = {r};
  two.anchors = {layering::RelationAnchor{Vec2(2, 1.5), Vec2(1, 0)}};
  layering::CaseScore wrong;
  wrong.name = "tiny";
  wrong.pairs = 1;
  wrong.outcomes = {layering::PairOutcome{1, 2, Relation::kBelow, Relation::kAbove, false}};
  const Image marked = render_eval_overlay(Image(4, 3, Rgba{200, 180, 160, 255}), two, wrong);
  EXPECT_GE(marked.width(), 200);  // 4 px drawn 16 px wide, the caption wider
  EXPECT_GT(count_red(marked, 12, marked.height()), 30);  // the caption's wrong pair
}

}  // namespace
}  // namespace hair25d::pipeline
