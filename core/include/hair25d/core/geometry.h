// Plane geometry in image pixels (origin top-left, x right, y down) with Eigen.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hair25d {

using Vec2 = Eigen::Vector2d;
using Polyline = std::vector<Vec2>;  // open unless stated; a polygon is not closed by repetition

// Signed area by the shoelace formula on pixel coordinates. Positive for
// counter-clockwise order in the (x, y) frame, the convention of CGAL's
// orientation() and of TriMesh2; on a screen, whose y axis points down, such a
// polygon appears clockwise.
double signed_area(const Polyline& polygon);

// Even-odd point in polygon test.
bool point_in_polygon(const Polyline& polygon, const Vec2& p);

// Length of an open polyline.
double polyline_length(const Polyline& line);

// Resamples an open polyline to points spaced `spacing` apart along it (ends kept).
Polyline resample_polyline(const Polyline& line, double spacing);

}  // namespace hair25d
