// Completion time on generated 1024 × 1024 drawings with exact relations from
// the generator: with and without inpainting. Medians of 5 repetitions, wall
// time (strands and background are filled on two threads).
#include <benchmark/benchmark.h>

#include <map>

#include "hair25d/completion/completion.h"
#include "hair25d/generator/generator.h"

namespace {

using namespace hair25d;

const AnnotatedCase& generated(int strands) {
  static std::map<int, AnnotatedCase> cache;
  auto it = cache.find(strands);
  if (it == cache.end()) {
    generator::Options o;
    o.width = 1024;
    o.height = 1024;
    o.strand_count = strands;
    o.seed = 7;
    o.strand_masks = false;
    it = cache.emplace(strands, generator::generate_case(o)).first;
  }
  return it->second;
}

void run(benchmark::State& state, bool inpaint) {
  const AnnotatedCase& c = generated(static_cast<int>(state.range(0)));
  completion::Input in;
  in.image = &c.image;
  in.regions = &c.regions;
  for (const AnnotatedPair& p : c.pairs) in.relations.push_back({p.a, p.b, p.relation, 1.0});
  in.head_center = c.head_center;
  completion::Options o;
  o.inpaint_strands = inpaint;
  o.inpaint_background = inpaint;
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

BENCHMARK(BM_CompletionWithoutInpainting)
    ->Arg(10)
    ->Arg(40)
    ->Arg(160)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);
BENCHMARK(BM_CompletionWithInpainting)
    ->Arg(10)
    ->Arg(40)
    ->Arg(160)
    ->Unit(benchmark::kMillisecond)
    ->UseRealTime()
    ->Repetitions(5)
    ->ReportAggregatesOnly(true);

}  // namespace

BENCHMARK_MAIN();
