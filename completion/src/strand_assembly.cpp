#include "strand_assembly.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <future>
#include <map>
#include <mutex>
#include <opencv2/imgproc.hpp>

#include "hair25d/completion/inpaint.h"
#include "raster.h"

namespace hair25d::completion::detail {
namespace {

cv::Rect polygon_box(const Polyline& poly) {
  double x0 = 1e18, y0 = 1e18, x1 = -1e18, y1 = -1e18;
  for (const Vec2& p : poly) {
    x0 = std::min(x0, p.x()), y0 = std::min(y0, p.y());
    x1 = std::max(x1, p.x()), y1 = std::max(y1, p.y());
  }
  const int ix0 = static_cast<int>(std::floor(x0)), iy0 = static_cast<int>(std::floor(y0));
  return {ix0, iy0, static_cast<int>(std::ceil(x1)) - ix0 + 1,
          static_cast<int>(std::ceil(y1)) - iy0 + 1};
}

CompletedStrand build_strand(const Context& ctx, const std::vector<int>& members,
                             const std::vector<const PieceArea*>& areas,
                             std::vector<EdgeReport>* reports, InpaintResult* inpainted) {
  const Options& o = *ctx.options;
  const cv::Rect image_rect(0, 0, ctx.labels.width(), ctx.labels.height());
  cv::Rect box;
  for (int m : members) box = box.area() == 0 ? ctx.regions.at(m).box : box | ctx.regions.at(m).box;
  for (const PieceArea* a : areas) box |= polygon_box(a->polygon);
  const int pad = o.inpaint.patch_radius + 1;
  box = cv::Rect(box.x - pad, box.y - pad, box.width + 2 * pad, box.height + 2 * pad) & image_rect;

  const Occluders occluded_by_any(ctx, members);
  CompletedStrand s;
  s.regions = members;
  std::sort(s.regions.begin(), s.regions.end());
  s.origin = Eigen::Vector2i(box.x, box.y);
  cv::Mat mask(box.height, box.width, CV_8U, cv::Scalar(0));
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const int l = ctx.labels.at(x + box.x, y + box.y);
      if (l != 0 && std::find(members.begin(), members.end(), l) != members.end())
        mask.at<std::uint8_t>(y, x) = 1;
    }
  // Completed areas count only where an occluder of the strand is drawn: the
  // completed part never shows where the drawing is visible.
  Vec2 root_sum(0, 0);
  int root_count = 0;
  cv::Mat area(box.height, box.width, CV_8U, cv::Scalar(0));
  const cv::Rect crop(0, 0, box.width, box.height);
  for (const PieceArea* a : areas) {
    // The polygon paints within its box (and a pixel round it, for the
    // rounding): only that part is cleared before and scanned after.
    cv::Rect part = polygon_box(a->polygon);
    part = cv::Rect(part.x - box.x - 2, part.y - box.y - 2, part.width + 4, part.height + 4) & crop;
    fill_polygon(area, a->polygon, box.tl(), 1);
    int added = 0;
    for (int y = part.y; y < part.y + part.height; ++y)
      for (int x = part.x; x < part.x + part.width; ++x) {
        if (!area.at<std::uint8_t>(y, x) || mask.at<std::uint8_t>(y, x) == 1) continue;
        // Nothing drawn hides it where the sheet is transparent.
        if (ctx.image->at(x + box.x, y + box.y).a < 128) continue;
        const bool behind_face =
            a->face != nullptr && a->face->at<std::uint8_t>(y + box.y, x + box.x) != 0;
        if (!behind_face && !occluded_by_any(ctx.labels.at(x + box.x, y + box.y))) continue;
        if (mask.at<std::uint8_t>(y, x) == 0) ++added;
        mask.at<std::uint8_t>(y, x) = 2;
        if (a->root) root_sum += Vec2(x + box.x + 0.5, y + box.y + 0.5), ++root_count;
      }
    area(part).setTo(0);
    if (a->edge >= 0 && a->edge < static_cast<int>(reports->size()))
      (*reports)[a->edge].hidden_pixels += added;
  }
  if (root_count > 0) s.root_hint = root_sum / root_count;

  s.outline = strand_outline(mask, s.origin);
  s.body = s.outline;

  // Texture: the drawing, with the hidden part and the occluders' outlines
  // along it synthesised from the strand's own visible pixels.
  s.texture = Image(box.width, box.height);
  LabelMap fill(box.width, box.height), source(box.width, box.height);
  const int line_reach = o.occluder_reach + o.outline_reach;
  // A strand completed behind the face: the face's outline along it is an
  // occluder's line too, not the strand's texture.
  const cv::Mat* face = nullptr;
  for (const PieceArea* a : areas)
    if (a->face != nullptr) face = a->face;
  auto on_face = [&](int x, int y) {
    return face != nullptr && x >= 0 && y >= 0 && x < face->cols && y < face->rows &&
           face->at<std::uint8_t>(y, x) != 0;
  };
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const int m = mask.at<std::uint8_t>(y, x);
      const int gx = x + box.x, gy = y + box.y;
      Rgba c = ctx.image->at(gx, gy);
      // The visible part keeps the drawing's alpha (a transparent sheet
      // stays transparent at rest); the completed part is opaque.
      if (m != 1) c.a = m ? 255 : 0;
      s.texture.at(x, y) = c;
      if (m == 2) {
        fill.at(x, y) = 1;
        ++s.completed_pixels;
      } else if (m == 1) {
        ++s.visible_pixels;
        bool occluder_line = false;
        if (ctx.original->at(gx, gy) == 0) {
          for (int dy = -line_reach; dy <= line_reach && !occluder_line; ++dy)
            for (int dx = -line_reach; dx <= line_reach; ++dx)
              if (occluded_by_any(ctx.label(gx + dx, gy + dy)) || on_face(gx + dx, gy + dy)) {
                occluder_line = true;
                break;
              }
        }
        if (occluder_line)
          fill.at(x, y) = 1;
        else if (c.a != 0)  // transparent paper gives no texture to copy
          source.at(x, y) = 1;
      }
    }
  bool any_fill = false;
  for (std::size_t i = 0; i < fill.size() && !any_fill; ++i) any_fill = fill.data()[i] != 0;
  if (any_fill && o.inpaint_strands) {
    const InpaintResult r = inpaint_cel(s.texture, fill, source, o.inpaint);
    inpainted->filled += r.filled;
    inpainted->patches += r.patches;
    inpainted->unfilled += r.unfilled;
  }
  // The occluders' lines inpainted along the visible part keep the drawing's
  // alpha too (their anti-aliased rim over a transparent sheet).
  // Behind the face the completed part is the strand's shape but shows
  // nothing: the face is drawn in the background, below every strand, and
  // the strand's texture over it hid the face at rest.
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) {
      const int m = mask.at<std::uint8_t>(y, x), gx = x + box.x, gy = y + box.y;
      if (m == 1)
        s.texture.at(x, y).a = ctx.image->at(gx, gy).a;
      else if (m == 2 && on_face(gx, gy) && !occluded_by_any(ctx.labels.at(gx, gy)))
        s.texture.at(x, y).a = 0;
    }
  s.mask = LabelMap(box.width, box.height);
  for (int y = 0; y < box.height; ++y)
    for (int x = 0; x < box.width; ++x) s.mask.at(x, y) = mask.at<std::uint8_t>(y, x);
  return s;
}

}  // namespace

Polyline strand_outline(const cv::Mat& mask, const Eigen::Vector2i& origin) {
  Polyline outline;
  const auto contours = outer_contours(mask > 0);
  if (!contours.empty() && contours.front().size() >= 3) {
    std::vector<cv::Point> simple;
    cv::approxPolyDP(contours.front(), simple, 0.7, true);
    if (simple.size() < 3) simple = contours.front();
    for (const cv::Point& p : simple)
      outline.emplace_back(p.x + origin.x() + 0.5, p.y + origin.y() + 0.5);
  }
  return outline;
}

namespace {

// The strands, largest boxes first: two workers each take the next strand, so
// that one big strand does not leave the other worker idle at the end.
std::vector<std::size_t> largest_first(const Context& ctx, const StrandPieces& pieces) {
  const std::size_t n = pieces.groups.size();
  std::vector<std::size_t> order(n);
  std::vector<long> area(n, 0);
  for (std::size_t g = 0; g < n; ++g) {
    order[g] = g;
    cv::Rect box;
    for (int m : pieces.groups[g])
      box = box.area() == 0 ? ctx.regions.at(m).box : box | ctx.regions.at(m).box;
    area[g] = box.area();
  }
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return area[a] > area[b]; });
  return order;
}

void add_counts(const InpaintResult (&counts)[2], InpaintResult* inpainted) {
  for (const InpaintResult& c : counts) {
    inpainted->filled += c.filled;
    inpainted->patches += c.patches;
    inpainted->unfilled += c.unfilled;
  }
}

}  // namespace

std::vector<CompletedStrand> assemble_strands(const Context& ctx, const StrandPieces& pieces,
                                              std::vector<EdgeReport>* reports,
                                              InpaintResult* inpainted) {
  const std::size_t n = pieces.groups.size();
  std::vector<CompletedStrand> out(n);
  // Strands are independent (each edge report belongs to one strand): two
  // workers each take the next strand; counters are summed afterwards.
  const std::vector<std::size_t> order = largest_first(ctx, pieces);
  std::atomic<std::size_t> next{0};
  InpaintResult counts[2];
  auto work = [&](InpaintResult* count) {
    for (std::size_t k = next++; k < n; k = next++) {
      const std::size_t g = order[k];
      const std::vector<int>& members = pieces.groups[g];
      std::vector<const PieceArea*> areas;
      for (const PieceArea& a : pieces.areas)
        if (std::find(members.begin(), members.end(), a.region) != members.end())
          areas.push_back(&a);
      out[g] = build_strand(ctx, members, areas, reports, count);
    }
  };
  if (ctx.options->threads > 1 && n > 1) {
    auto other = std::async(std::launch::async, work, &counts[1]);
    work(&counts[0]);
    other.get();
  } else {
    work(&counts[0]);
  }
  add_counts(counts, inpainted);
  return out;
}

std::vector<CompletedStrand> assemble_strands(
    const Context& ctx, const StrandPieces& pieces, const std::vector<int>& late_region,
    const std::vector<std::size_t>& late_order,
    const std::function<const PieceArea*(std::size_t)>& make_late,
    const std::function<void(std::size_t)>& on_made, std::vector<EdgeReport>* reports,
    InpaintResult* inpainted) {
  const std::size_t n = pieces.groups.size(), m = late_region.size();
  std::vector<const PieceArea*> late(m, nullptr);
  if (ctx.options->threads <= 1) {
    for (std::size_t i = 0; i < m; ++i) {
      late[late_order[i]] = make_late(late_order[i]);
      on_made(i + 1);
    }
    StrandPieces all = pieces;
    for (const PieceArea* a : late)
      if (a != nullptr) all.areas.push_back(*a);
    return assemble_strands(ctx, all, reports, inpainted);
  }
  std::vector<CompletedStrand> out(n);
  const std::vector<std::size_t> order = largest_first(ctx, pieces);
  std::map<int, std::size_t> group_of;
  for (std::size_t g = 0; g < n; ++g)
    for (int r : pieces.groups[g]) group_of[r] = g;
  std::vector<int> waiting(n, 0);  // late areas of the strand's regions not made yet
  for (int r : late_region)
    if (auto it = group_of.find(r); it != group_of.end()) ++waiting[it->second];
  // Shared under `mu`: the next late area, the strands taken, the late areas made.
  std::mutex mu;
  std::condition_variable changed;
  std::size_t next_late = 0, made = 0;
  std::vector<char> taken(n, 0);
  std::exception_ptr failure;
  InpaintResult counts[2];
  const auto is_member = [&](const std::vector<int>& members, int region) {
    return std::find(members.begin(), members.end(), region) != members.end();
  };
  // Late areas first (they free the strands waiting for them), then the
  // largest strand whose late areas are all made.
  auto work = [&](InpaintResult* count, bool caller) {
    std::unique_lock<std::mutex> lock(mu);
    while (!failure) {
      if (next_late < m) {
        const std::size_t k = late_order[next_late++];
        lock.unlock();
        const PieceArea* a = nullptr;
        try {
          a = make_late(k);
        } catch (...) {
          lock.lock();
          failure = std::current_exception();
          break;
        }
        lock.lock();
        late[k] = a;
        if (auto it = group_of.find(late_region[k]); it != group_of.end()) --waiting[it->second];
        ++made;
        if (caller) {
          const std::size_t done = made;
          lock.unlock();
          on_made(done);
          lock.lock();
        }
        changed.notify_all();
        continue;
      }
      std::size_t pick = n;
      bool left = false;
      for (std::size_t g : order) {
        if (taken[g]) continue;
        left = true;
        if (waiting[g] == 0) {
          pick = g;
          break;
        }
      }
      if (!left) break;
      if (pick == n) {
        changed.wait(lock);
        continue;
      }
      taken[pick] = 1;
      const std::vector<int>& members = pieces.groups[pick];
      std::vector<const PieceArea*> areas;
      for (const PieceArea& a : pieces.areas)
        if (is_member(members, a.region)) areas.push_back(&a);
      for (const PieceArea* a : late)
        if (a != nullptr && is_member(members, a->region)) areas.push_back(a);
      lock.unlock();
      try {
        out[pick] = build_strand(ctx, members, areas, reports, count);
      } catch (...) {
        lock.lock();
        failure = std::current_exception();
        break;
      }
      lock.lock();
    }
    changed.notify_all();
  };
  auto other = std::async(std::launch::async, work, &counts[1], false);
  work(&counts[0], true);
  other.get();
  if (failure) std::rethrow_exception(failure);
  add_counts(counts, inpainted);
  return out;
}

}  // namespace hair25d::completion::detail
