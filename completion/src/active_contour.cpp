#include "hair25d/completion/active_contour.h"

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#include <algorithm>
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

// The rows of I + τ K (K the discrete internal force −α D² + β D⁴) for the
// free points 2 … n − 3, on the free columns: the four fixed points (ends and
// their tangent neighbours) go to the right-hand side. Symmetric positive
// definite and pentadiagonal, so a sparse Cholesky solves it in O(n).
Eigen::SparseMatrix<double> free_block(int n, const ContourOptions& o) {
  const int m = n - 4;
  const double a = o.alpha * o.step, b = o.beta * o.step;
  std::vector<Eigen::Triplet<double>> t;
  for (int r = 0; r < m; ++r) {
    t.emplace_back(r, r, 1 + 2 * a + 6 * b);
    if (r + 1 < m) t.emplace_back(r, r + 1, -a - 4 * b), t.emplace_back(r + 1, r, -a - 4 * b);
    if (r + 2 < m) t.emplace_back(r, r + 2, b), t.emplace_back(r + 2, r, b);
  }
  Eigen::SparseMatrix<double> block(m, m);
  block.setFromTriplets(t.begin(), t.end());
  return block;
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
  if (!(max_reach > 0)) return fail("max_reach = " + std::to_string(max_reach) + "; must be > 0");
  if (!(hold_distance >= 0))
    return fail("hold_distance = " + std::to_string(hold_distance) + "; must be >= 0");
  if (!(stop_share >= 0 && stop_share <= 1))
    return fail("stop_share = " + std::to_string(stop_share) + "; must be in [0, 1]");
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

  // Hair under an occluder is unknown: the curve grows no farther from the
  // chord p q than `max_reach` chord lengths (a root under a wide occluder
  // would otherwise fill it).
  const Vec2 chord = q - p;
  const double reach = options.max_reach * chord.norm();
  auto beyond_reach = [&](const Vec2& x) {
    const double len2 = chord.squaredNorm();
    const double t = len2 > 0 ? std::clamp((x - p).dot(chord) / len2, 0.0, 1.0) : 0.0;
    return (x - (p + t * chord)).norm() > reach;
  };

  ContourResult result;
  Polyline curve = resample(initial, options.spacing);
  // Distance from C₀: a point nearer than hold_distance has not grown yet.
  const Polyline start = curve;
  auto grown = [&](const Vec2& x) {
    const double limit = options.hold_distance * options.hold_distance;
    for (std::size_t k = 1; k < start.size(); ++k) {
      const Vec2 a = start[k - 1], d = start[k] - a;
      const double len2 = d.squaredNorm();
      const double t = len2 > 0 ? std::clamp((x - a).dot(d) / len2, 0.0, 1.0) : 0.0;
      if ((x - (a + t * d)).squaredNorm() <= limit) return false;
    }
    return true;
  };
  auto pin_ends = [&](Polyline& c) {
    const int n = static_cast<int>(c.size());
    const double h = std::min(options.spacing, 0.25 * (q - p).norm() + 0.5);
    c[0] = p;
    c[1] = p + h * tangent_p;
    c[n - 1] = q;
    c[n - 2] = q + h * tangent_q;
  };
  pin_ends(curve);
  Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> solver;
  int factored_size = -1;
  // Points whose step would leave the allowed area stay where they are from
  // then on, while the others keep growing: in Algorithm 1 one point touching
  // an occluder's edge stops the whole curve, which on drawings stopped most
  // curves in their first step (C₀ lies on the occluding boundary).
  // A held point stays put until the next resample: whether it has grown is
  // found once (the test runs over all of C₀) and counted from then on.
  std::vector<char> held(curve.size(), 0), held_grown(curve.size(), 0);
  result.stop = ContourStop::kIterationCap;
  for (int it = 1; it <= options.max_iterations; ++it) {
    double longest = 0.0;
    for (std::size_t i = 1; i < curve.size(); ++i)
      longest = std::max(longest, (curve[i] - curve[i - 1]).norm());
    if (longest > 1.8 * options.spacing) {  // the curve lengthens as it grows
      curve = resample(curve, options.spacing);
      pin_ends(curve);
      held.assign(curve.size(), 0);  // held points find their edge again in one step
      held_grown.assign(curve.size(), 0);
    }
    const int n = static_cast<int>(curve.size());
    if (n != factored_size) {
      solver.compute(free_block(n, options));
      if (solver.info() != Eigen::Success)
        throw Error("completion::grow_contour: the smoothing matrix could not be factored");
      factored_size = n;
    }
    Eigen::MatrixX2d rhs(n - 4, 2);
    double largest = 0.0;
    for (int i = 0; i < n; ++i) {
      Vec2 v = Vec2::Zero();
      if (i >= 2 && i <= n - 3 && !held[i]) {
        const Vec2 tangent = curve[i + 1] - curve[i - 1];
        const double len = tangent.norm();
        if (len > 1e-12) {
          const Vec2 normal(-tangent.y() / len, tangent.x() / len);
          v = force(curve[i]).dot(normal) * normal;
          const double speed = v.norm();
          if (speed > options.max_speed) v *= options.max_speed / speed;
        }
      }
      if (i < 2 || i > n - 3) continue;
      largest = std::max(largest, v.norm());
      rhs.row(i - 2) = (curve[i] + v).transpose();
    }
    {  // the fixed points' share of the first two and last two free rows
      const double a = options.alpha * options.step, b = options.beta * options.step;
      rhs.row(0) -= (b * curve[0] + (-a - 4 * b) * curve[1]).transpose();
      if (n - 4 > 1) rhs.row(1) -= (b * curve[1]).transpose();
      rhs.row(n - 5) -= (b * curve[n - 1] + (-a - 4 * b) * curve[n - 2]).transpose();
      if (n - 4 > 1) rhs.row(n - 6) -= (b * curve[n - 2]).transpose();
    }
    const Eigen::MatrixX2d solved = solver.solve(rhs);
    const Polyline previous = curve;
    double moved_most = 0.0;
    int free_points = 0, met_edge = 0;
    for (int i = 2; i <= n - 3; ++i) {
      if (held[i]) {
        met_edge += held_grown[i];
        continue;
      }
      const Vec2 x = solved.row(i - 2).transpose();
      if (!allowed(x) || beyond_reach(x)) {
        held[i] = 1;
        held_grown[i] = grown(curve[i]) ? 1 : 0;
        met_edge += held_grown[i];
        continue;
      }
      ++free_points;
      moved_most = std::max(moved_most, (x - curve[i]).norm());
      curve[i] = x;
    }
    result.iterations = it;
    // Lines 7–8 of Algorithm 1: the grown curve meets the occluders' edge.
    if (met_edge > options.stop_share * (n - 4)) {
      curve = previous;
      result.stop = ContourStop::kLeftAllowed;
      break;
    }
    // Line 11 of Algorithm 1: no force left on the free points; or nothing moves.
    if (largest < options.epsilon || moved_most < options.epsilon) {
      result.stop = free_points < n - 4 ? ContourStop::kLeftAllowed : ContourStop::kConverged;
      break;
    }
  }
  result.curve = std::move(curve);
  return result;
}

}  // namespace hair25d::completion
