// The deformation mesh of one completed strand (paper §6.1 deforms it with the
// skeleton): a quality constrained Delaunay mesh of its outline, with interior
// vertices and bounded edge length, by CGAL's Delaunay mesher.
#pragma once

#include <string>

#include "hair25d/core/geometry.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d::skeleton {

struct MeshOptions {
  double max_edge = 12.0;        // pixels: longest triangle edge wanted inside
  double min_angle_deg = 20.0;   // wanted smallest angle (≤ 20.7° guarantees termination)
  int max_vertices = 20000;      // refinement stops here whatever the quality
  double outline_spacing = 0.0;  // most pixels between outline samples; 0 = max_edge / 2

  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

enum class MeshStatus { kRefined, kVertexLimit };

struct MeshResult {
  TriMesh2 mesh;  // counter-clockwise triangles; on_curve marks outline edges
  MeshStatus status = MeshStatus::kRefined;
  // Resampled every outline_spacing px the outline was not a simple polygon
  // within half a pixel of it, so it was simplified instead (topology kept).
  bool simplified = false;
  // The outline crossed or touched itself and was replaced by the boundary
  // of its filled shape (folds filled, parts under a pixel thick dropped).
  bool retraced = false;
  // Even the simplified outline was not a simple polygon (floating-point
  // rounding): meshed with exact constructions, slow, so refinement stopped
  // at 3000 vertices at most.
  bool exact = false;
};

// Meshes the inside of a closed outline (either orientation, not closed by
// repetition): resampled every outline_spacing px, or, where that would cut
// it by more than half a pixel or make it cross itself, simplified within
// half a pixel without changing its topology. Throws hair25d::Error for invalid options, fewer than
// 3 distinct points, non-finite coordinates or zero area.
MeshResult mesh_strand(const Polyline& outline, const MeshOptions& options = {});

}  // namespace hair25d::skeleton
