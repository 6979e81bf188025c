// Outline pixels are 0 in an annotation's regions.png; giving each to its
// nearest region puts the boundary between two regions in the middle of the
// drawn line, which is where the junction geometry of §4.2 is measured.
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>

#include "hair25d/core/error.h"
#include "hair25d/layering/boundary_graph.h"

namespace hair25d::layering {
namespace {

// Chamfer steps in fifths of a pixel: 5 across an edge, 7 across a corner.
constexpr int kOrtho = 5;
constexpr int kDiag = 7;
constexpr int kUnit = 5;
constexpr double kMaxReach = 7.0;  // pixels grown at most: outlines up to ~14 px wide

struct Growth {
  std::vector<std::uint16_t> dist;  // chamfer distance (fifths of a pixel) to the nearest region
  std::vector<int> owner;           // its label, 0 if unreachable
};

// Dial's algorithm: a multi-source shortest path on the 8-neighbour grid with a
// ring of buckets, linear in the pixel count.
Growth grow(const LabelMap& labels, int limit) {
  const int w = labels.width();
  const int h = labels.height();
  const std::size_t n = labels.size();
  // 16-bit distances halve the memory traffic of the relaxation; the growth
  // limit keeps them far below the maximum.
  Growth g{std::vector<std::uint16_t>(n, std::numeric_limits<std::uint16_t>::max()),
           std::vector<int>(n, 0)};
  std::array<std::vector<int>, kDiag + 1> ring;
  const int* lab = labels.data();
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      if (lab[i] == 0) continue;
      g.dist[i] = 0;
      g.owner[i] = lab[i];
      // Only region pixels on the edge of label 0 start a front.
      const bool edge = (x > 0 && lab[i - 1] == 0) || (x + 1 < w && lab[i + 1] == 0) ||
                        (y > 0 && lab[i - w] == 0) || (y + 1 < h && lab[i + w] == 0) ||
                        (x > 0 && y > 0 && lab[i - w - 1] == 0) ||
                        (x + 1 < w && y > 0 && lab[i - w + 1] == 0) ||
                        (x > 0 && y + 1 < h && lab[i + w - 1] == 0) ||
                        (x + 1 < w && y + 1 < h && lab[i + w + 1] == 0);
      if (edge) ring[0].push_back(i);
    }
  }
  static constexpr std::array<int, 8> kNx = {1, -1, 0, 0, 1, 1, -1, -1};
  static constexpr std::array<int, 8> kNy = {0, 0, 1, -1, 1, -1, 1, -1};
  std::size_t pending = ring[0].size();
  for (int d = 0; pending > 0; ++d) {
    auto& bucket = ring[d % ring.size()];
    // Entries may be added to this bucket while it is processed only with
    // weight 0, which never happens, so iterating by index is safe.
    for (std::size_t k = 0; k < bucket.size(); ++k) {
      const int i = bucket[k];
      --pending;
      if (g.dist[i] != d) continue;  // a stale entry
      const int x = i % w;
      const int y = i / w;
      for (int m = 0; m < 8; ++m) {
        const int nx = x + kNx[m];
        const int ny = y + kNy[m];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const int j = ny * w + nx;
        if (lab[j] != 0) continue;  // regions are sources, never grown into
        const int nd = d + (m < 4 ? kOrtho : kDiag);
        if (nd <= limit && nd < g.dist[j]) {
          g.dist[j] = static_cast<std::uint16_t>(nd);
          g.owner[j] = g.owner[i];
          ring[nd % ring.size()].push_back(j);
          ++pending;
        }
      }
    }
    bucket.clear();
  }
  return g;
}

}  // namespace

bool OutlineFillOptions::is_valid(std::string* error) const {
  if (!std::isfinite(max_distance)) {
    if (error)
      *error =
          "OutlineFillOptions::max_distance = " + std::to_string(max_distance) + "; must be finite";
    return false;
  }
  return true;
}

OutlineFill fill_outlines(const LabelMap& labels, const OutlineFillOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error("layering: " + why);
  if (labels.empty()) throw Error("layering: label map is empty; need at least one pixel");
  const int w = labels.width();
  // Lines wider than this are not outlines but background gaps; growing no
  // farther keeps the cost to a band around the regions.
  const double reach = options.max_distance > 0 ? options.max_distance : kMaxReach;
  const int limit = static_cast<int>(std::ceil(std::min(reach * kUnit, 60000.0)));
  const Growth g = grow(labels, limit);

  // Where fronts of two regions meet inside label-0 pixels, each side has come
  // about half a line width: the typical meeting distance measures the lines.
  std::vector<int> meet;
  for (int y = 0; y < labels.height(); ++y) {
    for (int x = 0; x < w; ++x) {
      const int i = y * w + x;
      if (labels.data()[i] != 0 || g.owner[i] == 0) continue;
      for (int j : {x + 1 < w ? i + 1 : -1, y + 1 < labels.height() ? i + w : -1}) {
        if (j < 0 || labels.data()[j] != 0 || g.owner[j] == 0 || g.owner[j] == g.owner[i]) continue;
        meet.push_back(std::max(g.dist[i], g.dist[j]));
      }
    }
  }
  OutlineFill out;
  if (!meet.empty()) {
    auto mid = meet.begin() + static_cast<std::ptrdiff_t>(meet.size() / 2);
    std::nth_element(meet.begin(), mid, meet.end());
    // A line w pixels wide is met at about w/2 from each side.
    out.line_width = std::max(1.0, 2.0 * (*mid) / kUnit - 1.0);
  }
  out.radius = options.max_distance > 0 ? options.max_distance
                                        : (out.line_width > 0 ? out.line_width + 1.5 : 0.0);
  out.radius = std::min(out.radius, static_cast<double>(limit) / kUnit);
  out.labels = labels;
  const int radius = static_cast<int>(std::floor(out.radius * kUnit));
  for (std::size_t i = 0; i < labels.size(); ++i)
    if (labels.data()[i] == 0 && g.owner[i] != 0 && g.dist[i] <= radius)
      out.labels.data()[i] = g.owner[i];
  return out;
}

}  // namespace hair25d::layering
