// Layering time per image (paper §7: 0.031 s per image) on generated drawings
// with about 10, 40 and 160 regions. Region and pair counts are reported as
// counters; the drawing is made once, outside the timed loop.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <map>

#include "hair25d/generator/generator.h"
#include "hair25d/layering/boundary_graph.h"
#include "hair25d/layering/layering.h"

namespace {

using namespace hair25d;

// The benchmark argument names a case: a target region count and an image
// size. The strand count is raised until the generated case has at least that
// many regions (the generator splits strands into several regions, so the
// ratio is not fixed). 1024 is ~40 regions on a 1024 × 1024 image.
struct CaseSize {
  int regions, width, height;
};
const std::map<int, CaseSize> kSizes = {
    {10, {10, 640, 480}}, {40, {40, 640, 480}}, {1024, {40, 1024, 1024}}, {160, {160, 1280, 960}}};

const AnnotatedCase& case_for(int id) {
  static std::map<int, AnnotatedCase> cache;
  auto it = cache.find(id);
  if (it == cache.end()) {
    const CaseSize size = kSizes.at(id);
    const int regions = size.regions;
    generator::Options o;
    o.width = size.width;
    o.height = size.height;
    o.seed = 42;
    AnnotatedCase c;
    for (int strands = std::max(1, regions * 2 / 3);; strands += std::max(1, strands / 10)) {
      o.strand_count = strands;
      c = generator::generate_case(o);
      if (static_cast<int>(c.regions.labels().size()) >= regions || strands > 4 * regions) break;
    }
    it = cache.emplace(id, std::move(c)).first;
  }
  return it->second;
}

void BM_LayerRegions(benchmark::State& state) {
  const AnnotatedCase& c = case_for(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    layering::Result r = layering::layer_regions(c.image, c.regions);
    benchmark::DoNotOptimize(r.depth);
  }
  state.counters["regions"] = static_cast<double>(c.regions.labels().size());
  state.counters["pairs"] = static_cast<double>(c.pairs.size());
  state.counters["pixels"] = static_cast<double>(c.image.width()) * c.image.height();
}
BENCHMARK(BM_LayerRegions)
    ->Arg(10)
    ->Arg(40)
    ->Arg(1024)
    ->Arg(160)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// Boundary extraction alone on the filled map (the crack-grid trace).
void BM_BoundaryGraph(benchmark::State& state) {
  const AnnotatedCase& c = case_for(static_cast<int>(state.range(0)));
  const LabelMap filled = layering::fill_outlines(c.regions).labels;
  for (auto _ : state) {
    layering::BoundaryGraph g = layering::build_boundary_graph(filled);
    benchmark::DoNotOptimize(g.junctions);
  }
}
BENCHMARK(BM_BoundaryGraph)
    ->Arg(40)
    ->Arg(160)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
