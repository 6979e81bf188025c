// Region boundaries between junctions (paper §4.1, §4.3): an exact boundary
// representation of a label map on the pixel-corner ("crack") grid, with
// junctions where three or more regions (background and the outside included) meet.
#pragma once

#include <string>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"

namespace hair25d::layering {

// Label given to the space outside the image. Boundaries against it are the
// image border, never a drawn line, so they are neither occluding nor cusps.
inline constexpr int kOutsideLabel = -1;

// A point where three or more labels meet, at a pixel corner (x, y) in pixels.
struct Junction {
  Vec2 position;
  std::vector<int> boundaries;  // ids of boundaries that start or end here
};

// A maximal chain of crack edges separating the same two labels. Walking from
// `points.front()` to `points.back()`, `left` lies on the left as seen on the
// screen (x right, y down), `right` on the right.
struct Boundary {
  int left = 0;
  int right = 0;
  int start = -1;   // junction id at points.front(), -1 for a closed loop
  int end = -1;     // junction id at points.back(), -1 for a closed loop
  Polyline points;  // pixel corners; a closed loop does not repeat its first point
  bool closed() const { return start < 0; }
  double length() const;  // in pixels (crack edges are 1 long)
};

struct BoundaryGraph {
  int width = 0;
  int height = 0;
  std::vector<Junction> junctions;
  std::vector<Boundary> boundaries;
};

// Traces every boundary of `labels` (any integer labels; pixels outside the
// image count as kOutsideLabel). Linear in the number of pixels. A corner where
// only two labels meet diagonally is passed through, joining the diagonal of
// the smaller label, so that chains stay between the same two labels.
// Throws hair25d::Error for an empty label map.
BoundaryGraph build_boundary_graph(const LabelMap& labels);

struct OutlineFillOptions {
  // Outline pixels (label 0) are given to the nearest region when they are at
  // most this many pixels from it; <= 0 estimates the radius from the map
  // (where growing fronts of different regions meet).
  double max_distance = 0.0;
  bool is_valid(std::string* error) const;
};

struct OutlineFill {
  LabelMap labels;        // the label map with outline pixels given away
  double line_width = 0;  // estimated width of the outlines, pixels (0 if none)
  double radius = 0;      // the growth radius used, pixels
};

// Gives label-0 outline pixels between regions to the regions they separate:
// a breadth-first growth (8-neighbour chamfer distance) of every non-zero
// label into label-0 pixels, up to the radius. Pixels farther away stay 0
// (background). Throws hair25d::Error for an empty map or invalid options.
OutlineFill fill_outlines(const LabelMap& labels, const OutlineFillOptions& options = {});

}  // namespace hair25d::layering
