// A drawing of the generator for the completion tests: without strand
// masks, as the joins are scored on pairs of the annotation's regions.
#pragma once

#include <cstdint>

#include "hair25d/core/annotation.h"
#include "hair25d/generator/generator.h"

namespace hair25d::completion::test {

inline AnnotatedCase generated_case(std::uint64_t seed, generator::Shading shading, int width = 800,
                                    int height = 640, int strands = 20) {
  generator::Options g;
  g.width = width;
  g.height = height;
  g.strand_count = strands;
  g.seed = seed;
  g.shading = shading;
  g.strand_masks = false;
  return generator::generate_case(g);
}

}  // namespace hair25d::completion::test
