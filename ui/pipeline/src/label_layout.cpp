#include "label_layout.h"

#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

namespace hair25d::pipeline::detail {

std::vector<Box> place_labels(const std::vector<LabelRequest>& requests, std::vector<Box> taken,
                              const Box& area, double step) {
  // The most constrained labels first: a crowded mark left for last finds
  // every nearby spot taken by marks that had room to spare.
  std::vector<int> crowd(requests.size(), 0);
  for (std::size_t i = 0; i < requests.size(); ++i)
    for (std::size_t j = 0; j < requests.size(); ++j)
      if (i != j && (requests[i].at - requests[j].at).norm() < 8 * step) ++crowd[i];
  std::vector<std::size_t> order(requests.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t i, std::size_t j) {
    if (requests[i].first != requests[j].first) return requests[i].first;
    return crowd[i] > crowd[j];
  });
  for (const LabelRequest& r : requests)
    taken.push_back(box_around(r.at, r.mark_radius, r.mark_radius));

  constexpr int kAngles = 16;
  std::vector<Box> placed(requests.size());
  for (std::size_t i : order) {
    const LabelRequest& q = requests[i];
    double best_cost = std::numeric_limits<double>::infinity();
    Box best = box_around(q.at, q.half_w, q.half_h);  // a drawing too small for any spot
    for (double r = q.mark_radius + 0.25 * step; r < 32 * step && best_cost > 0; r += step) {
      for (int k = 0; k < kAngles && best_cost > 0; ++k) {
        const double angle = -std::numbers::pi / 4 + 2 * std::numbers::pi * k / kAngles;
        const Vec2 dir(std::cos(angle), std::sin(angle));
        // The box's side nearest the mark at distance r from it.
        const Vec2 c =
            q.at + dir * (r + std::abs(dir.x()) * q.half_w + std::abs(dir.y()) * q.half_h);
        const Box b = box_around(c, q.half_w, q.half_h);
        if (b.x0 < area.x0 || b.y0 < area.y0 || b.x1 > area.x1 || b.y1 > area.y1) continue;
        double cost = 0;
        for (const Box& t : taken) cost += t.overlap(b);
        // When no spot is free: the least overlap, the nearer the better.
        if (cost == 0 || cost + r < best_cost) best = b, best_cost = cost == 0 ? 0 : cost + r;
      }
    }
    placed[i] = best;
    taken.push_back(best);
  }
  return placed;
}

}  // namespace hair25d::pipeline::detail
