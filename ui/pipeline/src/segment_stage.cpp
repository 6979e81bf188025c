#include "hair25d/pipeline/segment_stage.h"

#include <algorithm>
#include <cstdio>
#include <string>

#include "hair25d/core/atomic_file.h"
#include "hair25d/core/error.h"
#include "hair25d/core/image_io.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/overlay.h"
#include "hair25d/segment/regions.h"
#include "hair25d/segment/segmentation_io.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::pipeline {

SegmentRun run_segment(const Image& image, const Strokes* strokes, Progress* progress,
                       bool overlay) {
  segment::SegmentResult result = segment::segment_image(image, strokes, {}, progress);
  SegmentRun run;
  run.segmentation = std::move(result.segmentation);
  const Segmentation& s = run.segmentation;
  run.regions = segment::region_map(image, s.mesh, s.triangle_region);
  if (overlay) run.overlay = segment::draw_overlay(image, s, run.regions);
  return run;
}

SegmentRun run_segment_by_colour(const Image& image, std::array<std::uint8_t, 3> rgb,
                                 double tolerance, Progress* progress) {
  segment::SegmentResult result = segment::segment_image(image, nullptr, {}, progress);
  Segmentation& s = result.segmentation;
  segment::ColourPick pick;
  pick.rgb = rgb;
  pick.tolerance = tolerance;
  // Specks (a few pixels between crossing lines) are never a strand.
  pick.min_area = 1e-4 * image.width() * image.height();
  s.triangle_region =
      segment::label_regions_by_colour(image, s.mesh, s.triangle_region, result.line_mask, pick);
  if (std::none_of(s.triangle_region.begin(), s.triangle_region.end(),
                   [](int l) { return l > 0; })) {
    char hex[8];
    std::snprintf(hex, sizeof hex, "#%02x%02x%02x", rgb[0], rgb[1], rgb[2]);
    char within[32];
    std::snprintf(within, sizeof within, "%g", tolerance);  // 40, not 40.000000
    throw Error(std::string("segment: no region has a mean colour within ") + within + " of " +
                hex + "; pick another colour or a larger tolerance");
  }
  s.adjacency = segment::label_adjacency(s.mesh, s.triangle_region);
  SegmentRun run;
  run.segmentation = std::move(s);
  run.regions = segment::region_map(image, run.segmentation.mesh, run.segmentation.triangle_region);
  run.overlay = segment::draw_overlay(image, run.segmentation, run.regions);
  return run;
}

void write_segment_run(const std::filesystem::path& out_dir, const SegmentRun& run) {
  const auto& r = run.segmentation.triangle_region;
  if (!r.empty() && *std::max_element(r.begin(), r.end()) > 65535)
    throw Error("segment: region id " + std::to_string(*std::max_element(r.begin(), r.end())) +
                " does not fit regions.png; ids must be <= 65535");
  write_folder_atomically(
      out_dir,
      [&](const std::filesystem::path& tmp) {
        save_label_map(tmp / "regions.png", run.regions);
        segment::write_segmentation(tmp / "segmentation.json", run.segmentation);
        save_image(tmp / "overlay.png", run.overlay);
      },
      "segment");
}

void check_segment_folder(const std::filesystem::path& out_dir, const std::string& what) {
  check_output_folder(out_dir, what, {"regions.png", "segmentation.json", "overlay.png"},
                      "segment");
}

}  // namespace hair25d::pipeline
