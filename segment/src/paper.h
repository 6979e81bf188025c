// Private: transparent paper. A drawing's transparent pixels are no part of
// any hair region (alpha < kOpaqueAlpha, see hair25d/segment/regions.h).
#pragma once

#include <Eigen/Core>
#include <vector>

#include "hair25d/core/image.h"
#include "hair25d/core/tri_mesh.h"

namespace hair25d::segment::detail {

bool is_paper(const Rgba& p);

// The pixel's colour as seen on white paper (what the line detector sees).
Eigen::Vector3d colour_on_white(const Rgba& p);

// Per triangle: 1 if more than half of the pixel centres it holds are
// transparent paper (a triangle holding no pixel centre goes by the pixel
// under its centroid). `tri` is rasterize_triangles of the mesh.
std::vector<char> paper_triangles(const Image& image, const TriMesh2& mesh, const LabelMap& tri);

}  // namespace hair25d::segment::detail
