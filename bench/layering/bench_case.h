// The drawing the layering benchmarks time: generated (seed 42) with at least
// `regions` regions. The strand count is raised until the case has that many
// (the generator splits strands into several regions, so the ratio is not
// fixed).
#pragma once

#include <algorithm>

#include "hair25d/generator/generator.h"

namespace hair25d::bench {

inline AnnotatedCase layering_case(int regions, int width, int height) {
  generator::Options o;
  o.width = width;
  o.height = height;
  o.seed = 42;
  o.strand_masks = false;
  AnnotatedCase c;
  for (int strands = std::max(1, regions * 2 / 3);; strands += std::max(1, strands / 10)) {
    o.strand_count = strands;
    c = generator::generate_case(o);
    if (static_cast<int>(c.regions.labels().size()) >= regions || strands > 4 * regions) break;
  }
  return c;
}

}  // namespace hair25d::bench
