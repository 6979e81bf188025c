#include "paper.h"

#include "hair25d/segment/regions.h"

namespace hair25d::segment::detail {

bool is_paper(const Rgba& p) { return p.a < kOpaqueAlpha; }

Eigen::Vector3d colour_on_white(const Rgba& p) {
  const double a = p.a / 255.0;
  return Eigen::Vector3d(a * p.r + (1.0 - a) * 255.0, a * p.g + (1.0 - a) * 255.0,
                         a * p.b + (1.0 - a) * 255.0);
}

}  // namespace hair25d::segment::detail
