#pragma once
// The files of one result written all or nothing (docs/RELIABILITY.md): `bearing-sim run`'s
// folder, `bearing-fem contact`'s folder and `bearing-fem calibrate`'s calibration file with its
// race folders.

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

namespace bearing {

/// Where AtomicFileSet writes `name` of folder `dir` until its commit: dir/.NAME.partial, a
/// subfolder of the name kept ("inner/contact.json" -> dir/inner/.contact.json.partial; a folder's
/// "vtu/" -> dir/.vtu.partial). Every MPI rank can compute it, without the set.
std::filesystem::path temporary_path(const std::filesystem::path& dir, const std::string& name);

/// Writes `text` to `path` (created or truncated). Throws OutputError naming the file and the
/// system's reason ("No space left on device"): a file that could not be written whole is an
/// error, never a silently shorter file.
void write_file(const std::filesystem::path& path, std::string_view text);

/// The files of one result in the folder `dir`, written all or nothing. Each file (or folder) is
/// written under its temporary name (temporary_path) and commit() puts each under its final name,
/// replacing its predecessor in one step: a process killed at any moment leaves under every final
/// name a complete file, the previous one or the new one. The set holds an exclusive flock on
/// dir/.run.lock from construction to destruction, so writers of one folder write and commit one at
/// a time (the lock goes with the process: a killed writer holds nothing). A set not committed (an
/// exception, a return before commit()) removes its temporaries when destroyed.
class AtomicFileSet {
 public:
  /// Locks dir/.run.lock (created if missing, never removed; `dir` must exist), waiting while
  /// another writer holds it. `names`: this result's files, committed in this order (a name may
  /// lie in a subfolder of `dir`, which must exist; a name ending in '/' is a folder, replaced as
  /// a whole). `others`: what an earlier result in `dir` may hold that this one does not (another
  /// format, an output switched off): their temporaries that a killed writer left are removed
  /// now, the files themselves by commit(). `shown` names the folder in messages ("--out
  /// out/6308"). Throws OutputError if the lock cannot be created or taken.
  AtomicFileSet(std::filesystem::path dir, std::vector<std::string> names,
                std::vector<std::string> others, std::string shown);
  ~AtomicFileSet();
  AtomicFileSet(const AtomicFileSet&) = delete;
  AtomicFileSet& operator=(const AtomicFileSet&) = delete;

  /// temporary_path(dir, name): where the set's file `name` is written before the commit.
  std::filesystem::path temporary(const std::string& name) const;

  /// write_file(temporary(name), text).
  void write(const std::string& name, std::string_view text) const;

  /// Creates the folder `name` ("vtu/") empty under its temporary name (what a killed writer
  /// left there removed) and returns that path. Throws OutputError.
  std::filesystem::path fresh_folder(const std::string& name) const;

  /// Puts every temporary under its final name, in the order of `names`, each replacing its
  /// predecessor in one step (renameat2 RENAME_EXCHANGE, then the old one removed; a plain rename
  /// where there is none), then removes `others`. Throws OutputError ("SHOWN: " and the system's
  /// message) if a rename or a removal fails; the set, destroyed, then removes the temporaries
  /// not yet renamed.
  void commit();

 private:
  std::filesystem::path dir_;
  std::vector<std::string> names_, others_;
  std::string shown_;
  int lock_fd_;
  bool committed_ = false;
};

}  // namespace bearing
