#include "hair25d/completion/hamiltonian.h"

#include <Eigen/Dense>
#include <cmath>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::completion {

double HamiltonianField::value(const Vec2& x) const {
  const Vec2 d = x - origin;
  return 0.5 * d.dot(A * d) + d.dot(B);
}

Vec2 HamiltonianField::gradient(const Vec2& x) const { return A * (x - origin) + B; }

Vec2 HamiltonianField::flow(const Vec2& x) const {
  const Vec2 g = gradient(x);
  return {g.y(), -g.x()};
}

HamiltonianField fit_hamiltonian(const Polyline& piece, double regularization) {
  Polyline pts;
  for (const Vec2& p : piece) {
    if (!std::isfinite(p.x()) || !std::isfinite(p.y()))
      throw Error("completion::fit_hamiltonian: a curve point is not finite");
    if (pts.empty() || (pts.back() - p).norm() > 1e-9) pts.push_back(p);
  }
  if (pts.size() < 3) {
    throw Error("completion::fit_hamiltonian: the curve piece has " + std::to_string(pts.size()) +
                " distinct points; at least 3 are needed");
  }
  if (!(regularization >= 0.0))
    throw Error("completion::fit_hamiltonian: regularization must be >= 0");
  HamiltonianField field;
  field.origin = pts.back();  // H is evaluated near the end the flow leaves from
  const int n = static_cast<int>(pts.size());
  // Unknowns u = (a11, a12, a22, b1, b2); two rows a point: H_y = τx, −H_x = τy.
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(2 * n + 3, 5);
  Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n + 3);
  for (int i = 0; i < n; ++i) {
    const Vec2 tangent = (pts[std::min(i + 1, n - 1)] - pts[std::max(i - 1, 0)]).normalized();
    const Vec2 x = pts[i] - field.origin;
    M.row(2 * i) << 0, x.x(), x.y(), 0, 1;
    rhs(2 * i) = tangent.x();
    M.row(2 * i + 1) << x.x(), x.y(), 0, 1, 0;
    rhs(2 * i + 1) = -tangent.y();
  }
  // Tikhonov rows on A, scaled by the piece's extent so the pull is unit-free.
  double extent = 0.0;
  for (const Vec2& p : pts) extent = std::max(extent, (p - field.origin).norm());
  const double w = std::sqrt(regularization * n) * std::max(extent, 1.0);
  M(2 * n, 0) = w;
  M(2 * n + 1, 1) = w;
  M(2 * n + 2, 2) = w;
  const Eigen::VectorXd u = M.colPivHouseholderQr().solve(rhs);
  field.A << u(0), u(1), u(1), u(2);
  field.B = Vec2(u(3), u(4));
  double misfit = 0.0;
  for (int i = 0; i < n; ++i) {
    const Vec2 tangent = (pts[std::min(i + 1, n - 1)] - pts[std::max(i - 1, 0)]).normalized();
    misfit += (field.flow(pts[i]) - tangent).squaredNorm();
  }
  field.residual = std::sqrt(misfit / n);
  return field;
}

}  // namespace hair25d::completion
