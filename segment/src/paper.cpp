#include "paper.h"

#include <algorithm>

#include "hair25d/segment/regions.h"

namespace hair25d::segment::detail {

bool is_paper(const Rgba& p) { return p.a < kOpaqueAlpha; }

Eigen::Vector3d colour_on_white(const Rgba& p) {
  const double a = p.a / 255.0;
  return Eigen::Vector3d(a * p.r + (1.0 - a) * 255.0, a * p.g + (1.0 - a) * 255.0,
                         a * p.b + (1.0 - a) * 255.0);
}

std::vector<char> paper_triangles(const Image& image, const TriMesh2& mesh, const LabelMap& tri) {
  const int nf = mesh.triangle_count();
  std::vector<int> paper(nf, 0), all(nf, 0);
  for (int y = 0; y < image.height(); ++y) {
    for (int x = 0; x < image.width(); ++x) {
      const int t = tri.at(x, y);
      if (t < 0) continue;
      ++all[t];
      if (is_paper(image.at(x, y))) ++paper[t];
    }
  }
  std::vector<char> out(nf, 0);
  for (int t = 0; t < nf; ++t) {
    if (all[t] > 0) {
      out[t] = 2 * paper[t] > all[t];
      continue;
    }
    const Eigen::Vector2d c =
        (mesh.V.row(mesh.F(t, 0)) + mesh.V.row(mesh.F(t, 1)) + mesh.V.row(mesh.F(t, 2))) / 3.0;
    if (image.empty()) continue;
    const int x = std::clamp(static_cast<int>(c.x()), 0, image.width() - 1);
    const int y = std::clamp(static_cast<int>(c.y()), 0, image.height() - 1);
    out[t] = is_paper(image.at(x, y));
  }
  return out;
}

}  // namespace hair25d::segment::detail
