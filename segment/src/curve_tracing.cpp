#include "curve_tracing.h"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace hair25d::segment::detail {
namespace {

constexpr int kRecent = 4;  // own points this close along the curve are not a hit

struct Tracer {
  const LineField& field;
  const cv::Mat& ridge;
  int w, h;
  TraceResult& out;
  // Position along the curve being traced: negative before the seed.
  std::vector<int> seq;

  bool is_ridge(int x, int y) const {
    return x >= 0 && y >= 0 && x < w && y < h && ridge.at<std::uint8_t>(y, x) != 0;
  }
  Vec2 tangent(int x, int y) const {
    return Vec2(-field.ny.at<float>(y, x), field.nx.at<float>(y, x));
  }
  Vec2 centre(int x, int y) const {
    const double t = field.offset.at<float>(y, x);
    return Vec2(x + 0.5 + t * field.nx.at<float>(y, x), y + 0.5 + t * field.ny.at<float>(y, x));
  }

  // Follows the line from (x, y) in direction d; returns the pixels visited
  // (not the start) and sets `hit` to a pixel of another curve that stopped it.
  std::vector<int> walk(int x, int y, Vec2 d, int curve, int sign, int* hit) {
    std::vector<int> path;
    *hit = -1;
    int cur_seq = 0;
    for (;;) {
      int best = -1, best_hit = -1;
      double best_score = -1.0, best_hit_cos = -1.0;
      for (int radius = 1; radius <= 2 && best < 0 && best_hit < 0; ++radius) {
        // Radius 2 bridges a one-pixel gap in the centre line.
        const double min_cos = radius == 1 ? 0.5 : 0.75;
        for (int dy = -radius; dy <= radius; ++dy) {
          for (int dx = -radius; dx <= radius; ++dx) {
            if (std::max(std::abs(dx), std::abs(dy)) != radius) continue;
            const int qx = x + dx, qy = y + dy;
            if (!is_ridge(qx, qy)) continue;
            const Vec2 v = Vec2(dx, dy).normalized();
            const double c = v.dot(d);
            if (c < min_cos) continue;
            const int q = qy * w + qx;
            const int o = out.owner[q];
            if (o == curve) {
              if (std::abs(seq[q] - cur_seq) <= kRecent + radius) continue;
              if (c > best_hit_cos) best_hit_cos = c, best_hit = q;
            } else if (o >= 0) {
              if (c > best_hit_cos) best_hit_cos = c, best_hit = q;
            } else {
              const double score = field.response.at<float>(qy, qx) * (0.5 + c);
              if (score > best_score) best_score = score, best = q;
            }
          }
        }
      }
      if (best < 0) {
        *hit = best_hit;
        return path;
      }
      const int bx = best % w, by = best / w;
      // Pixels beside the step that also touch the new pixel are the same
      // line drawn two pixels thick: take them so they seed no stray curve.
      for (int dy = -1; dy <= 1; ++dy) {
        for (int dx = -1; dx <= 1; ++dx) {
          const int qx = x + dx, qy = y + dy;
          if ((dx == 0 && dy == 0) || !is_ridge(qx, qy)) continue;
          const int q = qy * w + qx;
          if (q == best || out.owner[q] >= 0) continue;
          if (std::abs(qx - bx) > 1 || std::abs(qy - by) > 1) continue;
          out.owner[q] = curve;
          seq[q] = cur_seq;
          out.owner_point[q] = -(1 + static_cast<int>(path.size()));  // fixed up later
        }
      }
      cur_seq += sign;
      out.owner[best] = curve;
      seq[best] = cur_seq;
      path.push_back(best);
      Vec2 t = tangent(bx, by);
      const Vec2 step = Vec2(bx - x, by - y).normalized();
      if (t.dot(d) < 0) t = -t;
      d = (t + step).normalized();
      if (!std::isfinite(d.x())) d = step;
      x = bx;
      y = by;
    }
  }
};

}  // namespace

TraceResult trace_curves(const LineField& field, const cv::Mat& ridge, float high_threshold) {
  const int w = ridge.cols, h = ridge.rows;
  TraceResult out;
  out.owner.assign(static_cast<std::size_t>(w) * h, -1);
  out.owner_point.assign(out.owner.size(), -1);
  Tracer tracer{field, ridge, w, h, out, std::vector<int>(out.owner.size(), 0)};

  std::vector<int> seeds;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (ridge.at<std::uint8_t>(y, x) && field.response.at<float>(y, x) > high_threshold)
        seeds.push_back(y * w + x);
    }
  }
  std::sort(seeds.begin(), seeds.end(), [&](int a, int b) {
    const float ra = field.response.at<float>(a / w, a % w);
    const float rb = field.response.at<float>(b / w, b % w);
    return ra != rb ? ra > rb : a < b;
  });

  for (int s : seeds) {
    if (out.owner[s] >= 0) continue;
    const int id = static_cast<int>(out.curves.size());
    const int sx = s % w, sy = s / w;
    out.owner[s] = id;
    tracer.seq[s] = 0;
    const Vec2 t = tracer.tangent(sx, sy);
    int hit_fwd = -1, hit_back = -1;
    std::vector<int> fwd = tracer.walk(sx, sy, t, id, +1, &hit_fwd);
    bool closed = false;
    std::vector<int> back;
    if (hit_fwd >= 0 && out.owner[hit_fwd] == id && std::abs(tracer.seq[hit_fwd]) <= kRecent + 2 &&
        fwd.size() > 2 * kRecent) {
      closed = true;  // came round to the seed
      hit_fwd = -1;
    } else {
      back = tracer.walk(sx, sy, -t, id, -1, &hit_back);
    }
    TracedCurve c;
    c.closed = closed;
    c.pixels.assign(back.rbegin(), back.rend());
    c.pixels.push_back(s);
    c.pixels.insert(c.pixels.end(), fwd.begin(), fwd.end());
    const int nb = static_cast<int>(back.size());
    for (std::size_t i = 0; i < c.pixels.size(); ++i) {
      const int p = c.pixels[i];
      c.points.push_back(tracer.centre(p % w, p / w));
      out.owner_point[p] = static_cast<int>(i);
    }
    // Pixels taken beside the path point at the point of their step.
    auto fix_absorbed = [&](const std::vector<int>& path, bool forward) {
      for (std::size_t i = 0; i < path.size(); ++i) {
        const int p = path[i];
        const int px = p % w, py = p / w;
        for (int dy = -2; dy <= 2; ++dy) {
          for (int dx = -2; dx <= 2; ++dx) {
            const int qx = px + dx, qy = py + dy;
            if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
            const int q = qy * w + qx;
            if (out.owner[q] == id && out.owner_point[q] < 0)
              out.owner_point[q] =
                  forward ? nb + 1 + static_cast<int>(i) : nb - 1 - static_cast<int>(i);
          }
        }
      }
    };
    fix_absorbed(fwd, true);
    fix_absorbed(back, false);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const int qx = sx + dx, qy = sy + dy;
        if (qx < 0 || qy < 0 || qx >= w || qy >= h) continue;
        const int q = qy * w + qx;
        if (out.owner[q] == id && out.owner_point[q] < 0) out.owner_point[q] = nb;
      }
    }
    if (hit_back >= 0) out.attachments.push_back({id, 0, hit_back});
    if (hit_fwd >= 0) out.attachments.push_back({id, 1, hit_fwd});
    out.curves.push_back(std::move(c));
  }
  return out;
}

}  // namespace hair25d::segment::detail
