// Progress on the terminal: a redrawn bar on a TTY, plain lines in logs, and
// nothing with --quiet.
#pragma once

#include <chrono>
#include <cstdio>
#include <string>

#include "hair25d/core/progress.h"

namespace hair25d::cli {

class TerminalProgress final : public Progress {
 public:
  enum class Mode { kBar, kLines, kSilent };
  // kBar when `stream` is a terminal, kLines otherwise, kSilent when quiet.
  static Mode pick_mode(std::FILE* stream, bool quiet);

  TerminalProgress(std::FILE* stream, Mode mode);
  ~TerminalProgress() override;
  void report(std::string_view stage, double fraction, std::string_view message) override;
  // Ends an open bar line, so that a summary or warning printed next (to this
  // stream or to another on the same terminal) starts on a line of its own.
  void end_line();

 private:
  std::FILE* stream_;
  Mode mode_;
  std::string last_stage_;
  int last_percent_ = -1;
  bool bar_open_ = false;
  std::chrono::steady_clock::time_point last_draw_{};
};

}  // namespace hair25d::cli
