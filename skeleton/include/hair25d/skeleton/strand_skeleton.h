// The skeleton of one completed hair strand (paper §6, first part): the medial
// axis from the root to each tip (a visible sharp corner, or a visible rounded
// tapering end), joined into one tree.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/hair_model.h"

namespace hair25d::skeleton {

struct Options {
  double sample_spacing = 3.0;      // pixels between outline samples fed to the triangulation
  double corner_arm = 9.0;          // pixels along the outline on each side to measure a corner
  double tip_angle_deg = 80.0;      // a convex corner narrower than this is a tip candidate
  double node_spacing = 8.0;        // pixels between skeleton nodes after resampling
  int smoothing_passes = 20;        // Laplacian passes on each branch before resampling
  int max_tips = 8;                 // keep at most this many tips (the sharpest)
  double min_tip_separation = 0.0;  // pixels between tips; 0 = 2 × corner_arm
  bool find_rounded_tips = true;    // also visible tapering axis ends without a sharp corner

  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

struct Input {
  // The completed strand's outline: one closed polygon in image pixels (either
  // orientation, not closed by repetition), at least 3 distinct points.
  Polyline outline;
  // Optional, #outline flags: true where that outline vertex lies under another
  // strand (a corner there is hidden, so it is not a tip; §6 "locally above").
  std::vector<bool> covered;
  // Optional: where the root is (the head centre, or the middle of the occluded
  // root part). The root is the skeleton end nearest to it.
  std::optional<Vec2> root_hint;
};

// Why the skeleton looks the way it does.
enum class SkeletonStatus {
  kTips,         // tips found at sharp visible corners or visible rounded tapering ends
  kFarthestTip,  // neither: the medial-axis end farthest from the root
  kDegenerate,   // the outline encloses (almost) no area: a single node at its centre
};

const char* to_string(SkeletonStatus status);

struct Result {
  Skeleton skeleton;              // node 0 is the root, parent[i] < i, tips are leaves
  std::vector<Vec2> tip_corners;  // the outline corners (or rounded ends) that became tips
  int rounded_tips = 0;           // how many tips are rounded ends, not sharp corners
  Vec2 root{0.0, 0.0};
  SkeletonStatus status = SkeletonStatus::kTips;
};

// Builds the tip-to-root medial-axis tree of the outline and resamples it to
// nodes `node_spacing` apart. Throws hair25d::Error for invalid options, fewer
// than 3 distinct outline points, non-finite coordinates or a `covered` of the
// wrong size; a polygon of (almost) zero area gives a one-node skeleton.
Result build_skeleton(const Input& input, const Options& options = {});

// Sharp convex corners of a closed outline: indices into `outline`, sharpest
// first. `covered` (optional, #outline) removes hidden corners.
std::vector<int> find_tip_corners(const Polyline& outline, const std::vector<bool>& covered,
                                  const Options& options = {});

}  // namespace hair25d::skeleton
