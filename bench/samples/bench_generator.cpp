// Cost of one synthetic case (generator::generate_case) at growing sizes and
// strand counts, with and without the per-strand masks, per shading style.
#include <benchmark/benchmark.h>

#include "hair25d/generator/generator.h"

namespace {

namespace gen = hair25d::generator;

// Args: side (pixels, width; height is 5/4 of it), strands, masks (0/1).
void BM_GenerateCase(benchmark::State& state) {
  gen::Options o;
  o.width = static_cast<int>(state.range(0));
  o.height = o.width * 5 / 4;
  o.strand_count = static_cast<int>(state.range(1));
  o.strand_masks = state.range(2) != 0;
  o.line_width = 3.0;
  o.seed = 7;
  std::size_t regions = 0;
  for (auto _ : state) {
    const hair25d::AnnotatedCase c = gen::generate_case(o);
    regions = c.region_list.size();
    benchmark::DoNotOptimize(c.image.data());
  }
  state.counters["regions"] = static_cast<double>(regions);
  state.counters["Mpixels/s"] = benchmark::Counter(static_cast<double>(o.width) * o.height * 1e-6,
                                                   benchmark::Counter::kIsIterationInvariantRate);
}
BENCHMARK(BM_GenerateCase)
    ->ArgsProduct({{256, 512, 1024}, {12, 40}, {0, 1}})
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

// Arg: shading (0 flat, 1 two-tone, 2 gradient, 3 screentone), 1024 x 1024, 40 strands.
void BM_Shading(benchmark::State& state) {
  gen::Options o;
  o.width = 1024;
  o.height = 1024;
  o.strand_count = 40;
  o.shading = static_cast<gen::Shading>(state.range(0));
  o.strand_masks = false;
  o.seed = 7;
  for (auto _ : state) benchmark::DoNotOptimize(gen::generate_case(o).image.data());
}
BENCHMARK(BM_Shading)
    ->DenseRange(0, 3)
    ->Unit(benchmark::kMillisecond)
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
