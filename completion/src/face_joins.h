// Joins across the face (private): the face is no hair region, yet it hides
// the back hair behind it just as a strand does. Back-hair pieces seen on
// opposite sides of the face are joined like case-1 pieces of §5.1.
#pragma once

#include <set>
#include <vector>

#include "bank_crossings.h"
#include "context.h"

namespace hair25d::completion::detail {

// The face: the connected non-hair, non-ink area around the head centre,
// with its drawn outline, clipped to a disc around the head (an open line
// lets it leak into the neck or the paper). Empty when none is found.
struct Face {
  cv::Mat mask;  // CV_8U, image size, 1 = face
  int pixels = 0;
  Vec2 centroid{0, 0};
};
Face find_face(const Context& ctx);

// CV_8U, image size: 1 where no region lies and the drawing is neither
// transparent nor dark — what the face, the neck, the body and the paper
// are made of (find_face and body_mask split it into areas).
cv::Mat open_pixels(const Context& ctx);

// A pair of back-hair pieces joined across the face: cost (lower is surer)
// and the completed area (the face between their bordering outlines).
struct FaceJoin {
  int region_a = 0, region_b = 0;
  Vec2 pa{0, 0}, qa{0, 0}, pb{0, 0}, qb{0, 0};  // ends of the outlines along the face
  // The same runs as spans of each region's contour (unwrapped, begin <= end).
  int begin_a = 0, end_a = 0, begin_b = 0, end_b = 0;
  double cost = 0.0;
  // Closed polygon between two C¹ Béziers across the face (join_curves.h);
  // it counts only over the face and occluders.
  Polyline patch;
};

// Candidates, cheapest first. A piece qualifies when it is above no other
// region (back hair, not bangs lying on the face) and its outline runs along
// the face with the face bulging into it (the face occludes it; a bang's tip
// lying on the face is convex instead).
// `front` holds the regions that are no back hair: above some region, or one
// strand with such a region (related `equal` or joined).
std::vector<FaceJoin> face_join_candidates(const Context& ctx, const Face& face,
                                           const std::set<int>& front);

// The head, neck and body in front of the back hair (body_joins.cpp): the
// face and the open (non-hair, non-ink) areas next to its drawn outline,
// not the paper (the open area with most pixels on the image's border).
// CV_8U, image size, 1 = body; empty without a face. With `dark_body` the
// areas darker than Options::dark_luma count too (dark clothes; only ink
// parts the areas then).
cv::Mat body_mask(const Context& ctx, const Face& face, bool dark_body = false);

// Back-hair pieces (not in `front`, no tails) seen on both sides of the
// neck or body: rays from each piece's outline across the body (at least
// a few pixels of it not the face: across the face alone the face joins
// decide) and hair lying over either piece land on the other both ways;
// not when both pieces have the body behind them too (strands lying on the
// neck); their paint agrees (tone, cel colours, windows or one field).
// `body` gets body_mask (left empty when there are no two pieces): the
// joins' bands count over it. Most rays first.
class RegionTones;
class RegionFields;
std::vector<MassJoin> body_join_candidates(const Context& ctx, const Face& face,
                                           const std::set<int>& front, RegionTones& tones,
                                           RegionFields& fields, cv::Mat* body);

}  // namespace hair25d::completion::detail
