#include "cover_labels.h"

#include <vector>

namespace hair25d::completion::detail {

LabelMap fringe_labels(const LabelMap& labels, int reach) {
  LabelMap out = labels;
  const int w = labels.width(), h = labels.height();
  std::vector<int> dist(static_cast<std::size_t>(w) * h, -1);
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
      if (dist[j] >= 0) continue;
      dist[j] = dist[i] + 1;
      out.data()[j] = out.data()[i];
      queue.push_back(j);
    }
  }
  return out;
}

}  // namespace hair25d::completion::detail
