// The output of segmentation (paper §3): extracted curves, the constrained
// Delaunay mesh whose constrained edges are those curves, and a region label per
// triangle.
#pragma once

#include <array>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d {

enum class CurveEnd { kFree, kEndpoint, kJunction };

// A drawn line as a polyline. Its two ends are free endpoints (the line stops)
// or junctions (three or more curve branches meet). A closed curve has ends
// kFree and repeats no point.
struct Curve {
  Polyline points;
  std::array<CurveEnd, 2> ends{CurveEnd::kEndpoint, CurveEnd::kEndpoint};
  bool closed = false;
};

struct Segmentation {
  int width = 0;
  int height = 0;
  std::vector<Curve> curves;
  TriMesh2 mesh;
  // #F region id per mesh triangle: a stroke label (> 0), 0 = background.
  std::vector<int> triangle_region;
  // Pairs (a < b) of region ids whose triangles share an edge (0 included).
  std::vector<std::array<int, 2>> adjacency;
};

}  // namespace hair25d
