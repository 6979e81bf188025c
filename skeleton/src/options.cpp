#include <cmath>
#include <string>

#include "hair25d/skeleton/strand_mesh.h"
#include "hair25d/skeleton/strand_skeleton.h"

namespace hair25d::skeleton {
namespace {

bool fail(std::string* error, const std::string& message) {
  if (error != nullptr) *error = message;
  return false;
}

bool positive(double v) { return std::isfinite(v) && v > 0.0; }

}  // namespace

bool Options::is_valid(std::string* error) const {
  if (!positive(sample_spacing))
    return fail(error, "skeleton::Options::sample_spacing = " + std::to_string(sample_spacing) +
                           "; must be > 0");
  if (!positive(corner_arm))
    return fail(error,
                "skeleton::Options::corner_arm = " + std::to_string(corner_arm) + "; must be > 0");
  if (!(tip_angle_deg > 0.0 && tip_angle_deg < 180.0))
    return fail(error, "skeleton::Options::tip_angle_deg = " + std::to_string(tip_angle_deg) +
                           "; must be in (0, 180)");
  if (!positive(node_spacing))
    return fail(error, "skeleton::Options::node_spacing = " + std::to_string(node_spacing) +
                           "; must be > 0");
  if (smoothing_passes < 0)
    return fail(error, "skeleton::Options::smoothing_passes = " + std::to_string(smoothing_passes) +
                           "; must be >= 0");
  if (max_tips < 1)
    return fail(error,
                "skeleton::Options::max_tips = " + std::to_string(max_tips) + "; must be >= 1");
  if (!(std::isfinite(min_tip_separation) && min_tip_separation >= 0.0))
    return fail(error, "skeleton::Options::min_tip_separation = " +
                           std::to_string(min_tip_separation) + "; must be >= 0");
  return true;
}

bool MeshOptions::is_valid(std::string* error) const {
  if (!positive(max_edge))
    return fail(error,
                "skeleton::MeshOptions::max_edge = " + std::to_string(max_edge) + "; must be > 0");
  if (!(min_angle_deg >= 0.0 && min_angle_deg <= 20.7))
    return fail(error, "skeleton::MeshOptions::min_angle_deg = " + std::to_string(min_angle_deg) +
                           "; must be in [0, 20.7] so that refinement terminates");
  if (max_vertices < 3)
    return fail(error, "skeleton::MeshOptions::max_vertices = " + std::to_string(max_vertices) +
                           "; must be >= 3");
  if (!(std::isfinite(outline_spacing) && outline_spacing >= 0.0))
    return fail(error, "skeleton::MeshOptions::outline_spacing = " +
                           std::to_string(outline_spacing) + "; must be >= 0");
  return true;
}

const char* to_string(SkeletonStatus status) {
  switch (status) {
    case SkeletonStatus::kTips:
      return "tips";
    case SkeletonStatus::kFarthestTip:
      return "farthest-tip";
    case SkeletonStatus::kDegenerate:
      return "degenerate";
  }
  return "unknown";
}

}  // namespace hair25d::skeleton
