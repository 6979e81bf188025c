// Whole-strand evidence of a seam (private): do two touching pieces continue
// one another as one strand across the line between them? Measured on
// slices parallel to that line on both sides of it, up to 24 px from it: a
// strand cut across shows side outlines that run on across the line
// (matching position and tangent of the slices' ends fitted on each side);
// a strand lying over another touches it along its own side, so its slices
// run along it, past the lower one's sides or out of reach. Where a region
// lies above a piece its outline hides the piece's side; only the slices'
// ends on the paper or on regions not above count, so the sides are read
// farther from the line than the seam geometry's 12 px round the meeting
// points (seam_joins.h). Session 27 (joins57, docs/completion-record.md).
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
  // Median slice widths (0: no slice with both ends seen) and the number of
  // such slices, for diag_relations: not used by continues_one_strand.
  double width_a = 0.0, width_b = 0.0;
  int slices_a = 0, slices_b = 0;
  SideFit low, high;
};

// The slices of a and b (outline-assigned labels, rims closed), up to a
// distance from the a–b line of its length (6 to 24 px). A slice end on a
// region directly above the piece (`above(x, y)`: x directly above y) or on
// the other piece is hidden, not a side.
StrandContinuation strand_continuation(const Context& ctx, int a, int b,
                                       const std::function<bool(int, int)>& above);

// Whether the measures say one strand cut across: some side outline fitted
// on both pieces, and every such side running on across the line (the
// fits within 2.5 px of one another at it, their directions within 20°).
// The widths are not used: both pieces' widths (both slice ends seen) were
// measured on none of the weak touching orders of one paint this rule takes
// on dev flat and mixed 2000-2099 (their far sides lie under other
// strands). Chosen on those (docs/completion-record.md, "Session 27").
bool continues_one_strand(const StrandContinuation& c);

}  // namespace hair25d::completion::detail
