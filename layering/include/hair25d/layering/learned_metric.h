// A learned boundary metric, an addition to paper §4.4: a logistic model over
// the paper's own cues (junction angles, Φ_J, Φ_R) and region shape, trained
// on generated drawings, that can stand in for Φ as the unary term of Eq. (2).
#pragma once

#include <array>
#include <vector>

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
  // The same sectors from tangents of quadratics fitted near the junction
  // (curved_leaving_direction): a rounded tip or a bent outline keeps its
  // own direction there.
  double curved_left = 0.0;
  double curved_right = 0.0;
  // The share of a circle about the junction (2.5 and 5 line widths) in the
  // left and right regions, × 2π: their sectors read off the label map, which
  // holds where boundaries are short or bend.
  double circle_left = 0.0, circle_right = 0.0;
  double circle_wide_left = 0.0, circle_wide_right = 0.0;
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
  // The share of each region's perimeter that borders the other (all their
  // common boundaries): a strand lying on a mass is bordered mostly by it.
  double shared_left = 0.0;
  double shared_right = 0.0;
};

inline constexpr int kBoundaryFeatureCount = 30;
using BoundaryFeatures = std::array<double, kBoundaryFeatureCount>;

BoundaryFeatures boundary_features(const BoundaryCues& cues);

// The model's terms: the features, then their products f_i · |f_j| (i ≠ j,
// row by row), which let one cue's meaning depend on another's strength (a
// tip counts where the other sector is not straight, Φ_R where the junctions
// are silent) and still change sign with the features.
inline constexpr int kLearnedTermCount = kBoundaryFeatureCount * kBoundaryFeatureCount;
using LearnedTerms = std::array<double, kLearnedTermCount>;
LearnedTerms learned_terms(const BoundaryFeatures& features);

// The model's log-odds that the left region lies above the right one.
double learned_metric(const BoundaryFeatures& features);

// The weights in use (layering/src/learned_weights.cpp says how they were made).
const LearnedTerms& learned_weights();

// Region context, a second stage (an addition to the paper): hair is drawn in
// layers, so a region that the boundary model puts over most of its other
// neighbours is likely over this one too. For every boundary, the length-
// weighted mean of tanh(log-odds / 2) "this region is above", over each
// region's occluding boundaries with other hair regions except those with the
// region across this boundary, left minus right (in [−2, 2]; 0 where a region
// has no other neighbour).
struct ContextBoundary {
  int left = 0, right = 0;  // hair regions (> 0); others are left out
  double length = 0.0;
  double log_odds = 0.0;  // the boundary model's, left above
  bool used = true;       // false: left out (not occluding, or same depth)
};
std::vector<double> context_differences(const std::vector<ContextBoundary>& boundaries);

// The second stage's terms: the boundary model's log-odds, the context
// difference, and the context where the boundary model is unsure. All change
// sign with the walking direction; no intercept.
inline constexpr int kContextTermCount = 3;
using ContextTerms = std::array<double, kContextTermCount>;
ContextTerms context_terms(double log_odds, double context);
// Log-odds that the left region lies above, after the context.
double context_metric(double log_odds, double context);
const ContextTerms& context_weights();

// Same depth or ordered? A second learned model, for occluding boundaries:
// two halves of a forked strand, or two pieces of one strand meeting where
// lines converge, are divided by a drawn line just like an occluder and its
// occludee. Its features do not change when left and right swap.
struct EqualCues {
  double length_widths = 0.0;              // boundary length / line width
  double contrast_ratio = 0.0;             // median line contrast / the occluding threshold
  double contrast_low_ratio = 0.0;         // lower-quartile contrast / the threshold
  double colour_difference = 0.0;          // across the boundary, 0..255 (LineResponse)
  double typical_colour_difference = 0.0;  // median of it over the image's hair boundaries
  double order_log_odds = 0.0;  // learned_metric of the boundary (its sign does not matter)
  double area_left = 0.0, area_right = 0.0;  // pixels
  EndAngles start, end;
  // The share of each region's perimeter on its common boundary with the
  // other (BoundaryCues::shared_left / shared_right).
  double shared_left = 0.0, shared_right = 0.0;
};

inline constexpr int kEqualFeatureCount = 14;
using EqualFeatures = std::array<double, kEqualFeatureCount>;

EqualFeatures equal_features(const EqualCues& cues);

// Log-odds that the boundary separates regions at the same depth.
double equal_metric(const EqualFeatures& features);

const EqualFeatures& equal_weights();

}  // namespace hair25d::layering
