// Pieces of the exemplar inpainting shared by inpaint.cpp and cel_fill.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "hair25d/completion/inpaint.h"

namespace hair25d::completion::detail {

// 1 where a pixel is ink: darker than options.ink_luma, or the darker side of
// a luma step above options.ink_step.
std::vector<std::uint8_t> ink_mask(const Image& image, const InpaintOptions& options);

// The coarse fill of inpaint_cel: `image` with every `fill` pixel set to the
// colour of the nearest known, ink-free source pixel.
Image coarse_fill(const Image& image, const LabelMap& fill, const LabelMap& source,
                  const InpaintOptions& options);

// Criminisi fill; with a guide, in cel mode (see inpaint_cel).
InpaintResult run_exemplar(Image& image, const LabelMap& fill, const LabelMap& source,
                           const InpaintOptions& options, const Image* guide);

}  // namespace hair25d::completion::detail
