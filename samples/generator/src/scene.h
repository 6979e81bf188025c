// The drawing as a list of filled, outlined shapes in painter's order (back to
// front): what the layout produces, and what both the renderer and the
// ground-truth pass read, so picture and annotation come from one geometry.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "hair25d/core/geometry.h"
#include "hair25d/generator/generator.h"

namespace hair25d::generator {

using Colour = Eigen::Vector3d;  // r, g, b in [0, 1]

// A tapered strand sampled along its centre line: the sides are the centre
// offset by ± width / 2 along the normal.
struct StrandGeometry {
  Polyline centre;
  Polyline left;
  Polyline right;
  std::vector<double> t;      // curve parameter of each sample, 0 root .. 1 tip
  std::vector<double> width;  // full width at each sample
};

struct FilledEllipse {
  Vec2 centre;
  Vec2 radii;
  double angle = 0.0;  // radians
  Colour colour;
};

struct Shape {
  bool hair = true;  // false: face, body
  int strand = 0;    // hair strand id (> 0), given in painter's order; 0 if not hair
  std::string name;
  Polyline outline;                   // closed polygon (not repeated at the end)
  std::vector<Polyline> inner_lines;  // drawn inside the shape only (forks)
  // In the annotation only (one pixel wide): the rest of a fading fork line.
  std::vector<Polyline> hidden_lines;
  Colour colour{0.5, 0.5, 0.5};
  double tone = 0.0;                       // screentone: dot area share in [0, 0.6]
  bool reverse_param = false;              // gradient runs tip to root instead
  std::optional<StrandGeometry> geometry;  // tapered strands: shading follows it
  Polyline band;                           // two-tone: darker band polygon (tapered strands)
  double band_level = 0.6;                 // two-tone on masses: darker below this height share
  std::vector<FilledEllipse> decorations;  // eyes etc., clipped to the shape
};

struct Scene {
  int width = 0;
  int height = 0;
  double line_width = 3.0;
  Shading shading = Shading::kFlat;
  Colour background{1, 1, 1};
  Colour line_colour{0.08, 0.07, 0.07};
  double tone_period = 6.0;   // screentone dot spacing, pixels
  double tone_angle = 0.785;  // screentone grid angle, radians
  Vec2 head_center{0, 0};
  std::vector<Shape> shapes;  // painter's order, back to front
  int strand_count = 0;       // hair strand ids are 1..strand_count
};

// Polygon through an ellipse, `n` points.
Polyline ellipse_polygon(const Vec2& centre, const Vec2& radii, double angle, int n);

// Cubic Bézier point and derivative.
Vec2 bezier_point(const Vec2 (&p)[4], double t);
Vec2 bezier_tangent(const Vec2 (&p)[4], double t);

// Builds the random layout of one drawing.
class Rng;
Scene make_scene(const Options& options, Rng& rng);

}  // namespace hair25d::generator
