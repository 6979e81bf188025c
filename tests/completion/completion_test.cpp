#include "hair25d/completion/completion.h"

#include <gtest/gtest.h>

#include <cmath>

#include "hair25d/core/error.h"
#include "invalid_options.h"
#include "synthetic.h"

namespace hair25d::completion {
namespace {

// The shared synthetic drawings and helpers (synthetic.h).
using namespace test;

const Rgba kHair{200, 170, 90, 255};
const Rgba kFront{120, 90, 160, 255};

Result run(const Drawing& d, std::optional<Vec2> head = std::nullopt, Options o = {}) {
  const Input in = test::input_of(d, head);
  return complete_strands(in, o);
}

// Every completed pixel lies where the drawing shows one of `occluders`.
void expect_under(const Result& r, const CompletedStrand& s, const std::vector<int>& occluders) {
  for (int y = 0; y < s.mask.height(); ++y)
    for (int x = 0; x < s.mask.width(); ++x) {
      if (s.mask.at(x, y) != 2) continue;
      const int l = r.regions.at(x + s.origin.x(), y + s.origin.y());
      EXPECT_TRUE(std::find(occluders.begin(), occluders.end(), l) != occluders.end())
          << "completed pixel at " << x + s.origin.x() << "," << y + s.origin.y()
          << " shows region " << l;
    }
}

// A horizontal band split by a vertical occluder (case 1).
Drawing crossed_bands() {
  Drawing d = blank(300, 170);
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 60 && y < 100; }, kHair, 1);
  paint(
      d, [](double x, double y) { return x >= 150 && x < 280 && y > 60 && y < 100; }, kHair, 2);
  paint(
      d, [](double x, double y) { return x > 130 && x < 170 && y > 10 && y < 150; }, kFront, 3);
  d.relations = {below(1, 3), below(2, 3)};
  return d;
}

TEST(Completion, IntersectingPiecesAreJoinedUnderTheOccluder) {
  const Drawing d = crossed_bands();
  const Result r = run(d, Vec2(150, 300));
  EXPECT_EQ(r.joins, 1);
  ASSERT_EQ(r.strands.size(), 2u);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->regions, (std::vector<int>{1, 2}));
  expect_under(r, *s, {3});
  // The hidden part is the band's 40 × 40 pixels under the occluder, less lines.
  EXPECT_GT(s->completed_pixels, 1200);
  EXPECT_LT(s->completed_pixels, 2000);
  // The completed band is straight: every hidden pixel lies within its rows.
  for (int y = 0; y < s->mask.height(); ++y)
    for (int x = 0; x < s->mask.width(); ++x)
      if (s->mask.at(x, y) == 2) {
        EXPECT_GT(y + s->origin.y(), 55);
        EXPECT_LT(y + s->origin.y(), 105);
      }
  // One closed outline around the whole band: it spans both pieces.
  double x0 = 1e9, x1 = -1e9;
  for (const Vec2& p : s->outline) x0 = std::min(x0, p.x()), x1 = std::max(x1, p.x());
  EXPECT_LT(x0, 25);
  EXPECT_GT(x1, 275);
  // The texture is the hair colour in the completed part (inpainted from its own pixels).
  int hair_coloured = 0;
  for (int y = 0; y < s->mask.height(); ++y)
    for (int x = 0; x < s->mask.width(); ++x)
      if (s->mask.at(x, y) == 2) {
        const Rgba c = s->texture.at(x, y);
        hair_coloured +=
            std::abs(c.r - kHair.r) + std::abs(c.g - kHair.g) + std::abs(c.b - kHair.b) < 30;
      }
  EXPECT_GT(hair_coloured, 0.9 * s->completed_pixels);
}

// The layering's relations are measured (a score) or, between regions that
// do not touch, only its drawing order (score 0). Neither a chain of weak
// measured orders (1 above the blob 4 above 2) nor an unmeasured order keeps
// two pieces out of one strand, and an unmeasured "equal" makes no strand of
// two regions. (Firm orders through the blob, which touches neither piece,
// are remote orders: RemoteOrdersDoNotKeepPiecesApart.)
TEST(Completion, WeakOrUnmeasuredRelationsDoNotDecideStrands) {
  Drawing d = crossed_bands();
  paint(
      d, [](double x, double y) { return x > 20 && x < 60 && y > 120 && y < 160; }, kFront, 4);
  const auto strand_of_1 = [&](const std::vector<RegionRelation>& extra) {
    Drawing with = d;
    with.relations.insert(with.relations.end(), extra.begin(), extra.end());
    const Result r = run(with, Vec2(150, 300));
    const CompletedStrand* s = strand_with(r, 1);
    return s != nullptr ? s->regions : std::vector<int>{};
  };
  const std::vector<int> joined{1, 2}, apart{1};
  EXPECT_EQ(strand_of_1({{1, 4, Relation::kAbove, 0.4}, {4, 2, Relation::kAbove, 0.6}}), joined);
  EXPECT_EQ(strand_of_1({{1, 2, Relation::kAbove, 0.0}}), joined);
  EXPECT_EQ(strand_of_1({{1, 4, Relation::kEqual, 0.0}}), joined);
}

// The layering also measures orders between regions that do not touch once
// the outlines are assigned (across a thin line or sliver between them);
// such a *remote* order, firm or weak, neither keeps the pieces' edges apart
// nor makes a chain that keeps them out of one strand: the crossed bands
// with a firm order 1 above 2 (across the occluder 3), or a firm chain
// through the blob 4 that touches neither, are joined. A firm chain
// through a region touching both pieces (a U under them, round the
// occluder's foot) still keeps them apart.
TEST(Completion, RemoteOrdersDoNotKeepPiecesApart) {
  const auto strand_of_1 = [&](const Drawing& d, const std::vector<RegionRelation>& extra) {
    Drawing with = d;
    with.relations.insert(with.relations.end(), extra.begin(), extra.end());
    const Result r = run(with, Vec2(150, 300));
    const CompletedStrand* s = strand_with(r, 1);
    return s != nullptr ? s->regions : std::vector<int>{};
  };
  const std::vector<int> joined{1, 2}, apart{1};
  Drawing blob = crossed_bands();
  paint(
      blob, [](double x, double y) { return x > 20 && x < 60 && y > 120 && y < 160; }, kFront, 4);
  EXPECT_EQ(strand_of_1(blob, {{1, 2, Relation::kAbove, 3.0}}), joined);
  EXPECT_EQ(strand_of_1(blob, {{1, 4, Relation::kAbove, 3.0}, {4, 2, Relation::kAbove, 2.5}}),
            joined);
  Drawing u = blank(300, 170);
  paint(
      u, [](double x, double y) { return x > 100 && x < 200 && y > 94 && y < 166; }, kFront, 4);
  paint(
      u, [](double x, double y) { return x > 20 && x < 150 && y > 60 && y < 100; }, kHair, 1);
  paint(
      u, [](double x, double y) { return x >= 150 && x < 280 && y > 60 && y < 100; }, kHair, 2);
  paint(
      u, [](double x, double y) { return x > 130 && x < 170 && y > 10 && y < 150; }, kFront, 3);
  u.relations = {below(1, 3), below(2, 3), below(4, 3)};
  EXPECT_EQ(strand_of_1(u, {{1, 4, Relation::kAbove, 3.0}, {4, 2, Relation::kAbove, 2.5}}), apart);
}

// A horizontal band of one paint cut across by a drawn line (pieces 1, x
// 20..150, and 2, x 150..280, y 60..100, each outlined: 4 px of ink between
// them) whose side outlines run on straight across it, the pieces ordered
// by `order` (1 above 2); or, `tee`, piece 2 a vertical band (x 150..190, y
// 10..150) that piece 1's sides end on.
std::vector<int> strand_of_cut_band(const RegionRelation& order, Rgba second = kHair,
                                    bool tee = false, Options o = {}) {
  Drawing d = blank(300, 170);
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 60 && y < 100; }, kHair, 1);
  if (tee)
    paint(
        d, [](double x, double y) { return x >= 150 && x < 190 && y > 10 && y < 150; }, second, 2);
  else
    paint(
        d, [](double x, double y) { return x >= 150 && x < 280 && y > 60 && y < 100; }, second, 2);
  d.relations = {order};
  return test::regions_with(run(d, Vec2(150, 300), o), 1);
}

TEST(Completion, WeaklyOrderedPiecesOfOneStrandCutByALineAreJoined) {
  const std::vector<int> joined{1, 2}, apart{1};
  EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kAbove, 0.8}), joined);
  EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kBelow, -1.5}), joined);
  // A firm order, another paint, or a T (piece 1 ends on a strand lying
  // across it) keep the pieces apart.
  EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kAbove, 3.0}), apart);
  EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kAbove, 0.8}, Rgba{185, 160, 100, 255}), apart);
  EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kBelow, -0.8}, kHair, true), apart);
}

// The layering's `equal`s carry its confidence (EqualEvidence). A weak one
// (same-depth log-odds under 2, or an open pair's under 0) between the cut
// band's pieces painted apart (20 RGB) makes no strand of them. One paint,
// a firm equal, an open pair leaning to one depth, the user's equal, or an
// equal without evidence (as before session 23) unite them, unless the
// strand's paint is judged as a whole (Options::strand_paint, the default
// since session 28): then only the user's equal unites two paints.
TEST(Completion, WeakEqualsBetweenTwoPaintsAreRefused) {
  const Rgba other{185, 160, 100, 255};
  const auto equal = [](double log_odds, bool open = false, bool user = false) {
    RegionRelation r{1, 2, Relation::kEqual, 0.0, user};
    r.equal_evidence = EqualEvidence{log_odds, open, open ? 0.9 : 0.1};
    return r;
  };
  const std::vector<int> joined{1, 2}, apart{1};
  Options pairs_only;
  pairs_only.strand_paint = false;
  for (const Options& o : {pairs_only, Options{}}) {
    SCOPED_TRACE(o.strand_paint ? "strand paint" : "pairs only");
    const std::vector<int>& firm = o.strand_paint ? apart : joined;
    EXPECT_EQ(strand_of_cut_band(equal(0.5), other, false, o), apart);
    EXPECT_EQ(strand_of_cut_band(equal(1.9), other, false, o), apart);
    EXPECT_EQ(strand_of_cut_band(equal(-1.0, true), other, false, o), apart);
    EXPECT_EQ(strand_of_cut_band(equal(0.5), kHair, false, o), joined);
    EXPECT_EQ(strand_of_cut_band(equal(2.5), other, false, o), firm);
    EXPECT_EQ(strand_of_cut_band(equal(1.0, true), other, false, o), firm);
    EXPECT_EQ(strand_of_cut_band(equal(0.5, false, true), other, false, o), joined);
    EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kEqual, 0.0}, other, false, o), firm);
  }
}

// The cut band's pieces on the generator's screentone paper (235, 205,
// 175): piece 1 toned (dots of 0.3 periods on a 6-px lattice), piece 2
// toned alike or left white, from x = 150 to `end` (130 px long, or a
// sliver).
Drawing dotted_cut_band(bool white, double end = 280) {
  Drawing d = blank(300, 170);
  const Rgba paper{235, 205, 175, 255};
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 60 && y < 100; }, paper, 1);
  paint(
      d, [&](double x, double y) { return x >= 150 && x < end && y > 60 && y < 100; }, paper, 2);
  const auto dots = [&](int x, int y) {
    const double k = test::dot_cover(x, y, 6.0, 0.3, 0.4);
    const auto mix = [&](int p, int ink) {
      return static_cast<std::uint8_t>(std::lround(p + k * (ink - p)));
    };
    return Rgba{mix(235, 60), mix(205, 40), mix(175, 30), 255};
  };
  repaint(d, 1, dots);
  if (!white) repaint(d, 2, dots);
  return d;
}

// On screentone the paint is the dots' (bank_crossings.h `two_paints`): a
// toned piece beside a paper-white one is two strands even where the dots
// of one of them cannot be measured (session 25). A weak equal between a
// toned and a white piece is refused; between two pieces of one tone, or
// firm, or the user's, it unites them, as it does a white 10-px sliver too
// small to hold three dot cells (a sliver of a toned strand may show no
// dot).
TEST(Completion, WeakEqualsBetweenAToneAndPaperWhiteAreRefused) {
  const auto strand_of = [](double log_odds, bool white, bool user = false, double end = 280) {
    Drawing d = dotted_cut_band(white, end);
    RegionRelation r{1, 2, Relation::kEqual, 0.0, user};
    if (!user) r.equal_evidence = EqualEvidence{log_odds, false, 0.1};
    d.relations = {r};
    return test::regions_with(run(d, Vec2(150, 300)), 1);
  };
  const std::vector<int> joined{1, 2}, apart{1};
  EXPECT_EQ(strand_of(0.5, true), apart);
  EXPECT_EQ(strand_of(1.9, true), apart);
  EXPECT_EQ(strand_of(0.5, false), joined);
  EXPECT_EQ(strand_of(2.5, true), joined);
  EXPECT_EQ(strand_of(0.5, true, true), joined);
  EXPECT_EQ(strand_of(0.5, true, false, 160), joined);
}

// An order the drawing order made of the layering's `equal` (overridden,
// with the equal's evidence) between pieces of one paint is a seam without
// the seam geometry (session 26): the T of strand_of_cut_band, whose sides
// say nothing, is joined where its weak order is such an equal measured
// over drawn lines (log-odds 1.5), not where the evidence is under the bar
// (0.5), open (no line between the pieces: the paint alone off
// screentone), the order a measured one (not overridden) or the paint
// another. On screentone (the pieces dotted as in the test above) an open
// overridden equal joins two pieces whose dots match, never a toned piece
// and a white one, and a plain weak order joins nothing.
TEST(Completion, EqualsTheDrawingOrderOverrodeBetweenOnePaintAreSeams) {
  const auto overridden = [](double log_odds, bool open = false) {
    RegionRelation r{1, 2, Relation::kBelow, 0.0, false, true};
    r.equal_evidence = EqualEvidence{log_odds, open, open ? 0.9 : 0.1};
    return r;
  };
  const std::vector<int> joined{1, 2}, apart{1};
  EXPECT_EQ(strand_of_cut_band(overridden(1.5), kHair, true), joined);
  EXPECT_EQ(strand_of_cut_band(overridden(0.5), kHair, true), apart);
  EXPECT_EQ(strand_of_cut_band(overridden(-1.0, true), kHair, true), apart);
  EXPECT_EQ(strand_of_cut_band({1, 2, Relation::kBelow, 0.0}, kHair, true), apart);
  EXPECT_EQ(strand_of_cut_band(overridden(1.5), Rgba{185, 160, 100, 255}, true), apart);

  const auto dotted = [](const RegionRelation& r, bool white) {
    Drawing d = dotted_cut_band(white);
    d.relations = {r};
    return test::regions_with(run(d, Vec2(150, 300)), 1);
  };
  EXPECT_EQ(dotted(overridden(-1.0, true), false), joined);
  EXPECT_EQ(dotted(overridden(-1.0, true), true), apart);
  EXPECT_EQ(dotted({1, 2, Relation::kBelow, 0.5}, false), apart);
}

// A wide piece (a cap, the back hair) cut by a strand lying over it, where
// the cut runs between two other occluders: no side outline reaches the cut,
// so only the banks of the strand facing each other tell that the two
// pieces are one.
Drawing wide_piece_under_strand() {
  Drawing d = blank(320, 190);
  paint(
      d, [](double x, double y) { return x > 20 && x < 150 && y > 40 && y < 150; }, kHair, 1);
  paint(
      d, [](double x, double y) { return x >= 150 && x < 290 && y > 0.1 * x + 25 && y < 150; },
      kHair, 2);
  // Bars over the top and bottom borders where the strand crosses them.
  paint(
      d, [](double x, double y) { return x > 100 && x < 200 && y > 28 && y < 58; }, kFront, 4);
  paint(
      d, [](double x, double y) { return x > 100 && x < 200 && y > 132 && y < 162; }, kFront, 5);
  paint(
      d, [](double x, double y) { return x > 138 && x < 162 && y > 5 && y < 185; }, kFront, 3);
  d.relations = {below(1, 3), below(2, 3), below(1, 4), below(2, 4),
                 below(1, 5), below(2, 5), below(4, 3), below(5, 3)};
  return d;
}

TEST(Completion, WidePieceCutByAStrandIsJoinedAcrossItsBanks) {
  const Drawing d = wide_piece_under_strand();
  // Strand joins (tangents along the chords, equal cut widths) ruled out:
  // the banks alone join.
  Options banks_only;
  banks_only.max_join_angle_deg = 0.5;
  banks_only.min_width_ratio = 0.99;
  // Path joins (mass_paths.cpp) have no depth rule (back-hair slivers are
  // thin) and would join the narrow end below through strand 3.
  banks_only.path_joins = false;
  const Result r = run(d, Vec2(160, 400), banks_only);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  EXPECT_EQ(s->regions, (std::vector<int>{1, 2}));
  expect_under(r, *s, {3, 4, 5});
  // The strand's pixels between the banks (x 142..158, y 62..128) are completed.
  int inside = 0, completed = 0;
  for (int y = 62; y <= 128; ++y)
    for (int x = 142; x <= 158; ++x) {
      ++inside;
      const int mx = x - s->origin.x(), my = y - s->origin.y();
      completed += s->mask.contains(mx, my) && s->mask.at(mx, my) == 2;
    }
  EXPECT_GT(completed, 0.8 * inside);
  // A narrow strand end facing the wide piece across the same strand is no
  // piece of it: the strand end is thinner behind its cut than the gap.
  Drawing narrow = blank(320, 190);
  paint(
      narrow, [](double x, double y) { return x > 20 && x < 150 && y > 40 && y < 150; }, kHair, 1);
  paint(
      narrow, [](double x, double y) { return x >= 150 && x < 166 && y > 80 && y < 110; }, kHair,
      2);
  paint(
      narrow, [](double x, double y) { return x > 100 && x < 200 && y > 28 && y < 58; }, kFront, 4);
  paint(
      narrow, [](double x, double y) { return x > 100 && x < 200 && y > 132 && y < 162; }, kFront,
      5);
  paint(
      narrow, [](double x, double y) { return x > 138 && x < 162 && y > 5 && y < 185; }, kFront, 3);
  narrow.relations = d.relations;
  const Result rn = run(narrow, Vec2(160, 400), banks_only);
  const CompletedStrand* sn = strand_with(rn, 1);
  ASSERT_NE(sn, nullptr);
  EXPECT_EQ(sn->regions, (std::vector<int>{1}));
}

// A strand tapering to a tip at x = 280; the part beyond x = 190 is hidden.
Drawing hidden_tip() {
  Drawing d = blank(320, 150);
  const auto strand = [](double x, double y) {
    if (x < 20 || x > 280) return false;
    const double half = 24.0 * (280 - x) / 260.0;
    return std::abs(y - 70) < half;
  };
  paint(d, strand, kHair, 1);
  paint(
      d, [](double x, double y) { return x > 190 && x < 310 && y > 15 && y < 130; }, kFront, 2);
  d.relations = {below(1, 2)};
  return d;
}

double corner_angle_deg(const Polyline& outline, const Vec2& at, double arm) {
  int best = 0;
  for (int i = 0; i < static_cast<int>(outline.size()); ++i)
    if ((outline[i] - at).norm() < (outline[best] - at).norm()) best = i;
  const int n = static_cast<int>(outline.size());
  auto walk = [&](int step) {
    double left = arm;
    int j = best;
    for (int k = 0; k < n; ++k) {
      const int next = ((j + step) % n + n) % n;
      left -= (outline[next] - outline[j]).norm();
      j = next;
      if (left <= 0) break;
    }
    return outline[j];
  };
  const Vec2 a = (walk(-1) - outline[best]).normalized(),
             b = (walk(1) - outline[best]).normalized();
  return std::acos(std::clamp(a.dot(b), -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(Completion, HiddenTipIsCompletedSharp) {
  const Drawing d = hidden_tip();
  const Result r = run(d, Vec2(-100, 70));  // the head is on the left: the hidden end is the tip
  EXPECT_EQ(r.tips, 1);
  EXPECT_EQ(r.roots, 0);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  expect_under(r, *s, {2});
  EXPECT_GT(s->completed_pixels, 100);
  // The farthest completed point from the cut is a sharp corner of the outline.
  Vec2 far(0, 0);
  for (const Vec2& p : s->outline)
    if (p.x() > far.x()) far = p;
  EXPECT_GT(far.x(), 200);
  EXPECT_LT(corner_angle_deg(s->outline, far, 8.0), 70.0);
  EXPECT_FALSE(s->root_hint.has_value());
}

TEST(Completion, HiddenRootIsGrownAndGivesARootHint) {
  const Drawing d = hidden_tip();
  const Result r = run(d, Vec2(420, 70));  // the head is on the right: the hidden end is the root
  EXPECT_EQ(r.roots, 1);
  EXPECT_EQ(r.tips, 0);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  expect_under(r, *s, {2});
  ASSERT_TRUE(s->root_hint.has_value());
  EXPECT_GT(s->root_hint->x(), 190);
}

// The strand of hidden_tip() whose hidden end lies under two occluders, one
// above the other (§5.2: neighbouring occluding edges are merged).
Drawing root_under_two_occluders() {
  Drawing d = hidden_tip();
  paint(
      d, [](double x, double y) { return x > 190 && x < 310 && y >= 70 && y < 130; }, kFront, 3);
  d.relations = {below(1, 2), below(1, 3)};
  return d;
}

TEST(Completion, EdgesUnderNeighbouringOccludersAreGrownAsOne) {
  const Drawing d = root_under_two_occluders();
  const Result r = run(d, Vec2(420, 70));
  // One root grown under both, not one under each occluder.
  EXPECT_EQ(r.roots, 1);
  EXPECT_EQ(r.tips, 0);
  const CompletedStrand* s = strand_with(r, 1);
  ASSERT_NE(s, nullptr);
  expect_under(r, *s, {2, 3});
  int under[4] = {0, 0, 0, 0};
  for (int y = 0; y < s->mask.height(); ++y)
    for (int x = 0; x < s->mask.width(); ++x)
      if (s->mask.at(x, y) == 2) ++under[r.regions.at(x + s->origin.x(), y + s->origin.y())];
  EXPECT_GT(under[2], 50);
  EXPECT_GT(under[3], 50);
}

TEST(Completion, BackgroundHasTheHairRemoved) {
  const Drawing d = crossed_bands();
  const Result r = run(d);
  EXPECT_TRUE(r.head_center_estimated);
  ASSERT_EQ(r.background.width(), 300);
  ASSERT_EQ(r.background.height(), 170);
  int hairy = 0, changed_outside = 0, hair_pixels = 0;
  for (int y = 0; y < 170; ++y)
    for (int x = 0; x < 300; ++x) {
      const Rgba c = r.background.at(x, y);
      if (r.regions.at(x, y) != 0) {
        ++hair_pixels;
        hairy += std::abs(c.r - kHair.r) + std::abs(c.g - kHair.g) < 40 ||
                 std::abs(c.r - kFront.r) + std::abs(c.g - kFront.g) < 40;
      } else {
        // The hair's drawn outline and its anti-aliased rim go with the
        // hair: pixels beside the assigned outline may change, none farther.
        bool beside = false;
        for (int dy = -3; dy <= 3 && !beside; ++dy)
          for (int dx = -3; dx <= 3; ++dx)
            if (r.regions.contains(x + dx, y + dy) && r.regions.at(x + dx, y + dy) != 0) {
              beside = true;
              break;
            }
        if (!beside) changed_outside += !(c == d.image.at(x, y));
      }
    }
  EXPECT_EQ(changed_outside, 0);
  EXPECT_LT(hairy, hair_pixels / 20);
}

TEST(Completion, BackgroundContinuesTheFaceNotItsEyes) {
  // A band of hair down the middle of a face, an eye 3 px each side of it.
  Drawing d = blank(300, 170);
  const Rgba skin{245, 215, 190, 255};
  paint(
      d, [](double x, double y) { return x > 30 && x < 270 && y > 10 && y < 160; }, skin, 0);
  for (const double ex : {122.0, 178.0})
    paint(
        d, [ex](double x, double y) { return (x - ex) * (x - ex) + (y - 80) * (y - 80) < 36; },
        Rgba{40, 30, 30, 255}, 0);
  paint(
      d, [](double x, double) { return x > 130 && x < 170; }, kHair, 1);
  Options o;
  o.threads = 1;
  const Result r = run(d, Vec2(150, 80), o);
  int dark = 0, off = 0, judged = 0;
  for (int y = 30; y < 140; ++y)
    for (int x = 128; x < 172; ++x) {
      const Rgba c = r.background.at(x, y);
      ++judged;
      dark += c.r < 150;
      off +=
          std::max({std::abs(c.r - skin.r), std::abs(c.g - skin.g), std::abs(c.b - skin.b)}) > 20;
    }
  EXPECT_EQ(dark, 0) << "an eye (or a line) was copied into the face";
  EXPECT_LT(off, judged / 50) << off << " of " << judged;
}

TEST(Completion, RegionsWithoutOccludersAndTinyRegions) {
  Drawing d = blank(200, 120);
  paint(
      d, [](double x, double y) { return x > 20 && x < 120 && y > 30 && y < 60; }, kHair, 4);
  d.regions.at(150, 100) = 9;  // a one-pixel region
  d.image.at(150, 100) = kHair;
  // A region wholly inside another (its outline is all occluded).
  paint(
      d, [](double x, double y) { return x > 130 && x < 190 && y > 10 && y < 80; }, kFront, 5);
  for (int y = 40; y < 45; ++y)
    for (int x = 150; x < 156; ++x) d.regions.at(x, y) = 6;
  d.relations = {below(6, 5)};
  const Result r = run(d, Vec2(100, 200));
  ASSERT_EQ(r.strands.size(), 4u);
  const CompletedStrand* alone = strand_with(r, 4);
  ASSERT_NE(alone, nullptr);
  EXPECT_EQ(alone->completed_pixels, 0);
  EXPECT_GE(alone->outline.size(), 4u);
  // Its texture is the drawing where the strand is, transparent elsewhere.
  for (int y = 0; y < alone->mask.height(); ++y)
    for (int x = 0; x < alone->mask.width(); ++x) {
      const Rgba t = alone->texture.at(x, y);
      if (alone->mask.at(x, y)) {
        Rgba c = d.image.at(x + alone->origin.x(), y + alone->origin.y());
        EXPECT_EQ(t, c);
      } else {
        EXPECT_EQ(t.a, 0);
      }
    }
  EXPECT_NE(strand_with(r, 9), nullptr);
  EXPECT_NE(strand_with(r, 6), nullptr);
}

TEST(Completion, OutlinePixelsGoToTheNearestRegion) {
  Image img(9, 5, Rgba{250, 250, 250, 255});
  LabelMap regions(9, 5);
  for (int y = 0; y < 5; ++y) {
    for (int x = 0; x < 3; ++x) regions.at(x, y) = 1;
    for (int x = 3; x < 6; ++x) img.at(x, y) = {10, 10, 10, 255};  // a dark line, label 0
    for (int x = 6; x < 8; ++x) regions.at(x, y) = 2;
  }
  const LabelMap out = assign_outline_pixels(img, regions, 4, 140);
  for (int y = 0; y < 5; ++y) {
    EXPECT_EQ(out.at(3, y), 1);
    EXPECT_EQ(out.at(5, y), 2);
    EXPECT_NE(out.at(4, y), 0);
    EXPECT_EQ(out.at(8, y), 2 * 0 + 0) << "light pixels stay background";
  }
}

TEST(Completion, BadInputThrows) {
  const Drawing d = crossed_bands();
  Input in;
  EXPECT_THROW(complete_strands(in), Error);
  in.image = &d.image;
  EXPECT_THROW(complete_strands(in), Error);
  LabelMap wrong(10, 10);
  in.regions = &wrong;
  EXPECT_THROW(complete_strands(in), Error);
  in.regions = &d.regions;
  in.relations = {below(1, 77)};
  EXPECT_THROW(complete_strands(in), Error);
  in.relations = {};
  Options bad;
  bad.min_join_coverage = 2;
  test::expect_invalid(bad, "min_join_coverage");
  EXPECT_THROW(complete_strands(in, bad), Error);
  Options bad_arms;
  bad_arms.join_arm_shares = {0.2, 0.0};
  test::expect_invalid(bad_arms, "join_arm_shares");
  EXPECT_THROW(complete_strands(in, bad_arms), Error);
  Options bad_corridor;
  bad_corridor.corridor_width = -0.5;
  test::expect_invalid(bad_corridor, "corridor_width");
  EXPECT_THROW(complete_strands(in, bad_corridor), Error);
  bad_corridor.corridor_width = 0.5;
  bad_corridor.corridor_min_probability = 1.5;
  test::expect_invalid(bad_corridor, "corridor_min_probability");
  in.head_center = Vec2(std::nan(""), 1);
  EXPECT_THROW(complete_strands(in), Error);
  EXPECT_THROW(assign_outline_pixels(d.image, wrong, 4, 140), Error);
}

}  // namespace
}  // namespace hair25d::completion
