// The strands' colour fill (inpaint_cel) on screentone against flat paint:
// a screentone's hidden parts are filled from whole dot-lattice translates
// (docs/completion-record.md, session 15). Milliseconds, medians of 5 repetitions.
#include <benchmark/benchmark.h>

#include <cmath>
#include <map>

#include "common/completion_input.h"
#include "hair25d/completion/completion.h"
#include "hair25d/completion/inpaint.h"
#include "hair25d/generator/generator.h"

namespace {

using namespace hair25d;

// Seed 7, 1024 × 1024, 40 strands, in one shading (made once).
const AnnotatedCase& shaded_case(generator::Shading shading) {
  static std::map<generator::Shading, AnnotatedCase> cache;
  auto it = cache.find(shading);
  if (it == cache.end()) {
    generator::Options o;
    o.width = 1024;
    o.height = 1024;
    o.strand_count = 40;
    o.seed = 7;
    o.strand_masks = false;
    o.shading = shading;
    it = cache.emplace(shading, generator::generate_case(o)).first;
  }
  return it->second;
}

// Completion with the strands' fill, without the background's.
void strands_filled(benchmark::State& state, generator::Shading shading) {
  const AnnotatedCase& c = shaded_case(shading);
  const completion::Input in = bench::completion_input(c);
  completion::Options o;
  o.inpaint_background = false;
  completion::Result r;
  for (auto _ : state) {
    r = completion::complete_strands(in, o);
    benchmark::DoNotOptimize(r.strands.data());
  }
  state.counters["strands"] = static_cast<double>(r.strands.size());
  state.counters["inpainted_px"] = r.strand_inpaint.filled;
}

void BM_StrandFillFlat(benchmark::State& state) {
  strands_filled(state, generator::Shading::kFlat);
}
void BM_StrandFillScreentone(benchmark::State& state) {
  strands_filled(state, generator::Shading::kScreentone);
}

// One strand texture, 640 × 480, of round dots on a turned lattice (period
// 7.3 px) or of flat paint, with a 300 × 200 hidden part: most targets are
// farther than search_radius from every whole source patch.
void one_strand(benchmark::State& state, bool dots) {
  const int w = 640, h = 480;
  Image image(w, h, Rgba{0, 0, 0, 0});
  LabelMap fill(w, h), source(w, h);
  const double c = std::cos(0.35) / 7.3, s = std::sin(0.35) / 7.3;
  for (int y = 10; y < h - 10; ++y)
    for (int x = 10; x < w - 10; ++x) {
      const double u = c * x + s * y, v = -s * x + c * y;
      const double fu = u - std::round(u), fv = v - std::round(v);
      const bool dot = dots && fu * fu + fv * fv < 0.09;
      const std::uint8_t grey = dot ? 25 : 215;
      image.at(x, y) = {grey, grey, grey, 255};
      const bool hidden = x >= 170 && x < 470 && y >= 140 && y < 340;
      (hidden ? fill : source).at(x, y) = 1;
    }
  completion::InpaintResult r;
  for (auto _ : state) {
    Image work = image;
    r = completion::inpaint_cel(work, fill, source);
    benchmark::DoNotOptimize(work.data());
  }
  state.counters["filled"] = r.filled;
}

void BM_InpaintCelToneStrand(benchmark::State& state) { one_strand(state, true); }
void BM_InpaintCelFlatStrand(benchmark::State& state) { one_strand(state, false); }

void settings(benchmark::internal::Benchmark* b) {
  b->Unit(benchmark::kMillisecond)->Repetitions(5)->ReportAggregatesOnly(true)->UseRealTime();
}

BENCHMARK(BM_StrandFillFlat)->Apply(settings);
BENCHMARK(BM_StrandFillScreentone)->Apply(settings);
BENCHMARK(BM_InpaintCelToneStrand)->Apply(settings);
BENCHMARK(BM_InpaintCelFlatStrand)->Apply(settings);

}  // namespace
