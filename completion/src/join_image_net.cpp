#include "join_image_net.h"

#include <cmath>
#include <fstream>

#include "hair25d/core/error.h"

namespace hair25d::completion::detail {

JoinImageNet::JoinImageNet(const std::string& path) {
  try {
    net_ = cv::dnn::readNetFromONNX(path);
  } catch (const cv::Exception& e) {
    throw Error("JoinScorerOptions::image_net = " + path + ": cannot read the net (" + e.what() +
                ")");
  }
  if (net_.empty()) throw Error("JoinScorerOptions::image_net = " + path + ": an empty net");
  std::ifstream norm(path + ".norm.txt");
  for (float& v : mean_) norm >> v;
  for (float& v : std_) norm >> v;
  if (!norm) throw Error("JoinScorerOptions::image_net: cannot read " + path + ".norm.txt");
}

double JoinImageNet::probability(const std::vector<std::uint8_t>& crop,
                                 const JoinFeatures& features) {
  constexpr int n = kJoinImageCropSize;
  if (crop.size() != static_cast<std::size_t>(kJoinCropChannels) * n * n)
    throw Error("JoinImageNet: a crop of " + std::to_string(crop.size()) + " bytes; must be " +
                std::to_string(kJoinCropChannels * n * n));
  const int crop_shape[] = {1, kJoinCropChannels, n, n};
  cv::Mat x(4, crop_shape, CV_32F);
  float* px = x.ptr<float>();
  for (std::size_t i = 0; i < crop.size(); ++i) px[i] = crop[i] / 255.0f;
  const int feature_shape[] = {1, kJoinFeatures};
  cv::Mat f(2, feature_shape, CV_32F);
  for (int k = 0; k < kJoinFeatures; ++k) f.ptr<float>()[k] = (features[k] - mean_[k]) / std_[k];
  try {
    net_.setInput(x, "crop");
    net_.setInput(f, "features");
    const cv::Mat out = net_.forward("logit");
    return 1.0 / (1.0 + std::exp(-static_cast<double>(out.ptr<float>()[0])));
  } catch (const cv::Exception& e) {
    throw Error(std::string("JoinImageNet: the net failed (") + e.what() + ")");
  }
}

}  // namespace hair25d::completion::detail
