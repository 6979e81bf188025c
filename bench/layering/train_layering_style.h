// The generated drawings the learned layering models are trained on
// (train_layering.cpp, train_layering_patch.cpp): drawing i of a run.
#pragma once

#include <cstdint>
#include <map>
#include <utility>

#include "hair25d/core/annotation.h"
#include "hair25d/generator/generator.h"

namespace hair25d::layering_training {

// A spread of styles so the weights do not learn one look: shading, line
// width, noise, JPEG, coloured lines, image size and strand count all vary.
inline hair25d::generator::Options training_style(int i, std::uint64_t seed) {
  static constexpr hair25d::generator::Shading kShadings[] = {
      hair25d::generator::Shading::kFlat, hair25d::generator::Shading::kTwoTone,
      hair25d::generator::Shading::kGradient, hair25d::generator::Shading::kScreentone};
  static constexpr double kLines[] = {1.0, 1.5, 2.0, 3.0, 4.0, 6.0, 2.5};
  static constexpr int kJpeg[] = {0, 40, 70, 0, 90};
  static constexpr double kNoise[] = {0.0, 4.0, 0.0, 8.0};
  static constexpr int kStrands[] = {8, 12, 16, 24, 10, 20};
  static constexpr int kSizes[][2] = {{640, 480}, {800, 600}, {960, 720}, {512, 640}};
  hair25d::generator::Options o;
  o.seed = seed + static_cast<std::uint64_t>(i);
  o.shading = kShadings[i % 4];
  o.line_width = kLines[i % 7];
  o.jpeg_quality = kJpeg[i % 5];
  o.noise_sigma = kNoise[i % 4];
  o.coloured_lines = i % 6 == 5;
  o.fading_forks = i % 3 == 1;
  o.strand_count = kStrands[i % 6];
  o.width = kSizes[i % 4][0];
  o.height = kSizes[i % 4][1];
  o.strand_masks = false;
  return o;
}

// The drawings the patch networks also learn from since session 10
// (train_layering_patch --extra-from): the same spread, but thin lines
// (1–1.8 px) and fork lines that fade out inside the strand in half of them,
// the two styles the layering read worst. The line widths cycle over 7 and
// the forks over blocks of 12 drawings, so neither is tied to the shading
// (4), JPEG (5) or strand count (6) of training_style.
inline hair25d::generator::Options thin_fork_style(int i, std::uint64_t seed) {
  static constexpr double kThinLines[] = {1.0, 1.2, 1.5, 1.2, 1.8, 1.0, 1.4};
  hair25d::generator::Options o = training_style(i, seed);
  o.line_width = kThinLines[i % 7];
  o.fading_forks = (i / 12) % 2 == 0;
  return o;
}

// Drawings the patch networks may also learn from since session 14
// (train_layering_patch --dark-from): training_style's spread with the hair
// painted about as dark as the ink (generator::Options::dark_hair), as in
// black-haired manga, where the grey levels show no line between the
// darkest strands and only the hue (or nothing) tells the ink from the
// paint.
inline hair25d::generator::Options dark_style(int i, std::uint64_t seed) {
  hair25d::generator::Options o = training_style(i, seed);
  o.dark_hair = true;
  return o;
}

// Drawing i of a patch-network run: from `dark_from` on in dark_style, else
// from `extra_from` on in thin_fork_style, else in training_style.
inline hair25d::generator::Options patch_style(int i, std::uint64_t seed, int extra_from,
                                               int dark_from) {
  if (i >= dark_from) return dark_style(i, seed);
  if (i >= extra_from) return thin_fork_style(i, seed);
  return training_style(i, seed);
}

// The annotated relation of every judged pair, both ways round.
inline std::map<std::pair<int, int>, hair25d::Relation> pair_truth(
    const hair25d::AnnotatedCase& c) {
  std::map<std::pair<int, int>, hair25d::Relation> truth;
  for (const hair25d::AnnotatedPair& p : c.pairs) {
    truth[{p.a, p.b}] = p.relation;
    truth[{p.b, p.a}] = hair25d::reversed(p.relation);
  }
  return truth;
}

}  // namespace hair25d::layering_training
