#include "bearing/npy.h"

#include <stdexcept>

namespace bearing {

std::string npy_header(std::size_t rows, std::size_t columns) {
  // Magic (6 bytes), version (2), header length (2), then the dict: 10 bytes before it.
  constexpr std::size_t kPrefix = 10;
  constexpr std::size_t kAlignment = 64;
  std::string dict = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(rows) +
                     ", " + std::to_string(columns) + "), }";
  const std::size_t unpadded = kPrefix + dict.size() + 1;  // + the final '\n'
  dict.append((kAlignment - unpadded % kAlignment) % kAlignment, ' ');
  dict += '\n';
  if (dict.size() > 0xffff) throw std::length_error("npy header longer than 65535 bytes");
  std::string out("\x93NUMPY\x01\x00", 8);
  out += static_cast<char>(dict.size() & 0xff);
  out += static_cast<char>((dict.size() >> 8) & 0xff);
  return out + dict;
}

}  // namespace bearing
