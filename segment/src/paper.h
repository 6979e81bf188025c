// Private: transparent paper. A drawing's transparent pixels are no part of
// any hair region (alpha < kOpaqueAlpha, see hair25d/segment/regions.h).
#pragma once

#include <Eigen/Core>

#include "hair25d/core/image.h"
#include "hair25d/segment/regions.h"

namespace hair25d::segment::detail {

inline bool is_paper(const Rgba& p) { return p.a < kOpaqueAlpha; }

// The pixel's colour as seen on white paper (what the line detector sees).
Eigen::Vector3d colour_on_white(const Rgba& p);

}  // namespace hair25d::segment::detail
