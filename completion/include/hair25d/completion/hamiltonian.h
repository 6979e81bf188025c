// The Hamiltonian vector field of paper §5.2: H(x) = ½ xᵀ A x + xᵀ B fitted by
// linear least squares (Eigen) so that a short curve piece c(t) follows
// ċ = (∂H/∂y, −∂H/∂x); its flow F = R(−π/2) ∇H extends the piece's shape.
#pragma once

#include <Eigen/Core>

#include "hair25d/core/geometry.h"

namespace hair25d::completion {

struct HamiltonianField {
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();  // symmetric
  Vec2 B = Vec2::Zero();
  Vec2 origin = Vec2::Zero();  // x is measured from here (conditioning)
  double residual = 0.0;       // RMS misfit of the tangents, unit-speed

  double value(const Vec2& x) const;   // H(x)
  Vec2 gradient(const Vec2& x) const;  // ∇H(x)
  // The flow (∂H/∂y, −∂H/∂x) = ∇H turned by −π/2.
  Vec2 flow(const Vec2& x) const;
};

// Fits H to `piece` (points in order of motion, at least 3 and not all equal)
// with its tangents taken at unit speed. `regularization` ≥ 0 pulls A to zero
// (a straight flow) when the piece carries no curvature information. Throws
// hair25d::Error for fewer than 3 distinct points or non-finite ones.
HamiltonianField fit_hamiltonian(const Polyline& piece, double regularization = 1e-3);

}  // namespace hair25d::completion
