#include "hair25d/layering/learned_metric.h"

namespace hair25d::layering {

// Produced by bench/layering/train_layering.cpp on generated drawings only
// (never the annotated cases), Release build:
//   train_layering --cases 200 --seed 20000
// 6984 occluding boundaries between hair regions of known order; sign right
// on them: paper Φ 78.8%, these 82.6%. Order as in boundary_features.
const BoundaryFeatures& learned_weights() {
  static constexpr BoundaryFeatures kWeights = {
      1.67047, 3.49366,   -0.159277, 0.274087, 2.40703,  -4.22548,  8.29806,  -0.469049, -3.54197,
      0.80221, -0.386472, -0.103737, 0.140321, 0.146257, -0.499055, -2.37399, 1.31283,   -0.105303};
  return kWeights;
}

// Same bench program, same drawings: occluding boundaries between hair
// regions, same depth against ordered. Order as in equal_features.
const EqualFeatures& equal_weights() {
  static constexpr EqualFeatures kWeights = {1.35717,   -1.02302, -2.6003,  -0.755346, 0.285989,
                                             -0.500651, 2.1925,   -1.60583, -7.54649,  2.55447};
  return kWeights;
}

}  // namespace hair25d::layering
