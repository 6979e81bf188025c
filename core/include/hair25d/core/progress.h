// Progress reporting from long stages: the CLI draws a bar (or plain lines, or
// nothing), the studio shows it in its window.
#pragma once

#include <string_view>

namespace hair25d {

class Progress {
 public:
  virtual ~Progress() = default;
  // `stage` names the pipeline stage, `fraction` in [0, 1] is done of it.
  virtual void report(std::string_view stage, double fraction, std::string_view message) = 0;
};

// Reports nothing.
class NullProgress final : public Progress {
 public:
  void report(std::string_view, double, std::string_view) override {}
};

// Reports into `sink` only when it is not null: the usual optional parameter.
inline void report(Progress* sink, std::string_view stage, double fraction,
                   std::string_view message = {}) {
  if (sink != nullptr) sink->report(stage, fraction, message);
}

}  // namespace hair25d
