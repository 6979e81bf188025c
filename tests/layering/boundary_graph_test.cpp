// Crack-grid boundaries and junctions on tiny hand-built label maps.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <random>
#include <set>

#include "hair25d/core/error.h"
#include "hair25d/layering/boundary_graph.h"

namespace hair25d::layering {
namespace {

// Regions: A (1) above y = 3, B (2) left and C (3) right of x = 4 below it.
LabelMap t_map(int w = 9, int h = 7) {
  LabelMap m(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) m.at(x, y) = y < 3 ? 1 : (x < 4 ? 2 : 3);
  return m;
}

const Boundary* find_boundary(const BoundaryGraph& g, int a, int b) {
  for (const Boundary& x : g.boundaries)
    if ((x.left == a && x.right == b) || (x.left == b && x.right == a)) return &x;
  return nullptr;
}

TEST(BoundaryGraph, TJunctionIsOneCornerWithThreeBoundaries) {
  const BoundaryGraph g = build_boundary_graph(t_map());
  // The T corner (4, 3) plus the three places where inner boundaries reach
  // the image border (meeting the outside label).
  const auto t = std::find_if(g.junctions.begin(), g.junctions.end(),
                              [](const Junction& j) { return j.position == Vec2(4, 3); });
  ASSERT_NE(t, g.junctions.end());
  EXPECT_EQ(t->boundaries.size(), 3u);
  const Boundary* ab = find_boundary(g, 1, 2);
  const Boundary* ac = find_boundary(g, 1, 3);
  const Boundary* bc = find_boundary(g, 2, 3);
  ASSERT_TRUE(ab && ac && bc);
  EXPECT_DOUBLE_EQ(ab->length(), 4.0);  // from x = 0 to x = 4 along y = 3
  EXPECT_DOUBLE_EQ(ac->length(), 5.0);
  EXPECT_DOUBLE_EQ(bc->length(), 4.0);  // from y = 3 to y = 7 along x = 4
  // Walking along a boundary, `left` is on the left as seen on the screen.
  const Vec2 dir = ab->points[1] - ab->points[0];
  const Vec2 left_normal(dir.y(), -dir.x());
  const Vec2 mid = 0.5 * (ab->points[0] + ab->points[1]) + 0.5 * left_normal;
  const int left_label = t_map().at(static_cast<int>(mid.x()), static_cast<int>(mid.y()));
  EXPECT_EQ(left_label, ab->left);
}

TEST(BoundaryGraph, EveryCrackEdgeIsInExactlyOneBoundary) {
  const LabelMap m = t_map(11, 6);
  const BoundaryGraph g = build_boundary_graph(m);
  // Count crack edges directly: adjacent pixels with different labels, and
  // the image border (against the outside).
  int expected = 2 * (m.width() + m.height());
  for (int y = 0; y < m.height(); ++y)
    for (int x = 0; x < m.width(); ++x) {
      if (x + 1 < m.width() && m.at(x, y) != m.at(x + 1, y)) ++expected;
      if (y + 1 < m.height() && m.at(x, y) != m.at(x, y + 1)) ++expected;
    }
  double total = 0;
  for (const Boundary& b : g.boundaries) total += b.length();
  EXPECT_DOUBLE_EQ(total, expected);
}

TEST(BoundaryGraph, IslandIsAClosedLoopWithoutJunctions) {
  LabelMap m(8, 6, 1);
  for (int y = 2; y < 4; ++y)
    for (int x = 3; x < 6; ++x) m.at(x, y) = 2;
  const BoundaryGraph g = build_boundary_graph(m);
  const Boundary* loop = find_boundary(g, 1, 2);
  ASSERT_NE(loop, nullptr);
  EXPECT_TRUE(loop->closed());
  EXPECT_DOUBLE_EQ(loop->length(), 10.0);  // 2 × (3 + 2)
  EXPECT_TRUE(g.junctions.empty());        // the border loop meets no third label either
}

TEST(BoundaryGraph, SaddleCornerIsNotAJunction) {
  // Two labels meeting diagonally at (2, 2).
  LabelMap m(4, 4, 1);
  for (int y = 0; y < 2; ++y)
    for (int x = 2; x < 4; ++x) m.at(x, y) = 2;
  for (int y = 2; y < 4; ++y)
    for (int x = 0; x < 2; ++x) m.at(x, y) = 2;
  const BoundaryGraph g = build_boundary_graph(m);
  for (const Junction& j : g.junctions) EXPECT_NE(j.position, Vec2(2, 2));
  for (const Boundary& b : g.boundaries) {
    if (b.left == kOutsideLabel || b.right == kOutsideLabel) continue;
    EXPECT_TRUE((b.left == 1 && b.right == 2) || (b.left == 2 && b.right == 1));
  }
}

TEST(BoundaryGraph, RejectsEmptyMap) { EXPECT_THROW(build_boundary_graph(LabelMap()), Error); }

TEST(OutlineFill, SplitsALineBetweenTwoRegionsInTheMiddle) {
  // Regions 1 and 2 separated by a 4-pixel wide column of 0 (an outline).
  LabelMap m(14, 9, 0);
  for (int y = 0; y < 9; ++y)
    for (int x = 0; x < 14; ++x) m.at(x, y) = x < 5 ? 1 : (x >= 9 ? 2 : 0);
  const OutlineFill f = fill_outlines(m);
  EXPECT_NEAR(f.line_width, 4.0, 1.0);
  for (int y = 0; y < 9; ++y) {
    EXPECT_EQ(f.labels.at(6, y), 1);
    EXPECT_EQ(f.labels.at(7, y), 2);
  }
}

// Lines one pixel wide, as a drawing with 1.2-px lines leaves them in its
// region map, plus a few blots where lines pile up (5 px across): the lines
// are 1 px wide. Fronts never meet inside a 1-px line, so the median of the
// meeting fronts alone measured the blots (5 px here; the generated 1.2-px
// drawings read 1 to 5 px, drawing by drawing).
TEST(OutlineFill, MeasuresLinesOnePixelWideBesideBlots) {
  LabelMap m(64, 48, 0);
  for (int y = 0; y < 48; ++y)
    for (int x = 0; x < 64; ++x)
      if (x % 16 != 15) m.at(x, y) = 1 + x / 16 + 4 * (y / 24);
  for (int x = 0; x < 64; ++x) m.at(x, 23) = 0;  // a horizontal line, too
  // Blots: 5 × 5 squares of 0 where the lines cross.
  for (int cx : {15, 31, 47})
    for (int y = 21; y < 26; ++y)
      for (int x = cx - 2; x <= cx + 2; ++x) m.at(x, y) = 0;
  const OutlineFill f = fill_outlines(m);
  EXPECT_NEAR(f.line_width, 1.0, 0.5);
  EXPECT_NE(f.labels.at(15, 5), 0);  // the lines are given away
  EXPECT_NE(f.labels.at(5, 23), 0);
  // Wide lines keep their measure beside a few one-pixel pinches.
  LabelMap w(40, 30, 0);
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) w.at(x, y) = x < 17 ? 1 : (x >= 22 ? 2 : 0);
  for (int y = 10; y < 13; ++y)
    for (int x = 17; x < 21; ++x) w.at(x, y) = 1;  // a tip of 1 reaching within a pixel of 2
  EXPECT_NEAR(fill_outlines(w).line_width, 5.0, 1.0);
}

TEST(OutlineFill, FarBackgroundStaysBackground) {
  LabelMap m(40, 12, 0);
  for (int y = 0; y < 12; ++y)
    for (int x = 0; x < 4; ++x) m.at(x, y) = 1;
  for (int y = 0; y < 12; ++y) m.at(39, y) = 2;
  const OutlineFill f = fill_outlines(m, {.max_distance = 3.0});
  EXPECT_EQ(f.labels.at(6, 5), 1);   // within 3 pixels
  EXPECT_EQ(f.labels.at(20, 5), 0);  // far from any region
}

// Random label maps for the properties below: blobs of a few labels with
// label-0 gaps of several widths, regions on every image border, and salt
// noise (labels touching only diagonally, single pixels, -1 labels like the
// outside).
LabelMap random_map(std::mt19937& rng, int w, int h, bool noise) {
  LabelMap m(w, h);
  if (noise) {
    const int kinds[] = {0, 0, 1, 2, 7, -1, -3};
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) m.at(x, y) = kinds[rng() % 7];
    return m;
  }
  std::vector<std::array<int, 3>> seeds(2 + rng() % 6);  // x, y, label
  for (auto& s : seeds) s = {int(rng() % w), int(rng() % h), 1 + int(rng() % 4)};
  const double gap = (rng() % 50) / 10.0;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      double d1 = 1e9, d2 = 1e9;
      int best = 0;
      for (const auto& s : seeds) {
        const double d = std::hypot(x - s[0], y - s[1]);
        if (d < d1) {
          d2 = d1, d1 = d, best = s[2];
        } else if (d < d2) {
          d2 = d;
        }
      }
      m.at(x, y) = d2 - d1 < gap ? 0 : best;
    }
  return m;
}

TEST(BoundaryGraph, RandomMapsAreCoveredExactlyAndConsistently) {
  std::mt19937 rng(11);
  for (int trial = 0; trial < 60; ++trial) {
    const int w = 1 + static_cast<int>(rng() % 41), h = 1 + static_cast<int>(rng() % 29);
    const LabelMap m = random_map(rng, w, h, trial % 2 == 0);
    const BoundaryGraph g = build_boundary_graph(m);
    auto label = [&](int x, int y) { return m.contains(x, y) ? m.at(x, y) : kOutsideLabel; };
    // Every crack edge between different labels (the border too) is walked
    // exactly once, with the labels on its sides.
    std::map<std::array<int, 4>, int> walked;  // (x, y, dx, dy) of the edge, from its smaller end
    for (const Boundary& b : g.boundaries) {
      const std::size_t n = b.points.size();
      ASSERT_GE(n, b.closed() ? 4u : 2u);
      for (std::size_t k = 0; k + (b.closed() ? 0 : 1) < n; ++k) {
        const Vec2 p = b.points[k], q = b.points[(k + 1) % n];
        const int dx = static_cast<int>(q.x() - p.x()), dy = static_cast<int>(q.y() - p.y());
        ASSERT_EQ(std::abs(dx) + std::abs(dy), 1);
        const int px = static_cast<int>(p.x()), py = static_cast<int>(p.y());
        // Screen orientation: left of travel (dx, dy) is the pixel at (dy, -dx).
        const int lx = dx > 0 ? px : dx < 0 ? px - 1 : (dy > 0 ? px : px - 1);
        const int ly = dy > 0 ? py : dy < 0 ? py - 1 : (dx > 0 ? py - 1 : py);
        const int rx = dx != 0 ? lx : (dy > 0 ? px - 1 : px);
        const int ry = dy != 0 ? ly : (dx > 0 ? py : py - 1);
        EXPECT_EQ(label(lx, ly), b.left);
        EXPECT_EQ(label(rx, ry), b.right);
        EXPECT_NE(b.left, b.right);
        const int sx = std::min(px, static_cast<int>(q.x())),
                  sy = std::min(py, static_cast<int>(q.y()));
        ++walked[{sx, sy, std::abs(dx), std::abs(dy)}];
      }
      if (!b.closed()) {
        EXPECT_EQ(g.junctions[b.start].position, b.points.front());
        EXPECT_EQ(g.junctions[b.end].position, b.points.back());
      }
    }
    int expected = 0;
    for (int y = 0; y <= h; ++y)
      for (int x = 0; x <= w; ++x) {
        if (x < w && label(x, y - 1) != label(x, y)) {
          ++expected;
          EXPECT_EQ((walked[{x, y, 1, 0}]), 1) << "horizontal edge at " << x << "," << y;
        }
        if (y < h && label(x - 1, y) != label(x, y)) {
          ++expected;
          EXPECT_EQ((walked[{x, y, 0, 1}]), 1) << "vertical edge at " << x << "," << y;
        }
      }
    int total = 0;
    for (const auto& [edge, count] : walked) total += count;
    EXPECT_EQ(total, expected);
    // Junctions are exactly the corners where three or more labels meet.
    std::set<std::pair<int, int>> at;
    for (const Junction& j : g.junctions) {
      at.insert({static_cast<int>(j.position.x()), static_cast<int>(j.position.y())});
      EXPECT_FALSE(j.boundaries.empty());
    }
    for (int y = 0; y <= h; ++y)
      for (int x = 0; x <= w; ++x) {
        const std::set<int> around = {label(x - 1, y - 1), label(x, y - 1), label(x - 1, y),
                                      label(x, y)};
        EXPECT_EQ(around.size() >= 3, at.contains({x, y})) << x << "," << y;
      }
  }
}

// The chamfer distance (fifths of a pixel) the fill grows by, between pixels.
int chamfer(int dx, int dy) {
  dx = std::abs(dx), dy = std::abs(dy);
  return 5 * std::max(dx, dy) + 2 * std::min(dx, dy);
}

TEST(OutlineFill, GivesEachOutlinePixelToANearestRegionWithinTheRadius) {
  std::mt19937 rng(5);
  for (int trial = 0; trial < 40; ++trial) {
    const int w = 2 + static_cast<int>(rng() % 45), h = 2 + static_cast<int>(rng() % 31);
    const LabelMap m = random_map(rng, w, h, false);
    const double reach = trial % 3 == 0 ? 0.0 : 0.5 + (rng() % 40) / 10.0;  // 0: estimated
    const OutlineFill f = fill_outlines(m, {.max_distance = reach});
    if (reach > 0) {
      EXPECT_DOUBLE_EQ(f.radius, reach);
    }
    const int radius = static_cast<int>(std::floor(f.radius * 5));
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x) {
        if (m.at(x, y) != 0) {
          ASSERT_EQ(f.labels.at(x, y), m.at(x, y));  // regions are never changed
          continue;
        }
        // Brute force: the nearest region pixels and their labels.
        int best = std::numeric_limits<int>::max();
        std::set<int> nearest;
        for (int v = 0; v < h; ++v)
          for (int u = 0; u < w; ++u) {
            if (m.at(u, v) == 0) continue;
            const int d = chamfer(u - x, v - y);
            if (d < best) best = d, nearest.clear();
            if (d == best) nearest.insert(m.at(u, v));
          }
        if (best <= radius) {
          EXPECT_TRUE(nearest.contains(f.labels.at(x, y)))
              << "pixel " << x << "," << y << " at " << best << " got " << f.labels.at(x, y);
        } else {
          EXPECT_EQ(f.labels.at(x, y), 0) << "pixel " << x << "," << y << " at " << best;
        }
      }
  }
}

TEST(OutlineFill, MapWithoutRegionsOrWithoutOutlinesIsUnchanged) {
  const LabelMap empty(13, 7, 0);
  const OutlineFill a = fill_outlines(empty);
  EXPECT_EQ(a.labels, empty);
  EXPECT_EQ(a.line_width, 0.0);
  LabelMap full(6, 11, 3);
  full.at(2, 4) = 5;
  const OutlineFill b = fill_outlines(full);
  EXPECT_EQ(b.labels, full);
  EXPECT_EQ(b.line_width, 0.0);
}

TEST(OutlineFill, RejectsBadInput) {
  EXPECT_THROW(fill_outlines(LabelMap()), Error);
  OutlineFillOptions bad;
  bad.max_distance = std::numeric_limits<double>::quiet_NaN();
  std::string why;
  EXPECT_FALSE(bad.is_valid(&why));
  EXPECT_NE(why.find("max_distance"), std::string::npos);
  EXPECT_THROW(fill_outlines(LabelMap(3, 2, 1), bad), Error);
}

}  // namespace
}  // namespace hair25d::layering
