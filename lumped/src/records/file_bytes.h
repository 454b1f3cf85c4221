#pragma once
// A record file's bytes, for the readers that parse text or bytes themselves (CSV, NPY).

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "bearing/records/raw_channel.h"

namespace bearing::records_detail {

/// The whole file; InputError naming it and the system's reason when it cannot be read.
inline std::string file_bytes(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw record_error(path.string(), "", std::string("cannot open: ") + std::strerror(errno));
  std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad())
    throw record_error(path.string(), "", "cannot read: " + std::string(std::strerror(errno)));
  return bytes;
}

}  // namespace bearing::records_detail
