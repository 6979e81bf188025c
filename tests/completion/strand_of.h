// Each region's strand (its index in Result::strands), for the tests that
// ask whether two pieces were made one strand.
#pragma once

#include <cstddef>
#include <map>

#include "hair25d/completion/completion.h"

namespace hair25d::completion::test {

inline std::map<int, int> strand_of(const Result& r) {
  std::map<int, int> out;
  for (std::size_t s = 0; s < r.strands.size(); ++s)
    for (int id : r.strands[s].regions) out[id] = static_cast<int>(s);
  return out;
}

}  // namespace hair25d::completion::test
