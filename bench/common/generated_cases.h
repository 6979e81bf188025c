// Benchmark inputs shared by the stage benchmarks: generated drawings cached
// per strand count (generation stays outside the timed loops), the strand
// counts of the issues' tables, and completion inputs with exact relations.
#pragma once

#include <benchmark/benchmark.h>

#include <cstdint>
#include <map>
#include <utility>

#include "hair25d/generator/generator.h"

namespace hair25d::bench {

// A 1024 × 1024 generated drawing with `strands` strands painted with
// `shading` and no strand masks, made once per strand count and shading.
inline const AnnotatedCase& generated_case(int strands,
                                           generator::Shading shading = generator::Shading::kFlat) {
  static std::map<std::pair<int, generator::Shading>, AnnotatedCase> cache;
  auto it = cache.find({strands, shading});
  if (it == cache.end()) {
    generator::Options o;
    o.width = 1024;
    o.height = 1024;
    o.strand_count = strands;
    o.seed = 7;
    o.shading = shading;
    o.strand_masks = false;
    it = cache.emplace(std::make_pair(strands, shading), generator::generate_case(o)).first;
  }
  return it->second;
}

// 10, 40 and 160 strands, milliseconds, medians of 5 repetitions.
inline void strand_counts(benchmark::internal::Benchmark* b) {
  b->Arg(10)
      ->Arg(40)
      ->Arg(160)
      ->Unit(benchmark::kMillisecond)
      ->Repetitions(5)
      ->ReportAggregatesOnly(true);
}

}  // namespace hair25d::bench
