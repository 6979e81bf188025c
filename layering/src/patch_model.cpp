#include "patch_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <string>

#include "hair25d/core/error.h"

namespace hair25d::layering::detail {

namespace {

// The grey level of a pixel as the line measurements read it (Rec. 601).
float grey_at(const Image& image, int x, int y) {
  const Rgba& c = image.at(x, y);
  return 0.299f * c.r + 0.587f * c.g + 0.114f * c.b;
}

}  // namespace

Patch junction_patch(const LabelMap& labels, const PatchImage& drawing, const Vec2& centre,
                     const Vec2& direction, int a, int b, bool a_on_left, double radius) {
  if (!(std::isfinite(radius) && radius > 0))
    throw Error("layering::junction_patch: radius = " + std::to_string(radius) +
                "; must be finite and > 0");
  const double norm = direction.norm();
  if (!(std::isfinite(norm) && norm > 0))
    throw Error("layering::junction_patch: direction (" + std::to_string(direction.x()) + ", " +
                std::to_string(direction.y()) + ") must be a finite non-zero vector");
  if (!(centre.allFinite() && centre.cwiseAbs().maxCoeff() < 1e8 && radius < 1e6))
    throw Error("layering::junction_patch: centre (" + std::to_string(centre.x()) + ", " +
                std::to_string(centre.y()) + ") and radius " + std::to_string(radius) +
                " must lie within 1e8 and 1e6 pixels");
  const Image* image = drawing.image;
  if (image != nullptr && (image->width() != labels.width() || image->height() != labels.height()))
    throw Error("layering::junction_patch: image " + std::to_string(image->width()) + " x " +
                std::to_string(image->height()) + " must be the label map's size " +
                std::to_string(labels.width()) + " x " + std::to_string(labels.height()));
  if (image != nullptr && !(std::isfinite(drawing.contrast) && drawing.contrast > 0))
    throw Error("layering::junction_patch: contrast = " + std::to_string(drawing.contrast) +
                "; must be finite and > 0");
  const Vec2 u = direction / norm;
  // On the screen (y down) the left of travel u is (u.y, −u.x).
  const Vec2 left(u.y(), -u.x());
  const Vec2 v = a_on_left ? left : Vec2(-left);
  Patch p{};
  // Grey sums of the first scale's cells and their sample counts (samples
  // outside the image are left out).
  std::array<float, kPatchGreyInputs> grey{};
  std::array<std::uint8_t, kPatchGreyInputs> counted{};
  // Sample offsets along u and v, products taken once: each sample point is
  // then (centre + cu·u) + cv·v, the same sums as written out per sample.
  constexpr int kSamples = 2 * kPatchCells;
  std::array<double, kSamples> ax{}, ay{}, bx{}, by{};
  for (int scale = 0; scale < kPatchScales; ++scale) {
    const double r = scale == 0 ? radius : kPatchWide * radius;
    const double cell = 2 * r / kPatchCells;
    for (int k = 0; k < kSamples; ++k) {
      const double c = -r + (k / 2 + 0.25 + 0.5 * (k % 2)) * cell;
      ax[k] = centre.x() + c * u.x();
      ay[k] = centre.y() + c * u.y();
      bx[k] = c * v.x();
      by[k] = c * v.y();
    }
    float* out = p.data() + scale * kPatchScaleInputs;
    auto add = [&](float* c, int l) {
      if (l == a)
        c[0] += 0.25f;
      else if (l == b)
        c[0] -= 0.25f;
      else if (l > 0)
        c[1] += 0.25f;
    };
    const auto [ax0, ax1] = std::minmax_element(ax.begin(), ax.end());
    const auto [ay0, ay1] = std::minmax_element(ay.begin(), ay.end());
    const auto [bx0, bx1] = std::minmax_element(bx.begin(), bx.end());
    const auto [by0, by1] = std::minmax_element(by.begin(), by.end());
    // Every sample a pixel or more inside the map (most junctions): no
    // bounds checks, and truncation is the floor of a positive value.
    const bool inside = *ax0 + *bx0 >= 1 && *ay0 + *by0 >= 1 && *ax1 + *bx1 < labels.width() - 1 &&
                        *ay1 + *by1 < labels.height() - 1;
    const bool with_grey = scale == 0 && image != nullptr;
    for (int sj = 0; sj < kSamples; ++sj) {
      float* row = out + (sj / 2) * kPatchCells * kPatchChannels;
      float* grey_row = grey.data() + (sj / 2) * kPatchCells;
      std::uint8_t* count_row = counted.data() + (sj / 2) * kPatchCells;
      if (inside && with_grey) {
        // Rows of the map and the image read straight from their data.
        const int* label_data = labels.data();
        const Rgba* pixels = image->data();
        const std::ptrdiff_t w = labels.width();
        for (int si = 0; si < kSamples; ++si) {
          const int x = static_cast<int>(ax[si] + bx[sj]);
          const int y = static_cast<int>(ay[si] + by[sj]);
          const std::ptrdiff_t at = y * w + x;
          add(row + (si / 2) * kPatchChannels, label_data[at]);
          const Rgba& c = pixels[at];
          grey_row[si / 2] += 0.299f * c.r + 0.587f * c.g + 0.114f * c.b;
        }
        for (int i = 0; i < kPatchCells; ++i) count_row[i] += 2;
        continue;
      }
      if (inside) {
        for (int si = 0; si < kSamples; ++si) {
          const int x = static_cast<int>(ax[si] + bx[sj]);
          const int y = static_cast<int>(ay[si] + by[sj]);
          add(row + (si / 2) * kPatchChannels, labels.at(x, y));
        }
        continue;
      }
      for (int si = 0; si < kSamples; ++si) {
        const double qx = ax[si] + bx[sj];
        const double qy = ay[si] + by[sj];
        // floor without a library call (the values are within 1e8)
        int x = static_cast<int>(qx), y = static_cast<int>(qy);
        x -= qx < x;
        y -= qy < y;
        if (!labels.contains(x, y)) continue;
        add(row + (si / 2) * kPatchChannels, labels.at(x, y));
        if (with_grey) grey_row[si / 2] += grey_at(*image, x, y), ++count_row[si / 2];
      }
    }
  }
  if (image == nullptr) return p;
  // Darkness below the brightest of the 3 × 3 cells about each cell, as a
  // bar detector reads a line against the paint on both sides (a flat tone
  // reads 0 however dark; cells wholly outside the image are left out).
  std::array<float, kPatchGreyInputs> mean{}, across{};
  for (int c = 0; c < kPatchGreyInputs; ++c)
    mean[c] = counted[c] > 0 ? grey[c] / counted[c] : -1.0f;
  // The 3 × 3 maximum as a maximum along rows, then down columns (exact, so
  // the same as over the nine cells at once; uncounted cells never win).
  for (int j = 0; j < kPatchCells; ++j) {
    const float* m = mean.data() + j * kPatchCells;
    float* a = across.data() + j * kPatchCells;
    for (int i = 0; i < kPatchCells; ++i) {
      float v = m[i];
      if (i > 0) v = std::max(v, m[i - 1]);
      if (i + 1 < kPatchCells) v = std::max(v, m[i + 1]);
      a[i] = v;
    }
  }
  const float scale = static_cast<float>(1.0 / drawing.contrast);
  float* dark = p.data() + kPatchLabelInputs;
  for (int j = 0; j < kPatchCells; ++j)
    for (int i = 0; i < kPatchCells; ++i) {
      const int c = j * kPatchCells + i;
      if (counted[c] == 0) continue;
      float bright = across[c];
      if (j > 0) bright = std::max(bright, across[c - kPatchCells]);
      if (j + 1 < kPatchCells) bright = std::max(bright, across[c + kPatchCells]);
      dark[c] = std::min((bright - mean[c]) * scale, 2.0f);
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
  for (int j = 0; j < kPatchCells; ++j)
    for (int i = 0; i < kPatchCells; ++i)
      s[kPatchLabelInputs + (kPatchCells - 1 - j) * kPatchCells + i] =
          patch[kPatchLabelInputs + j * kPatchCells + i];
  return s;
}

double patch_radius(double reach) { return reach; }

double patch_contrast(double line_threshold) { return 2.5 * line_threshold; }

// Two clones, chosen when the library loads: AVX2 adds the 16 hidden sums
// eight at a time. Neither has fused multiply-adds, so each lane does the
// same product and sum as the other clone and the scores are the same.
__attribute__((target_clones("avx2", "default"))) double patch_net(const PatchNet& net,
                                                                   const Patch& patch, int inputs) {
  // Most cells are background or one region on the fine scale's far side:
  // only non-zero inputs are added, each into all hidden sums at once.
  std::array<float, kPatchHidden> sum = net.b1;
  for (int k = 0; k < inputs; ++k) {
    const float x = patch[k];
    if (x == 0) continue;
    const std::array<float, kPatchHidden>& w = net.w1[k];
    for (int h = 0; h < kPatchHidden; ++h) sum[h] += w[h] * x;
  }
  // β (1 − e^{−αx}) / (1 + e^{−αx}), written so that it cannot overflow.
  auto activation = [&](double x) { return net.beta * std::tanh(0.5 * net.alpha * x); };
  double total = 0.0;
  for (int m = 0; m < kPatchMembers; ++m) {
    double out = net.b2[m];
    for (int h = m * kPatchMemberHidden; h < (m + 1) * kPatchMemberHidden; ++h)
      out += net.w2[h] * activation(sum[h]);
    total += activation(out);
  }
  return total;
}

double patch_score(const PatchNet& net, const Patch& patch) {
  return patch_net(net, patch) - patch_net(net, swapped(patch));
}

double patch_same_score(const PatchNet& net, const Patch& patch) {
  return patch_net(net, patch) + patch_net(net, swapped(patch));
}

int patch_inputs_used(const PatchNet& net) {
  int used = 0;
  for (int k = 0; k < kPatchInputs; ++k)
    for (float w : net.w1[k])
      if (w != 0) used = k + 1;
  return used;
}

PatchScores patch_scores(const PatchNet& order, int order_inputs, const PatchNet& same,
                         const Patch& patch) {
  const Patch other = swapped(patch);
  return {patch_net(order, patch, order_inputs) - patch_net(order, other, order_inputs),
          patch_net(same, patch) + patch_net(same, other)};
}

std::vector<Patch> boundary_patches(const LabelMap& labels, const PatchImage& drawing,
                                    const BoundaryGraph& graph, const Boundary& b,
                                    const Vec2& start_direction, const Vec2& end_direction,
                                    double radius) {
  std::vector<Patch> out;
  if (b.closed() || b.points.empty()) return out;
  // Walking away from the start, b.left is on the left; away from the end,
  // on the right.
  if (start_direction.squaredNorm() > 0)
    out.push_back(junction_patch(labels, drawing, graph.junctions[b.start].position,
                                 start_direction, b.left, b.right, true, radius));
  if (end_direction.squaredNorm() > 0)
    out.push_back(junction_patch(labels, drawing, graph.junctions[b.end].position, end_direction,
                                 b.left, b.right, false, radius));
  return out;
}

}  // namespace hair25d::layering::detail
