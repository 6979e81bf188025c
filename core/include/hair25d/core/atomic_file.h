// Writing outputs so that a crash never leaves a half-written file or folder
// that looks whole: write under a temporary name beside the target, then rename.
#pragma once

#include <filesystem>
#include <functional>
#include <string>
#include <vector>

namespace hair25d {

// A temporary sibling path of `target` that keeps its extension
// ("out/a.png" -> "out/.a.png.tmp-1234-0.png").
std::filesystem::path temporary_sibling(const std::filesystem::path& target);

// Calls write(tmp) with a temporary sibling path, then renames it onto target.
// On any exception the temporary is removed and the exception rethrown.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write);

// Throws hair25d::Error naming `target` (and `what`, e.g. "--json") when a file
// could not be written there: it names a folder, or a file stands where one
// of its folders would be (missing folders may be made when writing).
// Called before long work so that a bad output path fails first, not last.
void check_output_file(const std::filesystem::path& target, const std::string& what);

// Throws hair25d::Error naming `target` (and `what`, e.g. "-o") when
// write_folder_atomically would refuse it at the end of a long run: a file
// stands there or where one of its folders would be, or it is a folder that is
// neither empty nor an earlier output and holds an entry not in `names` (the
// names the command writes). Called before the work, as check_output_file is.
void check_output_folder(const std::filesystem::path& target, const std::string& what,
                         const std::vector<std::string>& names);

// Writes text to a file atomically.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

// Reads a whole text file; throws hair25d::Error naming the file if it cannot.
std::string read_text_file(const std::filesystem::path& path);

// Replaces folder `target` by a folder filled by fill(tmp_folder): the old
// folder (if any) is removed only after the new one is complete. An existing
// folder is replaced only when it is empty, was written by this function (it
// leaves a hidden mark) or holds nothing but names the new one holds too;
// otherwise it is left untouched and hair25d::Error names the foreign entry.
void write_folder_atomically(const std::filesystem::path& target,
                             const std::function<void(const std::filesystem::path&)>& fill);

}  // namespace hair25d
