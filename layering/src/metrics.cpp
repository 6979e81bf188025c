#include "hair25d/layering/metrics.h"

#include <Eigen/Cholesky>
#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>
#include <numeric>

namespace hair25d::layering {
namespace {
constexpr double kPi = std::numbers::pi;

double mod_pi(double angle) {
  double m = std::fmod(angle, kPi);
  return m < 0 ? m + kPi : m;
}
}  // namespace

double junction_metric(double alpha, double beta) {
  return std::abs(mod_pi(alpha) - kPi / 2) - std::abs(mod_pi(beta) - kPi / 2);
}

double overlap_metric(const Polyline& curve) {
  // The shoelace sum over the curve closed by the chord is positive for a
  // counter-clockwise loop in the (x, y) frame; a curve that bulges to its
  // right (into B) runs the other way, and that bulge is A's overlap δ_A.
  return -signed_area(curve);
}

double coupling_weight(double theta, double cap) {
  const double deviation = std::abs(mod_pi(theta) - kPi / 2);  // in [0, π/2]
  // tan grows without bound at π/2: clamp the angle, not the value, so the
  // weight is continuous and monotone up to the cap.
  const double limit = std::atan(std::max(0.0, cap));
  return std::tan(std::min(deviation, limit));
}

Vec2 leaving_direction(const Polyline& curve, double reach) {
  if (curve.size() < 2) return Vec2(1, 0);
  const Vec2 origin = curve.front();
  Eigen::Matrix2d scatter = Eigen::Matrix2d::Zero();
  Vec2 mean = Vec2::Zero();
  double along = 0.0;
  int used = 0;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    along += (curve[i] - curve[i - 1]).norm();
    if (along > reach && used >= 2) break;
    const Vec2 d = curve[i] - origin;
    scatter += d * d.transpose();
    mean += d;
    ++used;
  }
  if (mean.squaredNorm() == 0.0) return Vec2(1, 0);
  // The principal axis of the points about the junction is the tangent of
  // the least-squares line through it; orient it along the curve.
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix2d> eig(scatter);
  Vec2 axis = eig.eigenvectors().col(1);
  if (axis.dot(mean) < 0) axis = -axis;
  return axis.normalized();
}

Vec2 curved_leaving_direction(const Polyline& curve, double skip, double reach) {
  if (curve.size() < 2) return Vec2(1, 0);
  const Vec2 origin = curve.front();
  // x(u) = a u + b u², y likewise, through the junction, u the distance from
  // it: the tangent (a_x, a_y) at u = 0 is what a bent outline had there,
  // which a straight line through the points (leaving_direction) bends
  // toward its chord. The first `skip` pixels, where the lines of the
  // junction merge into one blob, are left out.
  Eigen::Matrix2d normal = Eigen::Matrix2d::Zero();
  Eigen::Vector2d rhs_x = Eigen::Vector2d::Zero(), rhs_y = Eigen::Vector2d::Zero();
  double along = 0.0;
  int used = 0;
  for (std::size_t i = 1; i < curve.size(); ++i) {
    along += (curve[i] - curve[i - 1]).norm();
    if (along > reach && used >= 3) break;
    const Vec2 d = curve[i] - origin;
    const double u = d.norm();
    if (u < skip) continue;
    const Eigen::Vector2d basis(u, u * u);
    normal += basis * basis.transpose();
    rhs_x += basis * d.x();
    rhs_y += basis * d.y();
    ++used;
  }
  if (used < 3) return leaving_direction(curve, reach);
  const Eigen::LDLT<Eigen::Matrix2d> solve(normal);
  const Vec2 tangent(solve.solve(rhs_x)(0), solve.solve(rhs_y)(0));
  if (!(tangent.squaredNorm() > 1e-12) || !tangent.allFinite())
    return leaving_direction(curve, reach);
  return tangent.normalized();
}

RaySectors sectors_around(const std::vector<Vec2>& rays) {
  RaySectors out;
  const std::size_t n = rays.size();
  std::vector<double> angle(n);
  for (std::size_t i = 0; i < n; ++i) angle[i] = std::atan2(rays[i].y(), rays[i].x());
  out.order.resize(n);
  std::iota(out.order.begin(), out.order.end(), 0);
  std::stable_sort(out.order.begin(), out.order.end(),
                   [&](int a, int b) { return angle[a] < angle[b]; });
  out.sectors.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    const double a = angle[out.order[k]];
    const double b = angle[out.order[(k + 1) % n]];
    // Only the last sector wraps around; coincident rays give an empty sector.
    out.sectors[k] = (k + 1 == n) ? b - a + 2 * kPi : b - a;
  }
  return out;
}

}  // namespace hair25d::layering
