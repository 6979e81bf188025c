// The stages of `hair25d model` that have no benchmark of their own, on the
// same generated 1024 × 1024 drawings of 10, 40 and 160 strands: segmentation
// from strokes (as the model pipeline runs it, without the overlay), the
// contact sheet, and writing the model folder. Layering, completion and
// skeletons are in bench_layering, bench_completion and bench_skeleton.
#include <benchmark/benchmark.h>

#include <filesystem>
#include <map>
#include <string>

#include "common/generated_cases.h"
#include "hair25d/pipeline/model_stage.h"
#include "hair25d/pipeline/segment_stage.h"

namespace {

using namespace hair25d;

// One model run per strand count, made once: only the stage is timed.
const pipeline::ModelRun& model_run(int strands) {
  static std::map<int, pipeline::ModelRun> cache;
  auto it = cache.find(strands);
  if (it == cache.end()) {
    const AnnotatedCase& c = bench::generated_case(strands);
    it = cache.emplace(strands, pipeline::run_model(c.image, &*c.strokes)).first;
  }
  return it->second;
}

void BM_SegmentFromStrokes(benchmark::State& state) {
  const AnnotatedCase& c = bench::generated_case(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    pipeline::SegmentRun run = pipeline::run_segment(c.image, &*c.strokes, nullptr, false);
    benchmark::DoNotOptimize(run.regions.data());
  }
  state.counters["labels"] = static_cast<double>(c.strokes->labels().size());
}

void BM_ContactSheet(benchmark::State& state) {
  const pipeline::ModelRun& run = model_run(static_cast<int>(state.range(0)));
  for (auto _ : state) {
    Image sheet = pipeline::render_contact_sheet(run);
    benchmark::DoNotOptimize(sheet.data());
  }
  state.counters["strands"] = static_cast<double>(run.model.strands.size());
}

// The model folder with its contact sheet (PNG encoding and model.json).
void BM_WriteModelFolder(benchmark::State& state) {
  const pipeline::ModelRun& run = model_run(static_cast<int>(state.range(0)));
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("hair25d_bench_write_" + std::to_string(state.range(0)));
  std::uintmax_t bytes = 0;
  for (auto _ : state) {
    pipeline::write_model_run(folder, run);
    state.PauseTiming();
    bytes = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(folder))
      if (e.is_regular_file()) bytes += e.file_size();
    std::filesystem::remove_all(folder);
    state.ResumeTiming();
  }
  state.counters["strands"] = static_cast<double>(run.model.strands.size());
  state.counters["folder_MB"] = static_cast<double>(bytes) / 1e6;
}

BENCHMARK(BM_SegmentFromStrokes)->Apply(hair25d::bench::strand_counts)->UseRealTime();
BENCHMARK(BM_ContactSheet)->Apply(hair25d::bench::strand_counts)->UseRealTime();
BENCHMARK(BM_WriteModelFolder)->Apply(hair25d::bench::strand_counts)->UseRealTime();

}  // namespace
