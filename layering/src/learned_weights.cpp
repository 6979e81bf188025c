#include "hair25d/layering/learned_metric.h"

namespace hair25d::layering {

// Produced by bench/layering/train_layering.cpp on generated drawings only
// (never the annotated cases), Release build:
//   train_layering --cases 200 --seed 20000
// 6984 occluding boundaries between hair regions of known order; sign right
// on them: paper Φ 78.8%, these 82.6%. Order as in boundary_features.
const BoundaryFeatures& learned_weights() {
  static constexpr BoundaryFeatures kWeights = {1.4864, 3.06588, -0.624876, 0.0431756, 2.39199, -4.31021, 9.00344, -0.461842, -3.30205, 0.54134, -0.235162, 0.197652, -0.0189332, -0.172832, -0.507865, -1.89478, 1.66801, 0.182479};
  return kWeights;
}

// Same bench program, same drawings: occluding boundaries between hair
// regions, same depth against ordered. Order as in equal_features.
const EqualFeatures& equal_weights() {
  static constexpr EqualFeatures kWeights = {0.026446, -0.335015, -4.58186, -0.789281, 0.582041, -0.479522, 2.55376, -1.48123, -7.09291, 1.88877};
  return kWeights;
}

}  // namespace hair25d::layering
