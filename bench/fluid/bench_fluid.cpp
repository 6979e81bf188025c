// Speed of the D2Q9 wind solver: million lattice updates per second (MLUPS) from a grid that
// fits in cache (256 x 192) to one that does not (2048 x 1024), on 1 and 2 threads, with moving
// hair-like filaments in the flow; and in the same run the memory bandwidth (STREAM-style
// triad) and the fraction of the bandwidth roofline the solver reaches (72 bytes per cell
// update in float, 144 in double: 9 populations read and 9 written):
//   roofline_frac = MLUPS x 72 B / triad bandwidth in counted bytes (same thread count).
// The solver writes with non-temporal stores once the lattice exceeds the L3 (the label of
// every BM_Step says which stores ran): those skip the write-allocate read that ordinary
// stores, and the triad, pay for. So out of cache the fraction can exceed 1 without any
// error: the triad's counted 24 bytes are 32 on the bus.
#include <benchmark/benchmark.h>
#include <emmintrin.h>
#include <omp.h>
#include <sys/mman.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <memory>
#include <vector>

#include "hair25d/fluid/solver.h"
#include "hair25d/fluid/wind.h"

namespace {

using hair25d::Polyline;
using hair25d::Vec2;
namespace fluid = hair25d::fluid;

// STREAM triad a = b + s c in double over three 128 MiB arrays (12 times the 32 MiB L3),
// best of `runs`, on `threads` threads, in counted bytes as STREAM counts them: 24 per element
// (2 reads + 1 write), although with ordinary stores the bus also carries the write-allocate
// read of `a` (32 bytes). The arrays get the same 2 MiB-page advice as the lattice, so the
// TLB does not handicap the triad. `non_temporal` = true writes `a` with streaming stores
// (no write-allocate): printed for information only, never used for the roofline.
struct Free {
  void operator()(void* p) const { std::free(p); }
};
double triad_bandwidth(int threads, int runs = 7, bool non_temporal = false) {
  const std::size_t n = std::size_t{1} << 24;
  const std::size_t bytes = n * sizeof(double);
  auto make = [&] {
    std::unique_ptr<double, Free> p(static_cast<double*>(std::aligned_alloc(2 << 20, bytes)));
    if (p) madvise(p.get(), bytes, MADV_HUGEPAGE);
    return p;
  };
  const auto pa = make(), pb = make(), pc = make();
  if (!pa || !pb || !pc) return 0.0;
  double* __restrict a = pa.get();
  const double* __restrict b = pb.get();
  const double* __restrict c = pc.get();
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = 0.0;
    pb.get()[i] = 1.0;
    pc.get()[i] = 2.0;
  }
  double best = 0.0;
  for (int r = 0; r < runs; ++r) {
    const auto t0 = std::chrono::steady_clock::now();
    const double s = 3.0 + r;
    if (non_temporal) {
#pragma omp parallel for num_threads(threads) schedule(static)
      for (std::size_t i = 0; i < n; i += 2)
        _mm_stream_pd(
            a + i, _mm_add_pd(_mm_load_pd(b + i), _mm_mul_pd(_mm_set1_pd(s), _mm_load_pd(c + i))));
      _mm_sfence();
    } else {
#pragma omp parallel for simd num_threads(threads) schedule(static)
      for (std::size_t i = 0; i < n; ++i) a[i] = b[i] + s * c[i];
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    benchmark::DoNotOptimize(a);
    benchmark::ClobberMemory();
    best = std::max(best, 3.0 * 8.0 * static_cast<double>(n) / seconds);
  }
  return best;
}

std::map<int, double>& bandwidth() {
  static std::map<int, double> by_threads;
  return by_threads;
}

void BM_Triad(benchmark::State& state) {
  const int threads = static_cast<int>(state.range(0));
  double bw = 0.0;
  for (auto _ : state) bw = triad_bandwidth(threads, 3);
  state.counters["GB/s"] = bw / 1e9;
}
BENCHMARK(BM_Triad)
    ->Arg(1)
    ->Arg(2)
    ->Iterations(1)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true)
    ->UseRealTime();

// The memory traffic of a D2Q9 step without its arithmetic: 9 float planes of a 2048 x 1024
// grid copied to 9 others (72 bytes per cell), with ordinary (arg 1) or non-temporal (arg 2)
// stores, on 1 or 2 threads. The ceiling a kernel with that store kind can reach out of cache,
// in MLUPS; planes staggered like the lattice's so the streams do not alias.
void BM_CopyStreams(benchmark::State& state) {
  const bool non_temporal = state.range(0) == 2;
  const int threads = static_cast<int>(state.range(1));
  const std::size_t cells = std::size_t{2048} * 1024;
  const std::size_t plane = cells + 4096 / sizeof(float) + 48;  // 192 B stagger
  const std::size_t bytes = 18 * plane * sizeof(float) + (2 << 20);
  std::unique_ptr<float, Free> store(
      static_cast<float*>(std::aligned_alloc(2 << 20, bytes / (2 << 20) * (2 << 20))));
  if (!store) {
    state.SkipWithError("cannot allocate");
    return;
  }
  madvise(store.get(), bytes / (2 << 20) * (2 << 20), MADV_HUGEPAGE);
  float* p[18];
  for (int k = 0; k < 18; ++k) p[k] = store.get() + k * plane;
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < cells; ++i)
    for (int k = 0; k < 18; ++k) p[k][i] = 1e-3f * static_cast<float>(k);
  for (auto _ : state) {
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < cells; i += 4)
      for (int k = 0; k < 9; ++k) {
        const __m128 v = _mm_load_ps(p[k] + i);
        if (non_temporal)
          _mm_stream_ps(p[9 + k] + i, v);
        else
          _mm_store_ps(p[9 + k] + i, v);
      }
    _mm_sfence();
    std::swap_ranges(p, p + 9, p + 9);
    benchmark::ClobberMemory();
  }
  state.SetLabel(non_temporal ? "non-temporal stores" : "ordinary stores");
  state.counters["MLUPS"] =
      benchmark::Counter(static_cast<double>(cells) * static_cast<double>(state.iterations()) / 1e6,
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_CopyStreams)
    ->ArgsProduct({{1, 2}, {1, 2}})
    ->ArgNames({"stores", "threads"})
    ->MinTime(0.3)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true)
    ->UseRealTime();

// Hair-like filaments: `count` wavy polylines hanging across the stream, 2 cells per segment.
std::vector<fluid::Filament> hair(int width, int height, int count, double phase) {
  std::vector<fluid::Filament> out;
  for (int k = 0; k < count; ++k) {
    fluid::Filament f;
    const double x0 = width * (0.3 + 0.4 * k / std::max(1, count - 1));
    const double len = 0.5 * height;
    for (double s = 0; s <= len; s += 2.0) {
      const double sway = 3.0 * std::sin(0.05 * s + phase + k);
      f.points.push_back(Vec2(x0 + sway + 0.2 * s, 0.2 * height + s));
      f.velocities.push_back(Vec2(0.01 * std::cos(0.05 * s + phase + k), 0.0));
    }
    out.push_back(std::move(f));
  }
  return out;
}

void BM_Step(benchmark::State& state) {
  const int width = static_cast<int>(state.range(0));
  const int height = static_cast<int>(state.range(1));
  const int threads = static_cast<int>(state.range(2));
  const bool dbl = state.range(3) != 0;
  const int filaments = static_cast<int>(state.range(4));
  const fluid::Stores stores = static_cast<fluid::Stores>(state.range(5));
  fluid::Options o;
  o.width = width;
  o.height = height;
  o.tau = 0.56;
  o.threads = threads;
  o.stores = stores;
  o.precision = dbl ? fluid::Precision::kDouble : fluid::Precision::kFloat;
  o.left.kind = fluid::SideKind::kInlet;
  o.left.velocity = Vec2(0.05, 0.0);
  o.right.kind = fluid::SideKind::kOutflow;
  o.top.kind = o.bottom.kind = fluid::SideKind::kWall;
  fluid::Solver solver(o);
  state.SetLabel(solver.streaming_stores() ? "non-temporal stores" : "ordinary stores");
  solver.step(5);
  int frame = 0;
  std::size_t segments = 0;
  for (auto _ : state) {
    // The filaments move every step, as the hair skeletons do.
    if (filaments > 0) {
      const auto f = hair(width, height, filaments, 0.01 * frame);
      segments = 0;
      for (const auto& fil : f) segments += fil.points.size() - 1;
      solver.set_filaments(f);
    }
    solver.step(1);
    ++frame;
  }
  const double cells = static_cast<double>(width) * height;
  state.counters["MLUPS"] = benchmark::Counter(
      cells * static_cast<double>(state.iterations()) / 1e6, benchmark::Counter::kIsRate);
  state.counters["segments"] = static_cast<double>(segments);
  const double bytes = dbl ? 144.0 : 72.0;
  const auto bw = bandwidth().find(threads);
  if (bw != bandwidth().end()) {
    // Roofline in MLUPS; the fraction is computed per repetition, the median is reported.
    state.counters["roofline_MLUPS"] = bw->second / bytes / 1e6;
    state.counters["roofline_frac"] =
        benchmark::Counter(cells * static_cast<double>(state.iterations()) * bytes / bw->second,
                           benchmark::Counter::kIsRate);
  }
}

// stores: 0 = automatic (what the solver does by default: non-temporal stores once the
// populations exceed the L3), 1 = ordinary stores, 2 = non-temporal stores. The label says
// which ran. Both forced kinds are swept for float without filaments, to show the crossover.
void step_args(benchmark::internal::Benchmark* b) {
  const int sizes[][2] = {{256, 192}, {512, 384}, {1024, 768}, {2048, 1024}};
  const auto auto_stores = static_cast<int>(fluid::Stores::kAuto);
  for (int dbl : {0, 1})
    for (const auto& s : sizes)
      for (int threads : {1, 2})
        for (int fil : {0, 24}) {
          if (dbl && fil) continue;
          b->Args({s[0], s[1], threads, dbl, fil, auto_stores});
          if (dbl || fil) continue;
          for (auto forced : {fluid::Stores::kCached, fluid::Stores::kStreaming})
            b->Args({s[0], s[1], threads, dbl, fil, static_cast<int>(forced)});
        }
  b->ArgNames({"w", "h", "threads", "double", "filaments", "stores"});
}
BENCHMARK(BM_Step)
    ->Apply(step_args)
    ->MinTime(0.3)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true)
    ->UseRealTime();

// Cost of cutting the lattice links of moving filaments alone (done every step).
void BM_SetFilaments(benchmark::State& state) {
  fluid::Options o;
  o.width = 512;
  o.height = 384;
  o.left.kind = o.right.kind = o.top.kind = o.bottom.kind = fluid::SideKind::kWall;
  fluid::Solver solver(o);
  const int count = static_cast<int>(state.range(0));
  int frame = 0;
  std::size_t segments = 0;
  for (auto _ : state) {
    const auto f = hair(o.width, o.height, count, 0.01 * frame++);
    segments = 0;
    for (const auto& fil : f) segments += fil.points.size() - 1;
    solver.set_filaments(f);
  }
  state.counters["segments/s"] =
      benchmark::Counter(static_cast<double>(segments) * static_cast<double>(state.iterations()),
                         benchmark::Counter::kIsRate);
}
BENCHMARK(BM_SetFilaments)->Arg(8)->Arg(64)->Repetitions(5)->ReportAggregatesOnly(true);

// What the animation pays per frame: a 640 x 480 image at 4 px per cell (160 x 120 cells),
// default wind (200 px/s, gusts, turbulence) at 24 fps, 30 hair strands of 20 segments that
// move; the skeletons are re-cut every lattice step (arg 1) or once per frame (arg 0, the
// node velocities carry the motion within the frame). Reports frames per second.
void BM_WindFrame(benchmark::State& state) {
  const bool every_step = state.range(0) != 0;
  const int threads = static_cast<int>(state.range(1));
  fluid::WindSettings wind;
  fluid::SceneUnits scene;
  scene.image_width = 640;
  scene.image_height = 480;
  const fluid::LatticeParameters p = fluid::to_lattice(wind, scene);
  fluid::Options o = fluid::wind_tunnel_options(wind, p);
  o.threads = threads;
  fluid::Solver solver(o);
  const fluid::WindField field(wind, p);
  auto strands = [&](double t) {
    std::vector<fluid::Filament> out;
    for (int k = 0; k < 30; ++k) {
      fluid::Filament f;
      for (int j = 0; j <= 20; ++j) {
        const double sway = 4.0 * std::sin(2.0 * t + 0.3 * j + k);
        f.points.push_back(p.to_grid(Vec2(200 + 8 * k + sway, 100 + 12 * j)));
        f.velocities.push_back(
            p.to_lattice_velocity(Vec2(8.0 * std::cos(2.0 * t + 0.3 * j + k), 0.0)));
      }
      out.push_back(std::move(f));
    }
    return out;
  };
  int frame = 0;
  for (auto _ : state) {
    for (int k = 0; k < p.steps_per_frame; ++k) {
      const double t = (frame * p.steps_per_frame + k) * p.dt;
      if (every_step || k == 0) solver.set_filaments(strands(t));
      field.apply(solver, t);
      solver.step();
    }
    ++frame;
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
  state.counters["steps/frame"] = p.steps_per_frame;
  state.counters["cells"] = static_cast<double>(p.width) * p.height;
}
BENCHMARK(BM_WindFrame)
    ->ArgsProduct({{0, 1}, {1, 2}})
    ->ArgNames({"recut_every_step", "threads"})
    ->Repetitions(5)
    ->ReportAggregatesOnly(true)
    ->UseRealTime();

// Validation run, not a speed figure: Schafer & Turek (1996) 2D-1 (Re = 20, published
// Cd = 5.5795, Cl = 0.0106) at D cells per cylinder diameter, reported as counters.
void BM_SchaferTurek2D1(benchmark::State& state) {
  const int D = static_cast<int>(state.range(0));
  const double umax = 0.05, umean = 2.0 / 3.0 * umax;
  const int W = 22 * D, H = 41 * D / 10;
  fluid::Options o;
  o.width = W;
  o.height = H;
  o.tau = fluid::tau_of_viscosity(umean * D / 20.0);
  o.threads = 1;  // a validation: robust to a busy machine rather than fast
  o.left.kind = fluid::SideKind::kInlet;
  o.left.velocity = Vec2(umax, 0);
  for (int j = 0; j < H; ++j) o.left.profile.push_back(4.0 * (j + 0.5) * (H - j - 0.5) / (H * H));
  o.right.kind = fluid::SideKind::kOutflow;
  o.top.kind = o.bottom.kind = fluid::SideKind::kWall;
  Polyline circle;
  for (int k = 0; k < 192; ++k) {
    const double a = 2 * 3.14159265358979323846 * k / 192;
    circle.push_back(Vec2(2.0 * D, 2.0 * D) + 0.5 * D * Vec2(std::cos(a), std::sin(a)));
  }
  o.obstacle_polygons.push_back(circle);
  double cd = 0, cl = 0, steps = 0;
  for (auto _ : state) {
    fluid::Solver s(o);
    Eigen::MatrixXd ux(H, W);
    for (int j = 0; j < H; ++j) ux.row(j).setConstant(umax * o.left.profile[j]);
    s.initialize(Eigen::MatrixXd::Ones(H, W), ux, Eigen::MatrixXd::Zero(H, W));
    steps = fluid::run_to_steady(s, {400000, 1000, 1e-4}).steps;
    const Vec2 f = s.obstacle_forces().at(0).force;
    cd = 2 * f.x() / (umean * umean * D);
    cl = 2 * f.y() / (umean * umean * D);
  }
  state.counters["Cd"] = cd;
  state.counters["Cl"] = cl;
  state.counters["Cd_err_pct"] = 100.0 * (cd / 5.5795 - 1.0);
  state.counters["steps"] = steps;
}
BENCHMARK(BM_SchaferTurek2D1)
    ->Arg(10)
    ->Arg(20)
    ->Iterations(1)
    ->Unit(benchmark::kSecond)
    ->UseRealTime();

}  // namespace

int main(int argc, char** argv) {
  // The bandwidth the roofline fractions refer to is measured first, in this same run, and
  // again at the end: on a shared machine a difference between the two says the load changed.
  for (int threads : {1, 2}) {
    bandwidth()[threads] = triad_bandwidth(threads);
    std::printf(
        "triad bandwidth, %d thread(s): %.2f GB/s (counted 24 B per element, best of 7; "
        "non-temporal stores, for information: %.2f GB/s)\n",
        threads, bandwidth()[threads] / 1e9, triad_bandwidth(threads, 7, true) / 1e9);
  }
  std::fflush(stdout);
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  for (int threads : {1, 2})
    std::printf("triad bandwidth at the end, %d thread(s): %.2f GB/s (start: %.2f)\n", threads,
                triad_bandwidth(threads) / 1e9, bandwidth()[threads] / 1e9);
  return 0;
}
