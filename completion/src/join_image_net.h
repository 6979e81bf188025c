// Session 28 (docs/completion-record.md): a join scorer that also looks at
// the drawing, a small convolutional net over the candidate's crop
// (join_crop.h) beside the scorer's inputs, trained offline by
// bench/completion/train_join_cnn.py and read from ONNX (private).
#pragma once

#include <array>
#include <cstdint>
#include <opencv2/dnn.hpp>
#include <string>
#include <vector>

#include "hair25d/completion/join_scorer.h"

namespace hair25d::completion::detail {

// The crop side the nets are trained on (train_join_cnn.py --size).
inline constexpr int kJoinImageCropSize = 48;

class JoinImageNet {
 public:
  // Reads the net `path` (inputs "crop": 1 × kJoinCropChannels × 48 × 48
  // in [0, 1], "features": 1 × kJoinFeatures standardised; output "logit")
  // and `path`.norm.txt (the features' means, then their deviations).
  // Throws hair25d::Error naming the file when either cannot be read.
  explicit JoinImageNet(const std::string& path);
  // Probability that the pieces are one strand; `crop` as
  // JoinCandidate::crop of kJoinImageCropSize.
  double probability(const std::vector<std::uint8_t>& crop, const JoinFeatures& features);

 private:
  cv::dnn::Net net_;
  std::array<float, kJoinFeatures> mean_{}, std_{};
};

}  // namespace hair25d::completion::detail
