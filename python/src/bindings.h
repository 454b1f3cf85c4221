#pragma once
// Shared by the translation units of the extension _bearing (module.cc, analysis.cc): JSON to
// Python, NumPy views of C++ arrays, and a case as the CLI builds it.

#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"

namespace bearing_python {

namespace py = pybind11;

/// A JSON value as Python objects, number for number (a double stays the same double, so the
/// dict equals json.load of the CLI's file).
py::object to_python(const nlohmann::json& j);

/// A read-only NumPy view of `data` that keeps `owner` (the Python object holding it) alive.
py::array view(const std::vector<double>& data, py::handle owner);

/// A case as the CLI builds it: a file (or TOML text, or the built-in default) plus overrides,
/// resolved again after every override so that errors surface where they are made.
struct CaseHandle {
  enum class Origin { file, text, builtin };
  Origin origin = Origin::builtin;
  std::string path;      // Origin::file: the file, as given
  std::string text;      // Origin::text: the TOML
  std::string base_dir;  // Origin::text: folder for relative table paths
  std::string source;    // Origin::text: the name used in messages
  std::vector<bearing::Override> overrides;
  bearing::Case resolved;

  // The case with `extra` overrides after this one's (a sweep point's).
  bearing::Case load(const std::vector<bearing::Override>& extra = {}) const {
    auto all = overrides;
    all.insert(all.end(), extra.begin(), extra.end());
    switch (origin) {
      case Origin::file:
        return bearing::read_case_file(path, all);
      case Origin::text:
        return bearing::parse_case(text, source, all, base_dir);
      case Origin::builtin:
        break;
    }
    return bearing::default_case(all);
  }
};

/// bearing.analyse and its result class Analysis (analysis.cc).
void bind_analysis(py::module_& m);

}  // namespace bearing_python
