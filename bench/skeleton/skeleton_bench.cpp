// Skeleton and mesh time for every completed strand of generated 1024 × 1024
// drawings (completion runs once, outside the timing). Medians of 5 repetitions.
#include <benchmark/benchmark.h>

#include <map>

#include "common/completion_input.h"
#include "common/generated_cases.h"
#include "hair25d/completion/completion.h"
#include "hair25d/skeleton/strand_mesh.h"
#include "hair25d/skeleton/strand_skeleton.h"

namespace {

using namespace hair25d;

struct Outlines {
  std::vector<skeleton::Input> strands;
};

const Outlines& outlines(int strands) {
  static std::map<int, Outlines> cache;
  auto it = cache.find(strands);
  if (it != cache.end()) return it->second;
  const AnnotatedCase& c = bench::generated_case(strands);
  const completion::Input in = bench::completion_input(c);
  completion::Options co;
  co.inpaint_strands = false;
  co.inpaint_background = false;
  const completion::Result r = completion::complete_strands(in, co);
  Outlines out;
  for (const completion::CompletedStrand& s : r.strands) {
    if (s.outline.size() < 3) continue;
    skeleton::Input si;
    si.outline = s.outline;
    si.root_hint = s.root_hint ? s.root_hint : c.head_center;
    out.strands.push_back(si);
  }
  return cache.emplace(strands, std::move(out)).first->second;
}

void BM_Skeletons(benchmark::State& state) {
  const Outlines& o = outlines(static_cast<int>(state.range(0)));
  std::size_t nodes = 0;
  for (auto _ : state) {
    nodes = 0;
    for (const skeleton::Input& in : o.strands)
      nodes += skeleton::build_skeleton(in).skeleton.nodes.size();
    benchmark::DoNotOptimize(nodes);
  }
  state.counters["strands"] = static_cast<double>(o.strands.size());
  state.counters["nodes"] = static_cast<double>(nodes);
}

void BM_StrandMeshes(benchmark::State& state) {
  const Outlines& o = outlines(static_cast<int>(state.range(0)));
  std::size_t triangles = 0;
  for (auto _ : state) {
    triangles = 0;
    for (const skeleton::Input& in : o.strands) {
      try {
        triangles += skeleton::mesh_strand(in.outline).mesh.triangle_count();
      } catch (const std::exception&) {
      }
    }
    benchmark::DoNotOptimize(triangles);
  }
  state.counters["strands"] = static_cast<double>(o.strands.size());
  state.counters["triangles"] = static_cast<double>(triangles);
}

BENCHMARK(BM_Skeletons)->Apply(bench::strand_counts);
BENCHMARK(BM_StrandMeshes)->Apply(bench::strand_counts);

}  // namespace

BENCHMARK_MAIN();
