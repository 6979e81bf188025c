#include "hair25d/completion/active_contour.h"

#include <Eigen/Sparse>
#include <Eigen/SparseLU>
#include <cmath>

#include "hair25d/core/error.h"

namespace hair25d::completion {
namespace {

// Resamples an open curve to about `spacing`, never fewer than 5 points.
Polyline resample(const Polyline& curve, double spacing) {
  const double length = polyline_length(curve);
  const double s = std::min(spacing, length / 4.0);
  Polyline out = s > 0 ? resample_polyline(curve, s) : curve;
  while (out.size() < 5) {  // a zero-length curve: repeat the point
    out.push_back(curve.back());
  }
  return out;
}

// I + τ K with K the discrete internal force (−α D² + β D⁴) on free points and
// identity rows on the four fixed ones.
Eigen::SparseMatrix<double> system_matrix(int n, const ContourOptions& o) {
  std::vector<Eigen::Triplet<double>> t;
  for (int i = 0; i < n; ++i) {
    if (i < 2 || i > n - 3) {
      t.emplace_back(i, i, 1.0);
      continue;
    }
    const double a = o.alpha * o.step, b = o.beta * o.step;
    t.emplace_back(i, i - 2, b);
    t.emplace_back(i, i - 1, -a - 4 * b);
    t.emplace_back(i, i, 1 + 2 * a + 6 * b);
    t.emplace_back(i, i + 1, -a - 4 * b);
    t.emplace_back(i, i + 2, b);
  }
  Eigen::SparseMatrix<double> m(n, n);
  m.setFromTriplets(t.begin(), t.end());
  return m;
}

}  // namespace

bool ContourOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "completion::ContourOptions::" + m;
    return false;
  };
  if (!(alpha >= 0)) return fail("alpha = " + std::to_string(alpha) + "; must be >= 0");
  if (!(beta >= 0)) return fail("beta = " + std::to_string(beta) + "; must be >= 0");
  if (!(step > 0)) return fail("step = " + std::to_string(step) + "; must be > 0");
  if (!(max_speed > 0)) return fail("max_speed = " + std::to_string(max_speed) + "; must be > 0");
  if (!(epsilon > 0)) return fail("epsilon = " + std::to_string(epsilon) + "; must be > 0");
  if (!(spacing > 0)) return fail("spacing = " + std::to_string(spacing) + "; must be > 0");
  if (max_iterations < 1)
    return fail("max_iterations = " + std::to_string(max_iterations) + "; must be >= 1");
  if (!(omega_gain > 0))
    return fail("omega_gain = " + std::to_string(omega_gain) + "; must be > 0");
  return true;
}

const char* to_string(ContourStop stop) {
  switch (stop) {
    case ContourStop::kLeftAllowed:
      return "left-occluders";
    case ContourStop::kConverged:
      return "converged";
    case ContourStop::kIterationCap:
      return "iteration-cap";
  }
  return "unknown";
}

ContourResult grow_contour(const Polyline& initial, const Vec2& tangent_p, const Vec2& tangent_q,
                           const ContourFields& fields,
                           const std::function<bool(const Vec2&)>& allowed,
                           const ContourOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (initial.size() < 2)
    throw Error("completion::grow_contour: the initial curve has " +
                std::to_string(initial.size()) + " points; at least 2 are needed");
  const Vec2 p = initial.front(), q = initial.back();
  const double hp = fields.at_p.value(p), hq = fields.at_q.value(q);
  auto force = [&](const Vec2& x) -> Vec2 {
    const double up = std::max(fields.sign_p * (hp - fields.at_p.value(x)), 0.0);
    const double uq = std::max(fields.sign_q * (hq - fields.at_q.value(x)), 0.0);
    const double omega = std::tanh(options.omega_gain * up * uq);
    if (omega <= 0.0) return Vec2::Zero();
    const double dp = (x - p).norm(), dq = (x - q).norm();
    const double t = dp + dq > 0 ? dq / (dp + dq) : 0.5;
    return omega * (t * fields.at_p.flow(x) + (1 - t) * fields.at_q.flow(x));
  };

  ContourResult result;
  Polyline curve = resample(initial, options.spacing);
  auto pin_ends = [&](Polyline& c) {
    const int n = static_cast<int>(c.size());
    const double h = std::min(options.spacing, 0.25 * (q - p).norm() + 0.5);
    c[0] = p;
    c[1] = p + h * tangent_p;
    c[n - 1] = q;
    c[n - 2] = q + h * tangent_q;
  };
  pin_ends(curve);
  Eigen::SparseLU<Eigen::SparseMatrix<double>> solver;
  int factored_size = -1;
  result.stop = ContourStop::kIterationCap;
  for (int it = 1; it <= options.max_iterations; ++it) {
    if (it % 8 == 0) {  // the curve lengthens as it grows: keep samples even
      curve = resample(curve, options.spacing);
      pin_ends(curve);
    }
    const int n = static_cast<int>(curve.size());
    if (n != factored_size) {
      solver.compute(system_matrix(n, options));
      if (solver.info() != Eigen::Success)
        throw Error("completion::grow_contour: the smoothing matrix could not be factored");
      factored_size = n;
    }
    Eigen::MatrixX2d rhs(n, 2);
    double largest = 0.0;
    for (int i = 0; i < n; ++i) {
      Vec2 v = Vec2::Zero();
      if (i >= 2 && i <= n - 3) {
        const Vec2 tangent = curve[i + 1] - curve[i - 1];
        const double len = tangent.norm();
        if (len > 1e-12) {
          const Vec2 normal(-tangent.y() / len, tangent.x() / len);
          v = force(curve[i]).dot(normal) * normal;
          const double speed = v.norm();
          if (speed > options.max_speed) v *= options.max_speed / speed;
        }
      }
      largest = std::max(largest, v.norm());
      rhs.row(i) = (curve[i] + v).transpose();
    }
    const Eigen::MatrixX2d next = solver.solve(rhs);
    Polyline moved(n);
    bool inside = true;
    for (int i = 0; i < n; ++i) {
      moved[i] = next.row(i).transpose();
      if (i >= 2 && i <= n - 3 && !allowed(moved[i])) inside = false;
    }
    result.iterations = it;
    if (!inside) {
      result.stop = ContourStop::kLeftAllowed;
      break;
    }
    curve = std::move(moved);
    if (largest < options.epsilon) {
      result.stop = ContourStop::kConverged;
      break;
    }
  }
  result.curve = std::move(curve);
  return result;
}

}  // namespace hair25d::completion
