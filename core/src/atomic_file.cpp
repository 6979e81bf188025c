#include "hair25d/core/atomic_file.h"

#include <fcntl.h>
#include <signal.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <charconv>
#include <climits>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <system_error>

#include "hair25d/core/error.h"

namespace hair25d {

namespace fs = std::filesystem;

namespace {

// "out/" names the folder "out": without this its temporary would land inside
// it (an empty filename) and the rename would fail.
fs::path without_trailing_slash(const fs::path& target) {
  return target.has_filename() || !target.has_parent_path() ? target : target.parent_path();
}

// Where a write to `target` lands: a link as its last component is followed
// (again and again, as open() would), so that writing through a link replaces
// the link's target and keeps the link, instead of replacing the link by a file.
fs::path follow_links(const fs::path& target) {
  constexpr int kMaxHops = 40;  // as the kernel's ELOOP limit
  fs::path path = target;
  std::error_code ec;
  for (int hops = 0; fs::is_symlink(fs::symlink_status(path, ec)); ++hops) {
    if (hops == kMaxHops) {
      throw Error(target.string() + ": more than " + std::to_string(kMaxHops) +
                  " symbolic links in a row (a loop?)");
    }
    const fs::path link = fs::read_symlink(path, ec);
    if (ec) throw Error(path.string() + ": cannot read the symbolic link: " + ec.message());
    path = without_trailing_slash(link.is_absolute() ? link : path.parent_path() / link);
  }
  return path;
}

// A device, pipe or socket (a terminal, /dev/stdout, a FIFO): renaming a file
// over it would replace it, so the bytes are written to it directly.
// A link into /proc/PID/fd or /dev/fd (/dev/stdout) names an open file of
// this process: whatever it is, replacing it by a new file would lose the
// bytes written to the old one through the descriptor, so it too is written
// directly.
bool is_special_file(const fs::path& target) {
  std::error_code ec;
  const fs::file_status status = fs::status(target, ec);
  if (!ec && fs::exists(status) && !fs::is_regular_file(status) && !fs::is_directory(status))
    return true;
  fs::path path = target;
  for (int hops = 0; hops < 40 && fs::is_symlink(fs::symlink_status(path, ec)); ++hops) {
    const fs::path link = fs::read_symlink(path, ec);
    if (ec) return false;
    path = link.is_absolute() ? link : path.parent_path() / link;
    const std::string text = path.lexically_normal().generic_string();
    if (text.rfind("/proc/", 0) == 0 || text.rfind("/dev/fd/", 0) == 0) return true;
  }
  return false;
}

// Temporaries of `target` (".NAME.tmp-PID-N[.ext]") left by a process that no
// longer runs (killed between writing and renaming) are removed; those of a
// running process, this one included, are left alone.
void sweep_stale_temporaries(const fs::path& target) {
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + string.
  std::string prefix = ".";
  prefix += target.filename().string();
  prefix += ".tmp-";
  const std::string extension = target.extension().string();
  std::error_code ec;
  std::vector<fs::path> stale;
  for (fs::directory_iterator it(parent, ec), end; !ec && it != end; it.increment(ec)) {
    const std::string name = it->path().filename().string();
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const char* first = name.data() + prefix.size();
    const char* last = name.data() + name.size();
    long pid = 0;
    unsigned long counter = 0;
    auto [after_pid, pid_error] = std::from_chars(first, last, pid);
    if (pid_error != std::errc() || pid <= 0 || pid > INT_MAX || after_pid == last ||
        *after_pid != '-')
      continue;
    auto [after_counter, counter_error] = std::from_chars(after_pid + 1, last, counter);
    if (counter_error != std::errc() || std::string(after_counter, last) != extension) continue;
    if (pid == ::getpid()) continue;
    if (::kill(static_cast<pid_t>(pid), 0) == -1 && errno == ESRCH) stale.push_back(it->path());
  }
  for (const fs::path& path : stale) fs::remove_all(path, ec);
}

// Left in every folder written here, holding the kind of output, so that a
// later run of the same command knows the folder is its own (a model without
// textures has no strands/, the next one may) and another command does not
// take it for its own (a generated case folder is input to segment).
constexpr const char* kOutputMark = ".hair25d-output";

std::string mark_text(const std::string& kind) { return "hair25d " + kind + "\n"; }

bool marked_as(const fs::path& folder, const std::string& kind) {
  std::ifstream in(folder / kOutputMark, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return in && text.str() == mark_text(kind);
}

// The first entry under `old` (relative path) that `ours` does not accept, or
// "" when every one is accepted or `old` is marked as this kind of output.
// Anything else is somebody's file that replacing the folder would delete.
// Folders are looked into: strands/notes.txt is somebody's even where a
// strands/ folder is ours.
std::string foreign_entry(const fs::path& old, const std::string& kind,
                          const std::function<bool(const fs::path&, bool folder)>& ours) {
  if (marked_as(old, kind)) return "";
  std::error_code ec;
  for (auto it = fs::recursive_directory_iterator(old); it != fs::recursive_directory_iterator();
       ++it) {
    const fs::path relative = it->path().lexically_relative(old);
    if (relative == kOutputMark) continue;  // another kind's mark: its entries decide
    if (!ours(relative, it->is_directory(ec))) return relative.generic_string();
  }
  return "";
}

// Against the new output itself: an entry is ours when the new folder holds
// it too (the same kind: a file for a file, a folder for a folder).
std::string foreign_entry(const fs::path& old, const fs::path& fresh, const std::string& kind) {
  return foreign_entry(old, kind, [&](const fs::path& relative, bool folder) {
    std::error_code ec;
    return folder ? fs::is_directory(fresh / relative, ec)
                  : fs::is_regular_file(fresh / relative, ec);
  });
}

// A folder target must have a name of its own: "" and "." would replace the
// current folder (and everything in it), ".." its parent.
void check_folder_name(const fs::path& target, const std::string& what) {
  const std::string name = target.filename().string();
  if (target.empty() || name == "." || name == "..") {
    throw Error(what + " \"" + target.string() +
                "\": give the output folder a name of its own (not \"\", \".\" or \"..\")");
  }
}

Error foreign_folder_error(const fs::path& target, const std::string& what,
                           const std::string& foreign) {
  return Error((what.empty() ? "" : what + " ") + target.string() + ": the folder holds " +
               foreign +
               ", which this command does not write; refusing to replace it (give a new "
               "or empty folder, or an earlier output of this command)");
}

// The nearest existing folder on the way to `target`; throws when a file
// stands where one of its folders would be.
void check_parent_folders(const fs::path& target, const std::string& what) {
  std::error_code ec;
  fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  while (!fs::exists(parent, ec) && parent.has_parent_path() && parent.parent_path() != parent)
    parent = parent.parent_path();
  if (fs::exists(parent, ec) && !fs::is_directory(parent, ec)) {
    throw Error(what + " " + target.string() + ": " + parent.string() + " is a file, not a folder");
  }
}

}  // namespace

fs::path temporary_sibling(const fs::path& target_in) {
  const fs::path target = without_trailing_slash(target_in);
  // A per-process counter keeps two temporaries of one process apart; the pid
  // keeps two processes apart.
  static std::atomic<unsigned> counter{0};
  // Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "." + string.
  std::string name = ".";
  name += target.filename().string();
  name += ".tmp-" + std::to_string(::getpid()) + "-" + std::to_string(counter++);
  name += target.extension().string();
  return target.parent_path() / name;
}

void write_atomically(const fs::path& target_in,
                      const std::function<void(const fs::path&)>& write) {
  if (is_special_file(target_in)) {
    write(target_in);
    return;
  }
  const fs::path target = follow_links(without_trailing_slash(target_in));
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  std::error_code ec;
  if (!fs::is_directory(parent, ec)) {
    throw Error(target.string() + ": the folder " + parent.string() + " does not exist");
  }
  sweep_stale_temporaries(target);
  const fs::path tmp = temporary_sibling(target);
  try {
    write(tmp);
    fs::rename(tmp, target);
  } catch (const fs::filesystem_error& e) {
    fs::remove(tmp, ec);
    throw Error(target.string() + ": cannot write: " + e.code().message());
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
}

void check_output_file(const fs::path& target_in, const std::string& what) {
  if (is_special_file(target_in)) return;  // written directly
  const fs::path target = follow_links(target_in);
  std::error_code ec;
  if (fs::is_directory(target, ec)) {
    throw Error(what + " " + target.string() + ": is a folder; expected a file name");
  }
  // The folder may be made later (as -o's are), but not where a file stands.
  check_parent_folders(target, what);
}

void check_output_folder(const fs::path& target_in, const std::string& what,
                         const std::vector<std::string>& names, const std::string& kind) {
  check_folder_name(without_trailing_slash(target_in), what);
  const fs::path target = follow_links(without_trailing_slash(target_in));
  check_folder_name(target, what);
  std::error_code ec;
  if (fs::exists(target, ec) && !fs::is_directory(target, ec)) {
    throw Error(what + " " + target.string() + ": exists and is not a folder");
  }
  check_parent_folders(target, what);
  if (!fs::is_directory(target, ec)) return;
  // Unmarked, only top-level names the command writes, and folders among them
  // empty: what is inside a folder the command has not marked is unknown.
  const std::string foreign = foreign_entry(target, kind, [&](const fs::path& relative, bool) {
    const std::string top = relative.begin()->string();
    return relative == top && std::find(names.begin(), names.end(), top) != names.end();
  });
  if (!foreign.empty()) throw foreign_folder_error(target, what, foreign);
}

bool lies_inside(const fs::path& path, const fs::path& folder) {
  if (path.empty() || folder.empty()) return false;
  std::error_code ec;
  // Links and ".." resolved as far as the paths exist.
  const fs::path out = fs::weakly_canonical(fs::absolute(without_trailing_slash(folder)), ec);
  if (ec) return false;
  const fs::path in = fs::weakly_canonical(fs::absolute(path), ec);
  if (ec) return false;
  const fs::path rel = in.lexically_relative(out);
  return !rel.empty() && *rel.begin() != "..";
}

void check_inputs_outside(const fs::path& folder, const std::vector<fs::path>& inputs,
                          const std::string& what) {
  for (const fs::path& input : inputs) {
    if (lies_inside(input, folder)) {
      throw Error(what + " " + folder.string() + ": the input " + input.string() +
                  " lies in it; writing the output there would replace it (give another folder)");
    }
  }
}

void write_text_atomically(const fs::path& target, const std::string& text) {
  write_atomically(target, [&](const fs::path& tmp) {
    std::ofstream out(tmp, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw Error(target.string() + ": cannot write the file");
  });
}

std::string read_text_file(const fs::path& path, std::uintmax_t max_bytes) {
  std::error_code ec;
  if (!fs::exists(path, ec)) throw Error(path.string() + ": no such file");
  if (fs::is_directory(path, ec)) throw Error(path.string() + ": is a folder, expected a file");
  const auto too_large = [&](const std::string& size) {
    return Error(path.string() + ": " + size + " bytes; a text file may hold at most " +
                 std::to_string(max_bytes));
  };
  // A regular file is measured before reading; anything else (a pipe,
  // /dev/zero) is read up to one byte past the limit, so it cannot fill memory.
  const bool regular = fs::is_regular_file(path, ec);
  const std::uintmax_t size = regular ? fs::file_size(path, ec) : 0;
  if (regular && !ec && size > max_bytes) throw too_large(std::to_string(size));
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path.string() + ": cannot open the file for reading");
  std::string text;
  char buffer[1 << 16];
  while (in.read(buffer, sizeof buffer) || in.gcount() > 0) {
    text.append(buffer, static_cast<std::size_t>(in.gcount()));
    if (text.size() > max_bytes) throw too_large("more than " + std::to_string(max_bytes));
  }
  if (in.bad()) throw Error(path.string() + ": read error");
  return text;
}

void write_folder_atomically(const fs::path& target_in,
                             const std::function<void(const fs::path&)>& fill,
                             const std::string& kind) {
  check_folder_name(without_trailing_slash(target_in), "");
  const fs::path target = follow_links(without_trailing_slash(target_in));
  check_folder_name(target, "");
  std::error_code ec;
  if (fs::exists(target, ec) && !fs::is_directory(target, ec)) {
    throw Error(target.string() + ": exists and is not a folder; refusing to replace it");
  }
  const fs::path parent = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  fs::create_directories(parent, ec);
  if (ec) throw Error(parent.string() + ": cannot create the folder: " + ec.message());
  sweep_stale_temporaries(target);
  const fs::path tmp = temporary_sibling(target);
  try {
    fs::create_directory(tmp);
    fill(tmp);
    std::ofstream(tmp / kOutputMark) << mark_text(kind);
    if (!fs::exists(target)) {
      fs::rename(tmp, target);
      return;
    }
    const std::string foreign = foreign_entry(target, tmp, kind);
    if (!foreign.empty()) throw foreign_folder_error(target, "", foreign);
    // rename() cannot replace a non-empty folder; exchanging the two swaps
    // them in one step, so that at every moment the old or the new complete
    // folder is at the target. The old one, now under the temporary name, is
    // removed after (or by the sweep of a later run if this one is killed).
    if (::renameat2(AT_FDCWD, tmp.c_str(), AT_FDCWD, target.c_str(), RENAME_EXCHANGE) == 0) {
      fs::remove_all(tmp, ec);
      return;
    }
    if (errno != EINVAL && errno != ENOSYS) {
      throw Error(target.string() + ": cannot replace the folder: " + std::strerror(errno));
    }
    // A filesystem without the exchange: the old folder moved aside first
    // (killed between the two renames, the target is missing but the old
    // folder survives under its temporary name).
    const fs::path old = temporary_sibling(target);
    fs::rename(target, old);
    fs::rename(tmp, target);
    fs::remove_all(old, ec);
  } catch (const fs::filesystem_error& e) {
    fs::remove_all(tmp, ec);
    // Name the path the system refused: for /proc/out the kernel answers
    // "No such file or directory" to making the temporary beside it, which
    // without the path reads as if the target were missing.
    const std::string where =
        e.path1().empty() ? std::string() : " (at " + e.path1().string() + ")";
    throw Error(target.string() + ": cannot write the folder" + where + ": " + e.code().message());
  } catch (...) {
    fs::remove_all(tmp, ec);
    throw;
  }
}

}  // namespace hair25d
