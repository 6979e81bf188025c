// The one exception type of hair25d: bad input and failures with a message that
// names the thing, the value and the rule. Third-party exceptions are turned
// into this at module boundaries; the CLI prints it and exits with status 1.
#pragma once

#include <stdexcept>
#include <string>

namespace hair25d {

class Error : public std::runtime_error {
 public:
  explicit Error(const std::string& message) : std::runtime_error(message) {}
};

}  // namespace hair25d
