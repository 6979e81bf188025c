// The user's markup, strokes.json ("hair25d-strokes/1", FORMATS.md): labelled
// brush strokes, label 0 = background, plus an optional head centre.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/core/image.h"

namespace hair25d {

struct Stroke {
  int label = 0;       // > 0 a hair region, 0 background
  double width = 1.0;  // brush diameter, pixels, >= 1
  Polyline points;     // one point is a dot; may leave the image (clipped)
};

struct Strokes {
  std::vector<Stroke> strokes;
  std::optional<Vec2> head_center;
  std::string source;  // the file read, named in messages ("" if made in code)

  // The distinct positive labels, sorted.
  std::vector<int> labels() const;
};

// What a stroke file may hold (docs/formats.md): a drawing's markup has tens
// of strokes of tens of points. 60000 one-pixel labels made segment take
// 270 s and 7.4 GB; the same number of regions is allowed as in a label map.
inline constexpr std::size_t kMaxStrokes = 100'000;
inline constexpr std::size_t kMaxStrokePoints = 1'000'000;
inline constexpr std::size_t kMaxStrokeLabels = 4096;

// Strict reader: a malformed file throws hair25d::Error naming the file, the key
// and what was expected, and so does one beyond the limits above.
Strokes read_strokes(const std::filesystem::path& path);
// The same from text; `source` names it in errors.
Strokes parse_strokes(const std::string& text, const std::string& source);
// Writes strokes.json atomically.
void write_strokes(const std::filesystem::path& path, const Strokes& strokes);

// Paints the strokes as round brushes of their width into a label map of the
// given size: kNoStroke where no stroke passes, 0 under background strokes,
// the label under hair strokes. Later strokes paint over earlier ones; points
// outside the image, however far, are clipped; a brush radius beyond the
// image's diagonal is taken as the diagonal. Throws hair25d::Error naming
// strokes.source when the segments' boxes (grown by the brush radius, within
// the image) hold more than kMaxBrushWork pixels together: the painting's cost.
inline constexpr int kNoStroke = -1;
inline constexpr double kMaxBrushWork = 1e9;
// Pixel centres sit on whole coordinates, so a point can lie up to sqrt(1/2)
// from the nearest one (a pixel corner): a brush narrower than that could
// pass through a pixel and mark none. Thin brushes are widened to it.
inline constexpr double kMinBrushRadius = 0.70711;
LabelMap rasterize_strokes(const Strokes& strokes, int width, int height);

}  // namespace hair25d
