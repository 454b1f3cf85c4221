#pragma once
// The check tables, one function per file in checks/. all_checks() (check_table.cc) joins them in
// this order; a new family is one more line there and one file here.

#include <vector>

#include "check.h"

namespace bearing::verify {

std::vector<Check> hertz_checks();         ///< checks/hertz.cc: Hertz methods, closed forms
std::vector<Check> hertz_fe_checks();      ///< checks/hertz_fe.cc: FE contact vs Hertz
std::vector<Check> hertz_groove_checks();  ///< checks/hertz_groove.cc: FE groove vs Hertz
std::vector<Check> static_load_checks();   ///< checks/static_load.cc: kinematics, load distribution
std::vector<Check> dynamics_checks();      ///< checks/dynamics.cc
std::vector<Check> acoustics_checks();     ///< checks/acoustics.cc: sources vs closed forms, decay
std::vector<Check> acoustics_fe_checks();  ///< checks/acoustics_fe.cc: FE radiation reference
std::vector<Check> paper_checks();         ///< checks/papers.cc: examples/README.md's tables

/// The families (Check::family), in report order, with the title the report gives each.
struct Family {
  const char* id;
  const char* title;
};
inline constexpr Family kFamilies[] = {
    {"hertz", "Hertz contact: methods, closed forms, finite elements"},
    {"static-load", "Kinematics and static load distribution"},
    {"dynamics", "Dynamics: conservation, limits, convergence, spectra"},
    {"acoustics", "Acoustics: sources, decay, finite-element radiation"},
    {"paper", "Source papers: reproduced tables and figures"},
};

/// Every check, in report order (families as above). Throws std::logic_error on a malformed
/// table: a duplicate id, an unknown family or mutation, a check that names no mutation.
std::vector<Check> all_checks();

}  // namespace bearing::verify
