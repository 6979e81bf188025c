#include "strand_paint.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace hair25d::completion::detail {
namespace {

// Two gradients across the groups: the joint linear field missing the
// pieces by more than this (RegionFields::step, RGB). The pair tests'
// kMinOtherFieldStep (3) compares pieces facing each other across one
// occluder; pieces of one strand far apart along it lie on a curve the
// generator shades by its parameter, which no one linear field follows:
// on dev mixed 2000-2099 and 3000-3099 (both relations) the joint field
// missed such pieces of one strand by 3.1, 3.5, 3.7 and 4.6 RGB, pieces of
// two strands the refusals stopped by 3.9, 4.3 and 6.8-25.8 (session 28).
constexpr double kMinStrandFieldStep = 6.0;

// RegionCels::step with a shade counted as the same paint: each flat of
// one piece to the nearest flat of the other, or 0 where either is the
// other's shade; the worst, the smaller way round. A two-tone back is one
// mass in a base and a band below a level a strand lying on it may hide,
// so one piece shows only the base and another only the band (the pair
// tests let such pieces join by the drawing's shadow ratio, `paint_step`).
double cel_step_beyond_shade(RegionCels& cels, int a, int b) {
  const auto one_way = [](const RegionCels::Cel& from, const RegionCels::Cel& to) {
    double worst = 0.0;
    for (const Eigen::Vector3d& f : from.flats) {
      double best = std::numeric_limits<double>::infinity();
      for (const Eigen::Vector3d& g : to.flats)
        best = std::min(best, shade_of(f, g) || shade_of(g, f) ? 0.0 : (f - g).norm());
      worst = std::max(worst, best);
    }
    return worst;
  };
  const RegionCels::Cel& ca = cels.cel(a);
  const RegionCels::Cel& cb = cels.cel(b);
  return std::min(one_way(ca, cb), one_way(cb, ca));
}

bool pair_apart(RegionTones& tones, RegionFields& fields, int a, int b) {
  if (tones.screentone()) return two_paints(tones, fields, a, b);
  RegionCels& cels = fields.cels();
  if (cels.cel_drawing()) {
    // Unmeasured (infinite) says nothing, as in `two_paints`.
    const double step = cels.step(a, b);
    return std::isfinite(step) && step > kMinTwoPaintStep &&
           cel_step_beyond_shade(cels, a, b) > kMinTwoPaintStep;
  }
  const double step = fields.step(a, b);
  return std::isfinite(step) && step > kMinStrandFieldStep;
}

}  // namespace

std::optional<PaintClash> painted_apart(RegionTones& tones, RegionFields& fields,
                                        const std::vector<int>& group_a,
                                        const std::vector<int>& group_b,
                                        std::optional<PaintClash> but) {
  for (int a : group_a)
    for (int b : group_b)
      if (!(but && but->a == a && but->b == b) && pair_apart(tones, fields, a, b))
        return PaintClash{a, b};
  return std::nullopt;
}

}  // namespace hair25d::completion::detail
