// Synthetic cartoon-hair drawings with exact ground truth, written in the
// annotated case format (FORMATS.md): drawing, regions, layering pairs,
// strokes and whole strand masks. Seeded and deterministic; used by tests and
// benchmarks of every stage.
#pragma once

#include <cstdint>
#include <string>

#include "hair25d/core/annotation.h"

namespace hair25d::generator {

enum class Shading {
  kFlat,        // one colour a strand
  kTwoTone,     // cel shading: a darker band along one side
  kGradient,    // smooth gradient along the strand
  kScreentone,  // grey manga: dotted tone instead of colour
};

struct Options {
  int width = 640;             // pixels
  int height = 480;            // pixels
  int strand_count = 12;       // hair strands (regions can be more: split strands)
  double line_width = 3.0;     // outline width, pixels (anti-aliased)
  Shading shading = Shading::kFlat;
  double noise_sigma = 0.0;    // Gaussian pixel noise, 0..255 scale
  int jpeg_quality = 0;        // > 0: pass the drawing through JPEG at this quality
  bool coloured_lines = false; // lines in a dark hair colour instead of black
  std::uint64_t seed = 1;

  // False, naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

// Draws one case. The result's regions hold every visible hair region (outline
// pixels between regions are 0), pairs every pair of regions that share a
// boundary with its true relation, strokes one stroke per region and some
// background strokes, strand_masks each strand's whole shape. Throws
// hair25d::Error if the options are invalid.
AnnotatedCase generate_case(const Options& options);

}  // namespace hair25d::generator
