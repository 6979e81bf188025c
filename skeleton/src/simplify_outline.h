// Topology-preserving simplification of closed outlines (CGAL's
// Polyline_simplification_2) so that large strands mesh quickly with inexact
// constructions (strand_mesh.cpp; paper §6.1 deforms that mesh).
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::skeleton::detail {

// Drops outline vertices while every dropped vertex stays within `tolerance`
// pixels of the simplified loop and no loop comes to cross itself or another
// one: disjoint simple loops stay disjoint and simple (up to floating-point
// rounding, which the caller checks). Each loop keeps at least 3 vertices.
std::vector<Polyline> simplify_loops(const std::vector<Polyline>& loops, double tolerance);

}  // namespace hair25d::skeleton::detail
