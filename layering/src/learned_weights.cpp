#include "hair25d/layering/learned_metric.h"

namespace hair25d::layering {

// Produced by bench/layering/train_layering.cpp on generated drawings only
// (never the annotated cases), Release build:
//   train_layering --cases 200 --seed 20000
// 6984 occluding boundaries between hair regions of known order; sign right
// on them: paper Φ 78.8%, these 82.6%. Order as in boundary_features.
const BoundaryFeatures& learned_weights() {
  static constexpr BoundaryFeatures kWeights = {
      1.42871,    3.1979,    -0.654759, 0.107401, 2.30708,   -4.35105,
      9.09997,    -0.466469, -3.27234,  0.420521, -0.150482, 0.073731,
      -0.0634916, -0.427399, -0.52139,  -1.88515, 1.65789,   0.338336};
  return kWeights;
}

// Same bench program, same drawings: occluding boundaries between hair
// regions, same depth against ordered. Order as in equal_features.
const EqualFeatures& equal_weights() {
  static constexpr EqualFeatures kWeights = {-0.740681, -0.191578, -4.76613,  -0.798823, 0.599937,
                                             -0.430811, 2.39866,   -0.939171, -7.49131,  1.57257};
  return kWeights;
}

}  // namespace hair25d::layering
