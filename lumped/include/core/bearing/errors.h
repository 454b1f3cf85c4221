#pragma once
// Errors the library reports instead of printing. Each message names the input (key), the value
// that was given and what is allowed, so the CLI can print it unchanged.

#include <stdexcept>
#include <string>

namespace bearing {

/// Bad user input: an unknown key, a wrong type or unit, a value outside its allowed range.
class InputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// A numerical procedure that did not reach its answer (the message says why and what to change).
class SolverError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// The result files could not be written (disk full, no permission, an I/O error): the message
/// names the file and the system's reason. Nothing is left under a final name.
class OutputError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace bearing
