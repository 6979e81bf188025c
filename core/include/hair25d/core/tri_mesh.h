// A 2D triangle mesh in image pixels: the segmentation mesh and each strand's
// deformation mesh.
#pragma once

#include <Eigen/Core>
#include <vector>

namespace hair25d {

struct TriMesh2 {
  // #V by 2 vertex positions, pixels.
  Eigen::MatrixX2d V;
  // #F by 3 vertex indices, counter-clockwise in the (x, y) pixel frame:
  // positive signed_area() (see geometry.h for how that looks on screen).
  Eigen::MatrixX3i F;
  // #F by 3: edge k of triangle t runs from F(t,k) to F(t,(k+1)%3); true when
  // that edge lies on a drawn curve (a constraint of the triangulation). May be
  // empty for meshes that have no curves.
  Eigen::Matrix<bool, Eigen::Dynamic, 3> on_curve;

  int vertex_count() const { return static_cast<int>(V.rows()); }
  int triangle_count() const { return static_cast<int>(F.rows()); }

  // Throws hair25d::Error naming `what` if indices are out of range, a
  // triangle is degenerate or on_curve has the wrong shape.
  void validate(const char* what) const;
};

}  // namespace hair25d
