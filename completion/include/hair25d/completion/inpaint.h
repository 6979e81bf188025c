// Exemplar-based inpainting after Criminisi, Pérez and Toyama (2004), used by
// paper §5.4 for the colours of completed hair and for the background behind
// the hair. Fast: SSD over square patches, candidates only in a bounded search
// window around the patch being filled (widened only when it holds none).
#pragma once

#include <string>

#include "hair25d/core/image.h"

namespace hair25d::completion {

struct InpaintOptions {
  int patch_radius = 4;    // patches are (2r+1)², 9×9 by default
  int search_radius = 16;  // candidates within this many pixels of the target patch
  int search_step = 2;     // candidate stride inside the window (2 = 4× faster)
  // Added to the SSD per squared pixel of distance between target and source:
  // among equal matches the nearest wins, so distinct features (an eye) are
  // not copied far across a flat area.
  double distance_weight = 2.0;
  // A target with no whole source patch within search_radius (deep in a large
  // hole) is matched against the sources continuing its neighbours' copies
  // and at most this many of the nearest candidates of the widened window;
  // 0 = every candidate of the window (exact, thousands per target).
  int far_candidates = 64;
  // Cel-art fill (inpaint_cel) only. Ink = luma below ink_luma, or a ridge
  // more than ink_step darker than both sides (1–2 px away): drawn lines,
  // hatching and small dark features, not the border of two flat regions.
  int ink_luma = 110;
  int ink_step = 24;
  // SSD weight of the coarse fill's colours on a target patch's unknown pixels.
  double guide_weight = 2.0;
  // False, with a message naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

struct InpaintResult {
  int filled = 0;    // pixels filled
  int patches = 0;   // patches copied
  int unfilled = 0;  // target pixels left (no source patch anywhere)
};

// Fills the pixels of `image` where `fill` is non-zero by copying patches whose
// pixels are all sources: `source` non-zero, or, when `source` is empty, every
// pixel not in `fill`. Pixels outside `fill` are never changed. Throws
// hair25d::Error if the sizes differ or the options are invalid.
InpaintResult inpaint_exemplar(Image& image, const LabelMap& fill, const LabelMap& source,
                               const InpaintOptions& options = {});

// inpaint_exemplar made right for cel art (flat regions bounded by ink): a
// coarse fill first gives every hole pixel the colour of the nearest known
// ink-free pixel (the flat region it continues); exemplar synthesis then adds
// texture, matching known pixels and the coarse fill, and may copy a patch
// holding ink only when the target's known part holds ink too — an eye or a
// hair clip next to the hole is never duplicated into it. On a screentone
// (the sources' small ink dots repeat on a lattice) the dots are paint, not
// ink, and patches are copied from whole lattice translates, so the dots go
// on in phase. Same contract as inpaint_exemplar: pixels outside `fill` are
// never changed.
InpaintResult inpaint_cel(Image& image, const LabelMap& fill, const LabelMap& source,
                          const InpaintOptions& options = {});

}  // namespace hair25d::completion
