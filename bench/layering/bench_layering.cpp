// Layering time per image (paper §7: 0.031 s per image, reported as the
// counter paper_s and in the label) on generated drawings with about 10, 40
// and 160 regions at 1024 × 1024, and at 640 × 480 for comparison. Region and
// pair counts are counters; the drawing is made once, outside the timed loop.
// The first stages (outline fill, crack-grid trace) are timed alone too.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>

#include "bench_case.h"
#include "hair25d/generator/generator.h"
#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"

namespace {

using namespace hair25d;

constexpr double kPaperSeconds = 0.031;  // §7, per image, on the authors' machine

// The benchmark arguments name a case: a target region count and an image
// size (bench_case.h).
const AnnotatedCase& case_for(int regions, int width, int height) {
  static std::map<std::tuple<int, int, int>, AnnotatedCase> cache;
  const auto key = std::make_tuple(regions, width, height);
  auto it = cache.find(key);
  if (it == cache.end()) {
    it = cache.emplace(key, bench::layering_case(regions, width, height)).first;
  }
  return it->second;
}

const AnnotatedCase& case_of(const benchmark::State& state) {
  return case_for(static_cast<int>(state.range(0)), static_cast<int>(state.range(1)),
                  static_cast<int>(state.range(2)));
}

void describe(benchmark::State& state, const AnnotatedCase& c) {
  state.counters["regions"] = static_cast<double>(c.regions.labels().size());
  state.counters["pairs"] = static_cast<double>(c.pairs.size());
  state.counters["pixels"] = static_cast<double>(c.image.width()) * c.image.height();
  state.counters["paper_s"] = kPaperSeconds;
  state.SetLabel("paper: 0.031 s/image");
}

void sizes(benchmark::internal::Benchmark* b) {
  b->ArgNames({"regions", "w", "h"});
  for (int regions : {10, 40, 160}) b->Args({regions, 1024, 1024});
  for (int regions : {10, 40}) b->Args({regions, 640, 480});
}

// The whole layering of one image (what eval-layering times).
void BM_LayerRegions(benchmark::State& state) {
  const AnnotatedCase& c = case_of(state);
  for (auto _ : state) {
    layering::Result r = layering::layer_regions(c.image, c.regions);
    benchmark::DoNotOptimize(r.depth);
  }
  describe(state, c);
}
// CPU is the process's (all threads: the layering's own and OpenCV's), so
// it stays comparable when work is spread over cores.
BENCHMARK(BM_LayerRegions)
    ->Apply(sizes)
    ->Unit(benchmark::kMillisecond)
    ->MeasureProcessCPUTime()
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// Outline pixels given to their nearest region (step 1).
void BM_FillOutlines(benchmark::State& state) {
  const AnnotatedCase& c = case_of(state);
  for (auto _ : state) {
    layering::OutlineFill f = layering::fill_outlines(c.regions);
    benchmark::DoNotOptimize(f.labels.data());
  }
  describe(state, c);
}
BENCHMARK(BM_FillOutlines)
    ->Args({40, 1024, 1024})
    ->Args({160, 1024, 1024})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// Boundary extraction alone on the filled map (the crack-grid trace, step 2).
void BM_BoundaryGraph(benchmark::State& state) {
  const AnnotatedCase& c = case_of(state);
  const LabelMap filled = layering::fill_outlines(c.regions).labels;
  for (auto _ : state) {
    layering::BoundaryGraph g = layering::build_boundary_graph(filled);
    benchmark::DoNotOptimize(g.junctions);
  }
  describe(state, c);
}
BENCHMARK(BM_BoundaryGraph)
    ->Args({40, 1024, 1024})
    ->Args({160, 1024, 1024})
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
