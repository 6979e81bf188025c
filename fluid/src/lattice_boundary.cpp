// The boundary side of the D2Q9 lattice: cells next to obstacles and filaments (bounce-back,
// interpolated bounce-back, momentum exchange), the halo that carries the domain sides, and
// the sponge in front of outflows.
#include <algorithm>
#include <cmath>

#include "lattice_d2q9.h"

namespace hair25d::fluid::detail {

double wall_fraction(const Polyline& poly, const Vec2& a, const Vec2& b) {
  double best = 2.0;
  const Vec2 e = b - a;
  for (std::size_t k = 0; k < poly.size(); ++k) {
    const Vec2& p = poly[k];
    const Vec2 d = poly[(k + 1) % poly.size()] - p;
    const double den = cross(e, d);
    if (den == 0.0) continue;
    const double t = cross(p - a, d) / den;  // along the link
    const double s = cross(p - a, e) / den;  // along the edge
    if (t >= 0.0 && t <= 1.0 && s >= 0.0 && s <= 1.0) best = std::min(best, t);
  }
  return best <= 1.0 ? best : 0.5;
}

template <typename T>
void Lattice<T>::set_cut_links(const std::vector<CutLink>& links, int segment_count) {
  segment_count_ = segment_count;
  links_.clear();
  special_.clear();
  special_.reserve(static_special_.size() + links.size());
  std::size_t s = 0, l = 0;
  // Merge the static boundary cells with the cells whose links the filaments cut, both
  // sorted by cell, so each boundary cell is recomputed exactly once.
  while (s < static_special_.size() || l < links.size()) {
    const std::int32_t cs = s < static_special_.size() ? static_special_[s].cell : INT32_MAX;
    const std::int32_t cl = l < links.size() ? links[l].cell : INT32_MAX;
    const std::int32_t cell = std::min(cs, cl);
    Special sp{0, cell, 0, static_cast<std::int32_t>(links_.size()), 0, -1};
    if (cs == cell) {
      sp.solid_mask = static_special_[s].solid_mask;
      sp.wall_q = static_special_[s++].wall_q;
    }
    while (l < links.size() && links[l].cell == cell) {
      const CutLink& c = links[l++];
      links_.push_back({c.dir, T(c.ux), T(c.uy), c.owner});
    }
    sp.link_end = static_cast<std::int32_t>(links_.size());
    if (labels_[cell] != 0) continue;  // a filament inside an obstacle changes nothing
    sp.idx = static_cast<std::int32_t>(idx(cell % width_, cell / width_));
    special_.push_back(sp);
  }
  for (auto& acc : segment_acc_) acc.assign(segment_count_, Vec2::Zero());
  segment_force_.assign(segment_count_, Vec2::Zero());
}

template <typename T>
void Lattice<T>::boundary(std::size_t begin, std::size_t end, int tid) {
  std::vector<Vec2>& seg = segment_acc_[tid];
  std::vector<Vec2>& obs = obstacle_acc_[tid];
  for (std::size_t k = begin; k < end; ++k) {
    const Special& sp = special_[k];
    const std::ptrdiff_t id = sp.idx;
    T f[9];
    f[0] = src_[0][id];
    T rho = T(-1);
    std::int32_t l = sp.link_begin;
    for (int i = 1; i < 9; ++i) {
      const int o = kOpp[i];
      const double cx = kCx[i], cy = kCy[i], w = kW[i];
      if (l < sp.link_end && links_[l].dir == i) {
        // Moving-wall bounce-back (Ladd) on the link the filament cuts; the momentum exchange
        // is the Galilean-invariant form of Wen et al. (2014), which stays right for moving walls.
        const Link& link = links_[l++];
        if (rho < T(0)) {
          rho = T(1);
          for (int q = 0; q < 9; ++q) rho += src_[q][id];
        }
        const T out = src_[o][id];
        f[i] = out + T(6.0 * w) * rho * (T(cx) * link.ux + T(cy) * link.uy);
        const double fo = static_cast<double>(out) + w, fi = static_cast<double>(f[i]) + w;
        const double ux = link.ux, uy = link.uy;
        seg[link.owner] += Vec2((-cx - ux) * fo - (cx - ux) * fi, (-cy - uy) * fo - (cy - uy) * fi);
      } else if (sp.solid_mask & (1u << i)) {
        const T out = src_[o][id];
        const float q = sp.wall_q >= 0 ? wall_q_[sp.wall_q][i] : 0.5f;
        if (q == 0.5f) {
          f[i] = out;
        } else if (q < 0.5f) {
          // Bouzidi: the wall is nearer than half-way; blend with the next node from the wall.
          const T tq = T(2 * q);
          f[i] = tq * out + (T(1) - tq) * src_[o][id + off_[i]];
        } else {
          const T inv = T(1 / (2 * q));
          f[i] = inv * out + (T(1) - inv) * src_[i][id];
        }
        const int x = sp.cell % width_ - kCx[i], y = sp.cell / width_ - kCy[i];
        const int label = labels_[y * width_ + x];
        const double m = static_cast<double>(out) + static_cast<double>(f[i]) + 2.0 * w;
        obs[label - 1] += Vec2(-cx * m, -cy * m);
      } else {
        f[i] = src_[i][id - off_[i]];
      }
    }
    if (les_)
      forced_ ? d2q9::collide<T, true, true>(f, relax_) : d2q9::collide<T, false, true>(f, relax_);
    else
      forced_ ? d2q9::collide<T, true>(f, relax_) : d2q9::collide<T, false>(f, relax_);
    for (int i = 0; i < 9; ++i) dst_[i][id] = f[i];
  }
}

template <typename T>
void Lattice<T>::absorb(std::size_t begin, std::size_t end) {
  // Moves the equilibrium part of each cell towards density 1 and the far-field velocity,
  // keeping its non-equilibrium (viscous) part.
  for (std::size_t k = begin; k < end; ++k) {
    const std::ptrdiff_t id = sponge_[k].idx;
    const T sigma = sponge_[k].strength;
    T f[9];
    for (int i = 0; i < 9; ++i) f[i] = dst_[i][id];
    const T rho = T(1) + f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8];
    const T ux = (f[1] - f[3] + f[5] - f[6] - f[7] + f[8]) / rho;
    const T uy = (f[2] - f[4] + f[5] + f[6] - f[7] - f[8]) / rho;
    T now[9], target[9];
    d2q9::equilibrium<T>(rho, ux, uy, now);
    d2q9::equilibrium<T>(T(1), sponge_ux_, sponge_uy_, target);
    for (int i = 0; i < 9; ++i) dst_[i][id] = f[i] + sigma * (target[i] - now[i]);
  }
}

template <typename T>
T Lattice<T>::halo_value(int hx, int hy, int i, int x, int y) const {
  const bool cross[4] = {hx < 0, hx >= width_, hy < 0, hy >= height_};
  const std::ptrdiff_t id = idx(x, y);
  // Walls win over inlets at corners, inlets over outlets, outlets over periodic sides.
  for (SideKind kind : {SideKind::kWall, SideKind::kInlet}) {
    for (int s = 0; s < 4; ++s) {
      if (!cross[s] || kind_[s] != kind) continue;
      const int along = s < 2 ? y : x;
      const T ux = side_ux_[s][along], uy = side_uy_[s][along];
      T out = src_[kOpp[i]][id];
      if (ux == T(0) && uy == T(0)) return out;
      T rho = T(1);
      for (int q = 0; q < 9; ++q) rho += src_[q][id];
      return out + T(6.0 * kW[i]) * rho * (T(kCx[i]) * ux + T(kCy[i]) * uy);
    }
  }
  for (int s = 0; s < 4; ++s) {
    if (!cross[s] || kind_[s] != SideKind::kOutflow) continue;
    // Pressure outlet by anti-bounce-back at density 1 with the velocity of the cell: it pins
    // the density, so the mass pushed in by the inlet cannot pile up (a zero-gradient copy
    // of the populations lets it grow without bound).
    T rho, ux, uy;
    moments(id, rho, ux, uy);
    // Flow coming back in through the outlet (a vortex crossing it) is what makes open
    // boundaries blow up: let it slide along the side but not enter.
    const int nx = s == kSideLeft ? -1 : s == kSideRight ? 1 : 0;
    const int ny = s == kSideTop ? -1 : s == kSideBottom ? 1 : 0;
    const T un = T(nx) * ux + T(ny) * uy;
    if (un < T(0)) {
      ux -= un * T(nx);
      uy -= un * T(ny);
    }
    const T cu = T(kCx[i]) * ux + T(kCy[i]) * uy;
    const T w = T(kW[i]);
    return -src_[kOpp[i]][id] +
           T(2) * w * ((T(1) + T(4.5) * cu * cu - T(1.5) * (ux * ux + uy * uy)) - T(1));
  }
  int qx = hx, qy = hy;
  if (cross[kSideLeft]) qx = hx + width_;
  if (cross[kSideRight]) qx = hx - width_;
  if (cross[kSideTop]) qy = hy + height_;
  if (cross[kSideBottom]) qy = hy - height_;
  return src_[i][idx(qx, qy)];
}

template <typename T>
void Lattice<T>::fill_halo() {
  auto visit = [&](int hx, int hy) {
    const std::ptrdiff_t h = idx(hx, hy);
    for (int i = 1; i < 9; ++i) {
      const int x = hx + kCx[i], y = hy + kCy[i];
      if (x < 0 || x >= width_ || y < 0 || y >= height_) continue;
      src_[i][h] = halo_value(hx, hy, i, x, y);
    }
  };
  for (int hx = -1; hx <= width_; ++hx) {
    visit(hx, -1);
    visit(hx, height_);
  }
  for (int hy = 0; hy < height_; ++hy) {
    visit(-1, hy);
    visit(width_, hy);
  }
}

// These members are defined here, the others in lattice_d2q9.cpp.
#define HAIR25D_FLUID_INSTANTIATE(T)                                         \
  template void Lattice<T>::set_cut_links(const std::vector<CutLink>&, int); \
  template void Lattice<T>::boundary(std::size_t, std::size_t, int);         \
  template void Lattice<T>::absorb(std::size_t, std::size_t);                \
  template T Lattice<T>::halo_value(int, int, int, int, int) const;          \
  template void Lattice<T>::fill_halo();
HAIR25D_FLUID_INSTANTIATE(float)
HAIR25D_FLUID_INSTANTIATE(double)
#undef HAIR25D_FLUID_INSTANTIATE

}  // namespace hair25d::fluid::detail
