// The line response (layering/src/line_response.h, paper §4.1) smooths only
// a window around the measured boundaries, grown by window_margin(): every
// measurement must equal, to the bit, the one made on the whole image — on
// generated drawings (non-square, all shadings, translucent pixels, line
// widths up to 21 pixels whose kernels reach far) and tiny hand-built images,
// where the window is cut by the image's edges.
#include "line_response.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "boundary_box.h"
#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"

#ifdef HAIR25D_HAVE_GENERATOR
#include "hair25d/generator/generator.h"
#endif

namespace hair25d::layering {
namespace {

using detail::BoundaryLine;
using detail::LineResponse;

// Measures every boundary between two regions of `labels` on the whole image
// and in the window layer_regions uses (the box of those boundaries grown by
// window_margin()); returns how many were compared.
int expect_same(const Image& image, const LabelMap& labels, double line_width) {
  const BoundaryGraph graph = build_boundary_graph(labels);
  const auto [x0, y0, x1, y1] = test::inner_boundary_box(graph, image.width(), image.height());
  const int m = LineResponse::window_margin(line_width);
  EXPECT_GE(m, 3.0 * line_width + 2.0);  // at least the search for paper
  const LineResponse whole(image, line_width, 0, 0, image.width(), image.height());
  const LineResponse window(image, line_width, x0 - m, y0 - m, x1 + m, y1 + m);
  int compared = 0;
  for (const Boundary& b : graph.boundaries) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    Polyline curve = b.points;
    if (b.closed()) curve.push_back(curve.front());
    const double skip = 1.5 * line_width;
    const BoundaryLine a = whole.measure(curve, skip, labels, b.left, b.right);
    const BoundaryLine t = window.measure(curve, skip, labels, b.left, b.right);
    EXPECT_EQ(a.contrast, t.contrast) << "boundary " << b.left << "|" << b.right;
    EXPECT_EQ(a.contrast_low, t.contrast_low) << "boundary " << b.left << "|" << b.right;
    EXPECT_EQ(a.colour_difference, t.colour_difference) << "boundary " << b.left << "|" << b.right;
    ++compared;
  }
  return compared;
}

// Two regions split by a vertical line, with a bright blob for the noise
// estimate; small enough that windows are a few pixels.
TEST(LineResponseWindow, TinyImagesMatchTheWholeImage) {
  for (const auto& [w, h] :
       {std::pair{7, 5}, std::pair{3, 2}, std::pair{40, 9}, std::pair{1, 1}, std::pair{300, 41}}) {
    Image image(w, h, Rgba{230, 225, 210, 255});
    LabelMap labels(w, h, 1);
    for (int y = 0; y < h; ++y)
      for (int x = w / 2; x < w; ++x) {
        labels.at(x, y) = 2;
        if (x == w / 2) image.at(x, y) = Rgba{30, 20, 20, 255};
        if ((x + y) % 3 == 0) image.at(x, y) = Rgba{200, 90, 40, static_cast<std::uint8_t>(x * 7)};
      }
    expect_same(image, labels, 1.0);
    expect_same(image, labels, 3.0);
  }
}

#ifdef HAIR25D_HAVE_GENERATOR
TEST(LineResponseWindow, GeneratedDrawingsMatchTheWholeImage) {
  const generator::Shading styles[] = {generator::Shading::kFlat, generator::Shading::kTwoTone,
                                       generator::Shading::kGradient,
                                       generator::Shading::kScreentone};
  int total = 0;
  for (int i = 0; i < 4; ++i) {
    generator::Options o;
    o.width = 700 - 90 * i;
    o.height = 520 + 37 * i;
    o.seed = 300 + i;
    o.strand_count = 12 + 6 * i;
    o.shading = styles[i];
    o.strand_masks = false;
    AnnotatedCase c = generator::generate_case(o);
    // Texture everywhere (paper included): pixels beyond a too small window
    // would then differ from the replicated edge.
    for (int y = 0; y < c.image.height(); ++y)
      for (int x = 0; x < c.image.width(); ++x) {
        Rgba& p = c.image.at(x, y);
        p.g = static_cast<std::uint8_t>(std::clamp(p.g + (x * 7 + y * 13) % 9 - 4, 0, 255));
      }
    if (i == 3)  // translucent pixels take the blended path
      for (int y = 0; y < c.image.height(); y += 3)
        for (int x = y % 5; x < c.image.width(); x += 5) c.image.at(x, y).a = 140;
    // Labels as layering measures them (outlines filled).
    const Result r = layer_regions(c.image, c.regions);
    ASSERT_GT(r.line_width, 0.0);
    // The line width used, and ones whose colour kernel reaches far.
    for (const double lw : {r.line_width, 1.0, 9.0, 21.0})
      total += expect_same(c.image, r.labels, lw);
  }
  EXPECT_GT(total, 100);  // many boundaries were compared
}
#endif

}  // namespace
}  // namespace hair25d::layering
