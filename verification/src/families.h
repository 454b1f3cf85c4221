#pragma once
// The check tables, one function per file in checks/. all_checks() (check_table.cc) joins them in
// this order; a new family is one more line there and one file here.

#include <vector>

#include "check.h"

namespace bearing::verify {

std::vector<Check> hertz_checks();                 ///< checks/hertz.cc: Hertz methods, closed forms
std::vector<Check> hertz_fe_checks();              ///< checks/hertz_fe.cc: FE contact vs Hertz
std::vector<Check> hertz_fe_convergence_checks();  ///< checks/hertz_fe_convergence.cc (full)
std::vector<Check> hertz_groove_checks();          ///< checks/hertz_groove.cc: FE groove vs Hertz
std::vector<Check> static_load_checks();  ///< checks/static_load.cc: kinematics, load distribution
std::vector<Check> stiffness_checks();    ///< checks/stiffness.cc: 5-DOF stiffness, closed forms
std::vector<Check> film_checks();  ///< checks/film.cc: EHL film, film law, squeeze damping
std::vector<Check> dynamics_checks();     ///< checks/dynamics.cc: conservation, limits, orders
std::vector<Check> dynamics_spectra_checks();   ///< checks/dynamics_spectra.cc: lines, reductions
std::vector<Check> dynamics_jacobian_checks();  ///< checks/dynamics_jacobian.cc: 2-DOF Jacobian
std::vector<Check> fault_checks();              ///< checks/faults.cc: spalls, envelope lines
std::vector<Check> acoustics_checks();          ///< checks/acoustics.cc: sources vs closed forms
std::vector<Check> acoustics_paper_checks();    ///< checks/acoustics_paper.cc: seed 000's forms
std::vector<Check> acoustics_decay_checks();    ///< checks/acoustics_decay.cc: 1/r, 1/√r decay
std::vector<Check> acoustics_fe_checks();       ///< checks/acoustics_fe.cc: FE radiation reference
std::vector<Check> paper_checks();              ///< checks/papers.cc: examples/README.md's tables
std::vector<Check> measured_checks();       ///< checks/measured.cc: the CWRU rig's records analysed
std::vector<Check> measured_development_checks();  ///< checks/measured_development.cc: fan-end set
std::vector<Check> unit_test_checks();      ///< checks/unit_tests.cc: the physics unit-test suites
std::vector<Check> paper_contact_checks();  ///< checks/papers_contact.cc: TVDS, ball approach, SPL
std::vector<Check> structure_checks();  ///< checks/structure.cc: FE natural modes, modal transfer

/// The families (Check::family), in report order, with the title the report gives each.
struct Family {
  const char* id;
  const char* title;
};
inline constexpr Family kFamilies[] = {
    {"hertz", "Hertz contact: methods, closed forms, finite elements"},
    {"static-load", "Kinematics and static load distribution"},
    {"stiffness", "Bearing stiffness for rotor models: the 5-DOF static solution"},
    {"film", "Lubricant film: Hamrock-Dowson thickness, film stiffness, squeeze-film damping"},
    {"dynamics", "Dynamics: conservation, limits, convergence, spectra"},
    {"acoustics", "Acoustics: sources, decay, finite-element radiation"},
    {"structure", "Structure: FE natural modes and the modal transfer path"},
    {"paper", "Source papers: reproduced tables and figures"},
    {"measured", "Measured records: the CWRU test rig and the fault-line threshold"},
    {"unit", "Unit tests of the physics: closed forms, orders, conservation laws, reductions"},
};

/// Every check, in report order (families as above). Throws std::logic_error on a malformed
/// table (validate_checks()).
std::vector<Check> all_checks();

/// The table's rules: unique ids, known families and mutations, a mutation named by every judged
/// check, a measurement, a justified bound, paper values on paper checks only, and no derived
/// tolerance justified by the error it judges (judged_by_its_own_error(): that is a pin()).
/// Throws std::logic_error naming the check.
void validate_checks(const std::vector<Check>& all);

/// True when a tolerance's justification says it is the judged error, measured and rounded up.
bool judged_by_its_own_error(const std::string& why);

}  // namespace bearing::verify
