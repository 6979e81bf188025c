// The whole segmentation of paper §3 in one call: curves, smoothing and
// simplification, constrained Delaunay mesh, then either the graph cut from
// strokes or the automatic regions.
#pragma once

#include <string>

#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"
#include "hair25d/core/segmentation.h"
#include "hair25d/core/strokes.h"
#include "hair25d/segment/curves.h"
#include "hair25d/segment/graph_cut.h"
#include "hair25d/segment/mesh.h"

namespace hair25d::segment {

struct SegmentOptions {
  CurveOptions curves;
  SimplifyOptions simplify;
  MeshOptions mesh;
  GraphCutOptions cut;

  bool is_valid(std::string* error) const;
};

// Wall-clock seconds of each step.
struct SegmentTimings {
  double curves = 0.0;    // curve extraction
  double simplify = 0.0;  // smoothing and Douglas–Peucker
  double mesh = 0.0;      // constrained Delaunay triangulation and refinement
  double labels = 0.0;    // graph cut, or automatic regions without strokes
};

struct SegmentResult {
  Segmentation segmentation;
  LabelMap line_mask;  // 1 on drawn lines
  double line_width = 0.0;
  SegmentTimings timings;
  bool from_strokes = false;  // false: automatic regions
  GraphCutResult cut;         // filled when from_strokes
};

// With strokes (not null): triangle_region holds stroke labels, 0 = background.
// Without: the automatic regions numbered from 1 (no background). Throws
// hair25d::Error for an empty image, invalid options, or strokes without a hair
// stroke inside the image.
SegmentResult segment_image(const Image& image, const Strokes* strokes,
                            const SegmentOptions& options = {}, Progress* progress = nullptr);

}  // namespace hair25d::segment
