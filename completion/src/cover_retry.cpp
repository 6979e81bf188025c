#include "cover_retry.h"

#include <algorithm>
#include <cmath>

#include "raster.h"

namespace hair25d::completion::detail {
namespace {

// An uncovered pixel this near a cut (the wider cut's width times this, at
// least kMinCutReach px) is "at the cut": the drawn outline and its light
// fringe lie there, where a right patch often leaves the occluder's region
// for a pixel or two (joins72, joins75); a wrong one misses in its middle.
constexpr double kCutReachShare = 0.15;
constexpr double kMinCutReach = 3.0;

double wider_cut(const CoverMisses& m) { return std::max({m.a->width, m.b->width, 1.0}); }

}  // namespace

void CoverMisses::clear() {
  total = missed = at_cuts = 0;
  paper = on_face = on_ink = below = sibling = other = 0;
  reach = std::max(kMinCutReach, kCutReachShare * wider_cut(*this));
}

bool CoverMisses::add_pixel(const Context& ctx, bool inside, int l, int x, int y) {
  ++missed;
  const Vec2 c(x + 0.5, y + 0.5);
  if (std::min(segment_distance(c, a->p, a->q), segment_distance(c, b->p, b->q)) <= reach)
    ++at_cuts;
  // Label 0 is no hair region: the face, a drawn line, or the paper (the
  // background); a hair region's pixel that was outline in the map as
  // given is ink assigned to it.
  if (!inside)
    ++paper;
  else if (l == 0 && !face->empty() && face->at<std::uint8_t>(y, x))
    ++on_face;
  else if (l == 0)
    ++(luma(ctx.image->at(x, y)) < ctx.options->dark_luma ? on_ink : paper);
  else if (ctx.original->at(x, y) == 0)
    ++on_ink;
  else
    return false;
  return true;
}

void CoverMisses::add_region(const Context& ctx, int l, int n) {
  switch (hole_kind(ctx, a->region, b->region, l)) {
    case HoleKind::kBelow:
      below += n;
      break;
    case HoleKind::kSibling:
      sibling += n;
      break;
    case HoleKind::kOther:
      other += n;
      break;
  }
}

void add_cover_terms(const CoverMisses& m, double shape_cover, JoinTerms* t) {
  t->cover_retried = true;
  t->shape_cover = shape_cover;
  if (m.total == 0) return;
  const double wide = wider_cut(m);
  t->miss_paper = m.paper / m.total;
  t->miss_face = m.on_face / m.total;
  t->miss_ink = m.on_ink / m.total;
  t->miss_below = m.below / m.total;
  t->miss_sibling = m.sibling / m.total;
  t->miss_other = m.other / m.total;
  t->miss_per_width = m.missed / (wide * wide);
  t->miss_at_cuts = m.missed > 0 ? static_cast<double>(m.at_cuts) / m.missed : 0.0;
}

}  // namespace hair25d::completion::detail
