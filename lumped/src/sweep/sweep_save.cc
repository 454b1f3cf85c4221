// `sweep --save` restartable through a spool of rows (sweep_save.h).

#include "bearing/sweep_save.h"

#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>

#include "bearing/errors.h"
#include "bearing/sweep_dataset.h"
#include "bearing/sweep_row_codec.h"

namespace bearing {

namespace fs = std::filesystem;

namespace {

constexpr const char* kSpool = ".sweep.h5.cases";
constexpr const char* kSavedFile = "saved";  // the --save list, one line

fs::path row_file(const fs::path& spool, std::size_t index) {
  return spool / (std::to_string(index) + ".row");
}

void write_file(const fs::path& path, const std::string& bytes) {
  const fs::path tmp = path.string() + ".tmp";
  {
    std::ofstream f(tmp, std::ios::binary | std::ios::trunc);
    if (!f.write(bytes.data(), static_cast<std::streamsize>(bytes.size())) || !f.flush())
      throw InputError("--save: cannot write " + tmp.string());
  }
  fs::rename(tmp, path);
}

std::string read_file(const fs::path& path) {
  std::ifstream f(path, std::ios::binary);
  if (!f)
    throw InputError("--save: " + path.string() +
                     " is missing: the spool of the killed sweep is incomplete; run it again");
  return std::string(std::istreambuf_iterator<char>(f), {});
}

// sweep.h5 from the spool: cases first … end − 1 in order, one in memory at a time.
void build_dataset(const fs::path& dir, const fs::path& spool, const SweepPlan& plan,
                   const std::vector<SweepSave>& what) {
  std::vector<SweepDatasetKey> keys;
  for (const auto& k : plan.design->keys())
    keys.push_back({k.key, std::string(si_unit(k.dimension))});
  SweepDataset dataset;
  dataset.open((dir / "sweep.h5").string(), keys, what, plan.design->size());
  const auto [first, end] = part_range(plan.design->size(), plan.part);
  for (std::size_t i = first; i < end; ++i) {
    std::size_t index = 0;
    const SweepRow row = decode_sweep_row(read_file(row_file(spool, i)), index);
    if (row.tables)
      dataset.add_case(i, row.values, *row.tables);
    else
      dataset.add_failed_case(i, row.values, row.error);
  }
  dataset.close();
}

}  // namespace

SweepRowHook sweep_save_hook(const std::string& dir, const SweepPlan& plan,
                             const std::vector<SweepSave>& what, bool resume) {
  if (what.empty()) return {};
  const fs::path folder(dir), spool = folder / kSpool;
  std::error_code ec;
  if (!resume) fs::remove_all(spool, ec);  // a killed sweep's spool does not belong to this one
  fs::create_directories(spool, ec);
  if (ec) throw InputError("--out " + dir + ": cannot create " + spool.string());
  if (!resume) {
    std::string names;
    for (SweepSave w : what) names += std::string(names.empty() ? "" : ",") + sweep_save_name(w);
    write_file(spool / kSavedFile, names + "\n");
  }
  SweepRowHook hook;
  hook.save = what;
  hook.add = [spool](std::size_t i, const SweepRow& row) {
    std::string bytes;
    encode_sweep_row(i, row, bytes);
    write_file(row_file(spool, i), bytes);
  };
  hook.commit = [folder, spool, plan, what] {
    build_dataset(folder, spool, plan, what);
    fs::remove_all(spool);
  };
  return hook;
}

std::vector<SweepSave> spooled_save(const std::string& dir) {
  const fs::path saved = fs::path(dir) / kSpool / kSavedFile;
  if (!fs::exists(saved)) return {};
  std::string line = read_file(saved);
  while (!line.empty() && (line.back() == '\n' || line.back() == '\r')) line.pop_back();
  return parse_sweep_save({line});
}

}  // namespace bearing
