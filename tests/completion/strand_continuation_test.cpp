// Seams read from the whole strand (Options::continuation_seams,
// completion.cpp read_relations, strand_continuation.h, session 27): two
// weakly ordered touching pieces of one paint whose side outlines run on
// across the line between them are one strand even where the seam geometry
// (the angles 3-12 px round the meeting points, seam_joins.h) refuses them.
#include <gtest/gtest.h>

#include <algorithm>

#include "hair25d/completion/completion.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

using namespace test;

const Rgba kHair{200, 170, 90, 255};

// A horizontal band (y 60..110) of one paint cut across by a drawn line at
// x = 150: piece 1 left of it, piece 2 right, each outlined. Two small
// shapes 3 and 4 (x 144..156) lie over both pieces where the line meets the
// band's sides (y 52..72 and 98..118): at both meeting points the third
// region lies above the pieces, where the seam geometry reads nothing, but
// farther from the line the band's sides run on across it.
Drawing band_cut_under_two_shapes() {
  Drawing d = blank(300, 170);
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 60 && y < 110; }, kHair, 1);
  paint(
      d, [](double x, double y) { return x >= 150 && x < 280 && y > 60 && y < 110; }, kHair, 2);
  const Rgba front{120, 90, 160, 255};
  paint(
      d, [](double x, double y) { return x > 144 && x < 156 && y > 52 && y < 72; }, front, 3);
  paint(
      d, [](double x, double y) { return x > 144 && x < 156 && y > 98 && y < 118; }, front, 4);
  return d;
}

// A band (y 70..94) under a vertical strand 3 of the same paint (x 150..174,
// y top..bottom) lying across it: pieces 1 (left) and 2 (right) touch the
// strand along its sides.
Drawing band_under_strand(double top, double bottom) {
  Drawing d = blank(300, 170);
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 70 && y < 94; }, kHair, 1);
  paint(
      d, [](double x, double y) { return x >= 174 && x < 280 && y > 70 && y < 94; }, kHair, 2);
  paint(
      d, [&](double x, double y) { return x >= 150 && x < 174 && y > top && y < bottom; }, kHair,
      3);
  return d;
}

std::vector<int> strand_of_1(Drawing d, const std::vector<RegionRelation>& relations,
                             bool continuation_seams = true) {
  d.relations = relations;
  const Input in = input_of(d, Vec2(150, 300));
  Options o;
  o.continuation_seams = continuation_seams;
  return regions_with(complete_strands(in, o), 1);
}

TEST(StrandContinuation, WeaklyOrderedHalvesWhoseSidesRunOnAreJoined) {
  const std::vector<int> joined{1, 2}, apart{1};
  const Drawing d = band_cut_under_two_shapes();
  const std::vector<RegionRelation> shapes{below(1, 3), below(2, 3), below(1, 4), below(2, 4)};
  const auto with = [&](const RegionRelation& order) {
    std::vector<RegionRelation> out = shapes;
    out.push_back(order);
    return out;
  };
  EXPECT_EQ(strand_of_1(d, with({1, 2, Relation::kAbove, 0.8})), joined);
  EXPECT_EQ(strand_of_1(d, with({1, 2, Relation::kBelow, -1.5})), joined);
  // Without the option only the seam geometry reads seams: apart.
  EXPECT_EQ(strand_of_1(d, with({1, 2, Relation::kAbove, 0.8}), false), apart);
  // A firm order keeps them apart.
  EXPECT_EQ(strand_of_1(d, with({1, 2, Relation::kAbove, 3.0})), apart);
  // So does another paint (the seam is read between pieces of one paint).
  Drawing other = d;
  repaint(other, 2, [](int, int) { return Rgba{185, 160, 100, 255}; });
  EXPECT_EQ(strand_of_1(other, with({1, 2, Relation::kAbove, 0.8})), apart);
}

// A strand lying over the band touches each piece along its own side: its
// slices run along it, past the band's sides (a long strand: no side seen
// within reach; a short one: its ends far off the band's sides). Weakly
// ordered over piece 1, it is not read as a seam, whatever its length.
TEST(StrandContinuation, AStrandLyingAcrossAnotherIsNoSeam) {
  for (const auto& [top, bottom] : {std::pair{10.0, 160.0}, std::pair{50.0, 115.0}}) {
    const std::vector<int> strand =
        strand_of_1(band_under_strand(top, bottom),
                    {{3, 1, Relation::kAbove, 0.8}, {3, 2, Relation::kAbove, 3.0}});
    EXPECT_EQ(std::count(strand.begin(), strand.end(), 3), 0) << "strand " << top << ".." << bottom;
    EXPECT_EQ(std::count(strand.begin(), strand.end(), 1), 1);
  }
}

}  // namespace
}  // namespace hair25d::completion
