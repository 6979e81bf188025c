// Random layout pieces of a cartoon head: palette, back-hair mass, cap, face,
// body, and the tapered strands (bangs, side locks, tails) with their layers.
#pragma once

#include "rng.h"
#include "scene.h"
#include "strand_shape.h"

namespace hair25d::generator {

// The head the layout is built around, in image pixels.
struct Head {
  Vec2 centre;       // cranium centre
  double radius;     // cranium radius
  Vec2 face_centre;  // skin ellipse
  Vec2 face_radii;
  double face_angle;
  double strand_scale;  // multiplies strand widths
};

struct Palette {
  Colour hair;
  Colour skin;
  Colour clothes;
  Colour eyes;
  Colour background;
  Colour line;
};

Palette make_palette(const Options& options, Rng& rng);
Head make_head(const Options& options, Rng& rng);

Shape make_back_mass(const Head& head, const Palette& pal, int image_height, Rng& rng);
Shape make_cap(const Head& head, const Palette& pal, Rng& rng);
Shape make_face(const Head& head, const Palette& pal, Rng& rng);
Shape make_body(const Head& head, const Palette& pal, int image_height, Rng& rng);
// A hair tie over the root of a tail on `side` (-1 left, 1 right).
Shape make_tie(const Head& head, const Palette& pal, int side, Rng& rng);

// Kinds of tapered strand; they differ in where the root sits, where the strand
// goes and how long and wide it is.
enum class StrandKind { kBang, kUnderCap, kSideFront, kBehindFace, kTail };

// `side`: -1 left, 1 right (side locks, tails); `slot` in [0, 1): where along
// the crown a bang's root goes (< 0: anywhere).
Shape make_strand(StrandKind kind, const Head& head, const Palette& pal, const Options& options,
                  int side, double slot, Rng& rng);

}  // namespace hair25d::generator
