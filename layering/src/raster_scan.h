// Helpers for scans over label rasters where almost every flag is 0 (outline
// fill, crack-grid trace): look at eight bytes at once and stop only at the
// few set ones.
#pragma once

#include <cstdint>
#include <cstring>
#include <vector>

namespace hair25d::layering::detail {

// Calls f(x) for every x in [from, to) with flags[x] != 0, in increasing x.
template <class T, class F>
void for_each_set(const std::vector<T>& flags, int from, int to, F&& f) {
  static_assert(sizeof(T) <= 8 && 8 % sizeof(T) == 0);
  constexpr int kPerWord = 8 / sizeof(T);
  int x = from;
  for (; x + kPerWord <= to; x += kPerWord) {
    std::uint64_t word;
    std::memcpy(&word, flags.data() + x, sizeof word);
    if (word == 0) continue;
    for (int k = 0; k < kPerWord; ++k)
      if (flags[x + k] != 0) f(x + k);
  }
  for (; x < to; ++x)
    if (flags[x] != 0) f(x);
}

// A fixed-size set of bits: an eighth of the memory of a byte a flag, so the
// per-corner and per-edge marks of a large image stay in cache.
class Bits {
 public:
  explicit Bits(std::size_t n) : words_((n + 63) / 64, 0) {}
  void set(std::size_t i) { words_[i >> 6] |= std::uint64_t{1} << (i & 63); }
  bool test(std::size_t i) const { return (words_[i >> 6] >> (i & 63)) & 1; }

 private:
  std::vector<std::uint64_t> words_;
};

}  // namespace hair25d::layering::detail
