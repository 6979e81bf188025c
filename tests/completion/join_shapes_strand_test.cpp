// Options::join_arm_shares through complete_strands: a strand that jogs
// sideways under a band shaped as its hidden part with long tangent arms
// joins when the other shapes are tried, though the patch of a third's
// arms runs off the band, and its completed part is drawn on the band.
#include <gtest/gtest.h>

#include <algorithm>

#include "hair25d/completion/bezier.h"
#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

using namespace test;

constexpr Rgba kStrand{200, 150, 110, 255};
constexpr Rgba kBand{120, 90, 160, 255};

// Even-odd rule.
bool inside_polygon(const Polyline& poly, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
    const Vec2 &a = poly[i], &b = poly[j];
    if ((a.y() > y) != (b.y() > y) && x < (b.x() - a.x()) * (y - a.y()) / (b.y() - a.y()) + a.x())
      in = !in;
  }
  return in;
}

// Piece 1 (x 100..140 down to y 116) and piece 2 (`shift` px further
// right, from y 168) of a strand running down, under band 3 shaped as the
// strand's hidden part with tangent arms `arms` of the chord at both cuts,
// `margin` px wider on each side (and a strip over each cut); paper
// elsewhere.
Drawing jogging_strand(double shift, double arms, double margin) {
  Drawing d = blank(260, 300);
  const Vec2 down(0, 1);
  const Polyline left = join_bezier_arms(Vec2(100 - margin, 114), down,
                                         Vec2(100 + shift - margin, 170), down, arms, arms)
                            .sample(64);
  const Polyline right = join_bezier_arms(Vec2(140 + shift + margin, 170), -down,
                                          Vec2(140 + margin, 114), -down, arms, arms)
                             .sample(64);
  Polyline hidden = left;
  hidden.insert(hidden.end(), right.begin(), right.end());
  paint(
      d, [](double x, double y) { return x > 100 && x < 140 && y > 30 && y < 118; }, kStrand, 1);
  paint(
      d,
      [&](double x, double y) { return x > 100 + shift && x < 140 + shift && y > 166 && y < 260; },
      kStrand, 2);
  paint(
      d,
      [&](double x, double y) {
        return (y > 110 && y < 116 && x > 96 && x < 144) ||
               (y > 168 && y < 174 && x > 96 + shift && x < 144 + shift) ||
               (y >= 114 && y <= 170 && inside_polygon(hidden, x, y));
      },
      kBand, 3);
  d.relations = {below(1, 3), below(2, 3)};
  return d;
}

Result run(const Drawing& d, bool shapes) {
  Options o;
  o.inpaint_background = false;
  o.inpaint_strands = false;
  o.face_joins = false;
  o.path_joins = false;
  o.trace_joins = true;
  // The jog (80 px over a 56 px gap) costs more than the default limit
  // (hand cost 3.5 before the cover term); the hand cost alone judges here.
  o.max_join_cost = 6.0;
  o.join_scorer.enabled = false;
  if (!shapes) o.join_arm_shares.clear();
  return complete_strands(input_of(d, Vec2(120, 10)), o);
}

const JoinTrace* trace_of(const Result& r) {
  for (const JoinTrace& t : r.join_trace)
    if (std::min(t.region_a, t.region_b) == 1 && std::max(t.region_a, t.region_b) == 2) return &t;
  return nullptr;
}

// The band follows arms of 0.7: the third's patch cuts its corners over
// the paper (cover 0.76), the 0.7 one lies on it.
TEST(JoinShapesStrand, JoggingStrandJoinsOnTheShapeItsBandHolds) {
  const Drawing d = jogging_strand(80, 0.7, 2);
  const Result plain = run(d, false);
  const JoinTrace* t = trace_of(plain);
  ASSERT_NE(t, nullptr);
  EXPECT_EQ(t->stage, JoinStage::kCover);
  EXPECT_LT(t->cover, 0.85);
  EXPECT_GE(t->cover, 0.6);  // kMinCoverToReshape
  const std::vector<int> apart = regions_with(plain, 1);
  EXPECT_EQ(std::count(apart.begin(), apart.end(), 2), 0);

  const Result shaped = run(d, true);
  const JoinTrace* s = trace_of(shaped);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->stage, JoinStage::kChosen);
  EXPECT_GE(s->cover, 0.85);
  const CompletedStrand* strand = strand_with(shaped, 1);
  ASSERT_NE(strand, nullptr);
  EXPECT_EQ(std::count(strand->regions.begin(), strand->regions.end(), 2), 1);
  // The completed part is the chosen shape's: it lies on the band (or its
  // ink) and fills it. The third's patch, clipped to the band, would fill
  // 0.87 of the band's pixels.
  int completed = 0, on_band = 0, band = 0;
  for (int y = 0; y < d.regions.height(); ++y)
    for (int x = 0; x < d.regions.width(); ++x) band += d.regions.at(x, y) == 3;
  for (int y = 0; y < strand->mask.height(); ++y)
    for (int x = 0; x < strand->mask.width(); ++x) {
      if (strand->mask.at(x, y) != 2) continue;
      const int gx = x + strand->origin.x(), gy = y + strand->origin.y();
      ++completed;
      // The band or its ink outline (label 0 too), not the paper.
      const Rgba c = d.image.at(gx, gy);
      on_band += d.regions.at(gx, gy) == 3 || (d.regions.at(gx, gy) == 0 && c.r < 100);
    }
  ASSERT_GT(completed, 0);
  EXPECT_GE(static_cast<double>(on_band) / completed, 0.9) << on_band << " / " << completed;
  EXPECT_GE(completed, 0.95 * band) << completed << " completed, band " << band;
}

}  // namespace
}  // namespace hair25d::completion
