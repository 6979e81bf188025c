#include "patch_model.h"

#include <cmath>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::layering::detail {

Patch junction_patch(const LabelMap& labels, const Vec2& centre, const Vec2& direction, int a,
                     int b, bool a_on_left, double radius) {
  if (!(std::isfinite(radius) && radius > 0))
    throw Error("layering::junction_patch: radius = " + std::to_string(radius) +
                "; must be finite and > 0");
  const double norm = direction.norm();
  if (!(std::isfinite(norm) && norm > 0))
    throw Error("layering::junction_patch: direction (" + std::to_string(direction.x()) + ", " +
                std::to_string(direction.y()) + ") must be a finite non-zero vector");
  const Vec2 u = direction / norm;
  // On the screen (y down) the left of travel u is (u.y, −u.x).
  const Vec2 left(u.y(), -u.x());
  const Vec2 v = a_on_left ? left : Vec2(-left);
  Patch p{};
  for (int scale = 0; scale < kPatchScales; ++scale) {
    const double r = scale == 0 ? radius : kPatchWide * radius;
    const double cell = 2 * r / kPatchCells;
    for (int j = 0; j < kPatchCells; ++j) {
      for (int i = 0; i < kPatchCells; ++i) {
        float diff = 0, other = 0;
        for (int sj = 0; sj < 2; ++sj) {
          for (int si = 0; si < 2; ++si) {
            const double cu = -r + (i + 0.25 + 0.5 * si) * cell;
            const double cv = -r + (j + 0.25 + 0.5 * sj) * cell;
            const Vec2 q = centre + cu * u + cv * v;
            const int x = static_cast<int>(std::floor(q.x()));
            const int y = static_cast<int>(std::floor(q.y()));
            if (!labels.contains(x, y)) continue;
            const int l = labels.at(x, y);
            if (l == a)
              diff += 0.25f;
            else if (l == b)
              diff -= 0.25f;
            else if (l > 0)
              other += 0.25f;
          }
        }
        const int k = scale * kPatchScaleInputs + (j * kPatchCells + i) * kPatchChannels;
        p[k] = diff;
        p[k + 1] = other;
      }
    }
  }
  return p;
}

Patch swapped(const Patch& patch) {
  Patch s{};
  for (int scale = 0; scale < kPatchScales; ++scale)
    for (int j = 0; j < kPatchCells; ++j)
      for (int i = 0; i < kPatchCells; ++i) {
        const int base = scale * kPatchScaleInputs;
        const int from = base + (j * kPatchCells + i) * kPatchChannels;
        const int to = base + ((kPatchCells - 1 - j) * kPatchCells + i) * kPatchChannels;
        s[to] = -patch[from];
        s[to + 1] = patch[from + 1];
      }
  return s;
}

double patch_radius(double reach) { return reach; }

double patch_net(const PatchNet& net, const Patch& patch) {
  // Most cells are background or one region on the fine scale's far side:
  // only non-zero inputs are added, each into all hidden sums at once.
  std::array<float, kPatchHidden> sum = net.b1;
  for (int k = 0; k < kPatchInputs; ++k) {
    const float x = patch[k];
    if (x == 0) continue;
    const std::array<float, kPatchHidden>& w = net.w1[k];
    for (int h = 0; h < kPatchHidden; ++h) sum[h] += w[h] * x;
  }
  // β (1 − e^{−αx}) / (1 + e^{−αx}), written so that it cannot overflow.
  auto activation = [&](double x) { return net.beta * std::tanh(0.5 * net.alpha * x); };
  double out = net.b2;
  for (int h = 0; h < kPatchHidden; ++h) out += net.w2[h] * activation(sum[h]);
  return activation(out);
}

double patch_score(const PatchNet& net, const Patch& patch) {
  return patch_net(net, patch) - patch_net(net, swapped(patch));
}

double patch_same_score(const PatchNet& net, const Patch& patch) {
  return patch_net(net, patch) + patch_net(net, swapped(patch));
}

std::vector<Patch> boundary_patches(const LabelMap& labels, const BoundaryGraph& graph,
                                    const Boundary& b, const Vec2& start_direction,
                                    const Vec2& end_direction, double radius) {
  std::vector<Patch> out;
  if (b.closed() || b.points.empty()) return out;
  // Walking away from the start, b.left is on the left; away from the end,
  // on the right.
  if (start_direction.squaredNorm() > 0)
    out.push_back(junction_patch(labels, graph.junctions[b.start].position, start_direction, b.left,
                                 b.right, true, radius));
  if (end_direction.squaredNorm() > 0)
    out.push_back(junction_patch(labels, graph.junctions[b.end].position, end_direction, b.left,
                                 b.right, false, radius));
  return out;
}

}  // namespace hair25d::layering::detail
