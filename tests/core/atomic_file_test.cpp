#include "hair25d/core/atomic_file.h"

#include <fcntl.h>
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <fstream>

#include "common/temp_dir.h"
#include "hair25d/core/error.h"

namespace hair25d {
namespace {

namespace fs = std::filesystem;

int count_entries(const fs::path& dir) {
  int n = 0;
  for ([[maybe_unused]] const auto& e : fs::directory_iterator(dir)) ++n;
  return n;
}

TEST(AtomicFile, FailureInsideTheWriterLeavesTheOldFileAndNoTemporary) {
  testing::TempDir dir;
  write_text_atomically(dir / "a.txt", "old");
  EXPECT_THROW(write_atomically(dir / "a.txt",
                                [](const fs::path& tmp) {
                                  std::ofstream(tmp) << "half";
                                  throw Error("disk on fire");
                                }),
               Error);
  EXPECT_EQ(read_text_file(dir / "a.txt"), "old");
  EXPECT_EQ(count_entries(dir.path()), 1);
}

TEST(AtomicFile, TemporaryKeepsTheExtensionSoFormatsAreChosenRight) {
  const fs::path tmp = temporary_sibling("out/clip.png");
  EXPECT_EQ(tmp.extension(), ".png");
  EXPECT_EQ(tmp.parent_path(), fs::path("out"));
  EXPECT_NE(tmp, temporary_sibling("out/clip.png"));
}

TEST(AtomicFile, FolderIsReplacedOnlyWhenTheNewOneIsComplete) {
  testing::TempDir dir;
  write_folder_atomically(
      dir / "f", [](const fs::path& tmp) { std::ofstream(tmp / "one") << "1"; }, "test");
  EXPECT_THROW(write_folder_atomically(
                   dir / "f",
                   [](const fs::path& tmp) {
                     std::ofstream(tmp / "two") << "2";
                     throw Error("stopped half way");
                   },
                   "test"),
               Error);
  EXPECT_TRUE(fs::exists(dir / "f" / "one"));
  EXPECT_FALSE(fs::exists(dir / "f" / "two"));
  EXPECT_EQ(count_entries(dir.path()), 1);
  write_text_atomically(dir / "file", "x");
  EXPECT_THROW(write_folder_atomically(
                   dir / "file", [](const fs::path&) {}, "test"),
               Error);
  // No name of its own: the current folder and everything in it would go.
  EXPECT_THROW(write_folder_atomically(
                   "", [](const fs::path&) {}, "test"),
               Error);
  EXPECT_THROW(write_folder_atomically(
                   dir / ".", [](const fs::path&) {}, "test"),
               Error);
}

TEST(AtomicFile, FolderHoldingSomebodysFilesIsNeverReplaced) {
  testing::TempDir dir;
  fs::create_directory(dir / "precious");
  std::ofstream(dir / "precious" / "notes.txt") << "mine";
  try {
    write_folder_atomically(
        dir / "precious", [](const fs::path& tmp) { std::ofstream(tmp / "model.json") << "{}"; },
        "model");
    FAIL() << "replaced a folder holding notes.txt";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text_file(dir / "precious" / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir / "precious" / "model.json"));
  EXPECT_EQ(count_entries(dir.path()), 1);  // no temporary left beside it
}

// A folder the new output also has may hold somebody's file inside it.
TEST(AtomicFile, FilesInsideFoldersOfTheSameNameAreLookedAt) {
  testing::TempDir dir;
  fs::create_directories(dir / "x" / "strands");
  std::ofstream(dir / "x" / "strands" / "notes.txt") << "mine";
  const auto fill = [](const fs::path& tmp) {
    fs::create_directory(tmp / "strands");
    std::ofstream(tmp / "strands" / "1.png") << "png";
  };
  try {
    write_folder_atomically(dir / "x", fill, "model");
    FAIL() << "replaced a folder holding strands/notes.txt";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("strands/notes.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text_file(dir / "x" / "strands" / "notes.txt"), "mine");
  EXPECT_THROW(check_output_folder(dir / "x", "-o", {"strands"}, "model"), Error);
  // The same files the new output writes, unmarked: replaced.
  fs::remove(dir / "x" / "strands" / "notes.txt");
  std::ofstream(dir / "x" / "strands" / "1.png") << "old png";
  write_folder_atomically(dir / "x", fill, "model");
  EXPECT_EQ(read_text_file(dir / "x" / "strands" / "1.png"), "png");
}

// The mark names the kind of output: one command's output (or a generated
// case, which is input) is not another's to replace.
TEST(AtomicFile, OutputOfAnotherKindIsNotReplaced) {
  testing::TempDir dir;
  write_folder_atomically(
      dir / "case", [](const fs::path& tmp) { std::ofstream(tmp / "layering.json") << "{}"; },
      "annotated case");
  EXPECT_THROW(
      write_folder_atomically(
          dir / "case", [](const fs::path& tmp) { std::ofstream(tmp / "regions.png") << "png"; },
          "segment"),
      Error);
  EXPECT_THROW(check_output_folder(dir / "case", "-o", {"regions.png"}, "segment"), Error);
  EXPECT_EQ(read_text_file(dir / "case" / "layering.json"), "{}");
  write_folder_atomically(
      dir / "case", [](const fs::path& tmp) { std::ofstream(tmp / "layering.json") << "[]"; },
      "annotated case");
  EXPECT_EQ(read_text_file(dir / "case" / "layering.json"), "[]");
}

TEST(AtomicFile, InputsInsideTheOutputFolderAreFound) {
  testing::TempDir dir;
  fs::create_directories(dir / "d" / "sub");
  std::ofstream(dir / "d" / "sub" / "image.png") << "png";
  EXPECT_TRUE(lies_inside(dir / "d" / "sub" / "image.png", dir / "d"));
  EXPECT_TRUE(lies_inside(dir / "d" / "sub" / ".." / "sub" / "image.png", dir / "d/"));
  EXPECT_TRUE(lies_inside(dir / "d", dir / "d"));
  EXPECT_FALSE(lies_inside(dir / "d2" / "image.png", dir / "d"));
  EXPECT_FALSE(lies_inside(dir / "image.png", dir / "d"));
  EXPECT_THROW(check_inputs_outside(dir / "d", {dir / "d" / "sub" / "image.png"}, "-o"), Error);
  check_inputs_outside(dir / "e", {dir / "d" / "sub" / "image.png", ""}, "-o");
}

// The check made before a long run refuses what the final write would refuse,
// and lets through what it would replace.
TEST(AtomicFile, OutputFolderIsCheckedBeforeTheWork) {
  testing::TempDir dir;
  const std::vector<std::string> names = {"model.json", "strands"};
  // Missing folders are made later.
  check_output_folder(dir / "new" / "deeper", "-o", names, "model");
  fs::create_directory(dir / "empty");
  check_output_folder(dir / "empty", "-o", names, "model");
  fs::create_directory(dir / "ours");
  std::ofstream(dir / "ours" / "model.json") << "{}";
  check_output_folder(dir / "ours/", "-o", names, "model");
  write_folder_atomically(
      dir / "marked",
      [](const fs::path& tmp) {
        std::ofstream(tmp / "other.txt") << "an earlier output with another name";
      },
      "model");
  check_output_folder(dir / "marked", "-o", names, "model");
  EXPECT_THROW(check_output_folder("", "-o", names, "model"), Error);
  EXPECT_THROW(check_output_folder(".", "-o", names, "model"), Error);

  fs::create_directory(dir / "precious");
  std::ofstream(dir / "precious" / "model.json") << "{}";
  std::ofstream(dir / "precious" / "notes.txt") << "mine";
  std::ofstream(dir / "a_file") << "x";
  const auto message = [&](const fs::path& target) {
    try {
      check_output_folder(target, "-o", names, "model");
    } catch (const Error& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message(dir / "precious").find("notes.txt"), std::string::npos);
  EXPECT_NE(message(dir / "precious").find("-o "), std::string::npos);
  EXPECT_NE(message(dir / "a_file").find("not a folder"), std::string::npos);
  EXPECT_NE(message(dir / "a_file" / "m").find("is a file"), std::string::npos);
  EXPECT_EQ(read_text_file(dir / "precious" / "notes.txt"), "mine");
}

TEST(AtomicFile, EarlierOutputOfTheSameCommandIsReplaced) {
  testing::TempDir dir;
  const auto fill = [](const std::string& text) {
    return [text](const fs::path& tmp) {
      std::ofstream(tmp / "model.json") << text;
      fs::create_directory(tmp / "strands");
    };
  };
  write_folder_atomically(dir / "m", fill("old"), "model");
  std::ofstream(dir / "m" / "strands" / "s9.png") << "from a run with more strands";
  write_folder_atomically(dir / "m", fill("new"), "model");
  EXPECT_EQ(read_text_file(dir / "m" / "model.json"), "new");
  EXPECT_FALSE(fs::exists(dir / "m" / "strands" / "s9.png"));
  // The next output may lack a name the earlier one had (no textures, no strands/).
  write_folder_atomically(
      dir / "m", [](const fs::path& tmp) { std::ofstream(tmp / "model.json") << "bare"; }, "model");
  EXPECT_EQ(read_text_file(dir / "m" / "model.json"), "bare");
  EXPECT_FALSE(fs::exists(dir / "m" / "strands"));
  fs::create_directory(dir / "empty");
  write_folder_atomically(dir / "empty", fill("x"), "model");
  EXPECT_EQ(read_text_file(dir / "empty" / "model.json"), "x");
}

TEST(AtomicFile, TrailingSlashNamesTheFolderItself) {
  testing::TempDir dir;
  write_folder_atomically(
      dir.path() / "out/", [](const fs::path& tmp) { std::ofstream(tmp / "a.txt") << "a"; },
      "test");
  EXPECT_EQ(read_text_file(dir / "out" / "a.txt"), "a");
  EXPECT_TRUE(fs::exists(dir / "out" / "a.txt"));
  EXPECT_EQ(count_entries(dir.path()), 1);
}

TEST(AtomicFile, ReadingMissingOrFolderIsAnError) {
  testing::TempDir dir;
  EXPECT_THROW(read_text_file(dir / "none"), Error);
  EXPECT_THROW(read_text_file(dir.path()), Error);
}

TEST(AtomicFile, WritingThroughALinkReplacesItsTargetAndKeepsTheLink) {
  testing::TempDir dir;
  fs::create_directory(dir / "real");
  write_text_atomically(dir / "real" / "report.json", "old");
  fs::create_symlink("real/report.json", dir / "link.json");
  fs::create_symlink("link.json", dir / "link2.json");  // a chain of two
  write_text_atomically(dir / "link2.json", "new");
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
  EXPECT_TRUE(fs::is_symlink(dir / "link2.json"));
  EXPECT_EQ(read_text_file(dir / "real" / "report.json"), "new");
  // A dangling link: the file is made where it points.
  fs::create_symlink("real/later.json", dir / "dangling.json");
  write_text_atomically(dir / "dangling.json", "made");
  EXPECT_TRUE(fs::is_symlink(dir / "dangling.json"));
  EXPECT_EQ(read_text_file(dir / "real" / "later.json"), "made");
  fs::create_symlink("loop_b", dir / "loop_a");
  fs::create_symlink("loop_a", dir / "loop_b");
  EXPECT_THROW(write_text_atomically(dir / "loop_a", "x"), Error);
}

TEST(AtomicFile, APipeIsWrittenDirectlyNotReplaced) {
  // A FIFO (as a device, a terminal or /dev/stdout would be): a rename over it
  // would replace it by a regular file; the bytes must go through it instead.
  testing::TempDir dir;
  const fs::path fifo = dir / "pipe.json";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  fs::create_symlink("pipe.json", dir / "link.json");
  const int reader = ::open(fifo.c_str(), O_RDONLY | O_NONBLOCK);
  ASSERT_GE(reader, 0);
  check_output_file(dir / "link.json", "--json");
  write_text_atomically(dir / "link.json", "report");
  char buffer[16] = {};
  const ssize_t n = ::read(reader, buffer, sizeof buffer);
  ::close(reader);
  EXPECT_EQ(std::string(buffer, n > 0 ? static_cast<std::size_t>(n) : 0), "report");
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_symlink(dir / "link.json"));
}

TEST(AtomicFile, FolderWrittenThroughALinkKeepsTheLink) {
  testing::TempDir dir;
  const auto fill = [](const char* text) {
    return [text](const fs::path& tmp) { std::ofstream(tmp / "a.txt") << text; };
  };
  write_folder_atomically(dir / "real", fill("old"), "model");
  fs::create_symlink("real", dir / "link");
  check_output_folder(dir / "link", "-o", {"a.txt"}, "model");
  write_folder_atomically(dir / "link", fill("new"), "model");
  EXPECT_TRUE(fs::is_symlink(dir / "link"));
  EXPECT_EQ(read_text_file(dir / "real" / "a.txt"), "new");
  // Checks look through the link: a folder not marked as ours holding a
  // foreign file is refused and left as it is.
  fs::create_directory(dir / "plain");
  std::ofstream(dir / "plain" / "notes.txt") << "mine";
  fs::create_symlink("plain", dir / "plain_link");
  EXPECT_THROW(check_output_folder(dir / "plain_link", "-o", {"a.txt"}, "model"), Error);
  EXPECT_THROW(write_folder_atomically(dir / "plain_link", fill("x"), "model"), Error);
  EXPECT_TRUE(fs::exists(dir / "plain" / "notes.txt"));
  EXPECT_TRUE(fs::is_symlink(dir / "plain_link"));
  // An input inside the link's target lies inside the output folder.
  EXPECT_TRUE(lies_inside(dir / "real" / "a.txt", dir / "link"));
}

TEST(AtomicFile, StaleTemporariesOfDeadProcessesAreSwept) {
  testing::TempDir dir;
  const auto fill = [](const fs::path& tmp) { std::ofstream(tmp / "a.txt") << "x"; };
  write_folder_atomically(dir / "m", fill, "model");
  // A pid above pid_max (4194304 at most on Linux) never runs.
  const fs::path dead = dir / ".m.tmp-2147483000-3";
  const fs::path alive = dir / (".m.tmp-" + std::to_string(::getppid()) + "-0");
  const fs::path other = dir / ".n.tmp-2147483000-3";
  for (const fs::path& p : {dead, alive, other}) {
    fs::create_directory(p);
    std::ofstream(p / "a.txt") << "half";
  }
  write_folder_atomically(dir / "m", fill, "model");
  EXPECT_FALSE(fs::exists(dead));
  EXPECT_TRUE(fs::exists(alive));  // its process runs: maybe still writing
  EXPECT_TRUE(fs::exists(other));  // another target's
  std::ofstream(dir / ".f.txt.tmp-2147483000-0.txt") << "half";
  write_text_atomically(dir / "f.txt", "whole");
  EXPECT_FALSE(fs::exists(dir / ".f.txt.tmp-2147483000-0.txt"));
}

TEST(AtomicFile, ExchangeLeavesOnlyTheNewFolderAndKeepsTheOldOnFailure) {
  testing::TempDir dir;
  const auto fill = [](const char* text) {
    return [text](const fs::path& tmp) {
      fs::create_directory(tmp / "strands");
      std::ofstream(tmp / "strands" / "s.txt") << text;
    };
  };
  write_folder_atomically(dir / "m", fill("old"), "model");
  EXPECT_THROW(write_folder_atomically(
                   dir / "m",
                   [](const fs::path& tmp) {
                     std::ofstream(tmp / "half") << "1";
                     throw Error("killed half way");
                   },
                   "model"),
               Error);
  EXPECT_EQ(read_text_file(dir / "m" / "strands" / "s.txt"), "old");
  EXPECT_FALSE(fs::exists(dir / "m" / "half"));
  write_folder_atomically(dir / "m", fill("new"), "model");
  EXPECT_EQ(read_text_file(dir / "m" / "strands" / "s.txt"), "new");
  EXPECT_EQ(count_entries(dir.path()), 1);  // the old folder is gone too
}

}  // namespace
}  // namespace hair25d
