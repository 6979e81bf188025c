#include "hair25d/pipeline/head_center.h"

#include <cmath>
#include <sstream>

#include "hair25d/core/error.h"

namespace hair25d::pipeline {

void check_head_center(const Vec2& head, int width, int height, const std::string& what) {
  std::ostringstream value;
  value << "(" << head.x() << ", " << head.y() << ")";
  if (!std::isfinite(head.x()) || !std::isfinite(head.y()))
    throw Error(what + " " + value.str() + ": the head centre must be finite");
  const auto within = [](double v, int size) {
    return v >= -kHeadReach * size && v <= (1.0 + kHeadReach) * size;
  };
  if (!within(head.x(), width) || !within(head.y(), height)) {
    std::ostringstream rule;
    rule << what << " " << value.str() << ": the head centre must lie within " << kHeadReach
         << " drawing sizes of the " << width << "x" << height << " drawing (x in ["
         << -kHeadReach * width << ", " << (1.0 + kHeadReach) * width << "], y in ["
         << -kHeadReach * height << ", " << (1.0 + kHeadReach) * height << "])";
    throw Error(rule.str());
  }
}

}  // namespace hair25d::pipeline
