// Segmentation steps (paper §3) on generated drawings of 512², 1024² and
// 2048² pixels with 40 strands: curve extraction, smoothing + Douglas–Peucker,
// constrained Delaunay mesh, graph cut, and the whole segment_image call.
// Goal: a 1024² drawing segmented in under 0.5 s on 2 cores.
#include <benchmark/benchmark.h>

#include <map>
#include <memory>

#include "hair25d/generator/generator.h"
#include "hair25d/segment/curves.h"
#include "hair25d/segment/graph_cut.h"
#include "hair25d/segment/mesh.h"
#include "hair25d/segment/segmenter.h"

namespace {

using namespace hair25d;

struct Input {
  AnnotatedCase drawing;
  segment::CurveResult curves;
  std::vector<Curve> simplified;
  TriMesh2 mesh;
};

// One drawing a size, made once: generating is not what is measured.
const Input& input(int side) {
  static std::map<int, std::unique_ptr<Input>> cache;
  auto& slot = cache[side];
  if (!slot) {
    slot = std::make_unique<Input>();
    generator::Options o;
    o.width = o.height = side;
    o.strand_count = 40;
    o.line_width = 3.0 * side / 1024.0 < 2.0 ? 2.0 : 3.0 * side / 1024.0;
    o.strand_masks = false;
    o.seed = 2024;
    slot->drawing = generator::generate_case(o);
    slot->curves = segment::extract_curves(slot->drawing.image);
    slot->simplified = segment::smooth_and_simplify(slot->curves.curves);
    slot->mesh = segment::build_mesh(slot->simplified, side, side).mesh;
  }
  return *slot;
}

void set_counters(benchmark::State& state, const Input& in) {
  state.counters["curves"] = static_cast<double>(in.simplified.size());
  state.counters["triangles"] = in.mesh.triangle_count();
  state.counters["labels"] = static_cast<double>(in.drawing.strokes->labels().size());
}

void BM_CurveExtraction(benchmark::State& state) {
  const Input& in = input(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(segment::extract_curves(in.drawing.image));
  set_counters(state, in);
}

void BM_SmoothSimplify(benchmark::State& state) {
  const Input& in = input(static_cast<int>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(segment::smooth_and_simplify(in.curves.curves));
  set_counters(state, in);
}

void BM_Mesh(benchmark::State& state) {
  const Input& in = input(static_cast<int>(state.range(0)));
  const int side = static_cast<int>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(segment::build_mesh(in.simplified, side, side));
  set_counters(state, in);
}

void BM_GraphCut(benchmark::State& state) {
  const Input& in = input(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(segment::graph_cut_labels(in.drawing.image, in.mesh,
                                                       *in.drawing.strokes, in.curves.line_mask));
  set_counters(state, in);
}

void BM_SegmentTotal(benchmark::State& state) {
  const Input& in = input(static_cast<int>(state.range(0)));
  for (auto _ : state)
    benchmark::DoNotOptimize(segment::segment_image(in.drawing.image, &*in.drawing.strokes));
  set_counters(state, in);
}

#define SEGMENT_BENCH(fn)             \
  BENCHMARK(fn)                       \
      ->Arg(512)                      \
      ->Arg(1024)                     \
      ->Arg(2048)                     \
      ->Unit(benchmark::kMillisecond) \
      ->UseRealTime()                 \
      ->Repetitions(5)                \
      ->ReportAggregatesOnly(true)

SEGMENT_BENCH(BM_CurveExtraction);
SEGMENT_BENCH(BM_SmoothSimplify);
SEGMENT_BENCH(BM_Mesh);
SEGMENT_BENCH(BM_GraphCut);
SEGMENT_BENCH(BM_SegmentTotal);

}  // namespace

BENCHMARK_MAIN();
