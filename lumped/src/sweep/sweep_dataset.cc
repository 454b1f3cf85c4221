#include "bearing/sweep_dataset.h"

#include <hdf5.h>

#include <algorithm>
#include <filesystem>
#include <string_view>
#include <system_error>

#include "bearing/errors.h"
#include "bearing/output.h"

namespace bearing {

namespace fs = std::filesystem;

namespace {

constexpr int kFormatVersion = 1;
constexpr unsigned kDeflateLevel = 4;
constexpr std::size_t kChunkBytes = 256 * 1024;
constexpr const char* kLayout =
    "/cases/<index> per case (attrs index, values, status, error, case_toml) holding float64 "
    "tables response, spectrum, envelope (samples x columns; attrs columns, units) and summary "
    "(rows mean, rms, ptp, kurtosis, crest x channel columns; attrs rows, columns, units, "
    "summary_json); see sweep_dataset.h";

// An HDF5 identifier closed by its own close function when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t), const char* what) : id_(id), close_(close) {
    if (id_ < 0) throw InputError(std::string("sweep.h5: HDF5 cannot ") + what);
  }
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(Handle&& o) noexcept : id_(o.id_), close_(o.close_) { o.id_ = -1; }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  Handle& operator=(Handle&&) = delete;
  operator hid_t() const { return id_; }
  /// Closes now, reporting a failure (a file's last write happens here).
  void close(const char* what) {
    const herr_t status = close_(id_);
    id_ = -1;
    if (status < 0) throw InputError(std::string("sweep.h5: HDF5 cannot ") + what);
  }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

void check(herr_t status, const char* what) {
  if (status < 0) throw InputError(std::string("sweep.h5: HDF5 cannot ") + what);
}

// HDF5 prints its error stack by default; the errors are reported as exceptions instead, so the
// printing is off while this lives (and restored after).
class QuietErrors {
 public:
  QuietErrors() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietErrors() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

// Variable-length UTF-8 strings: h5py 3 reads them as str.
Handle string_type() {
  Handle t(H5Tcopy(H5T_C_S1), H5Tclose, "copy the string type");
  check(H5Tset_size(t, H5T_VARIABLE), "size the string type");
  check(H5Tset_cset(t, H5T_CSET_UTF8), "set UTF-8");
  return t;
}

void write_attribute(hid_t object, const char* name, hid_t file_type, hid_t memory_type,
                     hid_t space, const void* data) {
  Handle a(H5Acreate2(object, name, file_type, space, H5P_DEFAULT, H5P_DEFAULT), H5Aclose,
           "create an attribute");
  // An empty array (no varied keys) has nothing to write; h5py reads it as an array of shape (0,).
  if (H5Sget_simple_extent_npoints(space) > 0)
    check(H5Awrite(a, memory_type, data), "write an attribute");
}

void string_attribute(hid_t object, const char* name, const std::string& value) {
  Handle type = string_type();
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a dataspace");
  const char* p = value.c_str();
  write_attribute(object, name, type, type, space, &p);
}

void strings_attribute(hid_t object, const char* name, const std::vector<std::string>& values) {
  Handle type = string_type();
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "create a dataspace");
  std::vector<const char*> p;
  for (const auto& v : values) p.push_back(v.c_str());
  write_attribute(object, name, type, type, space, p.data());
}

void doubles_attribute(hid_t object, const char* name, const std::vector<double>& values) {
  const hsize_t n = values.size();
  Handle space(H5Screate_simple(1, &n, nullptr), H5Sclose, "create a dataspace");
  write_attribute(object, name, H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE, space, values.data());
}

void integer_attribute(hid_t object, const char* name, long long value) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a dataspace");
  write_attribute(object, name, H5T_STD_I64LE, H5T_NATIVE_LLONG, space, &value);
}

void index_attribute(hid_t object, std::size_t index) {
  Handle space(H5Screate(H5S_SCALAR), H5Sclose, "create a dataspace");
  const unsigned long long v = index;
  write_attribute(object, "index", H5T_STD_U64LE, H5T_NATIVE_ULLONG, space, &v);
}

// The table as a float64 dataset (rows, columns) with attributes columns and units: chunked by
// whole rows (≈kChunkBytes per chunk) and compressed (shuffle, deflate). An empty table cannot be
// chunked: it is stored contiguous.
void write_table(hid_t group, const char* name, const SweepTable& t) {
  const hsize_t dims[2] = {t.rows, t.columns.size()};
  Handle space(H5Screate_simple(2, dims, nullptr), H5Sclose, "create a dataspace");
  Handle plist(H5Pcreate(H5P_DATASET_CREATE), H5Pclose, "create a property list");
  if (dims[0] > 0 && dims[1] > 0) {
    const hsize_t per_chunk = std::max<hsize_t>(1, kChunkBytes / (sizeof(double) * dims[1]));
    const hsize_t chunk[2] = {std::min(dims[0], per_chunk), dims[1]};
    check(H5Pset_chunk(plist, 2, chunk), "set the chunk size");
    check(H5Pset_shuffle(plist), "set the shuffle filter");
    check(H5Pset_deflate(plist, kDeflateLevel), "set the deflate filter");
  }
  Handle ds(H5Dcreate2(group, name, H5T_IEEE_F64LE, space, H5P_DEFAULT, plist, H5P_DEFAULT),
            H5Dclose, "create a dataset");
  if (!t.values.empty())
    check(H5Dwrite(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, t.values.data()),
          "write a dataset");
  strings_attribute(ds, "columns", t.columns);
  strings_attribute(ds, "units", t.units);
}

}  // namespace

struct SweepDataset::File {
  fs::path path, temporary;
  std::vector<SweepSave> what;
  int digits = 6;
  std::size_t cases = 0;  // groups written
  std::unique_ptr<Handle> file, cases_group;
  bool closed = false;
};

namespace {

// The group `name` of one case with its index, the design's values (SI) and its status.
Handle case_group(hid_t cases, const std::string& name, std::size_t index,
                  const std::vector<double>& values, const char* status) {
  Handle g(H5Gcreate2(cases, name.c_str(), H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose,
           ("create the group of case " + name).c_str());
  index_attribute(g, index);
  doubles_attribute(g, "values", values);
  string_attribute(g, "status", status);
  return g;
}

}  // namespace

SweepDataset::SweepDataset() = default;

SweepDataset::~SweepDataset() {
  if (!file_ || file_->closed) return;
  file_->cases_group.reset();
  file_->file.reset();
  std::error_code ec;
  fs::remove(file_->temporary, ec);
}

void SweepDataset::open(const std::string& path, const std::vector<SweepDatasetKey>& keys,
                        const std::vector<SweepSave>& what, std::size_t cases) {
  QuietErrors quiet;
  auto f = std::make_unique<File>();
  f->path = path;
  f->temporary = f->path.parent_path() / ("." + f->path.filename().string() + ".partial");
  f->what = what;
  for (std::size_t n = cases > 0 ? cases - 1 : 0; n >= 1000000; n /= 10) ++f->digits;
  if (!H5Zfilter_avail(H5Z_FILTER_DEFLATE) || !H5Zfilter_avail(H5Z_FILTER_SHUFFLE))
    throw InputError("sweep.h5: this HDF5 library has no deflate or shuffle filter");
  // Strong close: closing the file closes whatever is still open in it.
  Handle fapl(H5Pcreate(H5P_FILE_ACCESS), H5Pclose, "create a property list");
  check(H5Pset_fclose_degree(fapl, H5F_CLOSE_STRONG), "set the close degree");
  // The 1.8 file format: /cases with many groups keeps its links in a B-tree v2 and a fractal
  // heap (the 1.6 format's local heap holds every name in memory, which grows with the cases).
  check(H5Pset_libver_bounds(fapl, H5F_LIBVER_V18, H5F_LIBVER_LATEST), "set the file format");
  // A bounded metadata cache (default: adaptive up to 32 MiB, which grows with the cases).
  H5AC_cache_config_t cache;
  cache.version = H5AC__CURR_CACHE_CONFIG_VERSION;
  check(H5Pget_mdc_config(fapl, &cache), "read the metadata cache settings");
  cache.set_initial_size = true;
  cache.initial_size = 1 << 20;
  cache.min_size = 1 << 20;
  cache.max_size = 2 << 20;
  check(H5Pset_mdc_config(fapl, &cache), "bound the metadata cache");
  f->file =
      std::make_unique<Handle>(H5Fcreate(f->temporary.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, fapl),
                               H5Fclose, ("create " + f->temporary.string()).c_str());
  file_ = std::move(f);  // from here on the destructor removes the temporary file
  const hid_t root = *file_->file;
  string_attribute(root, "format", "bearing-sim sweep");
  integer_attribute(root, "format_version", kFormatVersion);
  std::vector<std::string> names, units, saved;
  for (const auto& k : keys) names.push_back(k.name), units.push_back(k.unit);
  for (SweepSave w : what) saved.push_back(sweep_save_name(w));
  strings_attribute(root, "keys", names);
  strings_attribute(root, "key_units", units);
  strings_attribute(root, "saved", saved);
  string_attribute(root, "layout", kLayout);
  file_->cases_group = std::make_unique<Handle>(
      H5Gcreate2(root, "cases", H5P_DEFAULT, H5P_DEFAULT, H5P_DEFAULT), H5Gclose, "create /cases");
}

std::string SweepDataset::group_name(std::size_t index) const {
  std::string s = std::to_string(index);
  const std::size_t width = file_ ? static_cast<std::size_t>(file_->digits) : 6;
  if (s.size() < width) s.insert(0, width - s.size(), '0');
  return s;
}

void SweepDataset::add_case(std::size_t index, const std::vector<double>& values, const Case& c,
                            const SimulationResult& r, const RunSummary& s) {
  if (!file_ || file_->closed) throw InputError("sweep.h5: add_case before open or after close");
  add_case(index, values, sweep_case_tables(c, r, s, file_->what));
}

void SweepDataset::add_case(std::size_t index, const std::vector<double>& values,
                            const std::string& case_toml, const Response& response,
                            const RunSummary& s, const std::string& summary_json) {
  if (!file_ || file_->closed) throw InputError("sweep.h5: add_case before open or after close");
  add_case(index, values, sweep_case_tables(case_toml, response, s, summary_json, file_->what));
}

void SweepDataset::add_case(std::size_t index, const std::vector<double>& values,
                            const SweepCaseTables& t) {
  if (!file_ || file_->closed) throw InputError("sweep.h5: add_case before open or after close");
  QuietErrors quiet;
  const Handle g = case_group(*file_->cases_group, group_name(index), index, values, "ok");
  string_attribute(g, "case_toml", t.case_toml);
  for (const SweepTable& table : t.tables) {
    write_table(g, table.name.c_str(), table);
    if (table.row_names.empty() && table.name != "summary") continue;
    Handle ds(H5Dopen2(g, table.name.c_str(), H5P_DEFAULT), H5Dclose, "open a table");
    if (!table.row_names.empty()) strings_attribute(ds, "rows", table.row_names);
    if (table.name == "summary" && !t.summary_json.empty())
      string_attribute(ds, "summary_json", t.summary_json);
  }
  ++file_->cases;
}

void SweepDataset::add_failed_case(std::size_t index, const std::vector<double>& values,
                                   const std::string& error, const std::string& case_toml) {
  if (!file_ || file_->closed) throw InputError("sweep.h5: add_case before open or after close");
  QuietErrors quiet;
  const Handle g = case_group(*file_->cases_group, group_name(index), index, values, "failed");
  string_attribute(g, "error", error);
  if (!case_toml.empty()) string_attribute(g, "case_toml", case_toml);
  ++file_->cases;
}

void SweepDataset::close() {
  if (!file_ || file_->closed) throw InputError("sweep.h5: close before open or twice");
  QuietErrors quiet;
  integer_attribute(*file_->file, "cases", static_cast<long long>(file_->cases));
  file_->cases_group->close("close /cases");
  file_->file->close(("write " + file_->temporary.string() + " (disk full?)").c_str());
  std::error_code ec;
  fs::rename(file_->temporary, file_->path, ec);
  if (ec)
    throw InputError("cannot rename " + file_->temporary.string() + " to " + file_->path.string() +
                     " (" + ec.message() + ")");
  file_->closed = true;
}

namespace {

// A 1-D attribute of variable-length strings (a part's `saved`).
std::vector<std::string> read_strings(hid_t object, const char* name) {
  Handle a(H5Aopen(object, name, H5P_DEFAULT), H5Aclose, "open an attribute");
  Handle space(H5Aget_space(a), H5Sclose, "read an attribute's dataspace");
  Handle type = string_type();
  std::vector<char*> p(static_cast<std::size_t>(H5Sget_simple_extent_npoints(space)), nullptr);
  if (!p.empty()) check(H5Aread(a, type, p.data()), "read an attribute");
  std::vector<std::string> out;
  for (const char* s : p) out.emplace_back(s ? s : "");
  if (!p.empty()) H5Dvlen_reclaim(type, space, H5P_DEFAULT, p.data());
  return out;
}

Handle open_file(const fs::path& path, unsigned flags) {
  return Handle(H5Fopen(path.c_str(), flags, H5P_DEFAULT), H5Fclose,
                ("open " + path.string()).c_str());
}

}  // namespace

std::size_t merge_datasets(const std::string& out, const std::vector<std::string>& parts) {
  if (parts.empty()) throw InputError("merge: no sweep.h5 to merge");
  QuietErrors quiet;
  const fs::path path(out),
      temporary = path.parent_path() / ("." + path.filename().string() + ".partial");
  std::vector<std::string> saved;
  {
    Handle first = open_file(parts.front(), H5F_ACC_RDONLY);
    saved = read_strings(first, "saved");
  }
  std::error_code ec;
  fs::copy_file(parts.front(), temporary, fs::copy_options::overwrite_existing, ec);
  if (ec) throw InputError("merge: cannot write " + temporary.string() + " (" + ec.message() + ")");
  std::size_t cases = 0;
  try {
    Handle merged = open_file(temporary, H5F_ACC_RDWR);
    Handle into(H5Gopen2(merged, "cases", H5P_DEFAULT), H5Gclose, "open /cases");
    for (std::size_t k = 1; k < parts.size(); ++k) {
      Handle part = open_file(parts[k], H5F_ACC_RDONLY);
      if (read_strings(part, "saved") != saved)
        throw InputError("merge: " + parts[k] + " saved other tables than " + parts.front() +
                         " (--save differed between the parts)");
      Handle from(H5Gopen2(part, "cases", H5P_DEFAULT), H5Gclose, "open /cases");
      H5G_info_t info;
      check(H5Gget_info(from, &info), "read /cases");
      for (hsize_t g = 0; g < info.nlinks; ++g) {
        char name[64];
        if (H5Lget_name_by_idx(from, ".", H5_INDEX_NAME, H5_ITER_INC, g, name, sizeof name,
                               H5P_DEFAULT) < 0)
          throw InputError("merge: cannot read the case groups of " + parts[k]);
        if (H5Lexists(into, name, H5P_DEFAULT) > 0)
          throw InputError("merge: case " + std::string(name) + " is in two parts' sweep.h5");
        check(H5Ocopy(from, name, into, name, H5P_DEFAULT, H5P_DEFAULT), "copy a case group");
      }
    }
    H5G_info_t info;
    check(H5Gget_info(into, &info), "read /cases");
    cases = static_cast<std::size_t>(info.nlinks);
    check(H5Adelete(merged, "cases"), "replace the count of cases");
    integer_attribute(merged, "cases", static_cast<long long>(cases));
    into.close("close /cases");
    merged.close(("write " + temporary.string()).c_str());
    fs::rename(temporary, path);
  } catch (...) {
    fs::remove(temporary, ec);
    throw;
  }
  return cases;
}

}  // namespace bearing
