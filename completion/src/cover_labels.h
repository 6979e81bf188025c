// Growing labels into unlabelled pixels: the outline assignment
// (assign_outline_pixels, dark pixels only) and the map the cover test
// reads (Context::cover_labels: the outlines' light fringe too).
#pragma once

#include <vector>

#include "hair25d/core/image.h"

namespace hair25d::completion::detail {

// `labels` with label-0 pixels that `may_take(x, y)` accepts given the
// label of the nearest labelled pixel within `reach` 4-connected steps
// (breadth first, ties to the pixel queued first, in index order), each
// step only through such pixels.
template <class MayTake>
LabelMap grow_labels(const LabelMap& labels, int reach, MayTake may_take) {
  LabelMap out = labels;
  const int w = labels.width(), h = labels.height();
  std::vector<int> dist(static_cast<std::size_t>(w) * h, -1);
  // The queue (a vector read from `head`): first every labelled pixel with
  // an unlabelled 4-neighbour, in index order; a pixel whose neighbours
  // are all labelled would add nothing, so it is left out.
  std::vector<int> queue;
  const int* in = labels.data();
  for (int i = 0; i < w * h; ++i) {
    if (in[i] == 0) continue;
    dist[i] = 0;
    const int x = i % w, y = i / w;
    if ((x > 0 && in[i - 1] == 0) || (x + 1 < w && in[i + 1] == 0) || (y > 0 && in[i - w] == 0) ||
        (y + 1 < h && in[i + w] == 0))
      queue.push_back(i);
  }
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    if (dist[i] >= reach) continue;
    const int x = i % w, y = i / w;
    static constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const int j = ny * w + nx;
      if (dist[j] >= 0 || !may_take(nx, ny)) continue;
      dist[j] = dist[i] + 1;
      out.data()[j] = out.data()[i];
      queue.push_back(j);
    }
  }
  return out;
}

// `labels` (outlines assigned) with every label-0 pixel within `reach`
// pixels of a labelled pixel given the nearest label, whatever its luma.
inline LabelMap fringe_labels(const LabelMap& labels, int reach) {
  return grow_labels(labels, reach, [](int, int) { return true; });
}

}  // namespace hair25d::completion::detail
