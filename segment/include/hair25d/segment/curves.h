// Curve extraction after Cheng (2009), paper §3: the drawn lines of a cartoon
// as polylines through their centres, with endpoints and junctions marked.
// Hessian line response, non-maximum suppression, hysteresis, linking.
#pragma once

#include <string>
#include <vector>

#include "hair25d/core/image.h"
#include "hair25d/core/segmentation.h"

namespace hair25d::segment {

struct CurveOptions {
  // Gaussian scales (pixels) at which dark lines are looked for; a line of
  // width w answers best at about w / 2. The default covers lines 1.5-8 px wide.
  std::vector<double> scales{1.0, 1.6, 2.5};
  // Hysteresis on the line response (grey levels, 0-255): a curve starts at a
  // response above high_threshold and goes on while it stays above low_threshold.
  double high_threshold = 18.0;
  double low_threshold = 7.0;
  // Isolated dark specks that fit in speck_size × speck_size pixels
  // (screentone dots, dirt) are painted over before lines are looked for; 0 keeps them.
  int speck_size = 6;
  // Dots (screentone) answer in both Hessian directions, lines in one: the
  // response is λ1 − blob_weight · max(λ2, 0).
  double blob_weight = 1.0;
  // Curves shorter than this (pixels) that touch nothing are dropped.
  double min_curve_length = 8.0;
  // Side branches shorter than spur_factor × line width that end freely are
  // noise at corners and line ends, and are removed.
  double spur_factor = 3.0;
  // A free end is joined to a curve it points at within gap_factor × line width
  // (lines that stop just short of another line, T-junctions the response misses).
  double gap_factor = 2.5;

  // False, naming the option, its value and the rule, if unusable.
  bool is_valid(std::string* error) const;
};

struct CurveResult {
  std::vector<Curve> curves;  // pixel coordinates, pixel (i, j) covers [i, i+1) × [j, j+1)
  // 1 where a drawn line covers the pixel (ink near a traced centre line), else 0.
  LabelMap line_mask;
  double line_width = 0.0;  // estimated typical line width, pixels (0 if no lines)
  int ridge_pixels = 0;     // centre-line pixels found before linking
};

// Extracts the dark lines of `image` (transparent pixels count as white).
// Throws hair25d::Error for invalid options. An empty or tiny image gives no curves.
CurveResult extract_curves(const Image& image, const CurveOptions& options = {});

struct SimplifyOptions {
  double smoothing_sigma = 1.0;  // Gaussian along the curve, in pixels of arc length
  double tolerance = 0.5;        // Douglas–Peucker distance, pixels

  bool is_valid(std::string* error) const;
};

// Smooths every curve by a Gaussian along it and simplifies it by
// Douglas–Peucker; endpoints and junctions (the curve ends) never move, so
// curves meeting at a junction still share that point exactly.
std::vector<Curve> smooth_and_simplify(const std::vector<Curve>& curves,
                                       const SimplifyOptions& options = {});

// Douglas–Peucker on an open polyline: the fewest points whose polyline stays
// within `tolerance` of the input; the first and last points are kept.
Polyline douglas_peucker(const Polyline& line, double tolerance);

}  // namespace hair25d::segment
