// Construction, the bulk kernel, the step and the read-out of the D2Q9 lattice. The domain
// sides live in a one-cell halo refilled before every step (lattice_boundary.cpp), so the
// bulk never tests where it is.
#ifdef __linux__
#include <sys/mman.h>
#endif

#if defined(__SSE2__)
#include <immintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <string>

#include "hair25d/core/error.h"

#include "lattice_d2q9.h"

namespace hair25d::fluid {
namespace detail {

template <typename T>
Lattice<T>::Lattice(const Options& o, const Eigen::MatrixXi& labels)
    : LatticeBase(o.width, o.height,
                  std::max(1, std::min(o.threads, o.width * o.height / kCellsPerThread))),
      width_(o.width),
      height_(o.height),
      threads_(pool.size()) {
  // Rows padded to whole cache lines, and never to a multiple of 512 bytes: rows whose length
  // is a power of two map the three rows a cell reads onto the same cache sets.
  std::size_t stride = round_up(static_cast<std::size_t>(width_) + 2, kAlign);
  while ((stride * sizeof(T)) % 512 == 0) stride += kAlign;
  stride_ = static_cast<std::ptrdiff_t>(stride);
  // Planes staggered by 192 bytes modulo 4 KiB so the 18 streams do not alias either.
  const std::size_t used = 2 * kAlign + (static_cast<std::size_t>(height_) + 2) * stride;
  plane_ = round_up(used, 4096 / sizeof(T)) + 192 / sizeof(T);
  // Out of cache the 18 streams walk hundreds of MiB: 2 MiB pages spare the TLB. Advise the
  // kernel before the first touch so the pages are huge from the start.
  constexpr std::size_t kHuge = std::size_t{2} << 20;
  const std::size_t bytes = round_up((18 * plane_ + kAlign) * sizeof(T), kHuge);
  storage_.reset(static_cast<T*>(std::aligned_alloc(kHuge, bytes)));
  if (!storage_)
    throw Error("fluid::Solver: cannot allocate " + std::to_string(bytes >> 20) + " MiB for a " +
                std::to_string(width_) + " x " + std::to_string(height_) + " lattice");
#ifdef __linux__
  madvise(storage_.get(), bytes, MADV_HUGEPAGE);  // a hint: failure only costs speed
#endif
  std::fill(storage_.get(), storage_.get() + bytes / sizeof(T), T(0));
  stream_ = o.stores == Stores::kStreaming ||
            (o.stores == Stores::kAuto &&
             static_cast<double>(18 * plane_ * sizeof(T)) > kStreamingStoresAbove);
  const auto address = reinterpret_cast<std::uintptr_t>(storage_.get());
  const std::size_t shift = (64 - address % 64) % 64 / sizeof(T);
  for (int i = 0; i < 9; ++i) {
    src_[i] = storage_.get() + shift + i * plane_;
    dst_[i] = storage_.get() + shift + (9 + i) * plane_;
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

namespace {

// Copies one block of relaxed populations to the destination row with non-temporal stores:
// whole cache lines go to memory without first being read (no write-allocate) and without
// evicting the source rows the next cells read. `dst` is 64-byte aligned (rows are).
template <typename T, int kBlock>
[[gnu::always_inline]] inline void stream_block(const T (&buf)[kBlock], T* __restrict dst, int m) {
#if defined(__SSE2__)
  constexpr int kLanes = 16 / static_cast<int>(sizeof(T));
  int k = 0;
  for (; k + kLanes <= m; k += kLanes) {
    if constexpr (sizeof(T) == 4)
      _mm_stream_ps(reinterpret_cast<float*>(dst + k),
                    _mm_load_ps(reinterpret_cast<const float*>(buf + k)));
    else
      _mm_stream_pd(reinterpret_cast<double*>(dst + k),
                    _mm_load_pd(reinterpret_cast<const double*>(buf + k)));
  }
  for (; k < m; ++k) dst[k] = buf[k];
#else
  for (int k = 0; k < m; ++k) dst[k] = buf[k];
#endif
}

}  // namespace

template <typename T>
template <bool kForce, bool kLes, bool kStream>
double Lattice<T>::bulk(int y0, int y1) {
  double total = 0.0;
  const d2q9::Relaxation<T> r = relax_;
  const int n = width_;
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
    T acc = T(0);
    if constexpr (!kStream) {
      T* __restrict d0 = dst_[0] + row;
      T* __restrict d1 = dst_[1] + row;
      T* __restrict d2 = dst_[2] + row;
      T* __restrict d3 = dst_[3] + row;
      T* __restrict d4 = dst_[4] + row;
      T* __restrict d5 = dst_[5] + row;
      T* __restrict d6 = dst_[6] + row;
      T* __restrict d7 = dst_[7] + row;
      T* __restrict d8 = dst_[8] + row;
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
    } else {
      // The same loop into a small buffer in L1, then streamed out: GCC has no way to make
      // the vectoriser emit non-temporal stores itself. 4 cache lines per plane per block.
      constexpr int kBlock = 256 / static_cast<int>(sizeof(T));
      alignas(64) T b0[kBlock], b1[kBlock], b2[kBlock], b3[kBlock], b4[kBlock], b5[kBlock],
          b6[kBlock], b7[kBlock], b8[kBlock];
      for (int x0 = 0; x0 < n; x0 += kBlock) {
        const int m = std::min(kBlock, n - x0);
#pragma omp simd reduction(+ : acc)
        for (int k = 0; k < m; ++k) {
          const int x = x0 + k;
          T f[9] = {s0[x], s1[x], s2[x], s3[x], s4[x], s5[x], s6[x], s7[x], s8[x]};
          acc += d2q9::collide<T, kForce, kLes>(f, r);
          b0[k] = f[0];
          b1[k] = f[1];
          b2[k] = f[2];
          b3[k] = f[3];
          b4[k] = f[4];
          b5[k] = f[5];
          b6[k] = f[6];
          b7[k] = f[7];
          b8[k] = f[8];
        }
        const std::ptrdiff_t at = row + x0;
        stream_block<T, kBlock>(b0, dst_[0] + at, m);
        stream_block<T, kBlock>(b1, dst_[1] + at, m);
        stream_block<T, kBlock>(b2, dst_[2] + at, m);
        stream_block<T, kBlock>(b3, dst_[3] + at, m);
        stream_block<T, kBlock>(b4, dst_[4] + at, m);
        stream_block<T, kBlock>(b5, dst_[5] + at, m);
        stream_block<T, kBlock>(b6, dst_[6] + at, m);
        stream_block<T, kBlock>(b7, dst_[7] + at, m);
        stream_block<T, kBlock>(b8, dst_[8] + at, m);
      }
    }
    total += static_cast<double>(acc);
  }
#if defined(__SSE2__)
  // Non-temporal stores are weakly ordered: make them visible before the chunk is reported
  // done, since the next step reads these rows on any thread.
  if constexpr (kStream) _mm_sfence();
#endif
  return total;
}

template <typename T>
double Lattice<T>::bulk_rows(int y0, int y1) {
  if (stream_) {
    if (les_) return forced_ ? bulk<true, true, true>(y0, y1) : bulk<false, true, true>(y0, y1);
    return forced_ ? bulk<true, false, true>(y0, y1) : bulk<false, false, true>(y0, y1);
  }
  if (les_) return forced_ ? bulk<true, true, false>(y0, y1) : bulk<false, true, false>(y0, y1);
  return forced_ ? bulk<true, false, false>(y0, y1) : bulk<false, false, false>(y0, y1);
}

template <typename T>
double Lattice<T>::step() {
  fill_halo();
  for (auto& acc : segment_acc_) std::fill(acc.begin(), acc.end(), Vec2::Zero());
  for (auto& acc : obstacle_acc_) std::fill(acc.begin(), acc.end(), Vec2::Zero());
  // Rows go out in chunks; every pass after the bulk writes only the cell it works on and
  // reads only the source planes, so a chunk does all passes for its rows with no barrier
  // in between (all three cell lists are in row order).
  const int rows =
      threads_ > 1 ? std::max(4, (height_ + kChunksPerStep - 1) / kChunksPerStep) : height_;
  const int chunks = (height_ + rows - 1) / rows;
  for (auto& u : usq_) u.value = 0.0;
  pool.run(chunks, [&](int c, int slot) {
    const int y0 = c * rows, y1 = std::min(height_, y0 + rows);
    double& usq = usq_[slot].value;
    usq += bulk_rows(y0, y1);
    const std::ptrdiff_t lo = idx(-1, y0), hi = idx(-1, y1);
    const auto sb = std::partition_point(special_.begin(), special_.end(),
                                         [&](const Special& sp) { return sp.idx < lo; });
    const auto se =
        std::partition_point(sb, special_.end(), [&](const Special& sp) { return sp.idx < hi; });
    boundary(static_cast<std::size_t>(sb - special_.begin()),
             static_cast<std::size_t>(se - special_.begin()), slot);
    const auto ob = std::lower_bound(solid_idx_.begin(), solid_idx_.end(), lo);
    const auto oe = std::lower_bound(ob, solid_idx_.end(), hi);
    for (auto k = ob; k != oe; ++k)
      for (int i = 0; i < 9; ++i) dst_[i][*k] = T(0);
    const auto ab = std::partition_point(sponge_.begin(), sponge_.end(),
                                         [&](const SpongeCell& sc) { return sc.idx < lo; });
    const auto ae =
        std::partition_point(ab, sponge_.end(), [&](const SpongeCell& sc) { return sc.idx < hi; });
    absorb(static_cast<std::size_t>(ab - sponge_.begin()),
           static_cast<std::size_t>(ae - sponge_.begin()));
  });
  double usq = 0.0;
  for (const auto& u : usq_) usq += u.value;
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

}  // namespace detail

std::unique_ptr<LatticeBase> make_lattice(const Options& options, const Eigen::MatrixXi& labels) {
  if (options.precision == Precision::kDouble)
    return std::make_unique<detail::Lattice<double>>(options, labels);
  return std::make_unique<detail::Lattice<float>>(options, labels);
}

}  // namespace hair25d::fluid
