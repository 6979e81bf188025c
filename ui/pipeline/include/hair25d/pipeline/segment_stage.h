// The segmentation stage as the pipeline runs it (paper §3): from a drawing and
// optional strokes to regions on a mesh, a region label map and an overlay.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>

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
// regions, the faces enclosed by curves, numbered from 1. `overlay` false
// leaves run.overlay empty (the model pipeline does not show it).
SegmentRun run_segment(const Image& image, const Strokes* strokes, Progress* progress = nullptr,
                       bool overlay = true);

// Without strokes, from a hair colour: the automatic regions whose mean colour
// lies within `tolerance` (RGB distance, 0-255) of `rgb` become regions 1..n,
// everything else background. Throws hair25d::Error if no region matches or
// the tolerance is negative.
SegmentRun run_segment_by_colour(const Image& image, std::array<std::uint8_t, 3> rgb,
                                 double tolerance, Progress* progress = nullptr);

// Writes the run into folder `out_dir`, replacing it atomically: regions.png
// (16-bit label map), segmentation.json ("hair25d-segmentation/1") and
// overlay.png. Throws hair25d::Error if a label does not fit in 16 bits or a
// file cannot be written.
void write_segment_run(const std::filesystem::path& out_dir, const SegmentRun& run);

// Throws hair25d::Error before any work when write_segment_run would refuse
// `out_dir` (a file there, or a folder of somebody else's files).
void check_segment_folder(const std::filesystem::path& out_dir, const std::string& what);

}  // namespace hair25d::pipeline
