// Private: a small Gaussian mixture of RGB colours fitted by EM, giving the
// colour similarity of the graph cut's terminal weights (paper §3).
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hair25d::segment::detail {

class ColourModel {
 public:
  // Up to `components` Gaussians fitted to `samples` (RGB 0-255); every
  // component's spread is at least `sigma_min` grey levels. No samples: an
  // empty model whose similarity is 0 everywhere.
  static ColourModel fit(const std::vector<Eigen::Vector3d>& samples, int components,
                         double sigma_min);

  // In [0, 1]: exp(-m² / 2) for the smallest Mahalanobis distance m to a component.
  double similarity(const Eigen::Vector3d& colour) const;
  bool empty() const { return means_.empty(); }
  int size() const { return static_cast<int>(means_.size()); }

 private:
  std::vector<Eigen::Vector3d> means_;
  std::vector<Eigen::Matrix3d> inverse_covariances_;
};

}  // namespace hair25d::segment::detail
