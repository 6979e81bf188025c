// Pieces of the exemplar inpainting shared by inpaint.cpp and cel_fill.cpp.
#pragma once

#include <cstdint>
#include <vector>

#include "hair25d/completion/inpaint.h"

namespace hair25d::completion::detail {

// 1 where a pixel is ink: darker than options.ink_luma, or the darker side of
// a luma step above options.ink_step.
std::vector<std::uint8_t> ink_mask(const Image& image, const InpaintOptions& options);

// The colours a set of pixels is painted in: a histogram in 8-level bins. A
// colour is common when the bins within one step of its own hold at least
// `share` of the pixels (a flat fill, its shading bands, the lines), not the
// few pixels of another colour a segmentation or an anti-aliased rim gives.
class CommonColours {
 public:
  explicit CommonColours(double share) : share_(share), count_(kSide * kSide * kSide, 0) {}
  // Pixels are added first; the first common() call sums the neighbourhoods.
  void add(const Rgba& c) { ++count_[bin(c)], ++total_; }
  bool common(const Rgba& c) const;
  long total() const { return total_; }

 private:
  static constexpr int kBin = 8, kSide = 256 / kBin;
  static std::size_t bin(const Rgba& c) {
    return static_cast<std::size_t>(((c.r / kBin) * kSide + c.g / kBin) * kSide + c.b / kBin);
  }
  double share_;
  std::vector<long> count_;
  long total_ = 0;
  mutable std::vector<std::uint8_t> common_;  // per bin, once summed
};

// The options inpaint_cel works with for these sources: ink_luma no higher
// than half the sources' median luma, so that on dark hair the fill is not
// taken for ink (only its darker lines are).
InpaintOptions source_ink_options(const Image& image, const LabelMap& fill, const LabelMap& source,
                                  const InpaintOptions& options);

// The coarse fill of inpaint_cel: `image` with every `fill` pixel set to the
// colour of the nearest known, ink-free source pixel; `ink` is the image's
// ink_mask.
Image coarse_fill(const Image& image, const LabelMap& fill, const LabelMap& source,
                  const std::vector<std::uint8_t>& ink);

// A screentone among the sources: its dots (small ink components) repeat by
// the basis vectors a and b (px). Found by find_dot_lattice; `valid` false
// where the sources hold no such tone (flat, two-tone and gradient paint).
struct DotLattice {
  bool valid = false;
  double ax = 0.0, ay = 0.0, bx = 0.0, by = 0.0;
  std::vector<std::uint8_t> dots;  // per pixel, 1 on a dot (valid only)
};
// A dot: an 8-connected ink component of the sources of kMinDotArea to
// kMaxDotArea px and at most kMaxDotSide px each way (the generator's dots
// cover 3-35 px; drawn lines are longer). A lattice needs kMinDots dots, and
// kMinWholeShare of the steps between neighbouring dots must be whole
// lattice vectors (within 0.2 of a cell each way).
constexpr int kMinDotArea = 2, kMaxDotArea = 60, kMaxDotSide = 10, kMinDots = 30;
constexpr double kMinWholeShare = 0.8;
// A dense tone's dot cores: darker than this share of the way from the
// sources' darkest pixels (5th percentile) to their paper (90th
// percentile), which must be at least kMinToneContrast apart.
constexpr double kCoreShare = 0.3;
constexpr int kMinToneContrast = 64;
// At most this many dots vote for the basis vectors.
constexpr std::size_t kSample = 300;
DotLattice find_dot_lattice(const Image& image, const LabelMap& fill, const LabelMap& source,
                            const std::vector<std::uint8_t>& ink);

// Criminisi fill; with a guide, in cel mode (see inpaint_cel). `ink`, when
// the caller has it, is ink_mask(image, options) (else it is computed).
InpaintResult run_exemplar(Image& image, const LabelMap& fill, const LabelMap& source,
                           const InpaintOptions& options, const Image* guide,
                           const std::vector<std::uint8_t>* ink = nullptr,
                           const DotLattice* lattice = nullptr);

}  // namespace hair25d::completion::detail
