// How the pieces of a strand join are painted (private, case 1 of §5.1):
// the colour step between two cut edges that their paint does not explain
// — cel paint compared by its flat colours, gradients by the change their
// slopes predict across the gap. The strand joins' colour term.
#pragma once

#include <Eigen/Core>
#include <map>
#include <opencv2/core.hpp>
#include <utility>
#include <vector>

#include "context.h"

namespace hair25d::completion::detail {

// How a piece is painted next to its cut: its flat colours (cel paint: a
// base and a shadow band) in the 11 x 11 windows along the edge, and a
// linear fit of its colour over 25 x 25 windows (a gradient along the
// strand). Drawn pixels of the region only, not outlines.
struct EdgePaint {
  std::vector<Eigen::Vector3d> flats;   // up to two flat colours, commonest first
  Eigen::Vector3d fit_colour{0, 0, 0};  // the fit's colour at fit_centre
  Vec2 fit_centre{0, 0};                // mean position of the fitted pixels
  Eigen::Matrix<double, 3, 2> slope = Eigen::Matrix<double, 3, 2>::Zero();  // RGB per px
  double fit_residual = 0.0;  // RGB deviation from the fit
};

// A region's flat colours (up to three, each at least 5 % of its pixels) and
// the share of its pixels that its three commonest colours hold (4-level
// bins): near 1 for flat and cel paint, low for gradients and real shading.
struct RegionPaint {
  std::vector<Eigen::Vector3d> flats;
  double exact_share = 0.0;
};

// Flat colours of `pixels` of `image`, at most `most`: in 8-level bins, the
// mean of the pixels in the 3 x 3 x 3 bins round the bin whose neighbourhood
// holds most, taken out in turn while that holds at least `min_share` of the
// pixels. With `exact_paint`, a cluster one exact colour holds more than
// half of is that colour's paint: the mean of the colours within 1 RGB of
// it (a cel band's anti-aliased blends left out).
std::vector<Eigen::Vector3d> flat_colours(const Image& image, const std::vector<cv::Point>& pixels,
                                          int most, double min_share, bool exact_paint = false);

// The paint next to edge `e`'s cut, and the paint of a whole region.
EdgePaint edge_paint(const Context& ctx, const Edge& e);
RegionPaint region_paint(const Context& ctx, int region);

// The drawing's cel shadow: per channel, the ratio of a flat-painted
// region's darker flat colour to its lighter one, when at least 3 regions
// show two and half of them agree within 0.05 on every channel (the median);
// none (all 0) otherwise.
Eigen::Vector3d shadow_ratio(const std::map<int, RegionPaint>& paints);

// The colour step between two pieces' cuts that their paint does not
// explain (RGB):
// - flat or cel paint (both regions): the flat colours at one cut that the
//   other piece is not painted in anywhere, the smaller way round. A cel
//   band spreads a window's colours, so the mean step beyond the spread
//   said nothing on two-tone drawings; a piece may show only the base or
//   only the band at its cut, but the strand is painted in both.
// - colour linear in position (both windows, a gradient along the strand):
//   the step beyond the change the mean slope of the two pieces predicts
//   between them, beyond the fits' deviations (`off_gradient` when that is
//   more than the extrapolation's error);
// - else the step between the windows' means beyond their spread.
struct PaintStep {
  double step = 0.0;               // RGB
  bool flat = false;               // compared as flat paint
  bool shading_continues = false;  // both pieces' gradients predict the step
  // Compared by the linear fits, the step is more than a gradient explains:
  // over 1 RGB where the slopes predict little change across the gap, over
  // 3 RGB and a fifth of the predicted change elsewhere (two strands).
  bool off_gradient = false;
  // Both windows linear, one's slope under kUnevenSlopeShare of the
  // other's: the shallow window missed the strand's rate (a gradient by the
  // curve's parameter changes fastest where the curve is slowest), so the
  // mean slope under-predicts the change and `off_gradient` says little.
  bool uneven_slopes = false;
};
PaintStep paint_step(const Edge& a, const Edge& b, const EdgePaint& pa, const EdgePaint& pb,
                     const RegionPaint& ra, const RegionPaint& rb, const Eigen::Vector3d& shadow);

}  // namespace hair25d::completion::detail

namespace hair25d::completion::detail {

// Whether `dark` is a cel shadow of `light` (join_paint.cpp: a steady share
// of it on every channel, as the generator's band is of its base).
bool shade_of(const Eigen::Vector3d& light, const Eigen::Vector3d& dark);

// Cel paint of whole pieces: up to three flat colours of a region's drawn
// pixels (2 px inside it — 1 px or all for a sliver — so that the drawn
// line's anti-aliased rim is no colour), each with the pixels' row range.
// The back hair of a cel-shaded drawing is one mass painted in a base and a
// shadow band below a (wavy) level; a strand lying on it may hide the level,
// so one piece is seen in the base and another in the band, and a big piece
// holding both tells which colour each of its hidden parts has.
class RegionCels {
 public:
  explicit RegionCels(const Context& ctx) : ctx_(&ctx) {}
  struct Cel {
    std::vector<Eigen::Vector3d> flats;  // commonest first
    std::vector<double> top, bottom;     // per flat: its pixels' rows (5th, 95th percentile)
    double share = 0.0;                  // pixels within 6 RGB of a flat
    int pixels = 0;
  };
  const Cel& cel(int region);
  // The RGB distance of the paint of one piece to the other's nearest flat
  // colour, the worse of its flats, the smaller way round; infinity when
  // either piece is no flat paint. `level` (optional) says whether each
  // matched flat lies on its side of the other piece's band level: a piece
  // matching the band lies not wholly above the band's top, one matching
  // the base not wholly below the base's bottom.
  double step(int a, int b, bool* level = nullptr);
  // On a cel drawing: `other` when the pieces are painted in other flat
  // colours (step over 3 RGB: the generator varies each strand's colour by
  // up to 8 %), `same` when one lies in the other's base or band on its
  // side of the band's level (step at most 1 RGB, the other piece showing
  // both under a level). Neither elsewhere.
  struct Judgement {
    bool other = false, same = false;
    double step = 0.0;
  };
  Judgement judge(int a, int b);
  // Whether the drawing is cel-painted: at least three quarters of its
  // regions with kMinCelDrawingPixels inner pixels are flat paint (generated
  // flat and two-tone drawings all; gradient ones only their small pieces).
  bool cel_drawing();

 private:
  const Context* ctx_;
  std::map<int, Cel> cels_;
  int cel_drawing_ = -1;
};

// Whether two pieces are painted by one linear colour field (a gradient
// running on under the occluders), judged over the pieces' whole
// interiors: least-squares fits colour = c + S (x − m) per piece and over
// both together, from sums kept per region (drawn pixels 2 px inside it —
// 1 px or all for a sliver — ink left out). A field fitted over a whole
// back-hair piece predicts its gradient far from the cut; the 11 x 11
// windows at a path's or ray's ends do not (the gradient across the
// crossed strands is the step they measure).
class RegionFields {
 public:
  explicit RegionFields(const Context& ctx) : ctx_(&ctx), cels_(ctx) {}
  // The RGB the joint fit misses by on each piece beyond that piece's own
  // fit (root of the excess mean square), summed over both pieces.
  // Infinity — nothing said — when either piece has too few pixels or is
  // not linear itself, or when the joint field is no gradient (too
  // shallow, or predicting little change between the pieces, or no piece
  // sloping on its own): pieces of one flat paint fit one field whichever
  // strands they belong to, and two flat pieces of nearly one colour fit
  // one sloping between them.
  double step(int a, int b);
  // The step of the drawing's kind of paint: the cel step on a drawing of
  // cel paint, else the field's.
  double paint_step(int a, int b) { return cels_.cel_drawing() ? cels_.step(a, b) : step(a, b); }
  // Session 39: how each piece's own field predicts the other piece's
  // paint where that piece is cut: |f_a(at_b) − f_b(at_b)| and
  // |f_b(at_a) − f_a(at_a)| (RGB, each piece's own fit standing for its
  // paint at its cut): the larger of the two, then the larger piece's
  // (more pixels) into the other's cut. Infinity for both when either
  // piece has too few pixels or is not linear itself.
  std::pair<double, double> cross_miss(int a, const Vec2& at_a, int b, const Vec2& at_b);
  // The pieces' cel paint (measured once for the mass and path joins).
  RegionCels& cels() { return cels_; }

  struct Sums {
    double n = 0;
    Eigen::Matrix3d xx = Eigen::Matrix3d::Zero();  // [1 x y]^T [1 x y]
    Eigen::Matrix3d xc = Eigen::Matrix3d::Zero();  // [1 x y]^T rgb, rows = design
    double cc = 0;                                 // sum |rgb|^2
  };

 private:
  const Sums& sums(int region);
  const Context* ctx_;
  RegionCels cels_;
  std::map<int, Sums> sums_;
};

}  // namespace hair25d::completion::detail
