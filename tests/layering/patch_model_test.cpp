// The junction patch model (layering/src/patch_model.h, internal: the test
// sees layering/src): rasterisation on a hand-built T-junction, the exact
// antisymmetry of its score, and bad input.
#include "patch_model.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "hair25d/core/error.h"
#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"
#include "hair25d/layering/metrics.h"

namespace hair25d::layering::detail {
namespace {

// 40 × 30: region 1 above y = 15, region 2 below and left of x = 20,
// region 3 below and right of it; a T-junction at the corner (20, 15).
LabelMap t_junction() {
  LabelMap m(40, 30, 1);
  for (int y = 15; y < 30; ++y)
    for (int x = 0; x < 40; ++x) m.at(x, y) = x < 20 ? 2 : 3;
  return m;
}

float cell(const Patch& p, int i, int j, int channel) {
  return p[(j * kPatchCells + i) * kPatchChannels + channel];
}

TEST(JunctionPatch, RasterisesTheTJunctionInTheBoundarysFrame) {
  // The boundary between 1 and 2 leaves the junction toward −x; walking
  // that way on the screen (y down), region 2 is on the left. One pixel per
  // cell (radius 8), so every cell lies in one region.
  const Patch p =
      junction_patch(t_junction(), PatchImage{}, Vec2(20, 15), Vec2(-1, 0), 2, 1, true, 8.0);
  for (int j = 0; j < kPatchCells; ++j)
    for (int i = 0; i < kPatchCells; ++i) {
      // u = along the boundary (x = 20 − u), v = toward A (y = 15 + v).
      const bool toward_a = j >= kPatchCells / 2;
      const bool ahead = i >= kPatchCells / 2;
      const float diff = toward_a ? (ahead ? 1.0f : 0.0f) : -1.0f;
      const float other = toward_a && !ahead ? 1.0f : 0.0f;  // region 3
      EXPECT_EQ(cell(p, i, j, 0), diff) << i << "," << j;
      EXPECT_EQ(cell(p, i, j, 1), other) << i << "," << j;
    }
  // Beyond the image: neither channel.
  const Patch edge =
      junction_patch(t_junction(), PatchImage{}, Vec2(0, 0), Vec2(1, 0), 1, 2, true, 8.0);
  EXPECT_EQ(cell(edge, 0, 0, 0), 0.0f);
  EXPECT_EQ(cell(edge, 0, 0, 1), 0.0f);
}

// The patch as its header defines it, sample by sample.
Patch reference_patch(const LabelMap& labels, const Vec2& centre, const Vec2& direction, int a,
                      int b, bool a_on_left, double radius, const Image* image = nullptr,
                      double contrast = 1.0) {
  const Vec2 u = direction.normalized();
  const Vec2 left(u.y(), -u.x());
  const Vec2 v = a_on_left ? left : Vec2(-left);
  Patch p{};
  std::array<float, kPatchGreyInputs> grey{};
  std::array<int, kPatchGreyInputs> count{};
  // The fine and wide scales, then the coarse one after the grey channel.
  for (int scale = 0; scale <= kPatchScales; ++scale) {
    const double r = scale == 0 ? radius : scale == 1 ? kPatchWide * radius : kPatchCoarse * radius;
    const int base = scale < kPatchScales ? scale * kPatchScaleInputs : kPatchCoarseStart;
    const double cell = 2 * r / kPatchCells;
    for (int j = 0; j < kPatchCells; ++j)
      for (int i = 0; i < kPatchCells; ++i)
        for (int sj = 0; sj < 2; ++sj)
          for (int si = 0; si < 2; ++si) {
            const double cu = -r + (i + 0.25 + 0.5 * si) * cell;
            const double cv = -r + (j + 0.25 + 0.5 * sj) * cell;
            const Vec2 q = centre + cu * u + cv * v;
            const int x = static_cast<int>(std::floor(q.x()));
            const int y = static_cast<int>(std::floor(q.y()));
            if (!labels.contains(x, y)) continue;
            if (image != nullptr && scale == 0) {
              const Rgba& px = image->at(x, y);
              grey[j * kPatchCells + i] += 0.299f * px.r + 0.587f * px.g + 0.114f * px.b;
              ++count[j * kPatchCells + i];
            }
            const int l = labels.at(x, y);
            const int k = base + (j * kPatchCells + i) * kPatchChannels;
            if (l == a)
              p[k] += 0.25f;
            else if (l == b)
              p[k] -= 0.25f;
            else if (l > 0)
              p[k + 1] += 0.25f;
          }
  }
  if (image == nullptr) return p;
  auto mean = [&](int i, int j) { return grey[j * kPatchCells + i] / count[j * kPatchCells + i]; };
  for (int j = 0; j < kPatchCells; ++j)
    for (int i = 0; i < kPatchCells; ++i) {
      if (count[j * kPatchCells + i] == 0) continue;
      float bright = mean(i, j);
      for (int dj = -1; dj <= 1; ++dj)
        for (int di = -1; di <= 1; ++di) {
          const int ii = i + di, jj = j + dj;
          if (ii < 0 || jj < 0 || ii >= kPatchCells || jj >= kPatchCells) continue;
          if (count[jj * kPatchCells + ii] > 0) bright = std::max(bright, mean(ii, jj));
        }
      p[kPatchLabelInputs + j * kPatchCells + i] =
          std::min((bright - mean(i, j)) * static_cast<float>(1.0 / contrast), 2.0f);
    }
  return p;
}

TEST(JunctionPatch, EqualsTheSampleBySampleDefinition) {
  // Random blobs of 5 labels on a non-square map, random junctions,
  // directions and radii, some reaching past the border.
  std::mt19937 rng(3);
  LabelMap m(53, 37, 0);
  for (int y = 0; y < 37; ++y)
    for (int x = 0; x < 53; ++x) m.at(x, y) = (x / 9 + 2 * (y / 7) + (x * y) % 3) % 5;
  std::uniform_real_distribution<double> px(-5, 58), py(-5, 42), angle(0, 6.3), radius(1, 20);
  for (int k = 0; k < 50; ++k) {
    const Vec2 c(px(rng), py(rng));
    const double t = angle(rng);
    const Vec2 d(std::cos(t), std::sin(t));
    const double r = radius(rng);
    const bool left = k % 2 == 0;
    EXPECT_EQ(junction_patch(m, PatchImage{}, c, d, 1, 2, left, r),
              reference_patch(m, c, d, 1, 2, left, r));
  }
  // With the drawing's grey levels (random, so every cell differs).
  Image image(53, 37);
  std::uniform_int_distribution<int> level(0, 255);
  for (int y = 0; y < 37; ++y)
    for (int x = 0; x < 53; ++x)
      image.at(x, y) =
          Rgba{static_cast<std::uint8_t>(level(rng)), static_cast<std::uint8_t>(level(rng)),
               static_cast<std::uint8_t>(level(rng)), 255};
  for (int k = 0; k < 30; ++k) {
    const Vec2 c(px(rng), py(rng));
    const double t = angle(rng);
    const Vec2 d(std::cos(t), std::sin(t));
    const double r = radius(rng);
    const double contrast = 10.0 + k;
    EXPECT_EQ(junction_patch(m, PatchImage{&image, contrast}, c, d, 2, 3, k % 3 == 0, r),
              reference_patch(m, c, d, 2, 3, k % 3 == 0, r, &image, contrast));
  }
  // Integer centres and axis directions put samples on pixel edges.
  EXPECT_EQ(junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(0, 3), 3, 4, true, 8.0),
            reference_patch(m, Vec2(20, 15), Vec2(0, 3), 3, 4, true, 8.0));
}

TEST(JunctionPatch, GatheredSamplesEqualTheLoopsSamples) {
  // Patches wholly inside the map are read a row of samples at a time, with
  // the processor's gathers where it has AVX-512F (`widest`) or by the
  // compiler's loops: the same patches, labels and grey channel, to the bit,
  // and the same as the sample-by-sample definition.
  std::mt19937 rng(8);
  std::uniform_int_distribution<int> label(0, 6), level(0, 255);
  LabelMap m(211, 157, 0);
  Image image(211, 157);
  for (int y = 0; y < 157; ++y)
    for (int x = 0; x < 211; ++x) {
      m.at(x, y) = (x / 11 + 3 * (y / 9)) % 7 == 0 ? label(rng) : (x / 13 + y / 8) % 6;
      image.at(x, y) =
          Rgba{static_cast<std::uint8_t>(level(rng)), static_cast<std::uint8_t>(level(rng)),
               static_cast<std::uint8_t>(level(rng)), 255};
    }
  std::uniform_real_distribution<double> px(70, 141), py(60, 97), angle(0, 6.3), radius(2, 12);
  for (int k = 0; k < 40; ++k) {
    const Vec2 c(px(rng), py(rng));
    const double t = angle(rng);
    const Vec2 d(std::cos(t), std::sin(t));
    const double r = radius(rng);
    const bool left = k % 2 == 0;
    for (const Image* drawing :
         {static_cast<const Image*>(nullptr), static_cast<const Image*>(&image)}) {
      const Patch wide = junction_patch(m, PatchImage{drawing, 25.0, true}, c, d, 2, 3, left, r);
      EXPECT_EQ(wide, junction_patch(m, PatchImage{drawing, 25.0, false}, c, d, 2, 3, left, r))
          << k;
      EXPECT_EQ(wide, reference_patch(m, c, d, 2, 3, left, r, drawing, 25.0)) << k;
    }
  }
}

// The map as bytes, as the layering gives it to the patches (padding
// included).
std::vector<std::uint8_t> bytes_of(const LabelMap& m) {
  std::vector<std::uint8_t> bytes(
      static_cast<std::size_t>(m.width()) * m.height() + kByteLabelsPadding, 0);
  byte_labels(m, 0, m.width(), 0, m.height(), bytes.data());
  return bytes;
}

TEST(JunctionPatch, MaskedGathersAndByteLabelsEqualTheDefinition) {
  // Patches reaching past the map's border (the coarse scale at most of the
  // layering's junctions) are read with masked gathers, and with the map as
  // bytes where both regions have a byte of their own: labels below 0, 0,
  // 254, 255 and above, grey or not, radii up to 25 on a 97 × 61 map, so
  // that every scale reaches past some border. Each path gives the
  // sample-by-sample definition's patch to the bit.
  std::mt19937 rng(53);
  const std::array<int, 9> palette{-2, 0, 1, 2, 3, 254, 255, 300, 7};
  std::uniform_int_distribution<int> pick(0, 8), level(0, 255);
  LabelMap m(97, 61, 0);
  Image image(97, 61);
  for (int y = 0; y < 61; ++y)
    for (int x = 0; x < 97; ++x) {
      m.at(x, y) = (x / 7 + y / 5) % 4 == 0 ? palette[pick(rng)] : palette[(x / 11 + y / 9) % 9];
      image.at(x, y) =
          Rgba{static_cast<std::uint8_t>(level(rng)), static_cast<std::uint8_t>(level(rng)),
               static_cast<std::uint8_t>(level(rng)), 255};
    }
  const std::vector<std::uint8_t> bytes = bytes_of(m);
  const std::array<std::pair<int, int>, 5> regions{
      {{1, 2}, {254, 3}, {255, 7}, {300, 2}, {2, 254}}};
  std::uniform_real_distribution<double> px(-10, 107), py(-10, 71), angle(0, 6.3), radius(1, 25);
  for (int k = 0; k < 60; ++k) {
    // Integer centres and axis directions now and then: samples on pixel
    // edges, and on the border's first and last pixels.
    const Vec2 c =
        k % 5 == 0 ? Vec2(std::round(px(rng)), std::round(py(rng))) : Vec2(px(rng), py(rng));
    const double t = k % 7 == 0 ? 1.5707963267948966 * (k % 4) : angle(rng);
    const Vec2 d(std::cos(t), std::sin(t));
    const double r = k % 5 == 0 ? std::round(radius(rng)) : radius(rng);
    const bool left = k % 2 == 0;
    const auto [a, b] = regions[k % regions.size()];
    for (const Image* drawing :
         {static_cast<const Image*>(nullptr), static_cast<const Image*>(&image)}) {
      const Patch want = reference_patch(m, c, d, a, b, left, r, drawing, 25.0);
      for (bool widest : {true, false})
        for (const std::uint8_t* given :
             {static_cast<const std::uint8_t*>(nullptr), bytes.data()}) {
          PatchImage pi{drawing, 25.0, widest};
          pi.bytes = given;
          EXPECT_EQ(junction_patch(m, pi, c, d, a, b, left, r), want)
              << k << " a " << a << " b " << b << " widest " << widest << " bytes "
              << (given != nullptr) << " grey " << (drawing != nullptr);
        }
    }
  }
}

TEST(ByteLabels, EachLabelClampedWithinTheRectangleOnly) {
  LabelMap m(37, 11, 0);
  for (int y = 0; y < 11; ++y)
    for (int x = 0; x < 37; ++x) m.at(x, y) = (x * 31 + y * 17) % 700 - 200;
  std::vector<std::uint8_t> bytes(37 * 11, 9);
  byte_labels(m, 3, 35, 2, 10, bytes.data());
  for (int y = 0; y < 11; ++y)
    for (int x = 0; x < 37; ++x) {
      const int l = m.at(x, y);
      const bool inside = x >= 3 && x < 35 && y >= 2 && y < 10;
      EXPECT_EQ(bytes[y * 37 + x], inside ? (l <= 0 ? 0 : l >= 255 ? 255 : l) : 9) << x << "," << y;
    }
}

TEST(JunctionPatch, MixedCellsHoldShares) {
  // Radius 16: two pixels per cell, 2 × 2 samples, so the cell across x = 20
  // still falls on one side; a diagonal direction gives shares in quarters.
  const Patch p = junction_patch(t_junction(), PatchImage{}, Vec2(20, 15), Vec2(-1, 1).normalized(),
                                 2, 1, true, 16.0);
  for (float v : p) {
    EXPECT_GE(v, -1.0f);
    EXPECT_LE(v, 1.0f);
    EXPECT_EQ(std::fmod(v * 4.0f, 1.0f), 0.0f);
  }
}

TEST(JunctionPatch, TheGreyChannelShowsLinesNotTones) {
  // The T of t_junction() drawn: region 1 light, region 2 dark paint, region
  // 3 mid, and a 1-px line of grey 20 along y = 15 (the bar's outline) that
  // stops where the stem's line (x = 20) would begin: the stem has none.
  const LabelMap m = t_junction();
  Image image(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      const std::uint8_t paint = m.at(x, y) == 1 ? 220 : m.at(x, y) == 2 ? 60 : 140;
      const std::uint8_t v = y == 15 ? 20 : paint;
      image.at(x, y) = Rgba{v, v, v, 255};
    }
  // One pixel per cell (radius 8): u = x − 20, v = y − 15 + 8 rows.
  const double contrast = 100.0;
  const Patch p =
      junction_patch(m, PatchImage{&image, contrast}, Vec2(20, 15), Vec2(1, 0), 1, 3, false, 8.0);
  auto dark = [&](int i, int j) { return p[kPatchLabelInputs + j * kPatchCells + i]; };
  // Region 1 (light) lies toward −v here (a on the right of +x on screen).
  for (int i = 1; i < kPatchCells - 1; ++i) {
    // The line's row (y = 15 is v = 0, row 8): its contrast with the
    // brightest neighbour, region 1's paint (220 − 20), clamped at 2.
    EXPECT_FLOAT_EQ(dark(i, 8), 2.0f) << i;
    // Flat paint two rows away reads 0, dark or light (but for region 2's
    // cells beside region 3, below).
    EXPECT_FLOAT_EQ(dark(i, 5), 0.0f) << i;
    if (i != 7) {
      EXPECT_FLOAT_EQ(dark(i, 11), 0.0f) << i;
    }
  }
  // A paint row next to a lighter row reads their difference: row 9 (the
  // first row of 2 and 3) borders the line only, so its brightest neighbour
  // is itself or row 10: 0.
  EXPECT_FLOAT_EQ(dark(3, 9), 0.0f);
  // Region 2 (x < 20, grey 60) beside region 3 (grey 140) at the stem
  // (i = 7 is x = 19, i = 8 is x = 20): the darker side reads 0.8.
  EXPECT_FLOAT_EQ(dark(7, 12), 0.8f);
  EXPECT_FLOAT_EQ(dark(8, 12), 0.0f);
  // Without an image, no grey channel; the label channels are the same.
  const Patch q = junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(1, 0), 1, 3, false, 8.0);
  for (int k = 0; k < kPatchInputs; ++k) {
    const bool label = k < kPatchLabelInputs || k >= kPatchCoarseStart;
    EXPECT_EQ(q[k], label ? p[k] : 0.0f) << k;
  }
}

TEST(JunctionPatch, SwappedTwiceIsTheSamePatch) {
  std::mt19937 rng(5);
  std::uniform_real_distribution<float> u(-1, 1);
  Patch p;
  for (float& v : p) v = u(rng);
  EXPECT_EQ(swapped(swapped(p)), p);
  const Patch s = swapped(p);
  EXPECT_EQ(s[1], p[((kPatchCells - 1) * kPatchCells) * kPatchChannels + 1]);
  EXPECT_EQ(s[0], -p[((kPatchCells - 1) * kPatchCells) * kPatchChannels]);
  // The grey channel is mirrored, not negated.
  EXPECT_EQ(s[kPatchLabelInputs + 3], p[kPatchLabelInputs + (kPatchCells - 1) * kPatchCells + 3]);
  EXPECT_EQ(s[kPatchLabelInputs + 2 * kPatchCells + 5],
            p[kPatchLabelInputs + (kPatchCells - 3) * kPatchCells + 5]);
  // The coarse scale as the others: mirrored, its A − B channel negated.
  const int last_row = (kPatchCells - 1) * kPatchCells * kPatchChannels;
  EXPECT_EQ(s[kPatchCoarseStart + 6], -p[kPatchCoarseStart + last_row + 6]);
  EXPECT_EQ(s[kPatchCoarseStart + 7], p[kPatchCoarseStart + last_row + 7]);
}

TEST(JunctionPatch, CoarseScaleIsNineTimesTheRadiusAndLeftOutWhenNotAsked) {
  // The T of t_junction() from (20, 15) along +x, region 1 (above) as A on
  // the left, 3 as B, radius 2: the coarse scale spans ±18 px in cells of
  // 2.25 px, so it reaches region 2 and the far side of region 3, which
  // the wide scale (±6 px) does not.
  const LabelMap m = t_junction();
  const Patch p = junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(1, 0), 1, 3, true, 2.0);
  EXPECT_EQ(p, reference_patch(m, Vec2(20, 15), Vec2(1, 0), 1, 3, true, 2.0));
  auto coarse = [&](int i, int j, int channel) {
    return p[kPatchCoarseStart + (j * kPatchCells + i) * kPatchChannels + channel];
  };
  EXPECT_EQ(coarse(0, 12, 0), 1.0f);   // x ≈ 2.5–3.6, y ≈ 4.3–5.4: region 1 (A)
  EXPECT_EQ(coarse(0, 3, 1), 1.0f);    // y ≈ 24.6–25.7: region 2 (other hair)
  EXPECT_EQ(coarse(15, 3, 0), -1.0f);  // x ≈ 36.3–37.4: region 3 (B)
  // Not asked for: the same patch with the coarse scale 0.
  PatchImage no_coarse;
  no_coarse.coarse = false;
  const Patch q = junction_patch(m, no_coarse, Vec2(20, 15), Vec2(1, 0), 1, 3, true, 2.0);
  for (int k = 0; k < kPatchInputs; ++k) EXPECT_EQ(q[k], k < kPatchCoarseStart ? p[k] : 0.0f) << k;
}

TEST(PatchScore, ExchangingTheRegionsFlipsTheSignExactly) {
  const PatchNet& net = patch_weights();
  std::mt19937 rng(11);
  std::uniform_real_distribution<float> u(-1, 1);
  int nonzero = 0;
  for (int k = 0; k < 20; ++k) {
    Patch p;
    for (float& v : p) v = u(rng);
    const double s = patch_score(net, p);
    EXPECT_EQ(patch_score(net, swapped(p)), -s);
    nonzero += s != 0;
  }
  EXPECT_GT(nonzero, 15);
}

TEST(PatchScore, TheSameDepthScoreIgnoresWhichSideIsWhich) {
  const PatchNet& net = patch_same_weights().net;
  std::mt19937 rng(13);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int k = 0; k < 20; ++k) {
    Patch p;
    for (float& v : p) v = u(rng);
    EXPECT_EQ(patch_same_score(net, swapped(p)), patch_same_score(net, p));
  }
}

TEST(PatchScore, BothScoresAtOnceAreTheSameScores) {
  const PatchNet& order = patch_weights();
  const PatchNet& same = patch_same_weights().net;
  const int used = patch_inputs_used(order);
  EXPECT_GT(used, 0);
  EXPECT_LE(used, kPatchInputs);
  for (int k = used; k < kPatchInputs; ++k)
    for (float w : order.w1[k]) ASSERT_EQ(w, 0.0f);
  std::mt19937 rng(17);
  std::uniform_real_distribution<float> u(-1, 1);
  for (int k = 0; k < 10; ++k) {
    Patch p;
    for (float& v : p) v = u(rng);
    const PatchScores s = patch_scores(order, used, same, p);
    EXPECT_EQ(s.order, patch_score(order, p));
    EXPECT_EQ(s.same, patch_same_score(same, p));
  }
}

// A patch as the layering makes them: label inputs (the coarse scale's too)
// mostly zero, else −0 or a quarter step; grey inputs zero or in [0, 2).
Patch sparse_patch(std::mt19937& rng) {
  std::uniform_int_distribution<int> quarter(-4, 4), pick(0, 9);
  std::uniform_real_distribution<float> grey(0, 2);
  Patch p{};
  for (int i = 0; i < kPatchInputs; ++i) {
    const int c = pick(rng);
    if (i >= kPatchLabelInputs && i < kPatchCoarseStart)
      p[i] = c < 5 ? 0.0f : grey(rng);
    else
      p[i] = c < 6 ? 0.0f : c == 6 ? -0.0f : 0.25f * static_cast<float>(quarter(rng));
  }
  return p;
}

// Networks of random weights on every input, the coarse scale's included
// (the committed ones may weigh it 0).
PatchNet random_net(std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-0.1f, 0.1f);
  PatchNet net;
  for (auto& row : net.w1)
    for (float& w : row) w = u(rng);
  for (float& b : net.b1) b = u(rng);
  for (float& w : net.w2) w = 10 * u(rng);
  return net;
}

TEST(PatchScore, BothScoresAtOnceReadTheCoarseScale) {
  // With weights on the coarse scale, patch_scores' swapped inputs (built
  // from the patch's, block by block) give the plain loops' scores to the
  // bit, and the coarse inputs change them.
  const PatchNet order = random_net(1), same = random_net(2);
  std::mt19937 rng(31);
  for (int k = 0; k < 20; ++k) {
    Patch p = sparse_patch(rng);
    for (int used : {kPatchInputs, kPatchCoarseStart, kPatchScaleInputs + 7}) {
      const PatchScores s = patch_scores(order, used, same, p);
      EXPECT_EQ(s.order, patch_net(order, p, used) - patch_net(order, swapped(p), used));
      EXPECT_EQ(s.same, patch_same_score(same, p));
    }
    const PatchScores before = patch_scores(order, kPatchInputs, same, p);
    for (int i = kPatchCoarseStart; i < kPatchInputs; ++i) p[i] = 0.0f;
    const PatchScores after = patch_scores(order, kPatchInputs, same, p);
    EXPECT_NE(before.order, after.order);
    EXPECT_NE(before.same, after.same);
  }
}

TEST(PatchScore, SameDepthNetworkReadsTheInputsItWeighs) {
  // The layering scores the same-depth network on the inputs up to its last
  // weighed one (patch_inputs_used) while the order network reads more (the
  // coarse scale): the same scores as the whole networks' to the bit, for
  // one and several patches, with and without the AVX-512 lists; with the
  // zeros' rows given weights, reading fewer inputs changes the score.
  const PatchNet order = random_net(5);
  PatchNet same = random_net(6);
  for (int k = kPatchCoarseStart; k < kPatchInputs; ++k) same.w1[k].fill(0.0f);
  const int same_used = patch_inputs_used(same);
  EXPECT_LE(same_used, kPatchCoarseStart);
  std::mt19937 rng(59);
  std::vector<Patch> patches(5);
  for (Patch& p : patches) p = sparse_patch(rng);
  for (int order_used : {kPatchInputs, kPatchLabelInputs})
    for (bool widest : {false, true}) {
      std::vector<PatchScores> out(patches.size());
      patch_scores(order, order_used, same, patches.data(), static_cast<int>(patches.size()),
                   out.data(), widest, same_used);
      for (std::size_t p = 0; p < patches.size(); ++p) {
        EXPECT_EQ(out[p].order, patch_net(order, patches[p], order_used) -
                                    patch_net(order, swapped(patches[p]), order_used));
        EXPECT_EQ(out[p].same, patch_same_score(same, patches[p]));
      }
    }
  const PatchNet full = random_net(6);
  PatchScores fewer;
  patch_scores(order, kPatchInputs, full, patches.data(), 1, &fewer, true, same_used);
  EXPECT_NE(fewer.same, patch_same_score(full, patches[0]));
  EXPECT_EQ(fewer.same, patch_net(full, patches[0], same_used) +
                            patch_net(full, swapped(patches[0]), same_used));
}

TEST(PatchScore, BothScoresAtOnceOnSparsePatches) {
  // Patches as the layering makes them (mostly zeros, quarters, a grey
  // channel), plus −0, NaN-free odd values and a network reading fewer
  // inputs: patch_scores skips the zeros and builds the swapped patch's
  // inputs itself, and must still give the two scores to the bit.
  const PatchNet& order = patch_weights();
  const PatchNet& same = patch_same_weights().net;
  std::mt19937 rng(29);
  for (int k = 0; k < 20; ++k) {
    const Patch p = sparse_patch(rng);
    for (int used : {kPatchInputs, kPatchLabelInputs, kPatchScaleInputs + 7}) {
      const PatchScores s = patch_scores(order, used, same, p);
      EXPECT_EQ(s.order, patch_net(order, p, used) - patch_net(order, swapped(p), used));
      EXPECT_EQ(s.same, patch_same_score(same, p));
    }
  }
  // A junction of the T map, with the drawing's grey channel.
  Image image(40, 30);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x)
      image.at(x, y) = Rgba{static_cast<std::uint8_t>(7 * x), static_cast<std::uint8_t>(5 * y),
                            static_cast<std::uint8_t>(x * y), 255};
  const Patch t = junction_patch(t_junction(), PatchImage{&image, 20.0}, Vec2(20, 15), Vec2(1, 0),
                                 1, 3, false, 6.0);
  const PatchScores s = patch_scores(order, patch_inputs_used(order), same, t);
  EXPECT_EQ(s.order, patch_score(order, t));
  EXPECT_EQ(s.same, patch_same_score(same, t));
}

TEST(PatchScore, ManyPatchesAtOnceScoreAsEachAlone) {
  // patch_scores over several patches (two at a time, the weights read once
  // for both) and with the non-zero inputs found sixteen at a time
  // (AVX-512F, where the processor has it) or one by one: every score the
  // same to the bit as the patch's own. Patches as the layering makes them,
  // with −0 and odd values, and counts that leave one patch over.
  const PatchNet& order = patch_weights();
  const PatchNet& same = patch_same_weights().net;
  std::mt19937 rng(41);
  std::vector<Patch> patches(7);
  for (Patch& p : patches) p = sparse_patch(rng);
  patches[3] = Patch{};     // no input at all
  patches[4].fill(-0.75f);  // every input
  for (int used : {kPatchInputs, kPatchLabelInputs, kPatchScaleInputs + 7, 0})
    for (int count = 1; count <= static_cast<int>(patches.size()); ++count)
      for (bool widest : {false, true}) {
        std::vector<PatchScores> out(count);
        patch_scores(order, used, same, patches.data(), count, out.data(), widest);
        for (int p = 0; p < count; ++p) {
          const Patch& one = patches[p];
          EXPECT_EQ(out[p].order,
                    patch_net(order, one, used) - patch_net(order, swapped(one), used))
              << used << " " << count << " " << widest << " " << p;
          EXPECT_EQ(out[p].same, patch_same_score(same, one))
              << used << " " << count << " " << widest << " " << p;
        }
      }
}

TEST(PatchScore, WalkingTheBoundaryBackwardsFlipsTheSignExactly) {
  const LabelMap m = t_junction();
  const BoundaryGraph g = build_boundary_graph(m);
  const PatchNet& net = patch_weights();
  int hair = 0;
  for (const Boundary& b : g.boundaries) {
    if (b.closed() || b.left <= 0 || b.right <= 0) continue;
    ++hair;
    const Polyline back(b.points.rbegin(), b.points.rend());
    const Vec2 start = leaving_direction(b.points, 12.0), end = leaving_direction(back, 12.0);
    Boundary r = b;
    std::swap(r.left, r.right);
    std::swap(r.start, r.end);
    r.points = back;
    const std::vector<Patch> forward = boundary_patches(m, PatchImage{}, g, b, start, end, 12.0);
    const std::vector<Patch> backward = boundary_patches(m, PatchImage{}, g, r, end, start, 12.0);
    ASSERT_EQ(forward.size(), 2u);
    ASSERT_EQ(backward.size(), 2u);
    // The reversed walk's start is the forward walk's end, regions exchanged.
    EXPECT_EQ(backward[0], swapped(forward[1]));
    EXPECT_EQ(backward[1], swapped(forward[0]));
    const double s = patch_score(net, forward[0]) + patch_score(net, forward[1]);
    const double t = patch_score(net, backward[1]) + patch_score(net, backward[0]);
    EXPECT_EQ(t, -s);
    const PatchNet& same = patch_same_weights().net;
    EXPECT_EQ(patch_same_score(same, backward[1]) + patch_same_score(same, backward[0]),
              patch_same_score(same, forward[0]) + patch_same_score(same, forward[1]));
  }
  EXPECT_GE(hair, 2);
}

TEST(PatchScore, TheBarOfTheTIsAbove) {
  // Region 1 is the bar: its outline runs straight through the junction, 2
  // and 3 end on it. The trained network should read that from one end.
  const LabelMap m = t_junction();
  const PatchNet& net = patch_weights();
  const Patch bar_over_2 =
      junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(-1, 0), 1, 2, false, 12.0);
  const Patch bar_over_3 =
      junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(1, 0), 1, 3, true, 12.0);
  EXPECT_GT(patch_score(net, bar_over_2), 0.0);
  EXPECT_GT(patch_score(net, bar_over_3), 0.0);
}

TEST(JunctionPatch, BadInputThrows) {
  const LabelMap m = t_junction();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, 0.0), Error);
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, -3.0), Error);
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, nan), Error);
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(0, 0), 1, 2, true, 8.0), Error);
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(20, 15), Vec2(nan, 1), 1, 2, true, 8.0), Error);
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(nan, 15), Vec2(1, 0), 1, 2, true, 8.0), Error);
  EXPECT_THROW(junction_patch(m, PatchImage{}, Vec2(1e12, 15), Vec2(1, 0), 1, 2, true, 8.0), Error);
  const Image image(40, 30), other(30, 40);
  EXPECT_THROW(
      junction_patch(m, PatchImage{&other, 10.0}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, 8.0),
      Error);
  EXPECT_THROW(
      junction_patch(m, PatchImage{&image, 0.0}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, 8.0), Error);
  EXPECT_THROW(
      junction_patch(m, PatchImage{&image, nan}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, 8.0), Error);
  EXPECT_NO_THROW(
      junction_patch(m, PatchImage{&image, 10.0}, Vec2(20, 15), Vec2(1, 0), 1, 2, true, 8.0));
}

TEST(Layering, PatchesJoinTheLearnedLogOddsOnlyWhenAsked) {
  // A T drawn with outlines (label 0) on a non-square map: region 1 is the
  // bar, regions 2 and 3 end on it, mirror images of each other.
  Image image(60, 44);
  LabelMap regions(60, 44, 0);
  for (int y = 4; y < 40; ++y)
    for (int x = 4; x < 56; ++x) {
      const bool line = y == 20 || y == 21 || ((x == 29 || x == 30) && y > 20);
      regions.at(x, y) = line ? 0 : y < 20 ? 1 : x < 30 ? 2 : 3;
    }
  for (int y = 0; y < 44; ++y)
    for (int x = 0; x < 60; ++x) {
      const bool dark = regions.at(x, y) == 0 && x >= 3 && x <= 56 && y >= 3 && y <= 40;
      image.at(x, y) = dark ? Rgba{20, 20, 20, 255} : Rgba{200, 170, 120, 255};
    }
  Options on, off;
  off.junction_patches = false;
  // Without the same-depth model: the stem between two mirror images is a
  // fork to it, and the cusps it makes would change the order features.
  on.learned_equal = off.learned_equal = false;
  const Result with = layer_regions(image, regions, on);
  const Result without = layer_regions(image, regions, off);
  const PatchNet& net = patch_weights();
  int read = 0;
  for (std::size_t i = 0; i < with.boundaries.size(); ++i) {
    const BoundaryReport& a = with.boundaries[i];
    const BoundaryReport& b = without.boundaries[i];
    EXPECT_EQ(a.learned, b.learned);
    EXPECT_EQ(b.patch, 0.0);
    if (!a.occluding || a.left <= 0 || a.right <= 0) continue;
    ++read;
    if (a.left == 1 || a.right == 1) {
      // The bar lies over both regions ending on it.
      EXPECT_GT(a.left == 1 ? a.patch : -a.patch, 0.0) << a.left << "|" << a.right;
    } else {
      // The stem between 2 and 3 is mirror-symmetric: no side is preferred.
      EXPECT_EQ(a.patch, 0.0);
    }
    EXPECT_DOUBLE_EQ(a.patch_log_odds, net.order_weight * a.learned + net.patch_weight * a.patch);
  }
  EXPECT_GE(read, 2);
}

}  // namespace
}  // namespace hair25d::layering::detail
