// For the tests of options out of range: is_valid refuses them and its
// message names the field (and the value, when `words` gives it), so a
// user reading the error knows what to change.
#pragma once

#include <gtest/gtest.h>

#include <string>

namespace hair25d::completion::test {

template <typename OptionsT>
void expect_invalid(const OptionsT& o, const std::string& words) {
  std::string why;
  EXPECT_FALSE(o.is_valid(&why)) << words;
  EXPECT_NE(why.find(words), std::string::npos) << "wanted \"" << words << "\" in: " << why;
}

}  // namespace hair25d::completion::test
