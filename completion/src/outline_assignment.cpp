#include <vector>

#include "hair25d/completion/completion.h"
#include "hair25d/core/error.h"
#include "raster.h"

namespace hair25d::completion {

LabelMap assign_outline_pixels(const Image& image, const LabelMap& regions, int reach,
                               int dark_luma) {
  detail::require_image_size("completion::assign_outline_pixels", "regions are", regions, image);
  LabelMap out = regions;
  const int w = regions.width(), h = regions.height();
  std::vector<int> dist(static_cast<std::size_t>(w) * h, -1);
  // The queue (a vector read from `head`): first every region pixel with an
  // unlabelled 4-neighbour, in index order; a region pixel whose neighbours
  // are all labelled would add nothing, so it is left out.
  std::vector<int> queue;
  const int* in = regions.data();
  for (int i = 0; i < w * h; ++i) {
    if (in[i] == 0) continue;
    dist[i] = 0;
    const int x = i % w, y = i / w;
    if ((x > 0 && in[i - 1] == 0) || (x + 1 < w && in[i + 1] == 0) || (y > 0 && in[i - w] == 0) ||
        (y + 1 < h && in[i + w] == 0))
      queue.push_back(i);
  }
  // Breadth-first growth: an outline pixel between two regions goes to the
  // one it is nearer to, so the line is split down its middle.
  for (std::size_t head = 0; head < queue.size(); ++head) {
    const int i = queue[head];
    if (dist[i] >= reach) continue;
    const int x = i % w, y = i / w;
    static constexpr int kDx[4] = {1, -1, 0, 0}, kDy[4] = {0, 0, 1, -1};
    for (int k = 0; k < 4; ++k) {
      const int nx = x + kDx[k], ny = y + kDy[k];
      if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
      const int j = ny * w + nx;
      if (dist[j] >= 0 || detail::luma(image.at(nx, ny)) >= dark_luma) continue;
      dist[j] = dist[i] + 1;
      out.data()[j] = out.data()[i];
      queue.push_back(j);
    }
  }
  return out;
}

}  // namespace hair25d::completion
