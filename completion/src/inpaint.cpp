#include "hair25d/completion/inpaint.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <queue>
#include <string>
#include <vector>

#include "hair25d/core/error.h"
#include "inpaint_internal.h"
#include "patch_ssd.h"
#include "raster.h"

namespace hair25d::completion {

bool InpaintOptions::is_valid(std::string* error) const {
  auto fail = [&](const std::string& m) {
    if (error != nullptr) *error = "completion::InpaintOptions::" + m;
    return false;
  };
  if (patch_radius < 1 || patch_radius > 16)
    return fail("patch_radius = " + std::to_string(patch_radius) + "; must be in [1, 16]");
  if (search_radius < 1)
    return fail("search_radius = " + std::to_string(search_radius) + "; must be >= 1");
  if (!(distance_weight >= 0))
    return fail("distance_weight = " + std::to_string(distance_weight) + "; must be >= 0");
  if (search_step < 1 || search_step > search_radius)
    return fail("search_step = " + std::to_string(search_step) + "; must be in [1, search_radius]");
  if (far_candidates < 0)
    return fail("far_candidates = " + std::to_string(far_candidates) + "; must be >= 0");
  if (ink_luma < 0 || ink_luma > 256)
    return fail("ink_luma = " + std::to_string(ink_luma) + "; must be in [0, 256]");
  if (ink_step < 1) return fail("ink_step = " + std::to_string(ink_step) + "; must be >= 1");
  if (!(guide_weight >= 0))
    return fail("guide_weight = " + std::to_string(guide_weight) + "; must be >= 0");
  return true;
}

namespace {

// Summed-area table of a w × h mask: the count of set pixels in any box in
// four reads (which candidate patches are whole sources, which windows hold
// a valid centre, how much ink a patch has).
class SummedArea {
 public:
  template <typename T>
  void build(const std::vector<T>& mask, int w, int h) {
    w1_ = w + 1;
    s_.assign(static_cast<std::size_t>(w1_) * (h + 1), 0);
    for (int y = 0; y < h; ++y)
      for (int x = 0; x < w; ++x)
        s_[at(x + 1, y + 1)] = (mask[static_cast<std::size_t>(y) * w + x] != 0) + s_[at(x, y + 1)] +
                               s_[at(x + 1, y)] - s_[at(x, y)];
  }
  // Set pixels in [x0, x1) × [y0, y1).
  int sum(int x0, int y0, int x1, int y1) const {
    return s_[at(x1, y1)] - s_[at(x0, y1)] - s_[at(x1, y0)] + s_[at(x0, y0)];
  }

 private:
  std::size_t at(int x, int y) const { return static_cast<std::size_t>(y) * w1_ + x; }
  int w1_ = 1;
  std::vector<int> s_;
};

// The state of one fill: the working crop, what is known, confidences.
class Filler {
 public:
  Filler(Image& image, const LabelMap& fill, const LabelMap& source, const InpaintOptions& o,
         const Image* guide, const std::vector<std::uint8_t>* ink,
         const detail::DotLattice* lattice)
      : image_(image), o_(o), guide_(guide), w_(image.width()), h_(image.height()) {
    const std::size_t n = static_cast<std::size_t>(w_) * h_;
    known_.assign(n, 1);
    from_.assign(n, -1);
    stamp_.assign(n, 0);
    confidence_.assign(n, 1.0f);
    std::vector<int> is_source(n, 0);
    for (std::size_t i = 0; i < n; ++i) {
      if (fill.data()[i] != 0) {
        known_[i] = 0;
        confidence_[i] = 0.0f;
        ++remaining_;
      }
      is_source[i] =
          source.empty() ? fill.data()[i] == 0 : (source.data()[i] != 0 && fill.data()[i] == 0);
    }
    // Integral image of source pixels: a candidate patch is usable when all
    // its pixels are sources (only original pixels are copied, as Criminisi).
    sources_.build(is_source, w_, h_);
    // Thin shapes hold no whole patch of the asked size: use the largest
    // size that has at least one whole source patch.
    for (r_ = o_.patch_radius; r_ >= 1; --r_) {
      const int r = r_;
      valid_.assign(n, 0);
      bool any = false;
      for (int y = r; y < h_ - r; ++y)
        for (int x = r; x < w_ - r; ++x) {
          const bool ok =
              source_sum(x - r, y - r, x + r + 1, y + r + 1) == (2 * r + 1) * (2 * r + 1);
          valid_[idx(x, y)] = ok;
          any = any || ok;
        }
      if (any || r_ == 1) break;
    }
    // Integral image of valid centres: a widened window holding none is
    // skipped without visiting its rows.
    valid_area_.build(valid_, w_, h_);
    row_start_.assign(h_ + 1, 0);
    for (int y = 0; y < h_; ++y) {
      for (int x = 0; x < w_; ++x)
        if (valid_[idx(x, y)]) valid_x_.push_back(x);
      row_start_[y + 1] = static_cast<int>(valid_x_.size());
    }
    // Whole source patches never change: candidates are read from this copy,
    // padded for the 4-pixel reads of the last row (patch_ssd.h).
    source_bytes_.assign(image_.bytes(), image_.bytes() + 4 * n);
    source_bytes_.resize(4 * n + 16, 0);
    grey_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      const Rgba& c = image_.data()[i];
      grey_[i] = 0.299f * c.r + 0.587f * c.g + 0.114f * c.b;
    }
    if (guide_ != nullptr) {
      ink_ = ink != nullptr ? *ink : detail::ink_mask(image_, o_);
      for (std::size_t i = 0; i < n; ++i)
        if (!known_[i]) ink_[i] = 0;
      // The ink rule counts drawn lines and features; a screentone's dots
      // are the paint itself.
      line_ink_ = ink_;
      if (lattice != nullptr && lattice->valid) {
        for (std::size_t i = 0; i < n; ++i)
          if (lattice->dots[i]) line_ink_[i] = 0;
        make_translates(*lattice);
      }
      ink_area_.build(line_ink_, w_, h_);
    }
  }

  InpaintResult run() {
    InpaintResult result;
    make_offsets();
    for (int y = 0; y < h_; ++y)
      for (int x = 0; x < w_; ++x)
        if (on_front(x, y)) push(x, y);
    while (remaining_ > 0) {
      if (heap_.empty()) {
        // Isolated unknown pixels with no known neighbour cannot happen unless
        // the whole image is unknown: give up on those.
        result.unfilled += remaining_;
        break;
      }
      const Item top = heap_.top();
      heap_.pop();
      if (known_[idx(top.x, top.y)] || top.stamp != stamp_[idx(top.x, top.y)]) continue;
      const int filled = fill_patch(top.x, top.y, &result);
      result.filled += filled;
      ++result.patches;
    }
    return result;
  }

 private:
  struct Item {
    float priority;
    int x, y;
    unsigned stamp;
    bool operator<(const Item& o) const { return priority < o.priority; }
  };

  std::size_t idx(int x, int y) const { return static_cast<std::size_t>(y) * w_ + x; }
  int ink_sum(int x0, int y0, int x1, int y1) const { return ink_area_.sum(x0, y0, x1, y1); }
  int valid_sum(int x0, int y0, int x1, int y1) const { return valid_area_.sum(x0, y0, x1, y1); }
  int source_sum(int x0, int y0, int x1, int y1) const { return sources_.sum(x0, y0, x1, y1); }
  bool is_known(int x, int y) const {
    return x >= 0 && y >= 0 && x < w_ && y < h_ && known_[idx(x, y)];
  }
  bool on_front(int x, int y) const {
    if (known_[idx(x, y)]) return false;
    return is_known(x - 1, y) || is_known(x + 1, y) || is_known(x, y - 1) || is_known(x, y + 1);
  }

  // C(p): the mean confidence over the patch's pixels inside the image
  // (unknown pixels have confidence 0), summed in raster order.
  float patch_confidence(int x, int y) const {
    const int r = r_;
    const int x0 = std::max(0, x - r), x1 = std::min(w_ - 1, x + r);
    const int y0 = std::max(0, y - r), y1 = std::min(h_ - 1, y + r);
    float c = 0;
    for (int py = y0; py <= y1; ++py) {
      const float* row = confidence_.data() + idx(0, py);
      for (int px = x0; px <= x1; ++px) c += row[px];
    }
    return c / std::max(1, (x1 - x0 + 1) * (y1 - y0 + 1));
  }

  // P(p) = C(p) D(p) (Criminisi et al. 2004, §3).
  void push(int x, int y) {
    float c = patch_confidence(x, y);
    // Front normal from the known indicator, isophote from known grey levels.
    auto k = [&](int px, int py) { return is_known(px, py) ? 1.0f : 0.0f; };
    float nx = k(x + 1, y) - k(x - 1, y), ny = k(x, y + 1) - k(x, y - 1);
    const float nn = std::sqrt(nx * nx + ny * ny);
    if (nn > 0) nx /= nn, ny /= nn;
    float gx = 0, gy = 0;
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        const int px = x + dx, py = y + dy;
        if (!is_known(px, py) || !is_known(px + 1, py) || !is_known(px - 1, py) ||
            !is_known(px, py + 1) || !is_known(px, py - 1))
          continue;
        // Cel art: an isolated dark feature must not pull the fill along it.
        if (!ink_.empty() && (ink_[idx(px, py)] || ink_[idx(px + 1, py)] || ink_[idx(px - 1, py)] ||
                              ink_[idx(px, py + 1)] || ink_[idx(px, py - 1)]))
          continue;
        const float ix = 0.5f * (grey_[idx(px + 1, py)] - grey_[idx(px - 1, py)]);
        const float iy = 0.5f * (grey_[idx(px, py + 1)] - grey_[idx(px, py - 1)]);
        if (ix * ix + iy * iy > gx * gx + gy * gy) gx = ix, gy = iy;
      }
    // Isophote = gradient turned 90°; D = |isophote · n| / α.
    const float d = std::abs(-gy * nx + gx * ny) / 255.0f + 1e-3f;
    const unsigned s = ++stamp_counter_;
    stamp_[idx(x, y)] = s;
    heap_.push({c * d, x, y, s});
  }

  // One unknown pixel of a cel-mode target patch: its offset from the patch
  // centre and the coarse fill's colour it is compared with.
  struct GuidedPixel {
    std::ptrdiff_t offset;
    int r, g, b, a;
  };

  // The target patch: its known pixels row by row (`rows`, summed four at a
  // time) and, in cel mode, its unknown ones (`guided`, rows ending at
  // `guided_end`), so a candidate can stop after any row once it is worse.
  struct Target {
    detail::PatchRows rows;
    std::vector<GuidedPixel> guided;
    std::vector<int> guided_end;
  };

  void make_target(int x, int y, Target* t) const {
    const int r = r_;
    t->rows.reset(r, w_);
    t->guided.clear();
    t->guided_end.clear();
    std::vector<std::uint8_t> pixels(4 * (2 * r + 1), 0);
    std::vector<bool> use(2 * r + 1);
    for (int dy = -r; dy <= r; ++dy) {
      const int ty = y + dy;
      if (ty < 0 || ty >= h_) continue;
      for (int dx = -r; dx <= r; ++dx) {
        const int tx = x + dx;
        use[dx + r] = tx >= 0 && tx < w_ && known_[idx(tx, ty)];
        if (!use[dx + r]) continue;
        const Rgba& a = image_.data()[idx(tx, ty)];
        std::uint8_t* out = &pixels[4 * (dx + r)];
        out[0] = a.r, out[1] = a.g, out[2] = a.b, out[3] = a.a;
      }
      t->rows.add_row(dy, pixels.data(), use, guide_ != nullptr);
      if (guide_ != nullptr)
        for (int dx = -r; dx <= r; ++dx) {
          const int tx = x + dx;
          if (tx < 0 || tx >= w_ || known_[idx(tx, ty)]) continue;
          const Rgba& a = guide_->data()[idx(tx, ty)];
          t->guided.push_back({static_cast<std::ptrdiff_t>(dy) * w_ + dx, a.r, a.g, a.b, a.a});
        }
      t->guided_end.push_back(static_cast<int>(t->guided.size()));
    }
  }

  // SSD of the candidate centred at pixel index `c`, starting from `ssd` (the
  // distance term); stops (returning a value >= limit) once it reaches
  // `limit`. Candidates are whole source patches, which never change: their
  // pixels are read from the padded copy `source_bytes_`.
  long patch_ssd(const Target& t, std::size_t c, long ssd, long limit, long guide_w) const {
    const std::uint8_t* centre = source_bytes_.data() + 4 * c;
    const Rgba* base = reinterpret_cast<const Rgba*>(centre);
    int begin = 0;
    for (std::size_t row = 0; row < t.rows.rows() && ssd < limit; ++row) {
      ssd += t.rows.row_ssd(row, centre);
      const int end = t.guided_end[row];
      for (int i = begin; i < end; ++i) {
        const GuidedPixel& p = t.guided[i];
        const Rgba& b = base[p.offset];
        const int dr = p.r - b.r, dg = p.g - b.g, db = p.b - b.b, da = p.a - b.a;
        ssd += (guide_w * (dr * dr + dg * dg + db * db + da * da)) >> 8;
      }
      begin = end;
    }
    return ssd;
  }

  // Best source patch centre for the target at (x, y): least SSD over the
  // target's known pixels plus distance_weight × squared distance, searched in
  // a window that widens until it holds one; ties go to the first candidate
  // in raster order. Candidates are visited nearest first, so a good match is
  // found early: a candidate stops summing once it is worse, and the search
  // stops once the distance term alone is worse than the best match.
  bool best_source(int x, int y, int* bx, int* by) const {
    const int r = r_;
    // Ink in the target's known part: a source may hold at most about twice
    // as much (the line continued), none when the known part has none. Only
    // original ink counts: copied ink licensing more ink would let a feature
    // chain across the hole.
    int target_ink = 0;
    if (!line_ink_.empty())
      for (int dy = -r; dy <= r; ++dy)
        for (int dx = -r; dx <= r; ++dx)
          if (is_known(x + dx, y + dy)) target_ink += line_ink_[idx(x + dx, y + dy)];
    // On a screentone the coarse fill is the paper between the dots: at the
    // full weight it pulls the copies towards patches whose dots miss the
    // target's unknown part (dots cut at the copies' seams).
    const double guide_weight =
        translates_.empty() ? o_.guide_weight : kLatticeGuideShare * o_.guide_weight;
    const long guide_w = std::lround(guide_weight * 256);
    Target& target = target_;
    make_target(x, y, &target);
    const int step = o_.search_step;
    long best = std::numeric_limits<long>::max();
    int best_x = 0, best_y = 0;
    // Whether the candidate is allowed (a whole source patch within the ink
    // rule), and if so, whether it is the best so far.
    auto consider = [&](int cx, int cy, long distance_term) {
      if (!valid_[idx(cx, cy)]) return false;
      if (!ink_.empty() && ink_sum(cx - r, cy - r, cx + r + 1, cy + r + 1) > 2 * target_ink)
        return false;
      // A candidate earlier in raster order than the best wins a tie.
      const bool none = best == std::numeric_limits<long>::max();
      const bool earlier = cy < best_y || (cy == best_y && cx < best_x);
      const long limit = none ? best : earlier ? best + 1 : best;
      if (distance_term >= limit) return true;
      const long ssd = patch_ssd(target, idx(cx, cy), distance_term, limit, guide_w);
      if (ssd < limit) best = ssd, best_x = cx, best_y = cy;
      return true;
    };
    const auto term = [&](int dx, int dy) {
      return static_cast<long>(o_.distance_weight * (dx * dx + dy * dy));
    };
    if (!translates_.empty()) {
      // Screentone: the sources continuing the copies around the target,
      // then whole lattice translates of it, so that the dots keep their
      // phase; the window search only where no translate is allowed.
      coherent_search(x, y, term, consider);
      lattice_search(x, y, term, best, consider);
      if (best != std::numeric_limits<long>::max()) {
        *bx = best_x, *by = best_y;
        return true;
      }
    }
    for (int radius = o_.search_radius;; radius *= 2) {
      const int y0 = std::max(r, y - radius), y1 = std::min(h_ - 1 - r, y + radius);
      const int x0 = std::max(r, x - radius), x1 = std::min(w_ - 1 - r, x + radius);
      // A window without any valid centre has nothing to visit.
      const bool empty = x0 > x1 || y0 > y1 || valid_sum(x0, y0, x1 + 1, y1 + 1) == 0;
      if (radius == o_.search_radius) {
        // The window's grid (every step-th pixel from its clamped corner)
        // visited nearest first from the precomputed order of its phase.
        const int phase_x = ((x0 - x) % step + step) % step;
        const int phase_y = ((y0 - y) % step + step) % step;
        for (const Offset& off : nearest_[phase_y * step + phase_x]) {
          if (empty || off.distance_term > best) break;  // every later one is farther
          const int cx = x + off.dx, cy = y + off.dy;
          if (cx < x0 || cx > x1 || cy < y0 || cy > y1) continue;
          consider(cx, cy, off.distance_term);
        }
      } else {
        // A wider window: the target is far from every whole source patch
        // (deep in a large hole, or in a thin strand).
        if (o_.far_candidates > 0) {
          // The coherent candidates do not depend on the window: the first
          // widened window tries them (they would fail alike in wider ones).
          if (radius == 2 * o_.search_radius) coherent_search(x, y, term, consider);
          if (!empty) far_search(x, y, x0, x1, y0, y1, term, best, consider);
        } else if (!empty) {
          // Exact: only the valid centres of each row, rows nearest first
          // and each row outward from x, so that once a match is found
          // whatever lies farther than its cost is never visited.
          // The first grid row at or below y.
          const int first_below = y <= y0 ? y0 : y0 + ((y - y0 + step - 1) / step) * step;
          for (int below = first_below, above = first_below - step; below <= y1 || above >= y0;) {
            // The nearer of the next row below and above.
            int cy;
            if (above < y0 || (below <= y1 && below - y <= y - above)) {
              cy = below;
              below += step;
            } else {
              cy = above;
              above -= step;
            }
            if (term(0, cy - y) > best) {
              // This row and every row farther on this side are too far.
              if (cy >= y)
                below = y1 + 1;
              else
                above = y0 - 1;
              continue;
            }
            const auto row_begin = valid_x_.begin() + row_start_[cy];
            const auto row_end = valid_x_.begin() + row_start_[cy + 1];
            const auto lo = std::lower_bound(row_begin, row_end, x0);
            const auto hi = std::upper_bound(lo, row_end, x1);
            const auto mid = std::lower_bound(lo, hi, x);
            for (auto it = mid; it != hi; ++it) {
              if ((*it - x0) % step != 0) continue;
              const long d = term(*it - x, cy - y);
              if (d > best) break;
              consider(*it, cy, d);
            }
            for (auto it = mid; it != lo;) {
              --it;
              if ((*it - x0) % step != 0) continue;
              const long d = term(*it - x, cy - y);
              if (d > best) break;
              consider(*it, cy, d);
            }
          }
        }
      }
      if (best != std::numeric_limits<long>::max()) {
        *bx = best_x, *by = best_y;
        return true;
      }
      if (radius > w_ + h_) return false;
    }
  }

  // Screentone (inpaint_cel with a dot lattice): the lattice vectors
  // i a + j b reaching no farther than the image's diagonal, nearest first.
  struct Translate {
    double x, y, length;
  };
  void make_translates(const detail::DotLattice& l) {
    const double cell = std::abs(l.ax * l.by - l.ay * l.bx);
    const double reach = std::hypot(w_, h_);
    const int max_i = static_cast<int>(std::ceil(reach * std::hypot(l.bx, l.by) / cell));
    const int max_j = static_cast<int>(std::ceil(reach * std::hypot(l.ax, l.ay) / cell));
    for (int i = -max_i; i <= max_i; ++i)
      for (int j = -max_j; j <= max_j; ++j) {
        if (i == 0 && j == 0) continue;
        const double tx = i * l.ax + j * l.bx, ty = i * l.ay + j * l.by;
        const double length = std::hypot(tx, ty);
        if (length <= reach) translates_.push_back({tx, ty, length});
      }
    std::stable_sort(translates_.begin(), translates_.end(),
                     [](const Translate& a, const Translate& b) { return a.length < b.length; });
  }

  // The candidates of a screentone target: each lattice translate of it,
  // rounded to the pixels round it (the dots' phase to within a pixel; the
  // SSD picks the closest), nearest first, until kLatticeTranslates
  // translates gave an allowed candidate or the distance term alone is
  // worse than the best match.
  template <typename Term, typename Consider>
  void lattice_search(int x, int y, const Term& term, const long& best,
                      const Consider& consider) const {
    const int r = r_;
    int allowed = 0;
    for (const Translate& t : translates_) {
      const double nearest = std::max(0.0, t.length - std::sqrt(2.0));
      if (o_.distance_weight * nearest * nearest > static_cast<double>(best)) return;
      const int fx = static_cast<int>(std::floor(t.x)), fy = static_cast<int>(std::floor(t.y));
      bool any = false;
      for (int oy = fy; oy <= fy + (fy != t.y); ++oy)
        for (int ox = fx; ox <= fx + (fx != t.x); ++ox) {
          const int cx = x + ox, cy = y + oy;
          if (cx < r || cy < r || cx >= w_ - r || cy >= h_ - r) continue;
          any = consider(cx, cy, term(ox, oy)) || any;
        }
      if (any && ++allowed >= kLatticeTranslates) return;
    }
  }
  static constexpr int kLatticeTranslates = 8;
  // Share of guide_weight a screentone's targets give the coarse fill (on
  // generated seed 7 the full weight left dots cut at the copies' seams in
  // the cap; none let dots into a paper-white lock joined to it).
  static constexpr double kLatticeGuideShare = 0.25;

  // A row's next valid centre in one direction (far_search): valid_x_[pos],
  // stepping by dir until end; d is its distance term.
  struct Cursor {
    long d;
    int cy, pos, end, dir;
  };

  // The coherent candidates of a target far from every source patch: the
  // sources that continue the copies already made around it (Ashikhmin 2001).
  template <typename Term, typename Consider>
  void coherent_search(int x, int y, const Term& term, const Consider& consider) const {
    const int r = r_;
    coherent_.clear();
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int qx = x + dx, qy = y + dy;
        if (qx < 0 || qy < 0 || qx >= w_ || qy >= h_ || from_[idx(qx, qy)] < 0) continue;
        const int from = from_[idx(qx, qy)];
        const int cx = from % w_ - dx, cy = from / w_ - dy;
        if (cx < r || cy < r || cx >= w_ - r || cy >= h_ - r) continue;
        const int c = static_cast<int>(idx(cx, cy));
        if (std::find(coherent_.begin(), coherent_.end(), c) == coherent_.end())
          coherent_.push_back(c);
      }
    for (int c : coherent_) consider(c % w_, c / w_, term(c % w_ - x, c / w_ - y));
  }

  // The search of a widened window, made cheap: after the coherent
  // candidates, the window's valid centres nearest first, at most
  // far_candidates of them (the lowest cost of a farther one is its distance
  // term alone, so the search also stops once that exceeds the best). Exact
  // search over the window would visit every valid centre: thousands per
  // target deep in a large hole.
  template <typename Term, typename Consider>
  void far_search(int x, int y, int x0, int x1, int y0, int y1, const Term& term, const long& best,
                  const Consider& consider) const {
    const int step = o_.search_step;
    // Each grid row of the window holds two cursors into its valid centres,
    // one going right from x and one going left; a heap yields the nearest.
    // Rows join the heap only once they could hold the nearest candidate.
    const auto farther = [](const Cursor& a, const Cursor& b) {
      return a.d != b.d ? a.d > b.d : a.cy != b.cy ? a.cy > b.cy : a.pos > b.pos;
    };
    std::vector<Cursor>& heap = cursors_;
    heap.clear();
    // Moves c to its next centre on the window's grid, pushing it if any.
    const auto advance = [&](Cursor c) {
      for (; c.pos != c.end; c.pos += c.dir) {
        const int cx = valid_x_[c.pos];
        if ((cx - x0) % step != 0) continue;
        c.d = term(cx - x, c.cy - y);
        heap.push_back(c);
        std::push_heap(heap.begin(), heap.end(), farther);
        return;
      }
    };
    const auto add_row = [&](int cy) {
      const auto row_begin = valid_x_.begin() + row_start_[cy];
      const auto row_end = valid_x_.begin() + row_start_[cy + 1];
      const int lo = static_cast<int>(std::lower_bound(row_begin, row_end, x0) - valid_x_.begin());
      const int hi = static_cast<int>(std::upper_bound(row_begin, row_end, x1) - valid_x_.begin());
      const int mid =
          std::max(lo, std::min(hi, static_cast<int>(std::lower_bound(row_begin, row_end, x) -
                                                     valid_x_.begin())));
      advance({0, cy, mid, hi, 1});
      advance({0, cy, mid - 1, lo - 1, -1});
    };
    const int first_below = y <= y0 ? y0 : y0 + ((y - y0 + step - 1) / step) * step;
    int below = first_below, above = first_below - step;
    int visited = 0;
    for (;;) {
      // Rows whose nearest possible centre is no farther than the heap's.
      while (below <= y1 || above >= y0) {
        const bool take_below = above < y0 || (below <= y1 && below - y <= y - above);
        const int cy = take_below ? below : above;
        if (!heap.empty() && term(0, cy - y) > heap.front().d) break;
        if (take_below)
          below += step;
        else
          above -= step;
        add_row(cy);
      }
      if (heap.empty()) return;
      std::pop_heap(heap.begin(), heap.end(), farther);
      const Cursor c = heap.back();
      heap.pop_back();
      if (c.d > best) return;
      consider(valid_x_[c.pos], c.cy, c.d);
      if (++visited >= o_.far_candidates && best != std::numeric_limits<long>::max()) return;
      advance({c.d, c.cy, c.pos + c.dir, c.end, c.dir});
    }
  }

  // Candidate offsets of the first search window for each phase of its grid
  // (dx ≡ phase_x, dy ≡ phase_y modulo search_step), nearest first.
  struct Offset {
    int dx, dy;
    long distance_term;
  };
  void make_offsets() {
    const int step = o_.search_step, radius = o_.search_radius;
    nearest_.assign(static_cast<std::size_t>(step) * step, {});
    for (int py = 0; py < step; ++py)
      for (int px = 0; px < step; ++px) {
        std::vector<Offset>& list = nearest_[py * step + px];
        // The grid starts at the clamped corner, at most `radius` away.
        for (int dy = -radius; dy <= radius; ++dy) {
          if (((dy % step) + step) % step != py) continue;
          for (int dx = -radius; dx <= radius; ++dx) {
            if (((dx % step) + step) % step != px) continue;
            list.push_back({dx, dy, static_cast<long>(o_.distance_weight * (dx * dx + dy * dy))});
          }
        }
        std::stable_sort(list.begin(), list.end(), [](const Offset& a, const Offset& b) {
          return a.distance_term < b.distance_term;
        });
      }
  }

  int fill_patch(int x, int y, InpaintResult* result) {
    const int r = r_;
    int bx = 0, by = 0;
    const bool found = best_source(x, y, &bx, &by);
    // Confidence of the filled pixels: the target patch's C(p).
    float c = 0;
    int count = 0;
    Rgba mean{};
    int sr = 0, sg = 0, sb = 0, known = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int px = x + dx, py = y + dy;
        if (px < 0 || py < 0 || px >= w_ || py >= h_) continue;
        ++count;
        if (known_[idx(px, py)]) {
          c += confidence_[idx(px, py)];
          const Rgba& v = image_.data()[idx(px, py)];
          sr += v.r, sg += v.g, sb += v.b, ++known;
        }
      }
    c /= std::max(1, count);
    if (known > 0)
      mean = {static_cast<std::uint8_t>(sr / known), static_cast<std::uint8_t>(sg / known),
              static_cast<std::uint8_t>(sb / known), 255};
    int filled = 0;
    for (int dy = -r; dy <= r; ++dy)
      for (int dx = -r; dx <= r; ++dx) {
        const int px = x + dx, py = y + dy;
        if (px < 0 || py < 0 || px >= w_ || py >= h_ || known_[idx(px, py)]) continue;
        Rgba& dst = image_.data()[idx(px, py)];
        const std::uint8_t alpha = dst.a;
        if (found) {
          dst = image_.data()[idx(bx + dx, by + dy)];
          from_[idx(px, py)] = static_cast<int>(idx(bx + dx, by + dy));
        } else if (guide_ != nullptr) {
          dst = guide_->data()[idx(px, py)];  // no allowed patch: the coarse fill
        } else {
          dst = mean;  // no source patch anywhere: the mean of what is known
          ++result->unfilled;
        }
        // Cel mode fills transparency too (a drawing on a transparent sheet).
        if (guide_ == nullptr) dst.a = alpha;
        grey_[idx(px, py)] = 0.299f * dst.r + 0.587f * dst.g + 0.114f * dst.b;
        known_[idx(px, py)] = 1;
        confidence_[idx(px, py)] = c;
        --remaining_;
        ++filled;
      }
    // Priorities change around the patch: re-push the front there.
    for (int dy = -r - 1; dy <= r + 1; ++dy)
      for (int dx = -r - 1; dx <= r + 1; ++dx) {
        const int px = x + dx, py = y + dy;
        if (px < 0 || py < 0 || px >= w_ || py >= h_) continue;
        if (on_front(px, py)) push(px, py);
      }
    return filled;
  }

  Image& image_;
  const InpaintOptions& o_;
  const Image* guide_;  // coarse fill (cel mode) or null
  int w_, h_;
  int r_ = 1;  // patch radius in use
  std::vector<std::uint8_t> known_;
  std::vector<float> confidence_;
  SummedArea sources_;  // of source pixels
  std::vector<std::uint8_t> valid_;
  SummedArea valid_area_;       // of valid_
  std::vector<int> valid_x_;    // x of every valid centre, row by row
  std::vector<int> row_start_;  // row y's centres: valid_x_[row_start_[y], row_start_[y + 1])
  std::vector<float> grey_;
  std::vector<std::uint8_t> source_bytes_;
  std::vector<std::uint8_t> ink_;       // cel mode only
  std::vector<std::uint8_t> line_ink_;  // ink_ less a screentone's dots: the ink rule's
  std::vector<Translate> translates_;   // screentone only (make_translates)
  SummedArea ink_area_;
  std::vector<unsigned> stamp_ = {};
  unsigned stamp_counter_ = 0;
  std::priority_queue<Item> heap_;
  long remaining_ = 0;
  std::vector<std::vector<Offset>> nearest_;  // make_offsets()
  mutable Target target_;                     // best_source's scratch
  std::vector<int> from_;              // the source pixel each filled pixel was copied from, or -1
  mutable std::vector<int> coherent_;  // coherent_search's scratch
  mutable std::vector<Cursor> cursors_;
};

}  // namespace

namespace {

void check_inputs(const Image& image, const LabelMap& fill, const LabelMap& source,
                  const InpaintOptions& options) {
  std::string why;
  if (!options.is_valid(&why)) throw Error(why);
  detail::require_image_size("completion::inpaint_exemplar", "fill mask is", fill, image);
  if (!source.empty())
    detail::require_image_size("completion::inpaint_exemplar", "source mask is", source, image,
                               " or empty");
}

}  // namespace

namespace detail {

std::vector<std::uint8_t> ink_mask(const Image& image, const InpaintOptions& o) {
  const int w = image.width(), h = image.height();
  std::vector<int> luma(static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < luma.size(); ++i) {
    // Over paper white: transparent pixels are background, not ink.
    const Rgba& c = image.data()[i];
    luma[i] = ((299 * c.r + 587 * c.g + 114 * c.b) / 1000 * c.a + 255 * (255 - c.a)) / 255;
  }
  std::vector<std::uint8_t> ink(luma.size(), 0);
  for (int y = 0; y < h; ++y) {
    // Rows and columns 2 px from the border read their neighbours without
    // clamping (the same values: the clamp changes nothing there).
    const bool inner_row = y >= 2 && y < h - 2;
    for (int x = 0; x < w; ++x) {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      bool dark = luma[i] < o.ink_luma;
      // A ridge: darker than both sides, 1 or 2 px away (a line or a dot,
      // not the border between two flat regions).
      if (!dark && inner_row && x >= 2 && x < w - 2) {
        const int* c = luma.data() + i;
        const std::ptrdiff_t row = w;
        for (int d = 1; d <= 2 && !dark; ++d)
          dark = std::min(c[-d], c[d]) - *c > o.ink_step ||
                 std::min(c[-d * row], c[d * row]) - *c > o.ink_step;
      } else {
        auto at = [&](int px, int py) {
          return luma[static_cast<std::size_t>(std::clamp(py, 0, h - 1)) * w +
                      std::clamp(px, 0, w - 1)];
        };
        for (int d = 1; d <= 2 && !dark; ++d)
          dark = std::min(at(x - d, y), at(x + d, y)) - luma[i] > o.ink_step ||
                 std::min(at(x, y - d), at(x, y + d)) - luma[i] > o.ink_step;
      }
      ink[i] = dark ? 1 : 0;
    }
  }
  return ink;
}

InpaintResult run_exemplar(Image& image, const LabelMap& fill, const LabelMap& source,
                           const InpaintOptions& options, const Image* guide,
                           const std::vector<std::uint8_t>* ink, const DotLattice* lattice) {
  Filler filler(image, fill, source, options, guide, ink, lattice);
  return filler.run();
}

}  // namespace detail

InpaintResult inpaint_exemplar(Image& image, const LabelMap& fill, const LabelMap& source,
                               const InpaintOptions& options) {
  check_inputs(image, fill, source, options);
  if (image.empty()) return {};
  return detail::run_exemplar(image, fill, source, options, nullptr);
}

InpaintResult inpaint_cel(Image& image, const LabelMap& fill, const LabelMap& source,
                          const InpaintOptions& options) {
  check_inputs(image, fill, source, options);
  if (image.empty()) return {};
  const InpaintOptions o = detail::source_ink_options(image, fill, source, options);
  // The ink mask serves the coarse fill and the exemplar pass alike.
  const std::vector<std::uint8_t> ink = detail::ink_mask(image, o);
  const Image guide = detail::coarse_fill(image, fill, source, ink);
  const detail::DotLattice lattice = detail::find_dot_lattice(image, fill, source, ink);
  return detail::run_exemplar(image, fill, source, o, &guide, &ink, &lattice);
}

}  // namespace hair25d::completion
