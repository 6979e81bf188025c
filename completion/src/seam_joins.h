// Seam joins (private): two touching pieces of one strand that the layering
// orders weakly. A strand cut across by a drawn line (a fork line bending
// into its side, a line drawn over it) shows two pieces of one paint whose
// side outlines run on straight across the line between them; where one
// strand lies on another, the line between them is the upper one's outline
// and runs on into it, and the lower one's side ends on it (a T).
#pragma once

#include <functional>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

// The outlines round one place where pieces a and b meet a third region (or
// the paper) X: the angles (degrees) between the directions leaving the
// meeting point along the a–X, b–X and a–b boundaries.
struct SeamEnd {
  Vec2 at{0, 0};
  int third = 0;         // X (0: no region)
  double sides = 0.0;    // between a–X and b–X: 180 where the sides run straight on
  double through = 0.0;  // the larger of a–b with a–X and with b–X: 180 for a T over a or b
};

// The labels of `box` (image pixels) with the drawn lines' light rims, left
// unlabelled by the outline assignment, closed by growing the labels 2 px.
cv::Mat closed_labels(const Context& ctx, const cv::Rect& box);

// The box round where a and b may touch, grown by `reach` px, clipped to the
// image (empty where their boxes are apart).
cv::Rect contact_box(const Context& ctx, int a, int b, int reach);

// The meeting points of a, b and a third region along their common line
// (outline-assigned labels, the drawn line's unlabelled rim closed), with
// the angles measured where each boundary runs at least a few pixels.
std::vector<SeamEnd> seam_ends(const Context& ctx, int a, int b);

// Whether a and b meet at a seam: some meeting point, with the paper or a
// region lying above neither (`above(x, y)`: x directly above y) as the
// third, where the side outlines run on across the line between them
// (`sides` at least 140°) and that line is no bar running on into a side
// (`through` at most 150°). Where a strand lies above both pieces, its own
// outline makes the sides and says nothing. Chosen on the weakly ordered
// touching pairs of one paint of dev sets flat and mixed 2000-2099
// (docs/completion-record.md, "Session 17: seam joins").
bool seam_geometry(const Context& ctx, int a, int b, const std::function<bool(int, int)>& above);

}  // namespace hair25d::completion::detail
