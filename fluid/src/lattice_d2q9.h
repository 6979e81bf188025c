// The D2Q9 lattice, templated on the scalar type: structure of arrays, one fused pull
// stream-and-collide pass over the bulk with no branches (lattice_d2q9.cpp), then a short pass
// over the cells next to obstacles and filaments and the halo of the domain sides
// (lattice_boundary.cpp). Private to the module.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <memory>
#include <vector>

#include "d2q9.h"
#include "lattice.h"

// The bulk kernel is compiled three times, for AVX-512 (x86-64-v4), AVX2+FMA (x86-64-v3) and
// the baseline, and the loader picks the best the CPU runs: same binary everywhere. AVX2 has
// twice the baseline's vector width; AVX-512 (still 256-bit vectors, GCC's default tuning)
// brings 32 vector registers, which the 9 populations and their moments need: the in-cache
// kernel ran about 1.7x faster than the AVX2 one on this machine (docs/fluid.md). A build can
// define HAIR25D_FLUID_CLONES empty to compile one path only (e.g. to test the baseline).
#if !defined(HAIR25D_FLUID_CLONES) && defined(__x86_64__) && defined(__GNUC__) && \
    !defined(__clang__)
#define HAIR25D_FLUID_CLONES \
  __attribute__((target_clones("arch=x86-64-v4", "arch=x86-64-v3", "default")))
#elif !defined(HAIR25D_FLUID_CLONES)
#define HAIR25D_FLUID_CLONES
#endif

namespace hair25d::fluid::detail {

using d2q9::kCx;
using d2q9::kCy;
using d2q9::kOpp;
using d2q9::kW;

// Below ~16k cells per thread a second thread does not pay for waking it.
constexpr int kCellsPerThread = 16384;
constexpr int kChunksPerStep = 16;  // row chunks per step with several threads
constexpr int kSideLeft = 0, kSideRight = 1, kSideTop = 2, kSideBottom = 3;

inline int side_index(SideName s) {
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

inline std::size_t round_up(std::size_t n, std::size_t m) { return (n + m - 1) / m * m; }

inline double cross(const Vec2& a, const Vec2& b) { return a.x() * b.y() - a.y() * b.x(); }

// Where along the link a -> b (a outside, b inside) the polygon's boundary is, as a fraction
// in [0, 1]; 1/2 when no edge is found (degenerate input).
double wall_fraction(const Polyline& poly, const Vec2& a, const Vec2& b);

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
  bool streaming_stores() const override { return stream_; }

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
  template <bool kForce, bool kLes, bool kStream>
  HAIR25D_FLUID_CLONES double bulk(int y0, int y1);
  double bulk_rows(int y0, int y1);
  void boundary(std::size_t begin, std::size_t end, int tid);
  void fill_halo();
  T halo_value(int hx, int hy, int i, int x, int y) const;
  void moments(std::ptrdiff_t id, T& rho, T& ux, T& uy) const;

  int width_, height_, threads_;
  struct alignas(64) Partial {
    double value = 0.0;
  };
  std::vector<Partial> usq_ = std::vector<Partial>(64);  // per thread slot, own cache line
  std::ptrdiff_t stride_ = 0;
  std::size_t plane_ = 0;
  struct Free {
    void operator()(void* p) const { std::free(p); }
  };
  std::unique_ptr<T, Free> storage_;  // 18 planes, 2 MiB aligned (huge pages where possible)
  std::array<T*, 9> src_{}, dst_{};
  std::array<std::ptrdiff_t, 9> off_{};
  d2q9::Relaxation<T> relax_{};
  bool forced_ = false;
  bool les_ = false;
  bool stream_ = false;  // non-temporal stores in the bulk (Options::stores)
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

}  // namespace hair25d::fluid::detail
