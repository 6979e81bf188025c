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

}  // namespace
}  // namespace hair25d
