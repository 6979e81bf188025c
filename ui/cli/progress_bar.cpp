#include "progress_bar.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>

namespace hair25d::cli {

TerminalProgress::Mode TerminalProgress::pick_mode(std::FILE* stream, bool quiet) {
  if (quiet) return Mode::kSilent;
  return ::isatty(::fileno(stream)) ? Mode::kBar : Mode::kLines;
}

TerminalProgress::TerminalProgress(std::FILE* stream, Mode mode) : stream_(stream), mode_(mode) {}

TerminalProgress::~TerminalProgress() { end_line(); }

void TerminalProgress::end_line() {
  if (!bar_open_) return;
  std::fputc('\n', stream_);
  std::fflush(stream_);
  bar_open_ = false;
  last_stage_.clear();  // a later report redraws its bar at once
}

void TerminalProgress::report(std::string_view stage, double fraction, std::string_view message) {
  if (mode_ == Mode::kSilent) return;
  const int percent = static_cast<int>(std::lround(std::clamp(fraction, 0.0, 1.0) * 100.0));
  const bool new_stage = stage != last_stage_;
  if (mode_ == Mode::kLines) {
    // Logs get a line when a stage starts or ends, and every 25% between.
    if (new_stage || percent == 100 || percent / 25 != last_percent_ / 25) {
      std::fprintf(stream_, "%.*s: %d%%%s%.*s\n", static_cast<int>(stage.size()), stage.data(),
                   percent, message.empty() ? "" : " ", static_cast<int>(message.size()),
                   message.data());
      std::fflush(stream_);
    }
  } else {
    // Redraw at most every 50 ms, always at stage changes and completion.
    const auto now = std::chrono::steady_clock::now();
    if (new_stage && bar_open_) std::fputc('\n', stream_);
    if (new_stage || percent == 100 || now - last_draw_ > std::chrono::milliseconds(50)) {
      constexpr int kWidth = 30;
      const int filled = percent * kWidth / 100;
      std::fprintf(stream_, "\r%-12.*s [%.*s%*s] %3d%% %.*s\x1b[K", static_cast<int>(stage.size()),
                   stage.data(), filled, "##############################", kWidth - filled, "",
                   percent, static_cast<int>(std::min<std::size_t>(message.size(), 40)),
                   message.data());
      std::fflush(stream_);
      bar_open_ = true;
      last_draw_ = now;
    }
  }
  last_stage_ = std::string(stage);
  last_percent_ = percent;
}

}  // namespace hair25d::cli
