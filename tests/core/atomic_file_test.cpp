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

TEST(AtomicFile, ReadingMissingOrFolderIsAnError) {
  testing::TempDir dir;
  EXPECT_THROW(read_text_file(dir / "none"), Error);
  EXPECT_THROW(read_text_file(dir.path()), Error);
}

}  // namespace
}  // namespace hair25d
