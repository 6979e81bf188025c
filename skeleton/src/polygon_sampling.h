// Closed-outline helpers shared by the skeleton and the mesh: validation,
// uniform resampling that remembers which input edge each sample came from.
#pragma once

#include <vector>

#include "hair25d/core/geometry.h"

namespace hair25d::skeleton::detail {

// Throws hair25d::Error naming `what` if a point is not finite or fewer than 3
// distinct points remain after dropping consecutive duplicates. Returns the
// cleaned polygon and, for each kept point, its index in `polygon`.
Polyline clean_polygon(const Polyline& polygon, const char* what, std::vector<int>* source_index);

// Samples a closed polygon every ~`spacing` pixels along its perimeter; every
// input vertex whose turn is sharper than ~30° is kept so corners stay exact.
// `source` receives for each sample the input vertex it is nearest to along
// the outline.
Polyline resample_closed(const Polyline& polygon, double spacing, std::vector<int>* source);

}  // namespace hair25d::skeleton::detail
