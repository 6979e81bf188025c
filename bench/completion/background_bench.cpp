// Background fill (paper §5.4) alone on generated 1024 × 1024 drawings: the
// hair (every region pixel, plus 2 px) removed and filled at full resolution.
// Medians of 5 repetitions; the fill runs on one thread, so CPU time is the
// figure that does not depend on the machine's load.
#include <benchmark/benchmark.h>

#include "common/completion_input.h"
#include "common/generated_cases.h"
#include "hair25d/completion/background.h"
#include "hair25d/completion/completion.h"

namespace {

using namespace hair25d;

// As the model command's: regions with their outlines (assigned as
// completion does), plus 2 px.
LabelMap hair_hole(const Image& image, const LabelMap& drawn) {
  const LabelMap regions = completion::assign_outline_pixels(image, drawn, 4, 140);
  const int w = regions.width(), h = regions.height();
  LabelMap hole(w, h);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      if (regions.at(x, y) == 0) continue;
      for (int dy = -2; dy <= 2; ++dy)
        for (int dx = -2; dx <= 2; ++dx)
          if (hole.contains(x + dx, y + dy)) hole.at(x + dx, y + dy) = 1;
    }
  return hole;
}

void run(benchmark::State& state, const completion::BackgroundOptions& options) {
  const AnnotatedCase& c = bench::generated_case(static_cast<int>(state.range(0)));
  const LabelMap hole = hair_hole(c.image, c.regions);
  completion::BackgroundResult r;
  for (auto _ : state) {
    r = completion::fill_background(c.image, hole, options);
    benchmark::DoNotOptimize(r.image.data());
  }
  state.counters["filled_px"] = r.filled;
  state.counters["unreached_px"] = r.unreached;
  state.counters["line_ends"] = r.line_ends;
  state.counters["joined"] = r.joined_lines;
  state.counters["extended"] = r.extended_lines;
  state.counters["seam_px"] = r.seam_pixels;
  state.counters["textured_px"] = r.texture.filled;
}

void BM_BackgroundFill(benchmark::State& state) { run(state, {}); }

// The flat fill alone: no line continuation, seam ink or texture pass.
void BM_BackgroundFlatFillOnly(benchmark::State& state) {
  completion::BackgroundOptions o;
  o.continue_lines = false;
  o.ink_seams = false;
  o.texture_threshold = 1e9;
  run(state, o);
}

// The whole completion stage on one thread with only the background filled:
// minus BM_CompletionWithoutInpainting, the background's share of the stage.
void BM_CompletionBackgroundOnly(benchmark::State& state) {
  const AnnotatedCase& c = bench::generated_case(static_cast<int>(state.range(0)));
  const completion::Input in = bench::completion_input(c);
  completion::Options o;
  o.inpaint_strands = false;
  o.threads = 1;
  completion::Result r;
  for (auto _ : state) {
    r = completion::complete_strands(in, o);
    benchmark::DoNotOptimize(r.background.data());
  }
  state.counters["background_px"] = r.background_inpaint.filled;
}

// Strands inpainted, no background: BM_CompletionWithInpainting minus this
// is what the background adds to the stage's wall time (it runs on a
// second thread beside the strands).
void BM_CompletionStrandsOnly(benchmark::State& state) {
  const AnnotatedCase& c = bench::generated_case(static_cast<int>(state.range(0)));
  const completion::Input in = bench::completion_input(c);
  completion::Options o;
  o.inpaint_background = false;
  completion::Result r;
  for (auto _ : state) {
    r = completion::complete_strands(in, o);
    benchmark::DoNotOptimize(r.strands.data());
  }
}

BENCHMARK(BM_BackgroundFill)->Apply(bench::strand_counts);
BENCHMARK(BM_CompletionStrandsOnly)->Apply(bench::strand_counts)->UseRealTime();
BENCHMARK(BM_CompletionBackgroundOnly)->Apply(bench::strand_counts);
BENCHMARK(BM_BackgroundFlatFillOnly)->Apply(bench::strand_counts);

}  // namespace
