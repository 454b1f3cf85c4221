#pragma once
// NumPy's .npy format, version 1.0, for `output.format = "npy"`: a 2-D array of little-endian
// float64 in C (row-major) order, as numpy.lib.format documents it
// (https://numpy.org/doc/stable/reference/generated/numpy.lib.format.html). numpy.load reads it,
// and so do MATLAB and Julia readers of .npy.

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>

namespace bearing {

/// The header of a (rows, columns) array of '<f8', C order: the magic "\x93NUMPY", version 1.0,
/// the header length (uint16, little-endian) and the dict
/// "{'descr': '<f8', 'fortran_order': False, 'shape': (rows, columns), }" padded with spaces and
/// ended by '\n' so that the data starts at a multiple of 64 bytes. Throws std::length_error if it
/// does not fit version 1.0's 65535 bytes (it never does for two numbers).
std::string npy_header(std::size_t rows, std::size_t columns);

/// Stores `v` at `out` as 8 little-endian bytes (IEEE 754 binary64), whatever the host's order.
inline void store_f8_le(char* out, double v) {
  std::uint64_t bits = 0;
  std::memcpy(&bits, &v, sizeof bits);
  for (int i = 0; i < 8; ++i) out[i] = static_cast<char>((bits >> (8 * i)) & 0xffu);
}

}  // namespace bearing
