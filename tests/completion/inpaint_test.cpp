#include "hair25d/completion/inpaint.h"

#include <gtest/gtest.h>

#include "hair25d/core/error.h"

namespace hair25d::completion {
namespace {

// Vertical stripes 6 px wide, on a non-square canvas.
Image stripes(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at(x, y) = (x / 6) % 2 ? Rgba{200, 60, 40, 255} : Rgba{40, 80, 200, 255};
  return img;
}

TEST(Inpaint, KnownPixelsUntouchedAndHoleFilledWithTheTexture) {
  const Image truth = stripes(97, 61);
  Image img = truth;
  LabelMap fill(97, 61);
  for (int y = 20; y < 40; ++y)
    for (int x = 30; x < 58; ++x) {
      fill.at(x, y) = 1;
      img.at(x, y) = {255, 255, 255, 255};
    }
  const InpaintResult r = inpaint_exemplar(img, fill, LabelMap{});
  EXPECT_EQ(r.filled, 20 * 28);
  EXPECT_EQ(r.unfilled, 0);
  EXPECT_GT(r.patches, 0);
  int wrong = 0;
  for (int y = 0; y < 61; ++y)
    for (int x = 0; x < 97; ++x) {
      if (!fill.at(x, y)) {
        ASSERT_EQ(img.at(x, y), truth.at(x, y)) << "known pixel changed at " << x << "," << y;
      } else {
        wrong += !(img.at(x, y) == truth.at(x, y));
      }
    }
  // Stripes continue through the hole (exemplar copies, not blur).
  EXPECT_LT(wrong, 20 * 28 / 10);
}

TEST(Inpaint, OnlySourcePixelsAreCopied) {
  Image img(80, 50, Rgba{10, 200, 10, 255});
  LabelMap fill(80, 50), source(80, 50);
  for (int y = 0; y < 50; ++y)
    for (int x = 0; x < 80; ++x) {
      if (x >= 40) img.at(x, y) = {250, 0, 0, 255};  // red: not a source
      if (x >= 30 && x < 40 && y >= 20 && y < 30) fill.at(x, y) = 1;
      source.at(x, y) = x < 30 ? 1 : 0;
    }
  inpaint_exemplar(img, fill, source);
  for (int y = 20; y < 30; ++y)
    for (int x = 30; x < 40; ++x) EXPECT_EQ(img.at(x, y), (Rgba{10, 200, 10, 255}));
}

TEST(Inpaint, NoSourceAnywhereIsReportedNotACrash) {
  Image img(20, 30, Rgba{1, 2, 3, 255});
  LabelMap fill(20, 30, 1);
  fill.at(0, 0) = 0;  // one known pixel, no whole source patch
  const InpaintResult r = inpaint_exemplar(img, fill, LabelMap{});
  EXPECT_GT(r.unfilled, 0);
}

TEST(Inpaint, BadInputThrows) {
  Image img(20, 30);
  EXPECT_THROW(inpaint_exemplar(img, LabelMap(30, 20), LabelMap{}), Error);
  EXPECT_THROW(inpaint_exemplar(img, LabelMap(20, 30), LabelMap(5, 5)), Error);
  InpaintOptions bad;
  bad.patch_radius = 0;
  EXPECT_THROW(inpaint_exemplar(img, LabelMap(20, 30), LabelMap{}, bad), Error);
}

}  // namespace
}  // namespace hair25d::completion
