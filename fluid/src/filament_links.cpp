// Which lattice links each filament segment cuts.
//
// Why link bounce-back rather than an immersed boundary: bounce-back on every cut link makes
// the filament exactly impermeable (no population ever crosses it, whatever its angle),
// conserves mass for a wall at rest and gives the force by momentum exchange on the same
// links, at the cost of O(length) work per segment per step. An immersed boundary spreads
// the wall over ~2 cells, so a zero-thickness plate leaks unless the coupling is iterated.
#include <algorithm>
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

std::vector<CutLink> cut_links(const std::vector<Filament>& filaments, int width, int height,
                               std::vector<int>* first_segment) {
  using d2q9::kCx;
  using d2q9::kCy;
  using d2q9::kOpp;
  std::vector<CutLink> links;
  first_segment->assign(1, 0);
  int segment = 0;
  // Each undirected link is visited once from its node a, towards a + c for these directions.
  constexpr int kHalf[4] = {1, 2, 5, 6};
  for (const Filament& fil : filaments) {
    for (std::size_t k = 0; k + 1 < fil.points.size(); ++k, ++segment) {
      const Vec2& p = fil.points[k];
      const Vec2& q = fil.points[k + 1];
      const Vec2 vp = fil.velocities.empty() ? Vec2::Zero() : fil.velocities[k];
      const Vec2 vq = fil.velocities.empty() ? Vec2::Zero() : fil.velocities[k + 1];
      // Nodes sit at cell + 0.5; a link from node a reaches one cell further.
      const int x0 = std::max(-1, static_cast<int>(std::floor(std::min(p.x(), q.x()) - 1.5)));
      const int x1 = std::min(width, static_cast<int>(std::ceil(std::max(p.x(), q.x()) + 0.5)));
      const int y0 = std::max(-1, static_cast<int>(std::floor(std::min(p.y(), q.y()) - 1.5)));
      const int y1 = std::min(height, static_cast<int>(std::ceil(std::max(p.y(), q.y()) + 0.5)));
      for (int y = y0; y <= y1; ++y)
        for (int x = x0; x <= x1; ++x) {
          const Vec2 a(x + 0.5, y + 0.5);
          for (int i : kHalf) {
            const int bx = x + kCx[i], by = y + kCy[i];
            const Vec2 b(bx + 0.5, by + 0.5);
            double t = 0.0;
            if (!link_cut(a, b, p, q, &t)) continue;
            const Vec2 v = (1.0 - t) * vp + t * vq;
            // The population travelling a -> b arrives at b along i; the one b -> a at a along
            // opp(i).
            if (bx >= 0 && bx < width && by >= 0 && by < height)
              links.push_back(
                  {by * width + bx, static_cast<std::uint8_t>(i), v.x(), v.y(), segment});
            if (x >= 0 && x < width && y >= 0 && y < height)
              links.push_back(
                  {y * width + x, static_cast<std::uint8_t>(kOpp[i]), v.x(), v.y(), segment});
          }
        }
    }
    first_segment->push_back(segment);
  }
  // A link cut by two segments (at a shared node, or where filaments cross) bounces once;
  // stable sort keeps the first segment as its owner.
  std::stable_sort(links.begin(), links.end(), [](const CutLink& l, const CutLink& r) {
    return l.cell != r.cell ? l.cell < r.cell : l.dir < r.dir;
  });
  links.erase(std::unique(links.begin(), links.end(),
                          [](const CutLink& l, const CutLink& r) {
                            return l.cell == r.cell && l.dir == r.dir;
                          }),
              links.end());
  return links;
}

}  // namespace hair25d::fluid
