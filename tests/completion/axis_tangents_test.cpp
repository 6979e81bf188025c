// On screentone an occluding edge whose end tangents are bent (an arm round
// the piece's tip or a corner) takes the piece's own axis near the cut
// (Options::screentone_axis_tangents, occluding_edges.cpp `axis_near_cut`).
#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

using namespace test;

// The generator's screentone paper and a dot tone over it (dots of 0.3
// periods on a 6-px lattice).
constexpr Rgba kPaper{235, 205, 175, 255};
Rgba dotted(int x, int y) {
  const double k = dot_cover(x, y, 6.0, 0.3, 0.4);
  const auto mix = [&](int p, int ink) {
    return static_cast<std::uint8_t>(std::lround(p + k * (ink - p)));
  };
  return Rgba{mix(235, 60), mix(205, 40), mix(175, 30), 255};
}

// A thin vertical strand (x 110..122) over a wide lowest region 4, cut by
// a band 3 (y 118..162) lying over it into the upper piece 1 (y 40..140)
// and the lower piece 2 (y 140..230). Piece 1's left side steps in 6 px
// (to x 116) over the last `step` px above the band, so that its visible
// outline at that end runs round the step, across the strand. Every region
// is toned with dots (a screentone drawing) unless `flat`.
Drawing stepped_thin_strand(double step, bool flat = false) {
  constexpr double in = 6, right = 122;
  Drawing d = blank(250, 300);
  paint(
      d, [](double x, double y) { return x > 20 && x < 230 && y > 20 && y < 280; }, kPaper, 4);
  paint(
      d,
      [=](double x, double y) {
        return x > 110 && x < right && y > 40 && y < 140 && !(x < 110 + in && y > 118 - step);
      },
      kPaper, 1);
  paint(
      d, [=](double x, double y) { return x > 110 && x < right && y >= 140 && y < 230; }, kPaper,
      2);
  paint(
      d, [](double x, double y) { return x > 40 && x < 210 && y > 118 && y < 162; }, kPaper, 3);
  if (!flat)
    for (int region : {1, 2, 3, 4}) repaint(d, region, dotted);
  d.relations = {below(4, 1), below(4, 2), below(4, 3), below(1, 3), below(2, 3)};
  return d;
}

// The regions completed in one strand with piece 1 (no background fill, no
// face joins, no path joins: on screentone one tone's pieces are joined
// through the band above them; the head above the strand).
std::vector<int> joined_with_1(const Drawing& d, bool axis) {
  Options o;
  o.inpaint_background = false;
  o.face_joins = false;
  o.screentone_axis_tangents = axis;
  o.path_joins = false;
  return regions_with(complete_strands(input_of(d, Vec2(125, 10)), o), 1);
}

TEST(AxisTangents, BentTangentOnScreentoneTakesThePiecesAxis) {
  // Straight sides: joined either way.
  const std::vector<int> joined{1, 2}, apart{1};
  const Drawing straight = stepped_thin_strand(0);
  EXPECT_EQ(joined_with_1(straight, false), joined);
  EXPECT_EQ(joined_with_1(straight, true), joined);
  // The step turns piece 1's left arm across the strand: over the angle
  // limit with its outline's tangents, joined with the piece's axis.
  for (double step : {4.0, 6.0}) {
    SCOPED_TRACE(step);
    const Drawing stepped = stepped_thin_strand(step);
    EXPECT_EQ(joined_with_1(stepped, false), apart);
    EXPECT_EQ(joined_with_1(stepped, true), joined);
    // Screentone only: the flat drawing's bent tangents stay its own.
    EXPECT_EQ(joined_with_1(stepped_thin_strand(step, true), true), apart);
  }
}

}  // namespace
}  // namespace hair25d::completion
