#include "bearing/records/mat_record.h"

#include <matio.h>

#include <cmath>
#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

#include "bearing/records/channel_choice.h"
#include "bearing/units.h"
#include "mat5_elements.h"
#include "record_bounds.h"
#ifdef BEARING_RECORDS_WITH_HDF5
#include "hdf5_handle.h"
#endif

namespace bearing {

namespace {

struct CloseMat {
  void operator()(mat_t* m) const { Mat_Close(m); }
};
struct FreeVar {
  void operator()(matvar_t* v) const { Mat_VarFree(v); }
};
using Var = std::unique_ptr<matvar_t, FreeVar>;

// matio logs its errors to stderr (and aborts on its fatal level, which no read path uses); the
// reader reports errors as InputError instead, so matio's log is silenced. The log function is
// matio's one process-wide setting; setting it is idempotent.
void quiet(int, char*) {}

// A variable as its header describes it, before its data is read.
struct VariableInfo {
  std::string name;
  matio_classes class_type = MAT_C_EMPTY;
  bool complex = false, logical = false;
  std::vector<std::size_t> dims;

  std::size_t numel() const {
    std::size_t n = 1;
    for (const std::size_t d : dims) n = d != 0 && n > SIZE_MAX / d ? SIZE_MAX : n * d;
    return dims.empty() ? 0 : n;
  }
  bool numeric() const { return class_type >= MAT_C_DOUBLE && class_type <= MAT_C_UINT64; }
  // A real numeric vector of at least 2 values: a channel.
  bool channel() const {
    if (!numeric() || complex || logical || dims.size() != 2) return false;
    return numel() >= 2 && (dims[0] == 1 || dims[1] == 1);
  }
  bool scalar() const { return numeric() && !complex && !logical && numel() == 1; }
  std::string shape() const {
    std::string s;
    for (const std::size_t d : dims) s += (s.empty() ? "" : "×") + std::to_string(d);
    return s.empty() ? "no size" : s;
  }
  // Why a variable is not a channel, for messages.
  std::string what() const {
    if (scalar()) return "a 1×1 scalar";
    if (class_type == MAT_C_CHAR) return "text";
    if (class_type == MAT_C_CELL) return "a cell array";
    if (class_type == MAT_C_STRUCT || class_type == MAT_C_OBJECT) return "a struct";
    if (class_type == MAT_C_SPARSE) return "a sparse matrix";
    if (!numeric()) return "not numeric";
    if (complex) return "complex";
    if (logical) return "logical";
    if (numel() < 2) return "a " + shape() + " array";
    return "a " + shape() + " matrix, not a vector";
  }
};

std::vector<VariableInfo> variables_of(mat_t* mat) {
  std::vector<VariableInfo> out;
  while (Var v{Mat_VarReadNextInfo(mat)}) {
    VariableInfo info;
    info.name = v->name ? v->name : "";
    info.class_type = v->class_type;
    info.complex = v->isComplex != 0;
    info.logical = v->isLogical != 0;
    if (v->rank > 0 && v->dims) info.dims.assign(v->dims, v->dims + v->rank);
    out.push_back(std::move(info));
  }
  return out;
}

#ifdef BEARING_RECORDS_WITH_HDF5
// A MATLAB 7.3 file is HDF5: matio reads a variable's data with HDF5, which allocates what the
// stored type claims per value; the variable must be stored as a plain number (hdf5_handle.h).
void check_mat73_type(const std::string& file, const std::string& name) {
  using records_detail::H5Handle;
  H5Handle h5(H5Fopen(file.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT), H5Fclose, file,
              "open it (corrupt file?)");
  H5Handle ds(H5Dopen2(h5, ("/" + name).c_str(), H5P_DEFAULT), H5Dclose, file,
              "open the variable " + name);
  H5Handle type(H5Dget_type(ds), H5Tclose, file, "read the type of " + name);
  if (!records_detail::plain_number_type(type))
    throw record_error(file, name,
                       "stored as an HDF5 type of " + std::to_string(H5Tget_size(type)) +
                           " bytes, not a number (corrupt file?)");
}
#endif

template <class T>
void append_as_double(const void* data, std::size_t n, std::vector<double>& out) {
  const T* p = static_cast<const T*>(data);
  out.reserve(n);
  for (std::size_t i = 0; i < n; ++i) out.push_back(static_cast<double>(p[i]));
}

std::size_t element_size(matio_classes c) {
  switch (c) {
    case MAT_C_DOUBLE:
    case MAT_C_INT64:
    case MAT_C_UINT64:
      return 8;
    case MAT_C_SINGLE:
    case MAT_C_INT32:
    case MAT_C_UINT32:
      return 4;
    case MAT_C_INT16:
    case MAT_C_UINT16:
      return 2;
    default:
      return 1;
  }
}

// The values of numeric variable `info`, read and converted exactly to double.
std::vector<double> values_of(mat_t* mat, const VariableInfo& info, const std::string& file,
                              std::uintmax_t file_size) {
  const std::size_t n = info.numel();
  const std::size_t size = element_size(info.class_type);
  records_detail::check_claimed_size(n, size, file_size, file, info.name);
#ifdef BEARING_RECORDS_WITH_HDF5
  if (Mat_GetVersion(mat) == MAT_FT_MAT73) check_mat73_type(file, info.name);
#endif
  Var v{Mat_VarRead(mat, info.name.c_str())};
  if (!v || !v->data)
    throw record_error(file, info.name, "matio cannot read the variable's data (corrupt file?)");
  if (v->class_type != info.class_type || v->isComplex || Mat_VarGetSize(v.get()) < n * size ||
      v->nbytes < n * size)
    throw record_error(file, info.name, "the variable's data does not match its header");
  std::vector<double> out;
  switch (info.class_type) {
    case MAT_C_DOUBLE:
      append_as_double<double>(v->data, n, out);
      break;
    case MAT_C_SINGLE:
      append_as_double<float>(v->data, n, out);
      break;
    case MAT_C_INT8:
      append_as_double<std::int8_t>(v->data, n, out);
      break;
    case MAT_C_UINT8:
      append_as_double<std::uint8_t>(v->data, n, out);
      break;
    case MAT_C_INT16:
      append_as_double<std::int16_t>(v->data, n, out);
      break;
    case MAT_C_UINT16:
      append_as_double<std::uint16_t>(v->data, n, out);
      break;
    case MAT_C_INT32:
      append_as_double<std::int32_t>(v->data, n, out);
      break;
    case MAT_C_UINT32:
      append_as_double<std::uint32_t>(v->data, n, out);
      break;
    case MAT_C_INT64:
      append_as_double<std::int64_t>(v->data, n, out);
      break;
    case MAT_C_UINT64:
      append_as_double<std::uint64_t>(v->data, n, out);
      break;
    default:
      throw record_error(file, info.name, "not numeric");
  }
  return out;
}

// The shaft speed scalar (…RPM) that goes with `channel`: the only one, or the one whose prefix
// begins the channel's name.
const VariableInfo* speed_variable(const std::vector<VariableInfo>& vars,
                                   const std::string& channel) {
  std::vector<const VariableInfo*> found;
  for (const VariableInfo& v : vars)
    if (v.scalar() && v.name.size() > 3 && v.name.compare(v.name.size() - 3, 3, "RPM") == 0)
      found.push_back(&v);
  if (found.size() == 1) return found.front();
  for (const VariableInfo* v : found)
    if (channel.compare(0, v->name.size() - 3, v->name, 0, v->name.size() - 3) == 0) return v;
  return nullptr;
}

}  // namespace

RawChannel read_mat_record(const std::filesystem::path& path, const RecordOptions& options) {
  const std::string file = path.string();
  Mat_LogInitFunc("bearing", quiet);
#ifdef BEARING_RECORDS_WITH_HDF5
  records_detail::QuietHdf5 quiet_hdf5;  // matio reads MATLAB 7.3 through HDF5
#endif
  std::error_code ec;
  const std::uintmax_t file_size = std::filesystem::file_size(path, ec);
  std::unique_ptr<mat_t, CloseMat> mat(Mat_Open(file.c_str(), MAT_ACC_RDONLY));
  if (ec || !mat)
    throw record_error(file, "",
                       "matio cannot open it as a MAT-file (MATLAB 5, 7 or 7.3): missing, "
                       "unreadable or corrupt");
  records_detail::check_mat5_elements(path, file_size, file);
  const std::vector<VariableInfo> vars = variables_of(mat.get());
  if (vars.empty())
    throw record_error(file, "", "matio finds no variable in it (empty, truncated or corrupt)");

  std::vector<std::string> candidates;
  std::vector<const VariableInfo*> channel_vars;
  std::string others;
  for (const VariableInfo& v : vars) {
    if (v.channel()) {
      candidates.push_back(v.name);
      channel_vars.push_back(&v);
    } else {
      others += (others.empty() ? "" : ", ") + v.name + " (" + v.what() + ")";
    }
  }
  // A variable named but not a channel: say what it is rather than that it is missing.
  if (!options.channel.empty())
    for (const VariableInfo& v : vars)
      if (v.name == options.channel && !v.channel())
        throw record_error(file, v.name, "the variable is " + v.what() + ", not a channel");
  const VariableInfo& chosen =
      *channel_vars[choose_channel(candidates, options, file, "variable", others)];

  RawChannel raw;
  raw.channel = chosen.name;
  raw.values = values_of(mat.get(), chosen, file, file_size);
  if (const VariableInfo* speed = speed_variable(vars, chosen.name)) {
    const double rpm = values_of(mat.get(), *speed, file, file_size).front();
    if (std::isfinite(rpm) && rpm > 0) {
      raw.shaft_speed = to_si(rpm, "rpm", Dimension::angular_speed, speed->name);
      raw.shaft_speed_origin = "variable " + speed->name + " (" + format_number(rpm) + " rpm)";
    }
  }
  return raw;
}

}  // namespace bearing
