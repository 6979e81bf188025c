// Writing outputs so that a crash never leaves a half-written file or folder
// that looks whole: write under a temporary name beside the target, then rename.
#pragma once

#include <cstdint>
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
// Symbolic links at target are followed first (the link stays, its target is
// replaced); a device, pipe or socket at target is written directly:
// write(target). Temporaries of target left by dead processes are removed.
void write_atomically(const std::filesystem::path& target,
                      const std::function<void(const std::filesystem::path&)>& write);

// Throws hair25d::Error naming `target` (and `what`, e.g. "--json") when a file
// could not be written there: it names a folder, or a file stands where one
// of its folders would be (missing folders may be made when writing).
// Called before long work so that a bad output path fails first, not last.
void check_output_file(const std::filesystem::path& target, const std::string& what);

// Throws hair25d::Error naming `target` (and `what`, e.g. "-o") when
// write_folder_atomically(target, ..., kind) would refuse it at the end of a
// long run: it has no name of its own ("", "."), a file stands there or where
// one of its folders would be, or it is a folder that is neither empty nor
// marked as an earlier output of this `kind` and holds anything but `names`
// (the names the command writes; folders among them empty). Called before the
// work, as check_output_file is.
void check_output_folder(const std::filesystem::path& target, const std::string& what,
                         const std::vector<std::string>& names, const std::string& kind);

// Whether `path` is `folder` or lies somewhere inside it (links and ".."
// resolved as far as the paths exist).
bool lies_inside(const std::filesystem::path& path, const std::filesystem::path& folder);

// Throws hair25d::Error naming `what` and `folder` when one of `inputs` lies
// inside the output folder, which replacing the folder would delete.
void check_inputs_outside(const std::filesystem::path& folder,
                          const std::vector<std::filesystem::path>& inputs,
                          const std::string& what);

// Writes text to a file atomically.
void write_text_atomically(const std::filesystem::path& target, const std::string& text);

// The largest text (JSON) file read: a model.json of a large drawing is a few
// MB; parsing takes about ten times the file's size in memory.
inline constexpr std::uintmax_t kMaxTextFileBytes = 256u << 20;

// Reads a whole text file; throws hair25d::Error naming the file if it cannot
// or if it holds more than max_bytes (checked before reading a regular file;
// a pipe or device is read no further than that).
std::string read_text_file(const std::filesystem::path& path,
                           std::uintmax_t max_bytes = kMaxTextFileBytes);

// Replaces folder `target` by a folder filled by fill(tmp_folder): the old
// folder (if any) is removed only after the new one is complete. An existing
// folder is replaced only when it is empty, was written by this function for
// the same `kind` of output ("model", "segment", ...: it leaves a hidden
// mark naming it) or holds nothing, folders looked into, that the new one
// does not hold too; otherwise it is left untouched and hair25d::Error names
// the foreign entry. Links at target are followed (the link stays); the old
// and the new folder are swapped in one step (renameat2 RENAME_EXCHANGE), and
// temporaries of target left by dead processes (killed runs) are removed.
void write_folder_atomically(const std::filesystem::path& target,
                             const std::function<void(const std::filesystem::path&)>& fill,
                             const std::string& kind);

}  // namespace hair25d
