// The background behind the hair (paper §5.4 "inpainting"): the drawing with
// a hole filled at full resolution so that moving hair uncovers face, skin or
// paper — ink lines continued across the hole, flat colours up to them.
#pragma once

#include <string>

#include "hair25d/completion/inpaint.h"
#include "hair25d/core/image.h"

namespace hair25d::completion {

struct BackgroundOptions {
  // Ink lines entering the hole are continued: two ends are joined by a C¹
  // cubic (as the case-1 joins of §5.1) when each end's tangent is within
  // this angle of the chord between them.
  double max_join_angle_deg = 45.0;
  double max_join_length = 300.0;   // pixels between joined ends
  double min_width_ratio = 0.35;    // thinner / thicker line end
  double max_colour_distance = 90;  // RGB distance of the two lines' colours
  double min_inside_share = 0.9;    // share of the join that must lie in the hole
  double tangent_arm = 14.0;        // pixels of visible line used for an end's tangent
  // An unpaired end whose line separates two different flat colours (a face
  // outline against the paper) is continued with its own curvature when it
  // meets ink or a continued line within this many pixels.
  double max_extension = 60.0;
  bool continue_lines = true;
  bool ink_seams = true;  // draw ink along seams between colours the drawing separates by ink
  int seam_radius = 2;    // median radius that straightens seams between fill colours
  // Where the known pixels around the hole vary more than this (luma standard
  // deviation of ink-free pixels, 0..255), the exemplar pass adds texture;
  // flat cel regions take the flat fill alone.
  double texture_threshold = 10.0;
  // Exemplar texture pass and the ink thresholds (ink_luma, ink_step).
  InpaintOptions inpaint;

  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

struct BackgroundResult {
  Image image;             // the input with every hole pixel filled
  int filled = 0;          // hole pixels written
  int line_ends = 0;       // ink line ends found on the hole's rim
  int joined_lines = 0;    // pairs of ends joined across the hole
  int extended_lines = 0;  // unpaired ends continued
  int seam_pixels = 0;     // fill seams drawn as ink (colours the drawing separates by ink)
  InpaintResult texture;   // the exemplar pass where the surroundings are textured
  int unreached = 0;       // hole pixels with no known pixel to take a colour from
};

// Fills the pixels of `image` where `hole` is non-zero; known pixels are never
// changed. Alpha is filled like colour (a drawing on a transparent sheet stays
// transparent where the hole was). Throws hair25d::Error if the sizes differ
// or the options are invalid.
BackgroundResult fill_background(const Image& image, const LabelMap& hole,
                                 const BackgroundOptions& options = {});

}  // namespace hair25d::completion
