// The segmentation stage as the pipeline runs it (paper §3): from a drawing and
// optional strokes to regions on a mesh, a region label map and an overlay.
#pragma once

#include "hair25d/core/image.h"
#include "hair25d/core/progress.h"
#include "hair25d/core/segmentation.h"
#include "hair25d/core/strokes.h"

namespace hair25d::pipeline {

struct SegmentRun {
  Segmentation segmentation;
  LabelMap regions;  // per pixel: the stroke label of its triangle, 0 = background
  Image overlay;     // curves, mesh and coloured regions over the drawing
};

// With strokes: one region per stroke label (graph cut). Without: automatic
// regions, the faces enclosed by curves, numbered from 1.
SegmentRun run_segment(const Image& image, const Strokes* strokes, Progress* progress = nullptr);

}  // namespace hair25d::pipeline
