// The local layering metrics of paper §4.2–4.4: the junction metric Φ_J from
// the angles two regions subtend at a junction, the region-overlap metric Φ_R
// from signed areas about the chord, and their combination Φ (Eq. 1).
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::layering {

// Φ_J(α, β) = |(α mod π) − π/2| − |(β mod π) − π/2|, angles in radians.
// Positive: the region subtending α (A) lies on top of the one subtending β (B).
double junction_metric(double alpha, double beta);

// Φ_R for a boundary walked from junction p1 = curve.front() to p2 =
// curve.back() with region A on its left (screen orientation, y down) and B on
// its right: δ_A − δ_B, where δ_A is the area of A beyond the chord p1→p2 (on
// its right) and δ_B the area of B beyond it (on its left), by Green's theorem
// over the curve closed by the chord. Positive: A on top. Pixels².
double overlap_metric(const Polyline& curve);

// φ_ij = tan(|(θ mod π) − π/2|) for the angle θ between two boundaries at a
// junction, capped at `cap` (θ near 0 or π would give infinity).
double coupling_weight(double theta, double cap);

// The direction (unit vector) in which a boundary leaves point `from` along
// `curve` (curve.front() == from), from a least-squares line through `from`
// fitted to the points within arc length `reach` — not from the last raster
// step. Returns the chord direction when the curve is shorter than 2 points apart.
Vec2 leaving_direction(const Polyline& curve, double reach);

// The tangent at `curve.front()` of a quadratic through it fitted to the
// points from distance `skip` to arc length `reach` (an addition to the
// paper: a bent outline keeps its direction at the junction instead of
// leaning toward its chord). Falls back to leaving_direction with fewer than
// three points.
Vec2 curved_leaving_direction(const Polyline& curve, double skip, double reach);

// The sectors between consecutive rays around a junction (rays as unit
// directions). `order` sorts the rays by increasing atan2(y, x) — clockwise on
// the screen — and sectors[k] (radians, in (0, 2π]) is the angle swept from
// ray order[k] to ray order[k + 1] (cyclic). For a boundary leaving the
// junction, the region on its right fills the sector after its ray and the one
// on its left the sector before it: these are α and β.
struct RaySectors {
  std::vector<int> order;       // ray indices, sorted around the junction
  std::vector<double> sectors;  // sector after order[k], radians
};
RaySectors sectors_around(const std::vector<Vec2>& rays);

}  // namespace hair25d::layering
