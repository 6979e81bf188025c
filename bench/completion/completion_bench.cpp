// Completion time on generated 1024 × 1024 drawings with exact relations from
// the generator: with and without inpainting. Medians of 5 repetitions, wall
// time (strands and background are filled on two threads).
#include <benchmark/benchmark.h>

#include "common/completion_input.h"
#include "common/generated_cases.h"
#include "hair25d/completion/completion.h"

namespace {

using namespace hair25d;

// far_candidates < 0: the default.
void run(benchmark::State& state, bool inpaint, bool background = true, int far_candidates = -1) {
  const AnnotatedCase& c = bench::generated_case(static_cast<int>(state.range(0)));
  const completion::Input in = bench::completion_input(c);
  completion::Options o;
  o.inpaint_strands = inpaint;
  o.inpaint_background = inpaint && background;
  if (far_candidates >= 0) o.inpaint.far_candidates = far_candidates;
  completion::Result r;
  for (auto _ : state) {
    r = completion::complete_strands(in, o);
    benchmark::DoNotOptimize(r.strands.data());
  }
  state.counters["regions"] = static_cast<double>(c.regions.labels().size());
  state.counters["strands"] = static_cast<double>(r.strands.size());
  state.counters["joins"] = r.joins;
  state.counters["grown"] = r.roots + r.tips;
  state.counters["inpainted_px"] = r.strand_inpaint.filled + r.background_inpaint.filled;
}

void BM_CompletionWithoutInpainting(benchmark::State& state) { run(state, false); }
void BM_CompletionWithInpainting(benchmark::State& state) { run(state, true); }

// Strands inpainted, no background: the search of targets far from every
// source patch cut to the nearest far_candidates (default) or exact (0).
void BM_CompletionStrandInpainting(benchmark::State& state) { run(state, true, false); }
void BM_CompletionStrandInpaintingExactFar(benchmark::State& state) { run(state, true, false, 0); }

BENCHMARK(BM_CompletionWithoutInpainting)->Apply(bench::strand_counts)->UseRealTime();
BENCHMARK(BM_CompletionWithInpainting)->Apply(bench::strand_counts)->UseRealTime();
BENCHMARK(BM_CompletionStrandInpainting)->Apply(bench::strand_counts)->UseRealTime();
BENCHMARK(BM_CompletionStrandInpaintingExactFar)->Apply(bench::strand_counts)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
