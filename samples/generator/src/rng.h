// A seeded random source whose results do not depend on the standard
// library's distribution classes (their output is implementation-defined);
// only std::mt19937_64's raw output, which the standard fixes, is used.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>

namespace hair25d::generator {

class Rng {
 public:
  explicit Rng(std::uint64_t seed) : engine_(seed) {}

  // Uniform in [0, 1) from the top 53 bits.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }
  double uniform(double lo, double hi) { return lo + (hi - lo) * uniform(); }
  // Uniform integer in [lo, hi]; the modulo bias is below 2^-40 for our ranges.
  int uniform_int(int lo, int hi) {
    const auto span = static_cast<std::uint64_t>(static_cast<std::int64_t>(hi) - lo + 1);
    return lo + static_cast<int>(engine_() % span);
  }
  bool chance(double p) { return uniform() < p; }
  // Standard normal by Box–Muller (one value per call keeps the state simple).
  double normal() {
    const double u1 = 1.0 - uniform();  // (0, 1]: log stays finite
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }
  // An independent stream for a sub-task, so adding draws in one part of the
  // layout does not shift every later part.
  Rng fork() { return Rng(engine_() ^ 0x9e3779b97f4a7c15ULL); }

 private:
  std::mt19937_64 engine_;
};

}  // namespace hair25d::generator
