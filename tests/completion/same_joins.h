// For tests that turn an option on where it must not act: the two results
// made the same candidates, at the same costs, chose the same ones and
// summed up the same.
#pragma once

#include <gtest/gtest.h>

#include "hair25d/completion/completion.h"

namespace hair25d::completion::test {

inline void expect_same_joins(const Result& off, const Result& on) {
  ASSERT_EQ(off.join_candidates.size(), on.join_candidates.size());
  for (std::size_t i = 0; i < on.join_candidates.size(); ++i) {
    EXPECT_EQ(off.join_candidates[i].cost, on.join_candidates[i].cost);
    EXPECT_EQ(off.join_candidates[i].chosen, on.join_candidates[i].chosen);
  }
  EXPECT_EQ(off.summary, on.summary);
}

}  // namespace hair25d::completion::test
