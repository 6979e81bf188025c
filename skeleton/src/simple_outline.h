// A simple polygon for an outline that crosses or touches itself: a completed
// strand can fold over itself where its grown part meets its visible part,
// and CGAL's mesher needs constraints that do not cross (strand_mesh.cpp).
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::skeleton::detail {

// The outer boundaries of the filled outline, traced on a half-pixel raster:
// folds are filled and parts thinner than about a pixel dropped; each
// boundary is a staircase of half-pixel steps. A shape pinched to a point
// comes back as several disjoint simple loops; none if nothing is left.
std::vector<Polyline> simple_outline(const Polyline& polygon);

}  // namespace hair25d::skeleton::detail
