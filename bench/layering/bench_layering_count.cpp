// A driver for instruction counts (valgrind --tool=callgrind), which the load
// of a shared machine does not move: generates the bench's drawing (seed 42,
// the same search for a strand count as bench_layering) and layers it N
// times. Instructions per layering = (count with N = 2 − count with N = 0) / 2.
//   bench_layering_count REGIONS WIDTH HEIGHT N
#include <cstdio>
#include <cstdlib>
#include <string>

#include "bench_case.h"
#include "hair25d/core/error.h"
#include "hair25d/generator/generator.h"
#include "hair25d/layering/layering.h"

int main(int argc, char** argv) {
  using namespace hair25d;
  if (argc != 5) {
    std::fprintf(stderr, "usage: bench_layering_count REGIONS WIDTH HEIGHT N\n");
    return 2;
  }
  try {
    const int regions = std::stoi(argv[1]);
    const AnnotatedCase c = bench::layering_case(regions, std::stoi(argv[2]), std::stoi(argv[3]));
    const int n = std::stoi(argv[4]);
    std::size_t relations = 0;
    for (int i = 0; i < n; ++i)
      relations += layering::layer_regions(c.image, c.regions).relations.size();
    std::printf("regions %zu, relations per run %zu\n", c.regions.labels().size(),
                n > 0 ? relations / n : 0);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "bench_layering_count: %s\n", e.what());
    return 1;
  }
  return 0;
}
