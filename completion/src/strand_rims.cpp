// The strands' drawn rims (private): what the background takes for hair but
// no strand shows at rest, carried by the strand that is drawn there.
#include <algorithm>
#include <cstdlib>
#include <future>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "raster.h"
#include "strand_assembly.h"

namespace hair25d::completion::detail {
namespace {

// Summed |RGBA| step above which a pixel at rest is not the drawing's; an
// anti-aliased rim pixel of the outline over the fill steps far more, an
// inpainted paper pixel over the paper not at all.
constexpr int kShownStep = 24;

bool differs(const Rgba& a, const Rgba& b) {
  constexpr int kClear = 8;  // both about transparent: their colours do not show
  if (a.a < kClear && b.a < kClear) return false;
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b) + std::abs(a.a - b.a) >
         kShownStep;
}

// Adds `points` (image pixels) to `s` as visible pixels drawn as they are,
// growing its box to hold them, and traces its outline again.
void carry(const Image& image, const std::vector<cv::Point>& points, CompletedStrand* s) {
  const cv::Rect old_box(s->origin.x(), s->origin.y(), s->mask.width(), s->mask.height());
  const cv::Rect box = old_box | cv::boundingRect(points);
  if (box != old_box) {
    LabelMap mask(box.width, box.height, 0);
    Image texture(box.width, box.height, Rgba{0, 0, 0, 0});
    for (int y = 0; y < old_box.height; ++y)
      for (int x = 0; x < old_box.width; ++x) {
        const int bx = x + old_box.x - box.x, by = y + old_box.y - box.y;
        mask.at(bx, by) = s->mask.at(x, y);
        texture.at(bx, by) = s->texture.at(x, y);
      }
    s->mask = std::move(mask);
    s->texture = std::move(texture);
    s->origin = Eigen::Vector2i(box.x, box.y);
  }
  for (const cv::Point& p : points) {
    const int x = p.x - box.x, y = p.y - box.y;
    s->texture.at(x, y) = image.at(p.x, p.y);
    if (s->mask.at(x, y) == 1) continue;
    if (s->mask.at(x, y) == 2) --s->completed_pixels;
    ++s->visible_pixels;
    s->mask.at(x, y) = 1;
  }
  s->outline = strand_outline(view(s->mask), s->origin);
}

}  // namespace

void carry_rims(const Context& ctx, const cv::Mat& holes,
                const std::vector<std::vector<int>>& groups, const Image& background,
                std::vector<CompletedStrand>* strands) {
  const LabelMap& labels = ctx.labels;
  const Image& image = *ctx.image;
  const int w = labels.width(), h = labels.height();
  if (holes.empty() || groups.empty() || strands->size() != groups.size()) return;
  int labels_end = 1;
  for (const auto& members : groups)
    for (int m : members) labels_end = std::max(labels_end, m + 1);
  std::vector<int> group_of(static_cast<std::size_t>(labels_end), -1);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (int m : groups[g])
      if (m > 0) group_of[static_cast<std::size_t>(m)] = static_cast<int>(g);
  auto group = [&](int label) {
    return label > 0 && label < labels_end ? group_of[static_cast<std::size_t>(label)] : -1;
  };
  std::vector<Occluders> occluders;
  occluders.reserve(groups.size());
  for (const auto& members : groups) occluders.emplace_back(ctx, members);

  // The region reached first from each pixel the background takes, going
  // through such pixels (4-connected, breadth first): whatever the hole
  // holds touches the hair or is enclosed by it.
  LabelMap reached(w, h, 0);
  std::vector<cv::Point> queue;
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (labels.at(x, y) != 0 || !holes.at<std::uint8_t>(y, x)) continue;
      for (const cv::Point d :
           {cv::Point(-1, 0), cv::Point(1, 0), cv::Point(0, -1), cv::Point(0, 1)}) {
        const int l = ctx.label(x + d.x, y + d.y);
        if (l != 0) {
          reached.at(x, y) = l;
          queue.emplace_back(x, y);
          break;
        }
      }
    }
  for (std::size_t k = 0; k < queue.size(); ++k) {
    const cv::Point p = queue[k];
    for (const cv::Point d :
         {cv::Point(-1, 0), cv::Point(1, 0), cv::Point(0, -1), cv::Point(0, 1)}) {
      const int x = p.x + d.x, y = p.y + d.y;
      if (x < 0 || y < 0 || x >= w || y >= h || labels.at(x, y) != 0 || reached.at(x, y) != 0 ||
          !holes.at<std::uint8_t>(y, x))
        continue;
      reached.at(x, y) = reached.at(p.x, p.y);
      queue.emplace_back(x, y);
    }
  }

  // The strand of the nearest pixel within `reach` (chessboard) of a label
  // drawn above strand g, or -1 (as build_strand's occluders' lines).
  const Options& o = *ctx.options;
  const int reach = o.occluder_reach + o.outline_reach;
  auto occluding_group = [&](int x, int y, int g) {
    int best = -1, best_d = std::numeric_limits<int>::max();
    const Occluders& above_g = occluders[static_cast<std::size_t>(g)];
    for (int dy = -reach; dy <= reach; ++dy)
      for (int dx = -reach; dx <= reach; ++dx) {
        const int u = ctx.label(x + dx, y + dy);
        if (!above_g(u)) continue;
        const int d = dx * dx + dy * dy;
        if (d < best_d && group(u) >= 0 && group(u) != g) best_d = d, best = group(u);
      }
    return best;
  };
  // What strand g's texture shows at an image pixel (transparent outside).
  auto texture_at = [&](int g, int x, int y) {
    const CompletedStrand& s = (*strands)[static_cast<std::size_t>(g)];
    const int tx = x - s.origin.x(), ty = y - s.origin.y();
    if (tx < 0 || ty < 0 || tx >= s.texture.width() || ty >= s.texture.height())
      return Rgba{0, 0, 0, 0};
    return s.texture.at(tx, ty);
  };

  // The rows in two halves, one per worker, each with its own lists.
  auto rows = [&](int y0, int y1) {
    std::vector<std::vector<cv::Point>> rims(groups.size());
    for (int y = y0; y < y1; ++y)
      for (int x = 0; x < w; ++x) {
        const int l = labels.at(x, y);
        const Rgba& drawn = image.at(x, y);
        int g = -1;
        if (l == 0) {
          // Taken by the background, held by no region, filled otherwise:
          // the strand of the region reached first.
          if (!holes.at<std::uint8_t>(y, x) || !differs(background.at(x, y), drawn)) continue;
          g = group(reached.at(x, y));
        } else if (ctx.original->at(x, y) == 0) {
          // An outline pixel given to a region whose strand paints it over:
          // an occluder's line, or the face's along back hair (the face lies
          // in the background, behind every strand, so the strand keeps it).
          g = group(l);
          if (g >= 0 && !differs(texture_at(g, x, y), drawn)) g = -1;
        }
        if (g < 0) continue;
        const int front = occluding_group(x, y, g);
        rims[static_cast<std::size_t>(front >= 0 ? front : g)].emplace_back(x, y);
      }
    return rims;
  };
  std::vector<std::vector<cv::Point>> rims;
  if (o.threads > 1 && h > 1) {
    auto lower = std::async(std::launch::async, rows, h / 2, h);
    rims = rows(0, h / 2);
    auto rest = lower.get();
    for (std::size_t g = 0; g < rims.size(); ++g)
      rims[g].insert(rims[g].end(), rest[g].begin(), rest[g].end());
  } else {
    rims = rows(0, h);
  }
  for (std::size_t g = 0; g < rims.size(); ++g)
    if (!rims[g].empty()) carry(image, rims[g], &(*strands)[g]);
}

}  // namespace hair25d::completion::detail
