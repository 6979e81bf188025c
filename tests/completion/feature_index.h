// The index of a join scorer input by its name (join_feature_name), for
// the tests that read recorded rows.
#pragma once

#include <gtest/gtest.h>

#include <string>

#include "hair25d/completion/join_scorer.h"

namespace hair25d::completion::test {

inline int feature_index(const char* name) {
  for (int k = 0; k < kJoinFeatures; ++k)
    if (std::string(join_feature_name(k)) == name) return k;
  ADD_FAILURE() << "no feature " << name;
  return 0;
}

}  // namespace hair25d::completion::test
