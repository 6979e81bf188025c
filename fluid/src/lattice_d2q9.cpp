// The D2Q9 lattice: structure of arrays, one fused pull stream-and-collide pass over the
// bulk with no branches, then a short boundary pass over the cells next to obstacles and
// filaments, which recomputes them with bounce-back. Domain sides live in a one-cell halo
// that is refilled before every step, so the bulk never tests where it is.
#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "d2q9.h"
#include "lattice.h"

// The bulk kernel is compiled twice, for AVX2+FMA (x86-64-v3) and for the baseline, and the
// loader picks the one the CPU runs: twice the vector width in cache, same binary everywhere.
#if defined(__x86_64__) && defined(__GNUC__) && !defined(__clang__)
#define HAIR25D_FLUID_CLONES __attribute__((target_clones("arch=x86-64-v3", "default")))
#else
#define HAIR25D_FLUID_CLONES
#endif

namespace hair25d::fluid {
namespace {

using d2q9::kCx;
using d2q9::kCy;
using d2q9::kOpp;
using d2q9::kW;

constexpr int kCellsPerThread = 16384;
constexpr int kSideLeft = 0, kSideRight = 1, kSideTop = 2, kSideBottom = 3;

int side_index(SideName s) {
  switch (s) {
    case SideName::kLeft:
      return kSideLeft;
    case SideName::kRight:
      return kSideRight;
    case SideName::kTop:
      return kSideTop;
    case SideName::kBottom:
      return kSideBottom;
  }
  return kSideLeft;
}

std::size_t round_up(std::size_t n, std::size_t m) { return (n + m - 1) / m * m; }

double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Where along the link a -> b (a outside, b inside) the polygon's boundary is, as a fraction
// in [0, 1]; 1/2 when no edge is found (degenerate input).
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
class Lattice final : public LatticeBase {
 public:
  Lattice(const Options& o, const Eigen::MatrixXi& labels);

  double step() override;
  void set_cut_links(const std::vector<CutLink>& links, int segment_count) override;
  const std::vector<Vec2>& segment_forces() const override { return segment_force_; }
  const std::vector<Vec2>& obstacle_forces() const override { return obstacle_force_; }
  void set_inlet(SideName side, const std::vector<Vec2>& per_cell) override;
  void set_body_acceleration(const Vec2& g) override;
  void set_sponge_velocity(const Vec2& v) override {
    sponge_ux_ = T(v.x());
    sponge_uy_ = T(v.y());
  }
  void initialize(const Eigen::MatrixXd& rho, const Eigen::MatrixXd& ux,
                  const Eigen::MatrixXd& uy) override;
  void read(FlowField& out) const override;
  double density(int x, int y) const override;
  Vec2 velocity(int x, int y) const override;
  double total_mass() const override;

 private:
  // 64-byte alignment of x = 0 in every row, in elements.
  static constexpr int kAlign = 64 / static_cast<int>(sizeof(T));

  struct Special {
    std::int32_t idx;          // plane index
    std::int32_t cell;         // y * width + x
    std::uint16_t solid_mask;  // bit i: the neighbour the population i comes from is solid
    std::int32_t link_begin, link_end;
    std::int32_t wall_q = -1;  // index into wall_q_ for interpolated walls, -1: half-way
  };
  struct Link {
    std::uint8_t dir;
    T ux, uy;
    std::int32_t owner;
  };

  std::ptrdiff_t idx(int x, int y) const {
    return kAlign + static_cast<std::ptrdiff_t>(y + 1) * stride_ + x;
  }
  template <bool kForce, bool kLes>
  HAIR25D_FLUID_CLONES double bulk(int y0, int y1);
  void boundary(std::size_t begin, std::size_t end, int tid);
  void fill_halo();
  T halo_value(int hx, int hy, int i, int x, int y) const;
  void moments(std::ptrdiff_t id, T& rho, T& ux, T& uy) const;

  int width_, height_, threads_;
  std::ptrdiff_t stride_ = 0;
  std::size_t plane_ = 0;
  std::vector<T> storage_;
  std::array<T*, 9> src_{}, dst_{};
  std::array<std::ptrdiff_t, 9> off_{};
  d2q9::Relaxation<T> relax_{};
  bool forced_ = false;
  bool les_ = false;
  std::array<SideKind, 4> kind_{};
  std::array<std::vector<T>, 4> side_ux_, side_uy_;  // per cell along each side
  std::vector<std::int32_t> labels_;
  int max_label_ = 0;
  std::vector<std::int32_t> solid_idx_;
  struct SpongeCell {
    std::int32_t idx;
    T strength;  // fraction of the way to the target per step
  };
  std::vector<SpongeCell> sponge_;
  T sponge_ux_ = T(0), sponge_uy_ = T(0);
  void absorb(std::size_t begin, std::size_t end);
  std::vector<Special> static_special_, special_;
  // Per static boundary cell with a polygon neighbour: for each direction i, the fraction q of
  // the link from the node towards x - c_i at which the polygon's boundary lies.
  std::vector<std::array<float, 9>> wall_q_;
  std::vector<Link> links_;
  int segment_count_ = 0;
  std::vector<std::vector<Vec2>> segment_acc_, obstacle_acc_;  // per thread
  std::vector<Vec2> segment_force_, obstacle_force_;
};

template <typename T>
Lattice<T>::Lattice(const Options& o, const Eigen::MatrixXi& labels)
    : LatticeBase(o.width, o.height), width_(o.width), height_(o.height), threads_(o.threads) {
  // Waking a second thread costs a few microseconds per step (far more on a loaded machine):
  // below ~16k cells per thread one thread wins
  // (and does not fight over a loaded machine).
  threads_ = std::max(1, std::min(threads_, width_ * height_ / kCellsPerThread));
  // Rows padded to whole cache lines, and never to a multiple of 512 bytes: rows whose length
  // is a power of two map the three rows a cell reads onto the same cache sets.
  std::size_t stride = round_up(static_cast<std::size_t>(width_) + 2, kAlign);
  while ((stride * sizeof(T)) % 512 == 0) stride += kAlign;
  stride_ = static_cast<std::ptrdiff_t>(stride);
  // Planes staggered by 192 bytes modulo 4 KiB so the 18 streams do not alias either.
  const std::size_t used = 2 * kAlign + (static_cast<std::size_t>(height_) + 2) * stride;
  plane_ = round_up(used, 4096 / sizeof(T)) + 192 / sizeof(T);
  storage_.assign(18 * plane_ + kAlign, T(0));
  const auto address = reinterpret_cast<std::uintptr_t>(storage_.data());
  const std::size_t shift = (64 - address % 64) % 64 / sizeof(T);
  for (int i = 0; i < 9; ++i) {
    src_[i] = storage_.data() + shift + i * plane_;
    dst_[i] = storage_.data() + shift + (9 + i) * plane_;
    off_[i] = kCx[i] + static_cast<std::ptrdiff_t>(kCy[i]) * stride_;
  }

  relax_.omega_plus = T(1.0 / o.tau);
  if (o.collision == Collision::kTrt) {
    const double tau_minus = 0.5 + o.trt_magic / (o.tau - 0.5);
    relax_.omega_minus = T(1.0 / tau_minus);
  } else {
    relax_.omega_minus = relax_.omega_plus;
  }
  relax_.tau0 = T(o.tau);
  relax_.magic = o.collision == Collision::kTrt ? T(o.trt_magic) : T(0);
  relax_.bgk = o.collision == Collision::kBgk ? T(1) : T(0);
  relax_.les = T(18.0 * std::sqrt(2.0) * o.smagorinsky * o.smagorinsky);
  les_ = o.smagorinsky > 0.0;
  set_body_acceleration(o.body_acceleration);

  const std::array<const Side*, 4> sides = {&o.left, &o.right, &o.top, &o.bottom};
  for (int s = 0; s < 4; ++s) {
    kind_[s] = sides[s]->kind;
    const int n = s < 2 ? height_ : width_;
    side_ux_[s].assign(n, T(0));
    side_uy_[s].assign(n, T(0));
    for (int k = 0; k < n; ++k) {
      const double factor = sides[s]->profile.empty() ? 1.0 : sides[s]->profile[k];
      side_ux_[s][k] = T(sides[s]->velocity.x() * factor);
      side_uy_[s][k] = T(sides[s]->velocity.y() * factor);
    }
  }

  labels_.assign(static_cast<std::size_t>(width_) * height_, 0);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const int l = labels.size() ? labels(y, x) : 0;
      labels_[y * width_ + x] = l;
      max_label_ = std::max(max_label_, l);
      if (l > 0) solid_idx_.push_back(static_cast<std::int32_t>(idx(x, y)));
    }
  const int first_polygon_label = max_label_ + 1 - static_cast<int>(o.obstacle_polygons.size());
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      if (labels_[y * width_ + x] != 0) continue;
      std::uint16_t mask = 0;
      for (int i = 1; i < 9; ++i) {
        const int nx = x - kCx[i], ny = y - kCy[i];
        if (nx >= 0 && nx < width_ && ny >= 0 && ny < height_ && labels_[ny * width_ + nx] > 0)
          mask |= static_cast<std::uint16_t>(1u << i);
      }
      if (!mask) continue;
      Special sp{static_cast<std::int32_t>(idx(x, y)), y * width_ + x, mask, 0, 0, -1};
      if (o.interpolated_walls && !o.obstacle_polygons.empty()) {
        std::array<float, 9> q;
        q.fill(0.5f);
        bool any = false;
        for (int i = 1; i < 9; ++i) {
          if (!(mask & (1u << i))) continue;
          const int label = labels_[(y - kCy[i]) * width_ + (x - kCx[i])];
          const int poly = label - first_polygon_label;
          if (poly < 0) continue;
          double t = wall_fraction(o.obstacle_polygons[poly], Vec2(x + 0.5, y + 0.5),
                                   Vec2(x + 0.5 - kCx[i], y + 0.5 - kCy[i]));
          // Below 1/2 the scheme also reads the next node away from the wall: it must be fluid.
          const int fx = x + kCx[i], fy = y + kCy[i];
          const bool next_fluid =
              fx >= 0 && fx < width_ && fy >= 0 && fy < height_ && labels_[fy * width_ + fx] == 0;
          if (t < 0.5 && !next_fluid) t = 0.5;
          q[i] = static_cast<float>(t);
          any = any || t != 0.5;
        }
        if (any) {
          sp.wall_q = static_cast<std::int32_t>(wall_q_.size());
          wall_q_.push_back(q);
        }
      }
      static_special_.push_back(sp);
    }
  special_ = static_special_;
  // Sponge: strength grows quadratically towards each outflow side.
  constexpr double kSpongeMax = 0.25;
  set_sponge_velocity(o.sponge_velocity);
  if (o.sponge_width > 0) {
    const double n = o.sponge_width;
    for (int y = 0; y < height_; ++y)
      for (int x = 0; x < width_; ++x) {
        if (labels_[y * width_ + x] != 0) continue;
        const int dist[4] = {x, width_ - 1 - x, y, height_ - 1 - y};
        double sigma = 0.0;
        for (int s = 0; s < 4; ++s)
          if (kind_[s] == SideKind::kOutflow && dist[s] < o.sponge_width) {
            const double a = (n - dist[s]) / n;
            sigma = std::max(sigma, kSpongeMax * a * a);
          }
        if (sigma > 0) sponge_.push_back({static_cast<std::int32_t>(idx(x, y)), T(sigma)});
      }
  }
  segment_acc_.assign(threads_, {});
  obstacle_acc_.assign(threads_, std::vector<Vec2>(max_label_, Vec2::Zero()));
  obstacle_force_.assign(max_label_, Vec2::Zero());
}

template <typename T>
void Lattice<T>::set_body_acceleration(const Vec2& g) {
  relax_.gx = T(g.x());
  relax_.gy = T(g.y());
  forced_ = g.x() != 0.0 || g.y() != 0.0;
}

template <typename T>
void Lattice<T>::set_inlet(SideName side, const std::vector<Vec2>& per_cell) {
  const int s = side_index(side);
  for (std::size_t k = 0; k < per_cell.size() && k < side_ux_[s].size(); ++k) {
    side_ux_[s][k] = T(per_cell[k].x());
    side_uy_[s][k] = T(per_cell[k].y());
  }
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
template <bool kForce, bool kLes>
double Lattice<T>::bulk(int y0, int y1) {
  double total = 0.0;
  const d2q9::Relaxation<T> r = relax_;
  for (int y = y0; y < y1; ++y) {
    const std::ptrdiff_t row = idx(0, y);
    const T* __restrict s0 = src_[0] + row - off_[0];
    const T* __restrict s1 = src_[1] + row - off_[1];
    const T* __restrict s2 = src_[2] + row - off_[2];
    const T* __restrict s3 = src_[3] + row - off_[3];
    const T* __restrict s4 = src_[4] + row - off_[4];
    const T* __restrict s5 = src_[5] + row - off_[5];
    const T* __restrict s6 = src_[6] + row - off_[6];
    const T* __restrict s7 = src_[7] + row - off_[7];
    const T* __restrict s8 = src_[8] + row - off_[8];
    T* __restrict d0 = dst_[0] + row;
    T* __restrict d1 = dst_[1] + row;
    T* __restrict d2 = dst_[2] + row;
    T* __restrict d3 = dst_[3] + row;
    T* __restrict d4 = dst_[4] + row;
    T* __restrict d5 = dst_[5] + row;
    T* __restrict d6 = dst_[6] + row;
    T* __restrict d7 = dst_[7] + row;
    T* __restrict d8 = dst_[8] + row;
    T acc = T(0);
    const int n = width_;
#pragma omp simd reduction(+ : acc)
    for (int x = 0; x < n; ++x) {
      T f[9] = {s0[x], s1[x], s2[x], s3[x], s4[x], s5[x], s6[x], s7[x], s8[x]};
      acc += d2q9::collide<T, kForce, kLes>(f, r);
      d0[x] = f[0];
      d1[x] = f[1];
      d2[x] = f[2];
      d3[x] = f[3];
      d4[x] = f[4];
      d5[x] = f[5];
      d6[x] = f[6];
      d7[x] = f[7];
      d8[x] = f[8];
    }
    total += static_cast<double>(acc);
  }
  return total;
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

template <typename T>
double Lattice<T>::step() {
  fill_halo();
  for (auto& acc : segment_acc_) std::fill(acc.begin(), acc.end(), Vec2::Zero());
  for (auto& acc : obstacle_acc_) std::fill(acc.begin(), acc.end(), Vec2::Zero());
  double usq = 0.0;
#pragma omp parallel num_threads(threads_) if (threads_ > 1) reduction(+ : usq)
  {
    const int nt = omp_get_num_threads();
    const int tid = omp_get_thread_num();
    const int y0 = static_cast<int>(static_cast<std::int64_t>(height_) * tid / nt);
    const int y1 = static_cast<int>(static_cast<std::int64_t>(height_) * (tid + 1) / nt);
    if (les_)
      usq += forced_ ? bulk<true, true>(y0, y1) : bulk<false, true>(y0, y1);
    else
      usq += forced_ ? bulk<true, false>(y0, y1) : bulk<false, false>(y0, y1);
#pragma omp barrier
    const std::size_t n = special_.size();
    boundary(n * tid / nt, n * (tid + 1) / nt, tid);
    const std::size_t m = solid_idx_.size();
    for (std::size_t k = m * tid / nt; k < m * (tid + 1) / nt; ++k)
      for (int i = 0; i < 9; ++i) dst_[i][solid_idx_[k]] = T(0);
    if (!sponge_.empty()) {
#pragma omp barrier
      const std::size_t ns = sponge_.size();
      absorb(ns * tid / nt, ns * (tid + 1) / nt);
    }
  }
  for (int s = 0; s < segment_count_; ++s) {
    Vec2 sum = Vec2::Zero();
    for (const auto& acc : segment_acc_) sum += acc[s];
    segment_force_[s] = sum;
  }
  for (int s = 0; s < max_label_; ++s) {
    Vec2 sum = Vec2::Zero();
    for (const auto& acc : obstacle_acc_) sum += acc[s];
    obstacle_force_[s] = sum;
  }
  std::swap(src_, dst_);
  return usq;
}

template <typename T>
void Lattice<T>::moments(std::ptrdiff_t id, T& rho, T& ux, T& uy) const {
  T f[9];
  for (int i = 0; i < 9; ++i) f[i] = src_[i][id];
  rho = T(1) + f[0] + f[1] + f[2] + f[3] + f[4] + f[5] + f[6] + f[7] + f[8];
  // The stored populations are post-collision: their momentum holds the whole body force,
  // the physical velocity (Guo) holds half of it.
  ux = (f[1] - f[3] + f[5] - f[6] - f[7] + f[8]) / rho - T(0.5) * relax_.gx;
  uy = (f[2] - f[4] + f[5] + f[6] - f[7] - f[8]) / rho - T(0.5) * relax_.gy;
}

template <typename T>
void Lattice<T>::initialize(const Eigen::MatrixXd& rho, const Eigen::MatrixXd& ux,
                            const Eigen::MatrixXd& uy) {
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const std::ptrdiff_t id = idx(x, y);
      T f[9] = {};
      if (labels_[y * width_ + x] == 0)
        d2q9::equilibrium<T>(T(rho(y, x)), T(ux(y, x)), T(uy(y, x)), f);
      for (int i = 0; i < 9; ++i) src_[i][id] = f[i];
    }
}

template <typename T>
void Lattice<T>::read(FlowField& out) const {
  out.density.resize(height_, width_);
  out.ux.resize(height_, width_);
  out.uy.resize(height_, width_);
  out.labels.resize(height_, width_);
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      const int label = labels_[y * width_ + x];
      out.labels(y, x) = label;
      T rho = T(1), ux = T(0), uy = T(0);
      if (label == 0) moments(idx(x, y), rho, ux, uy);
      out.density(y, x) = rho;
      out.ux(y, x) = ux;
      out.uy(y, x) = uy;
    }
}

template <typename T>
double Lattice<T>::density(int x, int y) const {
  if (labels_[y * width_ + x] != 0) return 1.0;
  T rho, ux, uy;
  moments(idx(x, y), rho, ux, uy);
  return rho;
}

template <typename T>
Vec2 Lattice<T>::velocity(int x, int y) const {
  if (labels_[y * width_ + x] != 0) return Vec2::Zero();
  T rho, ux, uy;
  moments(idx(x, y), rho, ux, uy);
  return Vec2(ux, uy);
}

template <typename T>
double Lattice<T>::total_mass() const {
  // Sum the deviations first: adding 1 per cell in float would swamp them.
  double deviation = 0.0;
  std::int64_t cells = 0;
  for (int y = 0; y < height_; ++y)
    for (int x = 0; x < width_; ++x) {
      if (labels_[y * width_ + x] != 0) continue;
      const std::ptrdiff_t id = idx(x, y);
      for (int i = 0; i < 9; ++i) deviation += static_cast<double>(src_[i][id]);
      ++cells;
    }
  return static_cast<double>(cells) + deviation;
}

}  // namespace

std::unique_ptr<LatticeBase> make_lattice(const Options& options, const Eigen::MatrixXi& labels) {
  if (options.precision == Precision::kDouble)
    return std::make_unique<Lattice<double>>(options, labels);
  return std::make_unique<Lattice<float>>(options, labels);
}

}  // namespace hair25d::fluid
