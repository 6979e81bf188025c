#include "hair25d/segment/segmenter.h"

#include <algorithm>
#include <chrono>

#include "hair25d/core/error.h"
#include "hair25d/segment/regions.h"

namespace hair25d::segment {

bool SegmentOptions::is_valid(std::string* error) const {
  return curves.is_valid(error) && simplify.is_valid(error) && mesh.is_valid(error) &&
         cut.is_valid(error);
}

namespace {
double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}
}  // namespace

SegmentResult segment_image(const Image& image, const Strokes* strokes,
                            const SegmentOptions& options, Progress* progress) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  if (image.empty())
    throw Error("segment::segment_image: the image is " + std::to_string(image.width()) + "x" +
                std::to_string(image.height()) + "; must have at least one pixel");
  if (strokes != nullptr) {
    // Fail before the slow steps: a hair stroke must reach into the image.
    const bool any =
        std::any_of(strokes->strokes.begin(), strokes->strokes.end(), [&](const Stroke& st) {
          if (st.label <= 0 || st.points.empty()) return false;
          double x0 = 1e300, y0 = 1e300, x1 = -1e300, y1 = -1e300;
          for (const Vec2& p : st.points)
            x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y()), x1 = std::max(x1, p.x()),
            y1 = std::max(y1, p.y());
          const double r = std::max(kMinBrushRadius, st.width / 2.0);
          return x1 + r >= 0 && y1 + r >= 0 && x0 - r <= image.width() - 1 &&
                 y0 - r <= image.height() - 1;
        });
    if (!any)
      throw Error("segment: the strokes hold no hair stroke (label > 0) inside the " +
                  std::to_string(image.width()) + "x" + std::to_string(image.height()) +
                  " image; mark at least one hair region");
  }
  constexpr const char* kStage = "segment";
  SegmentResult r;
  Segmentation& s = r.segmentation;
  s.width = image.width();
  s.height = image.height();

  report(progress, kStage, 0.0, "curve extraction");
  auto t0 = std::chrono::steady_clock::now();
  CurveResult curves = extract_curves(image, options.curves);
  r.timings.curves = seconds_since(t0);
  r.line_mask = std::move(curves.line_mask);
  r.line_width = curves.line_width;

  report(progress, kStage, 0.3, "smoothing and simplifying curves");
  t0 = std::chrono::steady_clock::now();
  s.curves = smooth_and_simplify(curves.curves, options.simplify);
  r.timings.simplify = seconds_since(t0);

  report(progress, kStage, 0.4, "constrained Delaunay mesh");
  t0 = std::chrono::steady_clock::now();
  s.mesh = build_mesh(s.curves, s.width, s.height, options.mesh).mesh;
  r.timings.mesh = seconds_since(t0);

  t0 = std::chrono::steady_clock::now();
  if (strokes != nullptr) {
    report(progress, kStage, 0.7, "graph cut");
    r.cut = graph_cut_labels(image, s.mesh, *strokes, r.line_mask, options.cut);
    s.triangle_region = r.cut.labels;
    r.from_strokes = true;
  } else {
    report(progress, kStage, 0.7, "automatic regions");
    s.triangle_region = automatic_regions(s.mesh);
    // Transparent paper is no region; the ids stay 1..n.
    if (clear_paper_regions(image, s.mesh, s.triangle_region) > 0)
      compact_labels(s.triangle_region);
  }
  s.adjacency = label_adjacency(s.mesh, s.triangle_region);
  r.timings.labels = seconds_since(t0);
  report(progress, kStage, 1.0, "done");
  return r;
}

}  // namespace hair25d::segment
