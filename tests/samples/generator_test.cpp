// Tests of the synthetic cartoon-hair generator: determinism, and that the
// ground truth (regions, pairs, relations, strokes, strand masks) is consistent
// with itself and with the drawing, over many seeds and sizes.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <map>
#include <set>

#include "common/temp_dir.h"
#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"

namespace hair25d::generator {
namespace {

namespace fs = std::filesystem;

Options small(std::uint64_t seed, Shading shading = Shading::kFlat) {
  Options o;
  o.width = 416;  // not square: catches swapped width and height
  o.height = 352;
  o.strand_count = 16;
  o.line_width = 2.0;
  o.shading = shading;
  o.seed = seed;
  return o;
}

// Pixels of each region.
std::map<int, std::vector<std::pair<int, int>>> pixels_of(const LabelMap& regions) {
  std::map<int, std::vector<std::pair<int, int>>> out;
  for (int y = 0; y < regions.height(); ++y) {
    for (int x = 0; x < regions.width(); ++x) {
      if (regions.at(x, y) > 0) out[regions.at(x, y)].emplace_back(x, y);
    }
  }
  return out;
}

// True if some pixel of `b` lies within Chebyshev distance `r` of a pixel of `a`.
bool near(const LabelMap& regions, const std::vector<std::pair<int, int>>& a, int b, int r) {
  for (auto [x, y] : a) {
    for (int dy = -r; dy <= r; ++dy) {
      for (int dx = -r; dx <= r; ++dx) {
        if (regions.contains(x + dx, y + dy) && regions.at(x + dx, y + dy) == b) return true;
      }
    }
  }
  return false;
}

std::map<int, int> strand_of(const AnnotatedCase& c) {
  std::map<int, int> out;
  for (const AnnotatedRegion& r : c.region_list) out[r.id] = r.strand;
  return out;
}

// Every structural property of one case; used over many seeds and options.
void check_case(const AnnotatedCase& c, const Options& o) {
  SCOPED_TRACE("seed " + std::to_string(o.seed));
  ASSERT_EQ(c.image.width(), o.width);
  ASSERT_EQ(c.image.height(), o.height);
  ASSERT_EQ(c.regions.width(), o.width);
  ASSERT_EQ(c.regions.height(), o.height);
  ASSERT_TRUE(c.head_center.has_value());
  EXPECT_TRUE(c.head_center->x() > 0 && c.head_center->x() < o.width);
  EXPECT_TRUE(c.head_center->y() > 0 && c.head_center->y() < o.height);

  // Region ids in the map are exactly the listed ones.
  std::vector<int> listed;
  for (const AnnotatedRegion& r : c.region_list) listed.push_back(r.id);
  std::sort(listed.begin(), listed.end());
  EXPECT_EQ(c.regions.labels(), listed);
  EXPECT_FALSE(listed.empty());

  // One mask a strand, and each mask holds all its regions' pixels.
  EXPECT_EQ(static_cast<int>(c.strand_masks.size()), o.strand_count);
  const auto pixels = pixels_of(c.regions);
  const auto strands = strand_of(c);
  for (const auto& [id, px] : pixels) {
    const auto mask = c.strand_masks.find(strands.at(id));
    ASSERT_NE(mask, c.strand_masks.end()) << "region " << id;
    for (auto [x, y] : px) {
      ASSERT_EQ(mask->second.at(x, y), 1) << "region " << id << " at " << x << "," << y;
    }
  }

  // Pairs: no duplicates either way, regions really meet across a line, and
  // the relation follows the painter's order (strand ids grow front-wards).
  std::set<std::pair<int, int>> seen;
  // Neighbours meet across one line: within its width plus 3 pixels.
  const int reach = 2 * static_cast<int>(std::ceil(o.line_width / 2.0)) + 3;
  for (const AnnotatedPair& p : c.pairs) {
    ASSERT_NE(p.a, p.b);
    EXPECT_TRUE(seen.insert({std::min(p.a, p.b), std::max(p.a, p.b)}).second)
        << "pair " << p.a << "," << p.b << " listed twice";
    EXPECT_TRUE(near(c.regions, pixels.at(p.a), p.b, reach))
        << "regions " << p.a << " and " << p.b << " do not touch";
    const int sa = strands.at(p.a), sb = strands.at(p.b);
    const Relation expected =
        sa == sb ? Relation::kEqual : (sa > sb ? Relation::kAbove : Relation::kBelow);
    EXPECT_EQ(p.relation, expected) << "pair " << p.a << "," << p.b;
  }

  // Strokes: every region has one, and every stroke pixel lies in its region
  // (label 0 strokes off the hair).
  ASSERT_TRUE(c.strokes.has_value());
  EXPECT_EQ(c.strokes->labels(), listed);
  const bool has_background = std::any_of(c.strokes->strokes.begin(), c.strokes->strokes.end(),
                                          [](const Stroke& s) { return s.label == 0; });
  EXPECT_TRUE(has_background);
  for (const Stroke& s : c.strokes->strokes) {
    Strokes one;
    one.strokes = {s};
    const LabelMap painted = rasterize_strokes(one, o.width, o.height);
    for (int y = 0; y < o.height; ++y) {
      for (int x = 0; x < o.width; ++x) {
        if (painted.at(x, y) == kNoStroke) continue;
        ASSERT_EQ(c.regions.at(x, y), s.label)
            << "stroke of label " << s.label << " at " << x << "," << y;
      }
    }
  }
}

TEST(Generator, SameSeedSameCase) {
  const Options o = small(5, Shading::kTwoTone);
  const AnnotatedCase a = generate_case(o);
  const AnnotatedCase b = generate_case(o);
  EXPECT_EQ(a.image, b.image);
  EXPECT_EQ(a.regions, b.regions);
  ASSERT_EQ(a.pairs.size(), b.pairs.size());
  for (std::size_t i = 0; i < a.pairs.size(); ++i) {
    EXPECT_EQ(a.pairs[i].a, b.pairs[i].a);
    EXPECT_EQ(a.pairs[i].b, b.pairs[i].b);
    EXPECT_EQ(a.pairs[i].relation, b.pairs[i].relation);
  }
  EXPECT_EQ(a.strand_masks, b.strand_masks);
}

TEST(Generator, DifferentSeedsDifferentCases) {
  const AnnotatedCase a = generate_case(small(1));
  const AnnotatedCase b = generate_case(small(2));
  EXPECT_NE(a.image, b.image);
  EXPECT_NE(a.regions, b.regions);
}

TEST(Generator, GroundTruthConsistentOverSeedsAndShadings) {
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const Options o = small(seed, static_cast<Shading>(seed % 4));
    check_case(generate_case(o), o);
  }
}

TEST(Generator, NonSquareSizesBothWays) {
  for (auto [w, h] : {std::pair{240, 520}, std::pair{640, 200}}) {
    Options o = small(3);
    o.width = w;
    o.height = h;
    o.strand_count = 10;
    check_case(generate_case(o), o);
  }
}

TEST(Generator, NoiseAndJpegChangeOnlyThePicture) {
  Options clean = small(9);
  Options noisy = clean;
  noisy.noise_sigma = 6.0;
  noisy.jpeg_quality = 60;
  const AnnotatedCase a = generate_case(clean);
  const AnnotatedCase b = generate_case(noisy);
  EXPECT_NE(a.image, b.image);
  EXPECT_EQ(a.regions, b.regions);
  EXPECT_EQ(a.pairs.size(), b.pairs.size());
  // The noise is small: the mean absolute change stays near the noise level.
  double sum = 0;
  for (int y = 0; y < a.image.height(); ++y) {
    for (int x = 0; x < a.image.width(); ++x)
      sum += std::abs(a.image.at(x, y).g - b.image.at(x, y).g);
  }
  EXPECT_LT(sum / (a.image.width() * a.image.height()), 12.0);
  check_case(b, noisy);
}

TEST(Generator, ScreentoneIsGrey) {
  const AnnotatedCase c = generate_case(small(4, Shading::kScreentone));
  for (int y = 0; y < c.image.height(); ++y) {
    for (int x = 0; x < c.image.width(); ++x) {
      const Rgba p = c.image.at(x, y);
      ASSERT_TRUE(p.r == p.g && p.g == p.b) << x << "," << y;
    }
  }
}

TEST(Generator, OutlinesSeparateRegions) {
  // Between two regions there is always a gap of outline (0) pixels: no two
  // different regions are 4-neighbours in regions.png.
  const AnnotatedCase c = generate_case(small(6));
  for (int y = 0; y + 1 < c.regions.height(); ++y) {
    for (int x = 0; x + 1 < c.regions.width(); ++x) {
      const int v = c.regions.at(x, y);
      for (int n : {c.regions.at(x + 1, y), c.regions.at(x, y + 1)}) {
        ASSERT_TRUE(v == 0 || n == 0 || v == n) << x << "," << y;
      }
    }
  }
}

TEST(Generator, OneStrandHasOnlyEqualPairs) {
  Options o = small(8);
  o.strand_count = 1;
  const AnnotatedCase c = generate_case(o);
  check_case(c, o);
  for (const AnnotatedRegion& r : c.region_list) EXPECT_EQ(r.strand, 1);
  for (const AnnotatedPair& p : c.pairs) EXPECT_EQ(p.relation, Relation::kEqual);
}

TEST(Generator, SplitStrandsAndForksOccur) {
  // Over a handful of seeds, some strand shows as several regions (one strand
  // crossing another or hidden in the middle: completion case 1) and some
  // pairs are "equal" (a forked strand).
  int split = 0, equal = 0, above = 0, below = 0;
  for (std::uint64_t seed = 20; seed < 26; ++seed) {
    Options o = small(seed);
    o.strand_count = 24;
    const AnnotatedCase c = generate_case(o);
    std::map<int, int> per_strand;
    for (const AnnotatedRegion& r : c.region_list) ++per_strand[r.strand];
    for (const auto& [s, n] : per_strand) split += n > 1 ? 1 : 0;
    for (const AnnotatedPair& p : c.pairs) {
      equal += p.relation == Relation::kEqual;
      above += p.relation == Relation::kAbove;
      below += p.relation == Relation::kBelow;
    }
  }
  EXPECT_GT(split, 5);
  EXPECT_GT(equal, 0);
  EXPECT_GT(above, 10);
  EXPECT_GT(below, 10);
}

TEST(Generator, StrokesReachEveryPartOfTheirRegion) {
  // A user marks each arm of a bent region; so do the generated strokes: few
  // pixels of a region lie far from all its strokes. "Far" grows with how wide
  // the region is (its deepest inside pixel).
  for (std::uint64_t seed = 40; seed < 43; ++seed) {
    const Options o = small(seed);
    const AnnotatedCase c = generate_case(o);
    std::map<int, std::vector<Vec2>> samples;  // points along each region's strokes
    for (const Stroke& s : c.strokes->strokes) {
      if (s.label == 0) continue;
      const Polyline dense = s.points.size() > 1 ? resample_polyline(s.points, 2.0) : s.points;
      samples[s.label].insert(samples[s.label].end(), dense.begin(), dense.end());
    }
    for (const auto& [id, px] : pixels_of(c.regions)) {
      // Depth of each pixel: distance along the axes to the nearest pixel
      // outside the region. Only pixels deep enough to hold a stroke count.
      std::vector<int> depth(px.size(), 0);
      int deepest = 0;
      for (std::size_t i = 0; i < px.size(); ++i) {
        const auto [x, y] = px[i];
        for (int r = 1; r < 400 && depth[i] == 0; ++r) {
          for (auto [dx, dy] : {std::pair{r, 0}, {-r, 0}, {0, r}, {0, -r}}) {
            if (!c.regions.contains(x + dx, y + dy) || c.regions.at(x + dx, y + dy) != id) {
              depth[i] = r;
            }
          }
        }
        deepest = std::max(deepest, depth[i]);
      }
      const double far = std::max(30.0, 3.0 * deepest);
      int deep = 0, far_pixels = 0;
      for (std::size_t i = 0; i < px.size(); ++i) {
        if (depth[i] < 4) continue;
        ++deep;
        double best = 1e300;
        for (const Vec2& q : samples.at(id)) {
          best = std::min(best, (q - Vec2(px[i].first, px[i].second)).norm());
        }
        far_pixels += best > far;
      }
      EXPECT_LE(far_pixels, 0.15 * deep) << "seed " << seed << " region " << id;
    }
  }
}

TEST(Generator, WriteReadRoundTrip) {
  const Options o = small(11, Shading::kGradient);
  const AnnotatedCase c = generate_case(o);
  const hair25d::testing::TempDir tmp;
  const fs::path dir = tmp.path();
  write_annotated_case(dir / "case", c);
  const AnnotatedCase r = read_annotated_case(dir / "case");
  EXPECT_EQ(r.image, c.image);
  EXPECT_EQ(r.regions, c.regions);
  ASSERT_TRUE(r.head_center.has_value());
  EXPECT_NEAR((*r.head_center - *c.head_center).norm(), 0.0, 1e-9);
  ASSERT_EQ(r.region_list.size(), c.region_list.size());
  for (std::size_t i = 0; i < c.region_list.size(); ++i) {
    EXPECT_EQ(r.region_list[i].id, c.region_list[i].id);
    EXPECT_EQ(r.region_list[i].strand, c.region_list[i].strand);
    EXPECT_EQ(r.region_list[i].name, c.region_list[i].name);
  }
  ASSERT_EQ(r.pairs.size(), c.pairs.size());
  for (std::size_t i = 0; i < c.pairs.size(); ++i) {
    EXPECT_EQ(r.pairs[i].a, c.pairs[i].a);
    EXPECT_EQ(r.pairs[i].b, c.pairs[i].b);
    EXPECT_EQ(r.pairs[i].relation, c.pairs[i].relation);
  }
  ASSERT_TRUE(r.strokes.has_value());
  ASSERT_EQ(r.strokes->strokes.size(), c.strokes->strokes.size());
  for (std::size_t i = 0; i < c.strokes->strokes.size(); ++i) {
    EXPECT_EQ(r.strokes->strokes[i].label, c.strokes->strokes[i].label);
    EXPECT_EQ(r.strokes->strokes[i].points, c.strokes->strokes[i].points);
  }
  EXPECT_EQ(r.strand_masks, c.strand_masks);
}

void expect_rejected(const Options& o, const std::string& option) {
  std::string why;
  EXPECT_FALSE(o.is_valid(&why));
  EXPECT_NE(why.find(option), std::string::npos) << why;
  try {
    generate_case(o);
    ADD_FAILURE() << "no error for bad " << option;
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find(option), std::string::npos) << e.what();
  }
}

TEST(Generator, BadOptionsNameTheOption) {
  Options o = small(1);
  EXPECT_TRUE(o.is_valid(nullptr));
  Options bad = o;
  bad.width = 10;
  expect_rejected(bad, "width");
  bad = o;
  bad.height = 100000;
  expect_rejected(bad, "height");
  bad = o;
  bad.strand_count = 0;
  expect_rejected(bad, "strand_count");
  bad = o;
  bad.line_width = 0.2;
  expect_rejected(bad, "line_width");
  bad = o;
  bad.line_width = 30.0;  // too wide for a 416 × 352 picture
  expect_rejected(bad, "line_width");
  bad = o;
  bad.noise_sigma = -1.0;
  expect_rejected(bad, "noise_sigma");
  bad = o;
  bad.noise_sigma = std::nan("");
  expect_rejected(bad, "noise_sigma");
  bad = o;
  bad.jpeg_quality = 101;
  expect_rejected(bad, "jpeg_quality");
  bad = o;
  bad.shading = static_cast<Shading>(7);
  expect_rejected(bad, "shading");
}

}  // namespace
}  // namespace hair25d::generator

namespace hair25d::generator {
namespace {

// Label-0 pixels with the two halves of one strand ("equal" regions) on
// either side, where the picture shows paint, not ink: a cut the annotation
// makes where the drawn fork line has faded out.
int undrawn_cuts(const AnnotatedCase& c) {
  std::set<std::pair<int, int>> equal;
  for (const AnnotatedPair& p : c.pairs)
    if (p.relation == Relation::kEqual) equal.insert({std::min(p.a, p.b), std::max(p.a, p.b)});
  auto grey = [&](int x, int y) {
    const Rgba& p = c.image.at(x, y);
    return (p.r + p.g + p.b) / 3.0;
  };
  int count = 0;
  for (int y = 1; y + 1 < c.regions.height(); ++y)
    for (int x = 1; x + 1 < c.regions.width(); ++x) {
      if (c.regions.at(x, y) != 0) continue;
      for (const auto& [dx, dy] : {std::pair{1, 0}, std::pair{0, 1}}) {
        const int a = c.regions.at(x - dx, y - dy), b = c.regions.at(x + dx, y + dy);
        if (a == 0 || b == 0 || a == b) continue;
        if (!equal.contains({std::min(a, b), std::max(a, b)})) continue;
        const double side = 0.5 * (grey(x - dx, y - dy) + grey(x + dx, y + dy));
        if (std::abs(grey(x, y) - side) < 12) ++count;
      }
    }
  return count;
}

TEST(Generator, FadingForksLeaveTheCutUndrawn) {
  int fading = 0, drawn = 0;
  for (std::uint64_t seed = 20; seed < 26; ++seed) {
    Options o = small(seed);
    o.strand_count = 24;
    drawn += undrawn_cuts(generate_case(o));
    o.fading_forks = true;
    const AnnotatedCase c = generate_case(o);
    fading += undrawn_cuts(c);
    // The option changes nothing else about the ground truth's rules.
    for (const AnnotatedPair& p : c.pairs) EXPECT_NE(p.a, p.b);
  }
  // Measured: 116 such pixels with fading forks, 0 without.
  EXPECT_GT(fading, 20);
  EXPECT_LT(drawn, fading / 4) << fading;
}

}  // namespace
}  // namespace hair25d::generator
