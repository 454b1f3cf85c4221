// AtomicFileSet (bearing/atomic_file_set.h), the commit that bearing-sim run, bearing-fem contact
// and bearing-fem calibrate share: what is under the final names before and after a commit, what
// a set that is not committed leaves, a write that fails, a folder in the set, and the lock.
// (The programs killed at each step of it: Guarantees.* and fem.atomic_writes.*.)

#include <chrono>
#include <filesystem>
#include <fstream>
#include <future>
#include <map>
#include <memory>
#include <sstream>
#include <string>

#include <gtest/gtest.h>

#include "bearing/atomic_file_set.h"
#include "bearing/errors.h"

namespace bearing {
namespace {

namespace fs = std::filesystem;

fs::path fresh_dir(const std::string& name) {
  const fs::path d = fs::path(::testing::TempDir()) / ("atomic_file_set_" + name);
  fs::remove_all(d);
  fs::create_directories(d);
  return d;
}

void put(const fs::path& p, const std::string& text) {
  std::ofstream(p, std::ios::binary) << text;
}

std::string text_of(const fs::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

// Every file under `dir` (recursively, hidden ones too): relative path -> text.
std::map<std::string, std::string> tree(const fs::path& dir) {
  std::map<std::string, std::string> out;
  for (const auto& e : fs::recursive_directory_iterator(dir))
    if (e.is_regular_file()) out[fs::relative(e.path(), dir).string()] = text_of(e.path());
  return out;
}

TEST(AtomicFileSet, TemporaryNamesAreHiddenBesideTheFinalOnes) {
  EXPECT_EQ(temporary_path("out/6308", "response.csv"), fs::path("out/6308/.response.csv.partial"));
  EXPECT_EQ(temporary_path("cal", "6308_inner/contact.json"),
            fs::path("cal/6308_inner/.contact.json.partial"));
  EXPECT_EQ(temporary_path("out", "vtu/"), fs::path("out/.vtu.partial"));
}

// The new files replace the old ones, `others` go, a folder is replaced as a whole (nothing of
// the old one stays, nothing a killed writer left in its temporary either), and no temporary is
// left: only the lock.
TEST(AtomicFileSet, CommitReplacesEveryFileAndRemovesTheOthers) {
  const fs::path dir = fresh_dir("commit");
  fs::create_directories(dir / "sub");
  fs::create_directories(dir / "vtu");
  put(dir / "a.csv", "old a");
  put(dir / "sub" / "b.json", "old b");
  put(dir / "vtu" / "old_step.vtu", "old vtu");
  put(dir / "gone.npy", "an earlier format");
  put(dir / ".gone.npy.partial", "what a killed writer left");
  fs::create_directories(dir / ".vtu.partial");
  put(dir / ".vtu.partial" / "stale.vtu", "a killed writer's step");  // fresh_folder empties it
  {
    AtomicFileSet set(dir, {"a.csv", "sub/b.json", "vtu/", "new.txt"}, {"gone.npy", "never.csv"},
                      "--out test");
    EXPECT_FALSE(fs::exists(dir / ".gone.npy.partial"));  // removed on construction
    set.write("a.csv", "new a");
    set.write("sub/b.json", "new b");
    set.write("new.txt", "new file");
    const fs::path vtu = set.fresh_folder("vtu/");
    EXPECT_EQ(vtu, dir / ".vtu.partial");
    put(vtu / "step_0.vtu", "new vtu");
    // Before the commit the final names still hold the old files.
    EXPECT_EQ(text_of(dir / "a.csv"), "old a");
    EXPECT_TRUE(fs::exists(dir / "gone.npy"));
    set.commit();
  }
  const std::map<std::string, std::string> expected = {{"a.csv", "new a"},
                                                       {"sub/b.json", "new b"},
                                                       {"vtu/step_0.vtu", "new vtu"},
                                                       {"new.txt", "new file"},
                                                       {".run.lock", ""}};
  EXPECT_EQ(tree(dir), expected);
  EXPECT_FALSE(fs::exists(dir / ".vtu.partial"));
}

// A set destroyed without its commit (a failed run) leaves the old files and no temporary.
TEST(AtomicFileSet, WithoutCommitTheOldFilesStayAndTheTemporariesGo) {
  const fs::path dir = fresh_dir("no_commit");
  put(dir / "a.csv", "old a");
  {
    AtomicFileSet set(dir, {"a.csv", "b.csv", "vtu/"}, {}, "--out test");
    set.write("a.csv", "new a");
    set.write("b.csv", "new b");
    put(set.fresh_folder("vtu/") / "x.vtu", "new vtu");
  }
  const std::map<std::string, std::string> expected = {{"a.csv", "old a"}, {".run.lock", ""}};
  EXPECT_EQ(tree(dir), expected);
  EXPECT_FALSE(fs::exists(dir / ".vtu.partial"));
}

// A write that fails (here /dev/full under the temporary name: "No space left on device" when the
// data reach it) is an OutputError naming the file and the reason; nothing of the set stays.
TEST(AtomicFileSet, AFailedWriteIsAnOutputErrorNamingTheFileAndTheReason) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  const fs::path dir = fresh_dir("full");
  put(dir / "a.csv", "old a");
  {
    AtomicFileSet set(dir, {"a.csv"}, {}, "--out test");
    fs::create_symlink("/dev/full", set.temporary("a.csv"));
    try {
      set.write("a.csv", "new a");
      ADD_FAILURE() << "the write to /dev/full succeeded";
    } catch (const OutputError& e) {
      const std::string what = e.what();
      EXPECT_NE(what.find("cannot write " + set.temporary("a.csv").string()), std::string::npos)
          << what;
      EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
    }
  }
  EXPECT_EQ(text_of(dir / "a.csv"), "old a");
  EXPECT_FALSE(fs::exists(fs::symlink_status(dir / ".a.csv.partial")));
}

// A rename that fails (a temporary never written) is an OutputError starting with `shown`; the
// files renamed before it are the new ones, those after it the old ones.
TEST(AtomicFileSet, AFailedCommitIsAnOutputErrorNamingTheFolder) {
  const fs::path dir = fresh_dir("bad_commit");
  put(dir / "a.csv", "old a");
  put(dir / "b.csv", "old b");
  AtomicFileSet set(dir, {"a.csv", "missing.csv", "b.csv"}, {}, "--out somewhere");
  set.write("a.csv", "new a");
  set.write("b.csv", "new b");
  try {
    set.commit();
    ADD_FAILURE() << "a commit without missing.csv succeeded";
  } catch (const OutputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("--out somewhere: ", 0), 0u) << e.what();
  }
  EXPECT_EQ(text_of(dir / "a.csv"), "new a");
  EXPECT_EQ(text_of(dir / "b.csv"), "old b");
}

TEST(AtomicFileSet, AFolderThatDoesNotExistIsAnOutputError) {
  const fs::path dir = fresh_dir("missing") / "not here";
  EXPECT_THROW({ AtomicFileSet set(dir, {"a.csv"}, {}, "--out x"); }, OutputError);
  EXPECT_FALSE(fs::exists(dir));
}

// A second writer of the folder waits for the first set to go (its commit done or abandoned).
TEST(AtomicFileSet, ASecondWriterWaitsForTheFirst) {
  const fs::path dir = fresh_dir("lock");
  auto first = std::make_unique<AtomicFileSet>(dir, std::vector<std::string>{"a.csv"},
                                               std::vector<std::string>{}, "--out x");
  first->write("a.csv", "first");
  auto second = std::async(std::launch::async, [&] {
    AtomicFileSet set(dir, {"a.csv"}, {}, "--out x");
    return text_of(dir / "a.csv");  // what the first left when the lock came free
  });
  EXPECT_EQ(second.wait_for(std::chrono::milliseconds(300)), std::future_status::timeout);
  first->commit();
  first.reset();
  EXPECT_EQ(second.get(), "first");
}

}  // namespace
}  // namespace bearing
