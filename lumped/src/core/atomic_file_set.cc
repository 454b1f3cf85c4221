#include "bearing/atomic_file_set.h"

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <system_error>
#include <utility>

#include "bearing/errors.h"

namespace bearing {

namespace fs = std::filesystem;

namespace {

// A name ending in '/' is a folder, replaced and removed as a whole.
bool is_folder(const std::string& name) {
  return !name.empty() && name.back() == '/';
}

std::string without_slash(const std::string& name) {
  return is_folder(name) ? name.substr(0, name.size() - 1) : name;
}

// Removes `path`, a file (one unlink, as fs::remove) or, if `folder`, a folder with everything
// in it; nothing if there is none. A file's name never removes a folder that happens to be there.
void remove_entry(const fs::path& path, bool folder, std::error_code& ec) {
  if (folder)
    fs::remove_all(path, ec);
  else
    fs::remove(path, ec);
}

void remove_entry(const fs::path& path, bool folder) {
  std::error_code ec;
  remove_entry(path, folder, ec);
  if (ec) throw fs::filesystem_error("cannot remove", path, ec);
}

// Puts the complete file (or folder) `from` under the name `to` in one step, so a kill at any
// moment leaves `to` the old file or the new one, never neither. An existing `to` is swapped with
// `from` (renameat2 RENAME_EXCHANGE) and the old file, now under `from`, removed: a plain rename
// onto an existing file makes ext4 write the new file's blocks out at once (auto_da_alloc, ~4 ms
// for bearing-sim's default run), which the exchange does not. Without the exchange (no `to` yet,
// a file system or kernel without it) a plain rename; an old folder then goes first (a rename
// cannot replace a folder that holds files), so there a kill in between leaves neither.
void replace_file(const fs::path& from, const fs::path& to, bool folder) {
#ifdef RENAME_EXCHANGE
  if (::renameat2(AT_FDCWD, from.c_str(), AT_FDCWD, to.c_str(), RENAME_EXCHANGE) == 0) {
    remove_entry(from, folder);
    return;
  }
#endif
  if (folder) {
    std::error_code ec;
    fs::rename(from, to, ec);
    if (!ec) return;
    if (ec != std::errc::directory_not_empty && ec != std::errc::file_exists)
      throw fs::filesystem_error("cannot rename", from, to, ec);
    fs::remove_all(to);
  }
  fs::rename(from, to);
}

}  // namespace

fs::path temporary_path(const fs::path& dir, const std::string& name) {
  const fs::path relative(without_slash(name));
  return dir / relative.parent_path() / ("." + relative.filename().string() + ".partial");
}

void write_file(const fs::path& path, std::string_view text) {
  const auto fail = [&](int error) {
    throw OutputError("cannot write " + path.string() + " (" + std::strerror(error) + ")");
  };
  std::FILE* file = std::fopen(path.c_str(), "wb");
  if (!file) fail(errno);
  const bool written = std::fwrite(text.data(), 1, text.size(), file) == text.size();
  const int write_error = errno;
  if (std::fclose(file) != 0) fail(errno);  // the buffered rest is written here (a full disk)
  if (!written) fail(write_error);
}

AtomicFileSet::AtomicFileSet(fs::path dir, std::vector<std::string> names,
                             std::vector<std::string> others, std::string shown)
    : dir_(std::move(dir)),
      names_(std::move(names)),
      others_(std::move(others)),
      shown_(std::move(shown)) {
  // An exclusive flock(2) on a file that is never removed: removing it would let a second writer
  // lock a new file while a third still waits on the old one.
  const fs::path lock = dir_ / ".run.lock";
  lock_fd_ = ::open(lock.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (lock_fd_ < 0)
    throw OutputError("cannot create " + lock.string() + " (" + std::strerror(errno) + ")");
  while (::flock(lock_fd_, LOCK_EX) != 0)
    if (errno != EINTR) {
      const std::string why = std::strerror(errno);
      ::close(lock_fd_);
      throw OutputError("cannot lock " + lock.string() + " (" + why + ")");
    }
  // The temporaries of this set's own names are overwritten; those of the others would be left.
  std::error_code ignored;
  for (const auto& name : others_) remove_entry(temporary(name), is_folder(name), ignored);
}

AtomicFileSet::~AtomicFileSet() {
  if (!committed_) {
    std::error_code ignored;
    for (const auto& name : names_) remove_entry(temporary(name), is_folder(name), ignored);
  }
  ::close(lock_fd_);  // closing releases the lock
}

fs::path AtomicFileSet::temporary(const std::string& name) const {
  return temporary_path(dir_, name);
}

void AtomicFileSet::write(const std::string& name, std::string_view text) const {
  write_file(temporary(name), text);
}

fs::path AtomicFileSet::fresh_folder(const std::string& name) const {
  const fs::path path = temporary(name);
  std::error_code ec;
  fs::remove_all(path, ec);
  if (!ec) fs::create_directory(path, ec);
  if (ec) throw OutputError("cannot create " + path.string() + " (" + ec.message() + ")");
  return path;
}

void AtomicFileSet::commit() {
  try {
    for (const auto& name : names_)
      replace_file(temporary(name), dir_ / without_slash(name), is_folder(name));
    committed_ = true;  // every temporary is renamed: nothing of this set is left to remove
    for (const auto& name : others_) remove_entry(dir_ / without_slash(name), is_folder(name));
  } catch (const fs::filesystem_error& e) {
    throw OutputError(shown_ + ": " + e.what());
  }
}

}  // namespace bearing
