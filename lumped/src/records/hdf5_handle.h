#pragma once
// HDF5 identifiers closed when they go out of scope, and HDF5's error printing silenced while a
// record is read: the readers report errors as InputError, one line, instead of HDF5's stack.

#include <hdf5.h>

#include <string>

#include "bearing/records/raw_channel.h"

namespace bearing::records_detail {

/// An HDF5 identifier and its close function; an invalid id (< 0) is an InputError naming the
/// file and what could not be done.
class H5Handle {
 public:
  H5Handle(hid_t id, herr_t (*close)(hid_t), const std::string& file, const std::string& what)
      : id_(id), close_(close) {
    if (id_ < 0) throw record_error(file, "", "HDF5 cannot " + what);
  }
  ~H5Handle() {
    if (id_ >= 0) close_(id_);
  }
  H5Handle(const H5Handle&) = delete;
  H5Handle& operator=(const H5Handle&) = delete;
  operator hid_t() const { return id_; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

/// HDF5's automatic error printing off while this lives (HDF5's process-wide setting, restored
/// after).
class QuietHdf5 {
 public:
  QuietHdf5() {
    H5Eget_auto2(H5E_DEFAULT, &func_, &data_);
    H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
  }
  ~QuietHdf5() { H5Eset_auto2(H5E_DEFAULT, func_, data_); }
  QuietHdf5(const QuietHdf5&) = delete;
  QuietHdf5& operator=(const QuietHdf5&) = delete;

 private:
  H5E_auto2_t func_ = nullptr;
  void* data_ = nullptr;
};

}  // namespace bearing::records_detail

namespace bearing::records_detail {

/// Whether an HDF5 datatype is a number as the readers convert it: an integer of 1, 2, 4 or 8
/// bytes, or a float of 4 or 8 bytes with at most 64 bits of precision. A corrupt file can
/// declare others (a "float" of 2 GB), for which HDF5 would allocate a conversion buffer of that
/// size per value.
inline bool plain_number_type(hid_t type) {
  const H5T_class_t cls = H5Tget_class(type);
  const std::size_t size = H5Tget_size(type);
  if (cls == H5T_INTEGER) return size == 1 || size == 2 || size == 4 || size == 8;
  if (cls != H5T_FLOAT) return false;
  return (size == 4 || size == 8) && H5Tget_precision(type) <= 8 * size;
}

}  // namespace bearing::records_detail
