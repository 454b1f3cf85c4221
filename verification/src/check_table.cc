#include <regex>
#include <set>
#include <stdexcept>

#include "families.h"
#include "mutations.h"

namespace bearing::verify {

namespace {

void append(std::vector<Check>& all, std::vector<Check> more) {
  for (auto& c : more) all.push_back(std::move(c));
}

bool known_family(const std::string& id) {
  for (const auto& f : kFamilies)
    if (id == f.id) return true;
  return false;
}

}  // namespace

bool judged_by_its_own_error(const std::string& why) {
  // A bound that admits it is the judged error: measured (or "is x % off" the reference) and then
  // rounded up. A derived bound rounded up ("<= 1e-8 dB, rounded up to 1e-7") is not one.
  static const std::regex own_error("(measured|\\boff\\b).{0,200}round(ed)? up", std::regex::icase);
  return std::regex_search(why, own_error);
}

void validate_checks(const std::vector<Check>& all) {
  std::set<std::string> ids;
  for (const auto& c : all) {
    const std::string where = "check \"" + c.id + "\": ";
    if (c.id.empty() || !ids.insert(c.id).second)
      throw std::logic_error(where + "empty or duplicate id");
    if (!known_family(c.family)) throw std::logic_error(where + "unknown family " + c.family);
    // A reported check judges nothing; a unit-test row is reached by code mutants only.
    if (c.catches.empty() && c.judged && c.reference != ReferenceKind::unit_test)
      throw std::logic_error(where + "names no mutation it must catch");
    for (const auto& m : c.catches)
      if (find_mutation(m) == nullptr) throw std::logic_error(where + "unknown mutation " + m);
    if (!c.measure) throw std::logic_error(where + "no measurement");
    if (c.tolerance.why.empty() || !(c.tolerance.bound >= 0))
      throw std::logic_error(where + "tolerance without a bound or a justification");
    if (c.tolerance.basis == Tolerance::Basis::derived && judged_by_its_own_error(c.tolerance.why))
      throw std::logic_error(where +
                             "a tolerance taken from the error it judges is a regression pin "
                             "(pin()), not a derived bound: " +
                             c.tolerance.why);
    if (c.compares.empty() || c.unit.empty())
      throw std::logic_error(where + "no description or unit");
    if ((c.reference == ReferenceKind::paper) != c.paper.has_value())
      throw std::logic_error(where + "paper checks, and only they, carry the paper's value");
  }
}

std::vector<Check> all_checks() {
  std::vector<Check> all;
  append(all, hertz_checks());
  append(all, hertz_fe_checks());
  append(all, hertz_fe_convergence_checks());
  append(all, hertz_groove_checks());
  append(all, static_load_checks());
  append(all, stiffness_checks());
  append(all, film_checks());
  append(all, dynamics_checks());
  append(all, dynamics_spectra_checks());
  append(all, dynamics_jacobian_checks());
  append(all, fault_checks());
  append(all, acoustics_checks());
  append(all, acoustics_paper_checks());
  append(all, acoustics_decay_checks());
  append(all, acoustics_fe_checks());
  append(all, structure_checks());
  append(all, paper_checks());
  append(all, paper_contact_checks());
  append(all, measured_checks());
  append(all, measured_development_checks());
  append(all, unit_test_checks());
  validate_checks(all);
  return all;
}

}  // namespace bearing::verify
