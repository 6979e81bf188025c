#include "paper.h"

namespace hair25d::segment::detail {

Eigen::Vector3d colour_on_white(const Rgba& p) {
  if (p.a == 255) return Eigen::Vector3d(p.r, p.g, p.b);
  const double a = p.a / 255.0;
  return Eigen::Vector3d(a * p.r + (1.0 - a) * 255.0, a * p.g + (1.0 - a) * 255.0,
                         a * p.b + (1.0 - a) * 255.0);
}

}  // namespace hair25d::segment::detail
