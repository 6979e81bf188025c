#include "hair25d/completion/inpaint.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>

#include "hair25d/core/error.h"
#include "synthetic.h"

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

// The only source patches lie far beyond the first search window (which
// then widens): the hole is filled from them, and only them.
TEST(Inpaint, SourceFarBeyondTheSearchWindowIsFound) {
  const int w = 230, h = 90;
  Image img(w, h, Rgba{90, 90, 90, 255});
  LabelMap fill(w, h), source(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x >= 200) img.at(x, y) = {20, 160, 220, 255}, source.at(x, y) = 1;  // a far stripe
      if (x >= 10 && x < 30 && y >= 30 && y < 50) fill.at(x, y) = 1;
    }
  InpaintOptions o;
  o.search_radius = 16;
  ASSERT_GT(200 - 30, 4 * o.search_radius);
  const InpaintResult r = inpaint_exemplar(img, fill, source, o);
  EXPECT_EQ(r.unfilled, 0);
  EXPECT_EQ(r.filled, 400);
  for (int y = 30; y < 50; ++y)
    for (int x = 10; x < 30; ++x) ASSERT_EQ(img.at(x, y), (Rgba{20, 160, 220, 255}));
  EXPECT_EQ(img.at(9, 30), (Rgba{90, 90, 90, 255}));
}

// Cells 8 × 5 px: a texture with a period in both directions.
Image checker(int w, int h) {
  Image img(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      img.at(x, y) = ((x / 8) + (y / 5)) % 2 ? Rgba{220, 180, 60, 255} : Rgba{90, 50, 30, 255};
  return img;
}

struct TextureScore {
  int wrong = 0;     // hole pixels unlike the truth
  int periodic = 0;  // hole pixels that repeat at the period and flip at half of it
  int checked = 0;   // hole pixels whose period neighbours are in the hole too
};

TextureScore fill_checker_hole(int far_candidates) {
  const int w = 211, h = 143;
  const Image truth = checker(w, h);
  Image img = truth;
  LabelMap fill(w, h);
  for (int y = 30; y < 115; ++y)
    for (int x = 40; x < 170; ++x) fill.at(x, y) = 1, img.at(x, y) = {255, 255, 255, 255};
  InpaintOptions o;
  o.far_candidates = far_candidates;
  const InpaintResult r = inpaint_exemplar(img, fill, LabelMap{}, o);
  EXPECT_EQ(r.filled, 85 * 130);
  EXPECT_EQ(r.unfilled, 0);
  TextureScore s;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (!fill.at(x, y)) {
        EXPECT_EQ(img.at(x, y), truth.at(x, y)) << "known pixel changed at " << x << "," << y;
        continue;
      }
      s.wrong += !(img.at(x, y) == truth.at(x, y));
      if (x + 16 >= w || y + 10 >= h || !fill.at(x + 16, y) || !fill.at(x, y + 10)) continue;
      ++s.checked;
      const Rgba c = img.at(x, y);
      s.periodic += c == img.at(x + 16, y) && c == img.at(x, y + 10) && !(c == img.at(x + 8, y)) &&
                    !(c == img.at(x, y + 5));
    }
  return s;
}

// Targets deep in a hole 130 × 85 px have no whole source patch within the
// search radius: the widened search (coherent candidates and the nearest
// far_candidates) still carries the texture through, nearly as well as the
// exact search over the whole window, and far better than with one candidate.
TEST(Inpaint, LargeHoleFarFromEverySourceCarriesThePeriodicTexture) {
  const TextureScore fast = fill_checker_hole(InpaintOptions{}.far_candidates);
  const TextureScore exact = fill_checker_hole(0);
  const TextureScore poor = fill_checker_hole(1);
  const int n = 85 * 130;
  EXPECT_LT(exact.wrong, n / 20);
  EXPECT_LT(fast.wrong, n / 10);
  EXPECT_GT(fast.periodic, fast.checked * 3 / 4);
  EXPECT_GT(exact.periodic, exact.checked * 3 / 4);
  // The property separates a good search from a poor one.
  EXPECT_GT(poor.wrong, n / 7);
  EXPECT_LT(poor.periodic, poor.checked / 2);
}

// A hole in a flat area between two flat areas of other colours is filled
// from its own area only (candidates visited nearest first, all compared).
TEST(Inpaint, HoleInAFlatAreaTakesItsColourNotItsNeighbours) {
  const int w = 150, h = 70;
  Image img(w, h, Rgba{200, 200, 200, 255});
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (x < 40) img.at(x, y) = {30, 30, 200, 255};
      if (x >= 110) img.at(x, y) = {200, 30, 30, 255};
    }
  LabelMap fill(w, h);
  for (int y = 30; y < 40; ++y)
    for (int x = 70; x < 80; ++x) fill.at(x, y) = 1, img.at(x, y) = {0, 0, 0, 255};
  inpaint_exemplar(img, fill, LabelMap{});
  for (int y = 30; y < 40; ++y)
    for (int x = 70; x < 80; ++x) ASSERT_EQ(img.at(x, y), (Rgba{200, 200, 200, 255}));
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
  InpaintOptions negative;
  negative.far_candidates = -1;
  EXPECT_THROW(inpaint_exemplar(img, LabelMap(20, 30), LabelMap{}, negative), Error);
}

}  // namespace
}  // namespace hair25d::completion

namespace hair25d::completion {
namespace {

constexpr Rgba kSkin{240, 200, 170, 255};

int channel_gap(const Rgba& a, const Rgba& b) {
  return std::max({std::abs(a.r - b.r), std::abs(a.g - b.g), std::abs(a.b - b.b)});
}

// A flat skin sheet with one dark dot (an "eye") 2 px left of a hole: inside
// the known part of the patches on the hole's left border.
struct DotFace {
  Image image{150, 110, kSkin};
  LabelMap hole{150, 110};
  DotFace() {
    for (int y = 0; y < 110; ++y)
      for (int x = 0; x < 150; ++x) {
        if ((x - 64) * (x - 64) + (y - 55) * (y - 55) <= 16) image.at(x, y) = {30, 20, 20, 255};
        if (x >= 70 && x < 115 && y >= 30 && y < 85) hole.at(x, y) = 1;
      }
  }
};

int dark_in_hole(const Image& img, const LabelMap& hole) {
  int dark = 0;
  for (int y = 0; y < img.height(); ++y)
    for (int x = 0; x < img.width(); ++x)
      if (hole.at(x, y) && img.at(x, y).r < 150) ++dark;
  return dark;
}

TEST(InpaintCel, DistinctFeatureNextToTheHoleIsNotCopiedIntoIt) {
  DotFace face;
  const Image before = face.image;
  const InpaintResult r = inpaint_cel(face.image, face.hole, LabelMap{});
  EXPECT_EQ(r.filled, 45 * 55);
  EXPECT_EQ(dark_in_hole(face.image, face.hole), 0);
  for (int y = 0; y < 110; ++y)
    for (int x = 0; x < 150; ++x) {
      if (!face.hole.at(x, y))
        ASSERT_EQ(face.image.at(x, y), before.at(x, y))
            << "known pixel changed at " << x << "," << y;
      else
        ASSERT_LE(channel_gap(face.image.at(x, y), kSkin), 6) << x << "," << y;
    }
}

TEST(InpaintCel, PlainExemplarFillDoesCopyTheFeature) {
  // The failure inpaint_cel exists for: patches on the border hold part of
  // the dot, so the best match continues the dot into the flat hole.
  DotFace face;
  inpaint_exemplar(face.image, face.hole, LabelMap{});
  EXPECT_GT(dark_in_hole(face.image, face.hole), 0);
}

TEST(InpaintCel, FlatRegionsAreContinuedAcrossTheHole) {
  // Left skin, right white, a dark line between; the hole covers the line.
  const Rgba white{252, 252, 250, 255};
  Image img(131, 87);
  LabelMap hole(131, 87);
  for (int y = 0; y < 87; ++y)
    for (int x = 0; x < 131; ++x) {
      img.at(x, y) = x < 64 ? kSkin : x < 67 ? Rgba{20, 20, 30, 255} : white;
      if (x >= 40 && x < 95 && y >= 25 && y < 60) hole.at(x, y) = 1;
    }
  inpaint_cel(img, hole, LabelMap{});
  int wrong = 0, total = 0;
  for (int y = 25; y < 60; ++y)
    for (int x = 40; x < 95; ++x) {
      if (x >= 56 && x < 75) continue;  // where the two regions meet, either is fine
      ++total;
      wrong += channel_gap(img.at(x, y), x < 64 ? kSkin : white) > 8;
    }
  EXPECT_LT(wrong, total / 50) << wrong << " of " << total;
}

TEST(InpaintCel, TransparentSheetStaysTransparent) {
  Image img(90, 70, Rgba{0, 0, 0, 0});
  LabelMap hole(90, 70);
  for (int y = 0; y < 70; ++y)
    for (int x = 0; x < 90; ++x) {
      if (x < 20) img.at(x, y) = kSkin;
      if (x >= 40 && x < 70 && y >= 20 && y < 50) hole.at(x, y) = 1;
    }
  inpaint_cel(img, hole, LabelMap{});
  for (int y = 20; y < 50; ++y)
    for (int x = 40; x < 70; ++x) ASSERT_LT(img.at(x, y).a, 16) << x << "," << y;
}

// A strand's texture as the completion builds it (transparent round the
// strand, the sources its visible pixels): near-black hair (fill of luma
// ~43 with darker vertical lines every 12 px) holding a 4×4 fleck of skin,
// 0.3% of its pixels, that a segmentation gave it, next to the hidden part.
// The hidden part runs along the strand's lower edge and on into a tail
// 3 px wide over the transparent paper. Before, every hair pixel was ink
// (luma < ink_luma), so the skin was the only flat colour: the guide was
// skin and the fleck was copied into the hidden part; and the coarse fill's
// median read the transparent paper round the tail: it came out
// transparent.
struct DarkStrand {
  static constexpr int kW = 120, kH = 96;
  static constexpr Rgba kFill{45, 40, 50, 255}, kLine{8, 6, 10, 255};
  Image image{kW, kH, Rgba{0, 0, 0, 0}};
  LabelMap fill{kW, kH}, source{kW, kH};
  static bool tail(int x, int y) { return x >= 60 && x < 63 && y >= 70 && y < 86; }
  DarkStrand() {
    for (int y = 10; y < kH; ++y)
      for (int x = 10; x < 110; ++x) {
        if (y >= 70 && !tail(x, y)) continue;
        image.at(x, y) = x % 12 < 2 ? kLine : kFill;
        if (x >= 44 && x < 48 && y >= 44 && y < 48) image.at(x, y) = kSkin;
        const bool hidden = (x >= 50 && x < 90 && y >= 40) || tail(x, y);
        (hidden ? fill : source).at(x, y) = 1;
      }
  }
};

TEST(InpaintCel, DarkHairIsContinuedInItsOwnColoursOpaque) {
  DarkStrand s;
  const Image before = s.image;
  const InpaintResult r = inpaint_cel(s.image, s.fill, s.source);
  EXPECT_EQ(r.filled, 40 * 30 + 3 * 16);
  int hidden = 0, dark = 0, skin = 0, transparent = 0;
  for (int y = 0; y < DarkStrand::kH; ++y)
    for (int x = 0; x < DarkStrand::kW; ++x) {
      const Rgba& c = s.image.at(x, y);
      if (!s.fill.at(x, y)) {
        ASSERT_EQ(c, before.at(x, y)) << "known pixel changed at " << x << "," << y;
        continue;
      }
      ++hidden;
      transparent += c.a < 255;
      dark += channel_gap(c, DarkStrand::kFill) <= 12 || channel_gap(c, DarkStrand::kLine) <= 12;
      skin += channel_gap(c, kSkin) <= 60;
    }
  EXPECT_EQ(transparent, 0);
  EXPECT_EQ(skin, 0);
  EXPECT_GE(dark, hidden * 98 / 100) << dark << " of " << hidden;
}

// A screentone strand (the generator's round anti-aliased dots on a turned
// lattice with a period of 7.3 px, on grey paper) over a transparent sheet,
// with a dark disc (radius 6, an eye's size) beside its hidden part: a
// 70 × 52 hole, most of it farther than search_radius from every whole
// source patch. Before, the dots were ink to the ink rule: no patch was
// allowed deep in the hole and it was left the coarse fill's flat paper.
struct ToneStrand {
  static constexpr int kW = 190, kH = 140;
  static constexpr double kPeriod = 7.3, kAngle = 0.35;
  Image image{kW, kH, Rgba{0, 0, 0, 0}};
  LabelMap fill{kW, kH}, source{kW, kH};
  static bool hidden(int x, int y) { return x >= 60 && x < 130 && y >= 45 && y < 97; }
  static bool eye(int x, int y) { return (x - 52) * (x - 52) + (y - 70) * (y - 70) <= 36; }
  // Dots of `radius` periods.
  explicit ToneStrand(double radius) {
    for (int y = 8; y < kH - 8; ++y)
      for (int x = 8; x < kW - 8; ++x) {
        const double k = test::dot_cover(x, y, kPeriod, radius, kAngle);
        const auto grey = static_cast<std::uint8_t>(std::lround(215 - k * (215 - 25)));
        image.at(x, y) = eye(x, y) ? Rgba{20, 20, 25, 255} : Rgba{grey, grey, grey, 255};
        (hidden(x, y) ? fill : source).at(x, y) = 1;
      }
  }
};

// The hole filled by inpaint_cel against the tone as drawn: its dot pixels
// (luma < 120 in the drawing) dark, its paper light, and dark pixels with
// no dot of the drawing within a pixel (the disc copied in).
struct ToneScore {
  int dots = 0, dots_kept = 0, paper = 0, paper_kept = 0, off_dots = 0;
};

ToneScore fill_tone(double radius) {
  ToneStrand s(radius);
  const Image truth = s.image;
  const InpaintResult r = inpaint_cel(s.image, s.fill, s.source);
  EXPECT_EQ(r.filled, 70 * 52);
  ToneScore score;
  const auto dot_near = [&](int x, int y) {
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        if (truth.at(x + dx, y + dy).r < 120) return true;
    return false;
  };
  for (int y = 0; y < ToneStrand::kH; ++y)
    for (int x = 0; x < ToneStrand::kW; ++x) {
      const Rgba& c = s.image.at(x, y);
      if (!s.fill.at(x, y)) {
        EXPECT_EQ(c, truth.at(x, y)) << "known pixel changed at " << x << "," << y;
        continue;
      }
      const bool dark = c.r < 120;
      if (truth.at(x, y).r < 120)
        ++score.dots, score.dots_kept += dark;
      else
        ++score.paper, score.paper_kept += !dark;
      score.off_dots += dark && !dot_near(x, y);
    }
  return score;
}

TEST(InpaintCel, ScreentoneDotsContinueInPhaseAcrossTheHiddenPart) {
  // Dots of 0.3 periods, apart: before, 95 of 973 dot pixels were dark.
  const ToneScore t = fill_tone(0.3);
  EXPECT_GT(t.dots_kept, t.dots * 8 / 10) << t.dots_kept << " of " << t.dots << " dot pixels";
  EXPECT_GT(t.paper_kept, t.paper * 9 / 10) << t.paper_kept << " of " << t.paper;
  EXPECT_LT(t.off_dots, 20);
}

TEST(InpaintCel, DenseScreentoneDotsContinueInPhaseAcrossTheHiddenPart) {
  // Dots of 0.47 periods touch through their anti-aliased rims: the ink is
  // one web, no dot is a component of its own; their dark cores still are.
  const ToneScore t = fill_tone(0.47);
  EXPECT_GT(t.dots_kept, t.dots * 8 / 10) << t.dots_kept << " of " << t.dots << " dot pixels";
  EXPECT_GT(t.paper_kept, t.paper * 7 / 10) << t.paper_kept << " of " << t.paper;
  EXPECT_LT(t.off_dots, 20);
}

TEST(InpaintCel, BadInputThrows) {
  Image img(20, 30);
  EXPECT_THROW(inpaint_cel(img, LabelMap(30, 20), LabelMap{}), Error);
  EXPECT_THROW(inpaint_cel(img, LabelMap(20, 30), LabelMap(5, 5)), Error);
  InpaintOptions bad;
  bad.ink_step = 0;
  EXPECT_THROW(inpaint_cel(img, LabelMap(20, 30), LabelMap{}, bad), Error);
  bad = {};
  bad.guide_weight = -1;
  EXPECT_THROW(inpaint_cel(img, LabelMap(20, 30), LabelMap{}, bad), Error);
  bad = {};
  bad.ink_luma = 300;
  EXPECT_THROW(inpaint_cel(img, LabelMap(20, 30), LabelMap{}, bad), Error);
}

}  // namespace
}  // namespace hair25d::completion
