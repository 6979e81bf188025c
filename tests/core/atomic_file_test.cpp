#include "hair25d/core/atomic_file.h"

#include <gtest/gtest.h>

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
  write_folder_atomically(dir / "f",
                          [](const fs::path& tmp) { std::ofstream(tmp / "one") << "1"; });
  EXPECT_THROW(write_folder_atomically(dir / "f",
                                       [](const fs::path& tmp) {
                                         std::ofstream(tmp / "two") << "2";
                                         throw Error("stopped half way");
                                       }),
               Error);
  EXPECT_TRUE(fs::exists(dir / "f" / "one"));
  EXPECT_FALSE(fs::exists(dir / "f" / "two"));
  EXPECT_EQ(count_entries(dir.path()), 1);
  write_text_atomically(dir / "file", "x");
  EXPECT_THROW(write_folder_atomically(dir / "file", [](const fs::path&) {}), Error);
}

TEST(AtomicFile, FolderHoldingSomebodysFilesIsNeverReplaced) {
  testing::TempDir dir;
  fs::create_directory(dir / "precious");
  std::ofstream(dir / "precious" / "notes.txt") << "mine";
  try {
    write_folder_atomically(dir / "precious",
                            [](const fs::path& tmp) { std::ofstream(tmp / "model.json") << "{}"; });
    FAIL() << "replaced a folder holding notes.txt";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("notes.txt"), std::string::npos) << e.what();
  }
  EXPECT_EQ(read_text_file(dir / "precious" / "notes.txt"), "mine");
  EXPECT_FALSE(fs::exists(dir / "precious" / "model.json"));
  EXPECT_EQ(count_entries(dir.path()), 1);  // no temporary left beside it
}

// The check made before a long run refuses what the final write would refuse,
// and lets through what it would replace.
TEST(AtomicFile, OutputFolderIsCheckedBeforeTheWork) {
  testing::TempDir dir;
  const std::vector<std::string> names = {"model.json", "strands"};
  check_output_folder(dir / "new" / "deeper", "-o", names);  // missing folders are made later
  fs::create_directory(dir / "empty");
  check_output_folder(dir / "empty", "-o", names);
  fs::create_directory(dir / "ours");
  std::ofstream(dir / "ours" / "model.json") << "{}";
  check_output_folder(dir / "ours/", "-o", names);
  write_folder_atomically(dir / "marked", [](const fs::path& tmp) {
    std::ofstream(tmp / "other.txt") << "an earlier output with another name";
  });
  check_output_folder(dir / "marked", "-o", names);

  fs::create_directory(dir / "precious");
  std::ofstream(dir / "precious" / "model.json") << "{}";
  std::ofstream(dir / "precious" / "notes.txt") << "mine";
  std::ofstream(dir / "a_file") << "x";
  const auto message = [&](const fs::path& target) {
    try {
      check_output_folder(target, "-o", names);
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
  write_folder_atomically(dir / "m", fill("old"));
  std::ofstream(dir / "m" / "strands" / "s9.png") << "from a run with more strands";
  write_folder_atomically(dir / "m", fill("new"));
  EXPECT_EQ(read_text_file(dir / "m" / "model.json"), "new");
  EXPECT_FALSE(fs::exists(dir / "m" / "strands" / "s9.png"));
  // The next output may lack a name the earlier one had (no textures, no strands/).
  write_folder_atomically(dir / "m",
                          [](const fs::path& tmp) { std::ofstream(tmp / "model.json") << "bare"; });
  EXPECT_EQ(read_text_file(dir / "m" / "model.json"), "bare");
  EXPECT_FALSE(fs::exists(dir / "m" / "strands"));
  fs::create_directory(dir / "empty");
  write_folder_atomically(dir / "empty", fill("x"));
  EXPECT_EQ(read_text_file(dir / "empty" / "model.json"), "x");
}

TEST(AtomicFile, TrailingSlashNamesTheFolderItself) {
  testing::TempDir dir;
  write_folder_atomically(dir.path() / "out/",
                          [](const fs::path& tmp) { std::ofstream(tmp / "a.txt") << "a"; });
  EXPECT_EQ(read_text_file(dir / "out" / "a.txt"), "a");
  EXPECT_TRUE(fs::exists(dir / "out" / "a.txt"));
  EXPECT_EQ(count_entries(dir.path()), 1);
}

TEST(AtomicFile, ReadingMissingOrFolderIsAnError) {
  testing::TempDir dir;
  EXPECT_THROW(read_text_file(dir / "none"), Error);
  EXPECT_THROW(read_text_file(dir.path()), Error);
}

}  // namespace
}  // namespace hair25d
