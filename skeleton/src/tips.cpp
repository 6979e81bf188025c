#include "tips.h"

#include <algorithm>
#include <cmath>

#include "hair25d/core/error.h"
#include "polygon_sampling.h"

namespace hair25d::skeleton::detail {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// The point `arm` pixels from sample i along the outline, walking by `step`.
Vec2 walk(const Polyline& s, int i, double arm, int step) {
  const int n = static_cast<int>(s.size());
  double left = arm;
  int j = i;
  for (int k = 0; k < n - 1; ++k) {
    const int next = ((j + step) % n + n) % n;
    const double len = (s[next] - s[j]).norm();
    if (len >= left) return s[j] + (left / len) * (s[next] - s[j]);
    left -= len;
    j = next;
  }
  return s[j];
}

}  // namespace

std::vector<int> sharp_corners(const Polyline& samples, const std::vector<bool>& covered,
                               const Options& options) {
  const int n = static_cast<int>(samples.size());
  const double orientation = signed_area(samples) >= 0.0 ? 1.0 : -1.0;
  const double cos_limit = std::cos(options.tip_angle_deg * M_PI / 180.0);
  // The arm may not exceed a third of the perimeter, or tiny shapes would
  // measure the angle against their far side.
  double perimeter = 0.0;
  for (int i = 0; i < n; ++i) perimeter += (samples[(i + 1) % n] - samples[i]).norm();
  const double arm = std::min(options.corner_arm, perimeter / 3.0);
  struct Candidate {
    int index;
    double cosine;
  };
  std::vector<Candidate> candidates;
  for (int i = 0; i < n; ++i) {
    if (!covered.empty() && covered[i]) continue;
    const Vec2 a = walk(samples, i, arm, -1) - samples[i];
    const Vec2 b = walk(samples, i, arm, +1) - samples[i];
    const double la = a.norm(), lb = b.norm();
    if (la <= 0 || lb <= 0) continue;
    const double c = a.dot(b) / (la * lb);
    // Convex corner: going prev -> i -> next turns the polygon's way.
    const bool convex = cross(-a, b) * orientation > 0;
    if (convex && c > cos_limit) candidates.push_back({i, c});
  }
  std::sort(candidates.begin(), candidates.end(),
            [](const Candidate& x, const Candidate& y) { return x.cosine > y.cosine; });
  // Arc-length position of each sample for the separation test.
  std::vector<double> arc(n, 0.0);
  for (int i = 1; i < n; ++i) arc[i] = arc[i - 1] + (samples[i] - samples[i - 1]).norm();
  const double separation =
      options.min_tip_separation > 0 ? options.min_tip_separation : 2.0 * options.corner_arm;
  std::vector<int> chosen;
  for (const Candidate& c : candidates) {
    bool far = true;
    for (int j : chosen) {
      const double d = std::abs(arc[c.index] - arc[j]);
      if (std::min(d, perimeter - d) < separation) far = false;
    }
    if (!far) continue;
    chosen.push_back(c.index);
    if (static_cast<int>(chosen.size()) >= options.max_tips) break;
  }
  return chosen;
}

bool near_covered(const Polyline& samples, const std::vector<bool>& covered, int i, double reach) {
  const int n = static_cast<int>(samples.size());
  if (covered.empty() || n == 0) return false;
  for (int step : {-1, +1}) {
    double walked = 0.0;
    for (int k = 0, j = i; k < n && walked <= reach; ++k) {
      if (covered[j]) return true;
      const int next = ((j + step) % n + n) % n;
      walked += (samples[next] - samples[j]).norm();
      j = next;
    }
  }
  return false;
}

}  // namespace hair25d::skeleton::detail

namespace hair25d::skeleton {

std::vector<int> find_tip_corners(const Polyline& outline, const std::vector<bool>& covered,
                                  const Options& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (!covered.empty() && covered.size() != outline.size()) {
    throw Error("skeleton::find_tip_corners: covered has " + std::to_string(covered.size()) +
                " flags for " + std::to_string(outline.size()) +
                " outline points; must be empty or one per point");
  }
  std::vector<int> kept;
  const Polyline clean = detail::clean_polygon(outline, "skeleton::find_tip_corners", &kept);
  std::vector<int> source;
  const Polyline samples = detail::resample_closed(clean, options.sample_spacing, &source);
  std::vector<bool> sample_covered;
  if (!covered.empty()) {
    sample_covered.resize(samples.size());
    for (std::size_t i = 0; i < samples.size(); ++i) sample_covered[i] = covered[kept[source[i]]];
  }
  std::vector<int> out;
  for (int i : detail::sharp_corners(samples, sample_covered, options))
    out.push_back(kept[source[i]]);
  return out;
}

}  // namespace hair25d::skeleton
