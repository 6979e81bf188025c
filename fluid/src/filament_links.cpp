// Which lattice links each filament segment cuts.
//
// Why link bounce-back rather than an immersed boundary: bounce-back on every cut link makes
// the filament exactly impermeable (no population ever crosses it, whatever its angle),
// conserves mass for a wall at rest and gives the force by momentum exchange on the same
// links, at the cost of O(length) work per segment per step. An immersed boundary spreads
// the wall over ~2 cells, so a zero-thickness plate leaks unless the coupling is iterated.
#include <algorithm>
#include <bit>
#include <cmath>

#include "d2q9.h"
#include "lattice.h"

namespace hair25d::fluid {
namespace {

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Closed segment intersection of the link a-b with the segment p-q. Touching counts: a link
// that only grazes a vertex is cut, so the polyline has no pin-hole at its nodes. On a hit,
// `t` is where along p-q the crossing is.
bool link_cut(const Vec2& a, const Vec2& b, const Vec2& p, const Vec2& q, double* t) {
  const Vec2 d = q - p;
  const Vec2 e = b - a;
  const double d1 = cross(d, a - p), d2 = cross(d, b - p);
  if ((d1 > 0 && d2 > 0) || (d1 < 0 && d2 < 0)) return false;
  const double d3 = cross(e, p - a), d4 = cross(e, q - a);
  if ((d3 > 0 && d4 > 0) || (d3 < 0 && d4 < 0)) return false;
  if (d1 == 0 && d2 == 0) {
    // Collinear: cut when the projections overlap.
    const double len2 = d.squaredNorm();
    const double ta = (a - p).dot(d) / len2, tb = (b - p).dot(d) / len2;
    const double lo = std::max(0.0, std::min(ta, tb)), hi = std::min(1.0, std::max(ta, tb));
    if (lo > hi) return false;
    *t = 0.5 * (lo + hi);
    return true;
  }
  *t = d3 == d4 ? 0.0 : std::clamp(d3 / (d3 - d4), 0.0, 1.0);
  return true;
}

}  // namespace

LinkCutter::LinkCutter(int width, int height)
    : width_(width),
      height_(height),
      mask_(static_cast<std::size_t>(width) * height, 0),
      slot_(static_cast<std::size_t>(width) * height, 0) {}

void LinkCutter::sort_by_cell(std::vector<std::int32_t>& cells) {
  scratch_.resize(cells.size());
  auto pass = [&](const std::vector<std::int32_t>& in, std::vector<std::int32_t>& out, int buckets,
                  auto key) {
    count_.assign(buckets + 1, 0);
    for (std::int32_t c : in) ++count_[key(c) + 1];
    for (int b = 0; b < buckets; ++b) count_[b + 1] += count_[b];
    for (std::int32_t c : in) out[count_[key(c)]++] = c;
  };
  pass(cells, scratch_, width_, [&](std::int32_t c) { return c % width_; });
  pass(scratch_, cells, height_, [&](std::int32_t c) { return c / width_; });
}

void LinkCutter::add(const CutLink& l) {
  std::uint8_t& m = mask_[l.cell];
  const auto bit = static_cast<std::uint8_t>(1u << (l.dir - 1));
  if (m & bit) return;  // already cut by an earlier segment, which keeps it
  if (m == 0) touched_.push_back(l.cell);
  m |= bit;
  raw_.push_back(l);
}

void LinkCutter::cut_segment(const Filament& fil, std::size_t k, std::int32_t segment,
                             std::vector<CutLink>& out) const {
  using d2q9::kCx;
  using d2q9::kCy;
  using d2q9::kOpp;
  constexpr double kLink = 1.4142135623730951 + 1e-9;  // longest link
  // Each undirected link is visited once from its node a, towards a + c for these directions.
  constexpr int kHalf[4] = {1, 2, 5, 6};
  const Vec2& p = fil.points[k];
  const Vec2& q = fil.points[k + 1];
  const Vec2 vp = fil.velocities.empty() ? Vec2::Zero() : fil.velocities[k];
  const Vec2 vq = fil.velocities.empty() ? Vec2::Zero() : fil.velocities[k + 1];
  const Vec2 d = q - p;
  const double len = d.norm();
  // Node a = (x + 1/2, y + 1/2) has links reaching 1 in x either way and 0..1 in y.
  const int x0 = std::max(-1, static_cast<int>(std::ceil(std::min(p.x(), q.x()) - 1.5)));
  const int x1 = std::min(width_, static_cast<int>(std::floor(std::max(p.x(), q.x()) + 0.5)));
  const int y0 = std::max(-1, static_cast<int>(std::ceil(std::min(p.y(), q.y()) - 1.5)));
  const int y1 = std::min(height_, static_cast<int>(std::floor(std::max(p.y(), q.y()) - 0.5)));
  for (int y = y0; y <= y1; ++y)
    for (int x = x0; x <= x1; ++x) {
      const Vec2 a(x + 0.5, y + 0.5);
      // Side of a relative to the segment's line (times |d|); along a link it changes
      // linearly, so each link's far end costs one add.
      const double sa = cross(d, a - p);
      // No link of a node farther than one link length from the line can cross it.
      if (std::abs(sa) > kLink * len) continue;
      for (int i : kHalf) {
        const double sb = sa + d.x() * kCy[i] - d.y() * kCx[i];
        if ((sa > 0 && sb > 0) || (sa < 0 && sb < 0)) continue;
        const int bx = x + kCx[i], by = y + kCy[i];
        double t = 0.0;
        if (!link_cut(a, Vec2(bx + 0.5, by + 0.5), p, q, &t)) continue;
        const Vec2 v = (1.0 - t) * vp + t * vq;
        const auto vx = static_cast<float>(v.x()), vy = static_cast<float>(v.y());
        // The population travelling a -> b arrives at b along i; the one b -> a at a along
        // opp(i).
        if (bx >= 0 && bx < width_ && by >= 0 && by < height_)
          out.push_back({by * width_ + bx, static_cast<std::uint8_t>(i), vx, vy, segment});
        if (x >= 0 && x < width_ && y >= 0 && y < height_)
          out.push_back({y * width_ + x, static_cast<std::uint8_t>(kOpp[i]), vx, vy, segment});
      }
    }
}

void LinkCutter::cut(const std::vector<Filament>& filaments, WorkerPool& pool,
                     std::vector<CutLink>* links, std::vector<int>* first_segment) {
  touched_.clear();
  raw_.clear();
  first_segment->assign(1, 0);
  segments_.clear();
  for (std::size_t f = 0; f < filaments.size(); ++f) {
    for (std::size_t k = 0; k + 1 < filaments[f].points.size(); ++k)
      segments_.push_back({static_cast<std::int32_t>(f), static_cast<std::int32_t>(k)});
    first_segment->push_back(static_cast<int>(segments_.size()));
  }
  // The geometry runs in parallel over chunks of segments; the chunks are then merged in
  // order, so the first segment to cut a link owns it, whatever the thread count.
  const int n = static_cast<int>(segments_.size());
  const int chunks = (n + kSegmentsPerChunk - 1) / kSegmentsPerChunk;
  if (static_cast<int>(found_.size()) < chunks) found_.resize(chunks);
  pool.run(chunks, [&](int c, int) {
    std::vector<CutLink>& out = found_[c];
    out.clear();
    for (int s = c * kSegmentsPerChunk; s < std::min(n, (c + 1) * kSegmentsPerChunk); ++s)
      cut_segment(filaments[segments_[s].first], segments_[s].second, s, out);
  });
  for (int c = 0; c < chunks; ++c)
    for (const CutLink& l : found_[c]) add(l);
  // Order by (cell, dir) without sorting the links: sort the cells, give each its offset, then
  // scatter every link to offset + rank of its direction among the cell's cut directions.
  // Two counting passes (x, then y) sort the cells in O(cells + width + height).
  sort_by_cell(touched_);
  std::int32_t offset = 0;
  for (std::int32_t cell : touched_) {
    slot_[cell] = offset;
    offset += std::popcount(mask_[cell]);
  }
  links->resize(offset);
  for (const CutLink& l : raw_) {
    const unsigned below = mask_[l.cell] & ((1u << (l.dir - 1)) - 1u);
    (*links)[slot_[l.cell] + std::popcount(below)] = l;
  }
  for (std::int32_t cell : touched_) mask_[cell] = 0;
}

}  // namespace hair25d::fluid
