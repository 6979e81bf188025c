// Whole-strand evidence of a seam (private): do two touching pieces continue
// one another as one strand across the line between them? Measured on
// slices parallel to that line on both sides of it: a strand cut across
// shows, on both sides, one width and side outlines that run on (matching
// position and tangent) across the line, and the line spans that width; a
// strand lying over another touches it along its side, so its own slices run
// along it (much wider than the lower one's).
#pragma once

#include <functional>

#include "context.h"

namespace hair25d::completion::detail {

// One side outline (the slices' low or high ends) fitted on each piece as a
// line over the distance from the dividing line, compared where it crosses.
struct SideFit {
  bool measured = false;  // both pieces had enough slices with that end seen
  double offset = 0.0;    // px between the two fits at the dividing line
  double angle = 0.0;     // degrees between their directions
};

struct StrandContinuation {
  bool measured = false;     // the a–b line and slices on both sides were found
  double line_length = 0.0;  // the a–b line's extent along its main direction (px)
  double bend = 0.0;         // its spread across that direction (px, standard deviation)
  double width_a = 0.0, width_b = 0.0;  // median slice widths (0: no slice with both ends seen)
  int slices_a = 0, slices_b = 0;       // slices with both ends seen
  SideFit low, high;
};

// The slices of a and b (outline-assigned labels, rims closed), up to a
// distance from the a–b line of its length (6 to 24 px). A slice end on a
// region directly above the piece (`above(x, y)`: x directly above y) or on
// the other piece is hidden, not a side.
StrandContinuation strand_continuation(const Context& ctx, int a, int b,
                                       const std::function<bool(int, int)>& above);

// Whether the measures say one strand cut across: widths that agree, a line
// spanning them, side outlines running on across it and none breaking.
bool continues_one_strand(const StrandContinuation& c);

}  // namespace hair25d::completion::detail
