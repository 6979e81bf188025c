#include "colour_model.h"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>

namespace hair25d::segment::detail {

ColourModel ColourModel::fit(const std::vector<Eigen::Vector3d>& all, int components,
                             double sigma_min) {
  ColourModel model;
  if (all.empty() || components < 1) return model;
  // A strided subsample keeps EM cheap on long strokes.
  std::vector<Eigen::Vector3d> x;
  const std::size_t stride = std::max<std::size_t>(1, all.size() / 1500);
  for (std::size_t i = 0; i < all.size(); i += stride) x.push_back(all[i]);
  const int n = static_cast<int>(x.size());
  const int k = std::clamp(n / 8, 1, components);

  // Farthest-point start: deterministic and spreads the components over the
  // distinct tones (light, shadow, highlight).
  Eigen::Vector3d mean = Eigen::Vector3d::Zero();
  for (const auto& v : x) mean += v;
  mean /= n;
  std::vector<Eigen::Vector3d> mu;
  {
    int first = 0;
    double bd = 1e300;
    for (int i = 0; i < n; ++i)
      if (double d = (x[i] - mean).squaredNorm(); d < bd) bd = d, first = i;
    mu.push_back(x[first]);
  }
  std::vector<double> dmin(n, 1e300);
  while (static_cast<int>(mu.size()) < k) {
    int far = 0;
    double fd = -1.0;
    for (int i = 0; i < n; ++i) {
      dmin[i] = std::min(dmin[i], (x[i] - mu.back()).squaredNorm());
      if (dmin[i] > fd) fd = dmin[i], far = i;
    }
    if (fd < sigma_min * sigma_min) break;  // no distinct second tone
    mu.push_back(x[far]);
  }
  const int kk = static_cast<int>(mu.size());
  const Eigen::Matrix3d floor = sigma_min * sigma_min * Eigen::Matrix3d::Identity();
  std::vector<Eigen::Matrix3d> cov(kk, floor * 4.0);
  std::vector<double> weight(kk, 1.0 / kk);
  Eigen::MatrixXd resp(n, kk);
  for (int iter = 0; iter < 12; ++iter) {
    // E step.
    std::vector<Eigen::Matrix3d> inv(kk);
    std::vector<double> lognorm(kk);
    for (int j = 0; j < kk; ++j) {
      inv[j] = cov[j].inverse();
      lognorm[j] = std::log(weight[j]) - 0.5 * std::log(std::max(cov[j].determinant(), 1e-300));
    }
    for (int i = 0; i < n; ++i) {
      double best = -1e300;
      for (int j = 0; j < kk; ++j) {
        const Eigen::Vector3d d = x[i] - mu[j];
        resp(i, j) = lognorm[j] - 0.5 * d.dot(inv[j] * d);
        best = std::max(best, resp(i, j));
      }
      double sum = 0.0;
      for (int j = 0; j < kk; ++j) sum += resp(i, j) = std::exp(resp(i, j) - best);
      resp.row(i) /= sum;
    }
    // M step.
    for (int j = 0; j < kk; ++j) {
      const double nj = resp.col(j).sum();
      if (nj < 1e-9) continue;
      Eigen::Vector3d m = Eigen::Vector3d::Zero();
      for (int i = 0; i < n; ++i) m += resp(i, j) * x[i];
      m /= nj;
      Eigen::Matrix3d c = Eigen::Matrix3d::Zero();
      for (int i = 0; i < n; ++i) {
        const Eigen::Vector3d d = x[i] - m;
        c += resp(i, j) * d * d.transpose();
      }
      mu[j] = m;
      cov[j] = c / nj + floor;
      weight[j] = nj / n;
    }
  }
  for (int j = 0; j < kk; ++j) {
    if (weight[j] < 0.02) continue;  // a stray component from a few line pixels
    model.means_.push_back(mu[j]);
    model.inverse_covariances_.push_back(cov[j].inverse());
  }
  if (model.means_.empty()) {
    model.means_.push_back(mean);
    model.inverse_covariances_.push_back(((floor * 4.0)).inverse());
  }
  return model;
}

double ColourModel::similarity(const Eigen::Vector3d& colour) const {
  double best = 1e300;
  for (std::size_t j = 0; j < means_.size(); ++j) {
    const Eigen::Vector3d d = colour - means_[j];
    best = std::min(best, d.dot(inverse_covariances_[j] * d));
  }
  return means_.empty() ? 0.0 : std::exp(-0.5 * best);
}

}  // namespace hair25d::segment::detail
