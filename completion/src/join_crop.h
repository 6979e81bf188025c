// A small image of the drawing around a strand-join candidate (session 28:
// an image cue for the join scorer, paper §5.1; private): the chord between
// the two cut ends runs left to right through the centre, piece a on the
// left, piece b on the right, scaled to the gap.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

// Where a size × size crop lies in the drawing: crop pixel (col, row)'s
// centre is centre + (u − ½)·side·along + (v − ½)·side·across with
// u = (col + ½) / size, v = (row + ½) / size.
struct JoinCropFrame {
  Vec2 centre{0, 0};
  Vec2 along{1, 0}, across{0, 1};  // unit; along: a's cut towards b's
  double side = 0;                 // drawing pixels the crop spans
  int size = 0;
  Vec2 to_drawing(double col, double row) const;
  Vec2 to_crop(const Vec2& p) const;  // (col, row), continuous
};

// The frame of the cuts p_a q_a and p_b q_b: centred between the cuts'
// middles, spanning twice the chord between them or twice the wider cut,
// at least kMinCropSide px.
JoinCropFrame join_crop_frame(const Vec2& pa, const Vec2& qa, const Vec2& pb, const Vec2& qb,
                              int size);

// The kJoinCropChannels planes (join_scorer.h) of `frame`, sampled at the
// nearest pixel: `labels` gives the regions, `above(l)` whether region l
// lies above piece a or b, `patch` (a closed polygon, drawing pixels) the
// hidden part. Outside the drawing: white paper, no region.
std::vector<std::uint8_t> render_join_crop(const Image& image, const LabelMap& labels, int a, int b,
                                           const std::function<bool(int)>& above,
                                           const Polyline& patch, const JoinCropFrame& frame);

// The crop of a candidate joining edges a and b with `patch`.
std::vector<std::uint8_t> join_crop(const Context& ctx, const Edge& a, const Edge& b,
                                    const Polyline& patch, int size);

}  // namespace hair25d::completion::detail
