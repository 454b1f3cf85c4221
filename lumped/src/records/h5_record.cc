#include "bearing/records/h5_record.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "bearing/records/channel_choice.h"
#include "bearing/records/time_column.h"
#include "bearing/units.h"
#include "h5_global_heaps.h"
#include "hdf5_handle.h"
#include "record_bounds.h"

namespace bearing {

namespace {

using records_detail::H5Handle;

// The file being read, for messages and for the guard run before its first variable-length read.
struct Source {
  std::filesystem::path path;
  std::string file;
  std::uintmax_t size = 0;
  bool heaps_checked = false;

  void before_variable_length_data() {
    if (!heaps_checked) records_detail::check_global_heaps(path, size, file);
    heaps_checked = true;
  }
};

struct DatasetInfo {
  std::string path;  // "/group/name"
  std::vector<hsize_t> dims;
  std::size_t element_size = 0;
};

struct Walk {
  std::vector<DatasetInfo> numeric;  // rank 1 or 2, integer or float
  std::vector<std::string> others;   // "path (why not)"
};

// The numeric datasets of rank 1 and 2 under the root, in name order, and the other ones.
herr_t visit(hid_t group, const char* name, const H5L_info_t* info, void* data) {
  auto& walk = *static_cast<Walk*>(data);
  if (info->type != H5L_TYPE_HARD) return 0;
  const hid_t ds = H5Dopen2(group, name, H5P_DEFAULT);
  if (ds < 0) return 0;  // a group, or something that is not a dataset
  const hid_t type = H5Dget_type(ds);
  const hid_t space = H5Dget_space(ds);
  const H5T_class_t cls = type >= 0 ? H5Tget_class(type) : H5T_NO_CLASS;
  const int rank = space >= 0 ? H5Sget_simple_extent_ndims(space) : -1;
  DatasetInfo d;
  d.path = std::string("/") + name;
  const bool number = type >= 0 && records_detail::plain_number_type(type);
  if (number && (rank == 1 || rank == 2)) {
    d.dims.resize(static_cast<std::size_t>(rank));
    H5Sget_simple_extent_dims(space, d.dims.data(), nullptr);
    d.element_size = H5Tget_size(type);
    walk.numeric.push_back(std::move(d));
  } else {
    const bool numeric = cls == H5T_INTEGER || cls == H5T_FLOAT;
    walk.others.push_back(d.path + (number    ? " (rank " + std::to_string(rank) + ")"
                                    : numeric ? " (a number type the reader does not convert)"
                                              : " (not numeric)"));
  }
  if (space >= 0) H5Sclose(space);
  if (type >= 0) H5Tclose(type);
  H5Dclose(ds);
  return 0;
}

// A string or string-array attribute's values; nothing when the attribute is absent.
std::optional<std::vector<std::string>> string_attribute(hid_t obj, const char* name,
                                                         Source& source, const std::string& where) {
  const std::string& file = source.file;
  if (H5Aexists(obj, name) <= 0) return std::nullopt;
  const std::string what = "attribute " + std::string(name) + " of " + where;
  H5Handle attr(H5Aopen(obj, name, H5P_DEFAULT), H5Aclose, file, "open " + what);
  H5Handle type(H5Aget_type(attr), H5Tclose, file, "read the type of " + what);
  H5Handle space(H5Aget_space(attr), H5Sclose, file, "read the size of " + what);
  if (H5Tget_class(type) != H5T_STRING) throw record_error(file, "", what + ": not text");
  const hssize_t n = H5Sget_simple_extent_npoints(space);
  if (n < 0 || n > 100000) throw record_error(file, "", what + ": unreadable size");
  const auto count = static_cast<std::size_t>(n);
  std::vector<std::string> out;
  if (H5Tis_variable_str(type) > 0) {
    source.before_variable_length_data();
    H5Handle mem(H5Tcopy(H5T_C_S1), H5Tclose, file, "copy a string type");
    H5Tset_size(mem, H5T_VARIABLE);
    H5Tset_cset(mem, H5Tget_cset(type));
    std::vector<char*> values(count, nullptr);
    if (H5Aread(attr, mem, values.data()) < 0) throw record_error(file, "", what + ": unreadable");
    for (char* v : values) {
      out.emplace_back(v ? v : "");
      H5free_memory(v);
    }
    return out;
  }
  const std::size_t size = H5Tget_size(type);
  if (size == 0 || size > 65536) throw record_error(file, "", what + ": unreadable size");
  std::vector<char> buffer(count * size + 1, '\0');
  if (H5Aread(attr, type, buffer.data()) < 0) throw record_error(file, "", what + ": unreadable");
  for (std::size_t i = 0; i < count; ++i) {
    std::string s(buffer.data() + i * size, size);
    s = s.substr(0, s.find('\0'));
    while (!s.empty() && s.back() == ' ') s.pop_back();
    out.push_back(s);
  }
  return out;
}

// The rate [Hz] of the first of the rate attributes the dataset has.
std::optional<std::pair<double, std::string>> rate_attribute(hid_t ds, const std::string& file,
                                                             const std::string& path) {
  for (const char* name : {"rate", "sample_rate", "sampling_rate", "fs"}) {
    if (H5Aexists(ds, name) <= 0) continue;
    const std::string what = "attribute " + std::string(name) + " of " + path;
    H5Handle attr(H5Aopen(ds, name, H5P_DEFAULT), H5Aclose, file, "open " + what);
    H5Handle type(H5Aget_type(attr), H5Tclose, file, "read the type of " + what);
    H5Handle space(H5Aget_space(attr), H5Sclose, file, "read the size of " + what);
    const H5T_class_t cls = H5Tget_class(type);
    if ((cls != H5T_INTEGER && cls != H5T_FLOAT) || H5Sget_simple_extent_npoints(space) != 1)
      throw record_error(file, "", what + ": must be one number (Hz)");
    double rate = 0;
    if (H5Aread(attr, H5T_NATIVE_DOUBLE, &rate) < 0)
      throw record_error(file, "", what + ": unreadable");
    return std::pair{rate, what};
  }
  return std::nullopt;
}

// Column `column` of the (rows × columns) dataset `d`, as doubles.
std::vector<double> read_column(hid_t ds, const DatasetInfo& d, std::size_t column,
                                const std::string& file, const std::string& channel) {
  const auto rows = static_cast<std::size_t>(d.dims[0]);
  H5Handle file_space(H5Dget_space(ds), H5Sclose, file, "read the size of " + d.path);
  const hsize_t count = rows;
  H5Handle mem_space(H5Screate_simple(1, &count, nullptr), H5Sclose, file, "make a memory space");
  const hsize_t start[2] = {0, column};
  const hsize_t block[2] = {rows, 1};
  if (H5Sselect_hyperslab(file_space, H5S_SELECT_SET, start, nullptr, block, nullptr) < 0)
    throw record_error(file, channel, "HDF5 cannot select the column");
  std::vector<double> values(rows);
  if (rows > 0 &&
      H5Dread(ds, H5T_NATIVE_DOUBLE, mem_space, file_space, H5P_DEFAULT, values.data()) < 0)
    throw record_error(file, channel, "HDF5 cannot read " + d.path + " (corrupt file?)");
  return values;
}

std::string without_slashes(const std::string& path) {
  std::string p = path;
  while (!p.empty() && p.front() == '/') p.erase(0, 1);
  return p;
}

// The dataset options.dataset names, or the file's only one.
const DatasetInfo& choose_dataset(const Walk& walk, const RecordOptions& options,
                                  const std::string& file) {
  std::vector<std::string> paths;
  for (const DatasetInfo& d : walk.numeric) paths.push_back(d.path);
  std::size_t index = 0;
  if (options.dataset.empty()) {
    if (paths.size() != 1)
      throw record_error(file, "",
                         paths.empty() ? "no numeric dataset of rank 1 or 2 to read"
                                       : std::to_string(paths.size()) + " datasets (" +
                                             join_names(paths) + "): choose one with --dataset");
  } else {
    const std::string wanted = "/" + without_slashes(options.dataset);
    while (index < paths.size() && paths[index] != wanted) ++index;
    if (index == paths.size())
      throw record_error(file, "",
                         "no numeric dataset " + wanted + " of rank 1 or 2; the file has " +
                             (paths.empty() ? "none" : join_names(paths)) +
                             (walk.others.empty() ? "" : "; also " + join_names(walk.others)));
  }
  return walk.numeric[index];
}

// The channels' names: a vector's path, or a table's columns (attribute columns, or "0", ...).
std::vector<std::string> column_names(hid_t ds, const DatasetInfo& d, bool table, Source& source) {
  if (!table) return {d.path};
  const std::size_t columns = static_cast<std::size_t>(d.dims[1]);
  std::vector<std::string> names;
  if (auto given = string_attribute(ds, "columns", source, d.path)) {
    if (given->size() != columns)
      throw record_error(source.file, "",
                         "attribute columns of " + d.path + " has " +
                             std::to_string(given->size()) + " names for " +
                             std::to_string(columns) + " columns");
    return *given;
  }
  for (std::size_t k = 0; k < columns; ++k) names.push_back(std::to_string(k));
  return names;
}

// The unit the dataset states: attribute unit (a vector: `columns` 0), or units, one per
// column of a table of `columns` columns (or one for a vector).
void unit_of(RawChannel& raw, hid_t ds, const std::string& path, std::size_t columns,
             std::size_t column, Source& source) {
  const std::string& file = source.file;
  if (const auto unit = string_attribute(ds, "unit", source, path); unit && columns == 0) {
    if (unit->size() != 1)
      throw record_error(file, "", "attribute unit of " + path + ": not one string");
    raw.unit = unit->front();
    raw.unit_origin = "attribute unit of " + path;
  } else if (const auto units = string_attribute(ds, "units", source, path)) {
    const std::size_t expected = std::max<std::size_t>(columns, 1);
    if (units->size() != expected)
      throw record_error(file, "",
                         "attribute units of " + path + " has " + std::to_string(units->size()) +
                             " units for " + std::to_string(expected) + " columns");
    raw.unit = (*units)[column];
    raw.unit_origin = "attribute units of " + path;
  }
}

}  // namespace

RawChannel read_h5_record(const std::filesystem::path& path, const RecordOptions& options) {
  const std::string file = path.string();
  records_detail::QuietHdf5 quiet;
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  Source source{path, file, file_size};
  if (ec || H5Fis_hdf5(file.c_str()) <= 0)
    throw record_error(file, "", "not an HDF5 file (missing, unreadable or corrupt)");
  H5Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, file,
              "open it (corrupt file?)");

  Walk walk;
  if (H5Lvisit(h5, H5_INDEX_NAME, H5_ITER_INC, visit, &walk) < 0)
    throw record_error(file, "", "HDF5 cannot list its datasets (corrupt file?)");
  const DatasetInfo& d = choose_dataset(walk, options, file);
  H5Handle ds(H5Dopen2(h5, d.path.c_str(), H5P_DEFAULT), H5Dclose, file, "open " + d.path);

  // A vector (rank 1, or rank 2 with one row or column) is one channel named by its path; a
  // table's columns are its channels.
  const bool table = d.dims.size() == 2 && d.dims[0] != 1 && d.dims[1] != 1;
  const std::size_t columns = table ? static_cast<std::size_t>(d.dims[1]) : 1;
  // (A rank-2 vector has a dimension of 1, so the product cannot overflow.)
  const std::size_t rows =
      static_cast<std::size_t>(table || d.dims.size() == 1 ? d.dims[0] : d.dims[0] * d.dims[1]);
  records_detail::check_claimed_size(rows, d.element_size * columns, file_size, file, d.path);
  const std::vector<std::string> names = column_names(ds, d, table, source);
  std::optional<std::size_t> time;
  std::vector<std::string> candidates;
  std::vector<std::size_t> column_of;
  for (std::size_t k = 0; k < names.size(); ++k) {
    if (table && !time && is_time_column_name(names[k])) {
      time = k;
      continue;
    }
    candidates.push_back(names[k]);
    column_of.push_back(k);
  }
  const std::size_t column = column_of[choose_channel(candidates, options, file, "column")];

  RawChannel raw;
  raw.channel = names[column];
  if (table) {
    raw.values = read_column(ds, d, column, file, raw.channel);
  } else {
    raw.values.resize(rows);
    if (rows > 0 &&
        H5Dread(ds, H5T_NATIVE_DOUBLE, H5S_ALL, H5S_ALL, H5P_DEFAULT, raw.values.data()) < 0)
      throw record_error(file, raw.channel, "HDF5 cannot read " + d.path + " (corrupt file?)");
  }

  if (const auto rate = rate_attribute(ds, file, d.path)) {
    raw.rate = rate->first;
    raw.rate_origin = rate->second;
  }
  if (time) {
    const std::vector<double> t = read_column(ds, d, *time, file, raw.channel);
    const TimeColumnRate r =
        time_column_rate(t, std::vector<double>(t.size(), 0.0), file, raw.channel, names[*time]);
    if (raw.rate && !(std::abs(*raw.rate - r.rate) <= r.tolerance * r.rate))
      throw record_error(file, raw.channel,
                         raw.rate_origin + " (" + format_number(*raw.rate) +
                             " Hz) contradicts time column " + names[*time] + " (" +
                             format_number(r.rate) + " Hz)");
    raw.rate = r.rate;
    raw.rate_tolerance = r.tolerance;
    raw.rate_origin = "time column " + names[*time] + " of " + d.path;
  }
  unit_of(raw, ds, d.path, table ? columns : 0, column, source);
  return raw;
}

}  // namespace bearing
