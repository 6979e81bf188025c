// Tapered strands: a cubic Bézier centre line with a width profile, turned into
// an outline polygon with a round root cap and a pointed or round tip, plus the
// two-tone band and the fork line that splits a strand into two visible halves.
#pragma once

#include "scene.h"

namespace hair25d::generator {

struct StrandSpec {
  Vec2 control[4];              // Bézier control points, root first
  double max_width = 20.0;      // pixels
  double root_ratio = 0.8;      // width at the root / max_width
  double peak_at = 0.25;        // curve parameter of the widest point
  double tip_ratio = 0.0;       // width at the tip / max_width; 0 = pointed tip
  double wave_amplitude = 0.0;  // pixels across the centre line; 0 = no waves
  double wave_cycles = 2.0;     // waves along the strand
  double wave_phase = 0.0;      // radians
};

StrandGeometry sample_strand(const StrandSpec& spec);

// Left side root to tip, tip (point or half disc), right side back, half disc
// around the root.
Polyline strand_outline(const StrandGeometry& g);

// A crescent along one side (side > 0: left) between curve parameters t0 and
// t1, reaching `depth` of the width into the strand at its middle.
Polyline band_polygon(const StrandGeometry& g, int side, double t0, double t1, double depth);

// A line from the tip up the middle of the strand that bends out through one
// side at parameter t_split, so the strand shows two pieces (a fork).
Polyline fork_line(const StrandGeometry& g, int side, double t_split);

}  // namespace hair25d::generator
