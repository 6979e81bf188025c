// Pieces of the background fill shared by background.cpp, line_continuation.cpp
// and cel_fill.cpp (private). All rasters are row-major, one byte a pixel, the
// size of the working crop.
#pragma once

#include <cstdint>
#include <vector>

#include "hair25d/completion/background.h"
#include "hair25d/core/geometry.h"

namespace hair25d::completion::detail {

using Mask = std::vector<std::uint8_t>;

// An ink line ending on the hole's rim.
struct LineEnd {
  Vec2 p{0, 0};          // where it meets the hole (pixel coordinates, centres at +0.5)
  Vec2 d{0, 0};          // unit tangent pointing into the hole
  double width = 1.0;    // pixels
  double curvature = 0;  // signed, 1/pixels: d turns towards +90° when > 0
  Rgba colour{};         // the line's ink colour
  // Flat colours beside the line just outside the hole, left (d turned −90°)
  // and right; `sides` is false when either side holds no flat pixel.
  Rgba left{}, right{};
  bool sides = false;
};

// A line to draw into the hole: a centre line with a width at each point.
struct Stroke {
  Polyline points;
  std::vector<double> widths;
  Rgba colour{};
};

// Line ends on the rim of `hole` (ink = known ink pixels of `image`).
std::vector<LineEnd> find_line_ends(const Image& image, const Mask& hole, const Mask& ink,
                                    const BackgroundOptions& options);

// Pairs of ends joined by C¹ cubics, then unpaired ends that separate two
// flat colours continued with their curvature. Counts go to `joined`, `extended`.
std::vector<Stroke> continue_lines(const std::vector<LineEnd>& ends, const Mask& hole,
                                   const Mask& ink, int width, int height,
                                   const BackgroundOptions& options, int* joined, int* extended);

// Solid (not anti-aliased) rasters of the strokes, at least 2 px wide so that
// an 8-connected fill cannot slip through: 1 where a stroke is.
Mask stroke_barrier(const std::vector<Stroke>& strokes, int width, int height);

// Anti-aliased strokes composited over `image`, hole pixels only.
void draw_strokes(Image& image, const Mask& hole, const std::vector<Stroke>& strokes);

// Flat fill: every hole pixel takes the colour of the nearest known flat
// pixel (not ink, not next to ink) reachable without crossing `barrier`
// (geodesic, chamfer 5-7); pixels cut off by barriers then take the nearest
// filled colour across them. Borders between materials of clearly different
// colours are rounded by a majority vote over a disc (steps and spikes go),
// then seams are straightened by a median of radius `seam_radius` away from
// barriers. `seed` (if not null) receives, per hole
// pixel, the index of the known pixel its colour came from (−1 if none).
// `drawing_edges` says which sides of `image` are the drawing's own edges
// (kLeftEdge | kTopEdge | kRightEdge | kBottomEdge; the rest are a crop's):
// what runs off the drawing is larger than it shows.
// Returns the number of hole pixels no known pixel reached.
constexpr int kLeftEdge = 1, kTopEdge = 2, kRightEdge = 4, kBottomEdge = 8;
int flat_fill(Image& image, const Mask& hole, const Mask& ink, const Mask& barrier, int seam_radius,
              std::vector<int>* seed,
              int drawing_edges = kLeftEdge | kTopEdge | kRightEdge | kBottomEdge);

// Draws a line along the seams of the flat fill in `filled` between two
// colours that `original` (the drawing, hole unknown) keeps apart with ink
// (colours within two 16-level steps counted as one); not on `barrier`
// pixels. The line takes the colour and width of that ink in the drawing,
// `fallback_colour` and `fallback_width` when no ink pixel was crossed.
// Returns the seam pixels.
int ink_seams(Image& filled, const Image& original, const Mask& hole, const Mask& ink,
              const Mask& barrier, const Rgba& fallback_colour, double fallback_width);

}  // namespace hair25d::completion::detail
