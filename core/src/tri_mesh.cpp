#include "hair25d/core/tri_mesh.h"

#include <string>

#include "hair25d/core/error.h"

namespace hair25d {

void TriMesh2::validate(const char* what) const {
  const std::string name(what);
  if (on_curve.rows() != 0 && on_curve.rows() != F.rows()) {
    throw Error(name + ": on_curve has " + std::to_string(on_curve.rows()) +
                " rows; must be 0 or one per triangle (" + std::to_string(F.rows()) + ")");
  }
  for (int t = 0; t < F.rows(); ++t) {
    for (int k = 0; k < 3; ++k) {
      const int v = F(t, k);
      if (v < 0 || v >= V.rows()) {
        throw Error(name + ": triangle " + std::to_string(t) + " names vertex " +
                    std::to_string(v) + "; vertices are 0.." + std::to_string(V.rows() - 1));
      }
    }
    if (F(t, 0) == F(t, 1) || F(t, 1) == F(t, 2) || F(t, 0) == F(t, 2)) {
      throw Error(name + ": triangle " + std::to_string(t) + " repeats a vertex");
    }
  }
  if (!V.allFinite()) throw Error(name + ": a vertex position is not finite");
}

}  // namespace hair25d
