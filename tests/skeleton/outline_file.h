#pragma once
// Reads an outline from tests/data/skeleton ("x y" per line, pixels), for the
// skeleton tests and the mesh benchmark. Needs HAIR25D_TEST_DATA_DIR.

#include <fstream>
#include <string>

#include "hair25d/core/geometry.h"

namespace hair25d::testing {

// Empty when the file is missing, which the callers' size checks report.
inline Polyline read_outline(const std::string& name) {
  std::ifstream in(std::string(HAIR25D_TEST_DATA_DIR) + "/skeleton/" + name);
  Polyline outline;
  double x = 0, y = 0;
  while (in >> x >> y) outline.emplace_back(x, y);
  return outline;
}

}  // namespace hair25d::testing
