// The segmentation mesh (paper §3): a constrained Delaunay triangulation of the
// image rectangle whose constraints are the drawn curves, refined so that
// regions have inner triangles. CGAL does the triangulation and refinement.
#pragma once

#include <string>
#include <vector>

#include "hair25d/core/image.h"
#include "hair25d/core/segmentation.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d::segment {

struct MeshOptions {
  // Longest triangle edge after refinement, as a fraction of sqrt(width × height);
  // small drawings get at least min_edge_px.
  double max_edge_fraction = 1.0 / 36.0;
  double min_edge_px = 6.0;
  // CGAL's shape bound B = 1 / (4 sin² α) on the smallest angle α; 0.125 asks
  // for α ≥ 20.7°, 0 refines by size only.
  double shape_bound = 0.125;
  bool refine = true;
  // Refinement stops after adding this many vertices (a guard against
  // constraints that nearly touch); MeshResult says whether it finished.
  int max_steiner_points = 200000;

  bool is_valid(std::string* error) const;
};

struct MeshResult {
  TriMesh2 mesh;  // covers [0, width] × [0, height]; on_curve marks curve edges
  int constraint_segments = 0;
  int steiner_points = 0;           // vertices added by refinement
  bool refinement_complete = true;  // false: stopped at max_steiner_points
};

// Triangulates the rectangle [0, width] × [0, height] with every curve segment
// (clipped to the rectangle) and the border as constraints. Intersecting curves
// are split at their crossing. Throws hair25d::Error for a non-positive size,
// non-finite points or invalid options.
MeshResult build_mesh(const std::vector<Curve>& curves, int width, int height,
                      const MeshOptions& options = {});

// Per pixel, the index of the triangle that holds its centre (-1 if none).
LabelMap rasterize_triangles(const TriMesh2& mesh, int width, int height);

// Per pixel, the value of the triangle holding its centre (`fill` where none).
LabelMap rasterize_triangle_values(const TriMesh2& mesh, const std::vector<int>& values, int width,
                                   int height, int fill = 0);

}  // namespace hair25d::segment
