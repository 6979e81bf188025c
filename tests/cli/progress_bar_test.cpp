// The terminal progress of the hair25d command (ui/cli/progress_bar.h): the
// bar's line is ended before a summary is printed after it.
#include "progress_bar.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <memory>
#include <string>

namespace hair25d::cli {
namespace {

std::string contents(std::FILE* f) {
  std::fflush(f);
  std::rewind(f);
  std::string text;
  for (int c = std::fgetc(f); c != EOF; c = std::fgetc(f)) text += static_cast<char>(c);
  return text;
}

TEST(TerminalProgress, BarLineIsEndedBeforeTheSummary) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::tmpfile(), &std::fclose);
  ASSERT_NE(f, nullptr);
  TerminalProgress progress(f.get(), TerminalProgress::Mode::kBar);
  progress.report("skeleton", 0.5, "");
  progress.report("skeleton", 1.0, "");
  progress.end_line();
  progress.end_line();  // a second call adds no empty line
  std::fputs("model: 20 strands\n", f.get());
  const std::string text = contents(f.get());
  EXPECT_NE(text.find("100% \x1b[K\nmodel: 20 strands\n"), std::string::npos) << text;
  EXPECT_EQ(text.find("\n\n"), std::string::npos) << text;
}

TEST(TerminalProgress, LinesInLogsAndNothingWhenQuiet) {
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> f(std::tmpfile(), &std::fclose);
  ASSERT_NE(f, nullptr);
  {
    TerminalProgress progress(f.get(), TerminalProgress::Mode::kLines);
    progress.report("segment", 0.0, "");
    progress.report("segment", 0.1, "");  // within the first quarter: no line
    progress.report("segment", 1.0, "done");
    progress.end_line();  // no bar: nothing to end
  }
  EXPECT_EQ(contents(f.get()), "segment: 0%\nsegment: 100% done\n");
  const std::unique_ptr<std::FILE, int (*)(std::FILE*)> g(std::tmpfile(), &std::fclose);
  {
    TerminalProgress progress(g.get(), TerminalProgress::Mode::kSilent);
    progress.report("segment", 1.0, "done");
  }
  EXPECT_EQ(contents(g.get()), "");
}

}  // namespace
}  // namespace hair25d::cli
