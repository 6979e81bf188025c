#include "hair25d/pipeline/segment_stage.h"

#include <algorithm>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/overlay.h"
#include "hair25d/segment/segmentation_io.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::pipeline {

SegmentRun run_segment(const Image& image, const Strokes* strokes, Progress* progress) {
  segment::SegmentResult result = segment::segment_image(image, strokes, {}, progress);
  SegmentRun run;
  run.segmentation = std::move(result.segmentation);
  const Segmentation& s = run.segmentation;
  run.regions =
      segment::rasterize_triangle_values(s.mesh, s.triangle_region, image.width(), image.height());
  run.overlay = segment::draw_overlay(image, s, run.regions);
  return run;
}

void write_segment_run(const std::filesystem::path& out_dir, const SegmentRun& run) {
  const auto& r = run.segmentation.triangle_region;
  if (!r.empty() && *std::max_element(r.begin(), r.end()) > 65535)
    throw Error("segment: region id " + std::to_string(*std::max_element(r.begin(), r.end())) +
                " does not fit regions.png; ids must be <= 65535");
  write_folder_atomically(out_dir, [&](const std::filesystem::path& tmp) {
    save_label_map(tmp / "regions.png", run.regions);
    segment::write_segmentation(tmp / "segmentation.json", run.segmentation);
    save_image(tmp / "overlay.png", run.overlay);
  });
}

}  // namespace hair25d::pipeline
