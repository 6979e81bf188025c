// A learned boundary metric, an addition to paper §4.4: a logistic model over
// the paper's own cues (junction angles, Φ_J, Φ_R) and region shape, trained
// on generated drawings, that can stand in for Φ as the unary term of Eq. (2).
#pragma once

#include <array>

namespace hair25d::layering {

// What one end of a boundary shows at its junction (walking away from it):
// the sectors of the boundary's left and right regions, radians.
struct EndAngles {
  bool used = false;  // false at a cusp or where the boundary has no junction
  double left = 0.0;
  double right = 0.0;
  int rays = 3;  // boundaries meeting at the junction
  // The same sectors from directions fitted over a 3 × longer arc.
  double wide_left = 0.0;
  double wide_right = 0.0;
};

// The cues of one boundary between regions `left` and `right`. Every feature
// changes sign when left and right swap, so a model without intercept gives
// the same answer whichever way the boundary is walked.
struct BoundaryCues {
  EndAngles start, end;
  double phi_r = 0.0;       // Φ_R / ‖L‖², left above when positive
  double area_left = 0.0;   // pixels
  double area_right = 0.0;  // pixels
  double perimeter_left = 0.0;
  double perimeter_right = 0.0;
  // How far the boundary turns from its first to its last direction, radians,
  // positive toward its left: the left region is then the convex one.
  double turning = 0.0;
};

inline constexpr int kBoundaryFeatureCount = 18;
using BoundaryFeatures = std::array<double, kBoundaryFeatureCount>;

BoundaryFeatures boundary_features(const BoundaryCues& cues);

// The model's log-odds that the left region lies above the right one.
double learned_metric(const BoundaryFeatures& features);

// The weights in use (layering/src/learned_weights.cpp says how they were made).
const BoundaryFeatures& learned_weights();

}  // namespace hair25d::layering
