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
  int width = 640;          // pixels
  int height = 480;         // pixels
  int strand_count = 12;    // hair strands (regions can be more: split strands)
  double line_width = 3.0;  // outline width, pixels (anti-aliased)
  Shading shading = Shading::kFlat;
  double noise_sigma = 0.0;     // Gaussian pixel noise, 0..255 scale
  int jpeg_quality = 0;         // > 0: pass the drawing through JPEG at this quality
  bool coloured_lines = false;  // lines in a dark hair colour instead of black
  // Fork lines stop inside the strand (as many artists draw them) while the
  // annotation still splits the strand along the whole fork: the two halves
  // meet without a drawn line where it fades. Off: fork lines run to the side.
  bool fading_forks = false;
  // Dark hair (black-haired manga): paint about as dark as the ink, in a
  // third of the cases on a backdrop as dark. Off: every output is as before.
  bool dark_hair = false;
  bool strand_masks = true;  // fill strand_masks (a full-size map a strand; off saves time)
  std::uint64_t seed = 1;

  // False, naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

// Draws one case. The result's regions hold every visible hair region (outline
// pixels between regions are 0), pairs every pair of regions that share a
// boundary with its true relation, strokes one stroke per region and some
// background strokes, strand_masks each strand's whole shape. Throws
// hair25d::Error if the options are invalid.
//
// Details the tests rely on:
// - strand ids 1..strand_count follow the painter's order: a larger id lies
//   above; regions of one strand are "equal" (split by an occluder, or the two
//   halves of a forked strand);
// - regions are 4-connected pieces of one strand's fill between lines; pieces
//   too thin to hold a width-3 stroke 3 pixels from their edge are left 0;
// - two regions are a pair when they meet across one line: after each region
//   grows by ceil(line_width / 2) + 1 pixels into the line around it, they
//   share at least 3 pixel edges;
// - strokes (width 3) follow the middle of their region, one to three per
//   region (more where a region bends); every pixel under a stroke lies in
//   the stroke's region (label 0 strokes: on paper, face or body, and a ring
//   of short ones around the hair);
// - head_center is the centre of the cranium circle the hair is laid around;
// - noise and JPEG change the picture only, never the ground truth.
AnnotatedCase generate_case(const Options& options);

}  // namespace hair25d::generator
