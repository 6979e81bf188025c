// Sylvie (samples/sylvie) segmented from her strokes: the right cheek and the
// ear behind the lock in front of it stay background (paper §3). The lock's
// stroke lay on the cheek's skin, 10 px left of the face's outline, so that
// label's colour model was skin and the graph cut gave it the whole cheek and
// ear; the background kept a hole there and the ear moved with the hair.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>

#include "hair25d/core/image_io.h"
#include "hair25d/core/strokes.h"
#include "hair25d/segment/regions.h"
#include "hair25d/segment/segmenter.h"

namespace hair25d::segment {
namespace {

namespace fs = std::filesystem;

struct Box {
  int x0, y0, x1, y1;  // inclusive-exclusive
};

// Share of the box's skin-light pixels (luma >= 185: no hair pixel of this
// drawing is that light but a highlight) that a hair region holds.
double hair_share(const Image& image, const LabelMap& regions, Box b) {
  int hair = 0, all = 0;
  for (int y = b.y0; y < b.y1; ++y)
    for (int x = b.x0; x < b.x1; ++x) {
      const Rgba& c = image.at(x, y);
      if (c.a < 255 || 299 * c.r + 587 * c.g + 114 * c.b < 185 * 1000) continue;
      ++all;
      hair += regions.at(x, y) != 0;
    }
  EXPECT_GT(all, 20) << "box " << b.x0 << "," << b.y0;
  return static_cast<double>(hair) / std::max(all, 1);
}

TEST(SylvieEars, CheekAndEarBehindTheFaceSideLockAreBackground) {
  const fs::path dir = fs::path(HAIR25D_SAMPLES_DIR) / "sylvie";
  const Image image = load_image(dir / "image.png");
  const Strokes strokes = read_strokes(dir / "strokes.json");
  const SegmentResult r = segment_image(image, &strokes);
  const LabelMap regions = region_map(image, r.segmentation.mesh, r.segmentation.triangle_region);
  // The right cheek between the eye and the face's outline.
  EXPECT_LE(hair_share(image, regions, {190, 108, 206, 140}), 0.05);
  // The ears' skin: right, behind the thin lock, and left.
  EXPECT_LE(hair_share(image, regions, {209, 96, 224, 120}), 0.05);
  EXPECT_LE(hair_share(image, regions, {95, 98, 114, 128}), 0.05);
  // The lock itself (label 15, 5 px wide between the face's outline and
  // the ear) is still a region.
  int lock = 0;
  for (int y = 98; y < 110; ++y)
    for (int x = 209; x < 216; ++x) lock += regions.at(x, y) == 15;
  EXPECT_GE(lock, 10);
}

}  // namespace
}  // namespace hair25d::segment
