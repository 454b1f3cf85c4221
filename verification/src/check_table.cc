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

// The table's own rules, checked once when it is built (and by tests/verification).
void validate(const std::vector<Check>& all) {
  std::set<std::string> ids;
  for (const auto& c : all) {
    const std::string where = "check \"" + c.id + "\": ";
    if (c.id.empty() || !ids.insert(c.id).second)
      throw std::logic_error(where + "empty or duplicate id");
    if (!known_family(c.family)) throw std::logic_error(where + "unknown family " + c.family);
    if (c.catches.empty() && c.judged)
      throw std::logic_error(where + "names no mutation it must catch");
    for (const auto& m : c.catches)
      if (find_mutation(m) == nullptr) throw std::logic_error(where + "unknown mutation " + m);
    if (!c.measure) throw std::logic_error(where + "no measurement");
    if (c.tolerance.why.empty() || !(c.tolerance.bound >= 0))
      throw std::logic_error(where + "tolerance without a bound or a justification");
    if (c.compares.empty() || c.unit.empty())
      throw std::logic_error(where + "no description or unit");
    if ((c.reference == ReferenceKind::paper) != c.paper.has_value())
      throw std::logic_error(where + "paper checks, and only they, carry the paper's value");
  }
}

}  // namespace

std::vector<Check> all_checks() {
  std::vector<Check> all;
  append(all, hertz_checks());
  append(all, hertz_fe_checks());
  append(all, hertz_fe_convergence_checks());
  append(all, hertz_groove_checks());
  append(all, static_load_checks());
  append(all, dynamics_checks());
  append(all, dynamics_spectra_checks());
  append(all, dynamics_jacobian_checks());
  append(all, fault_checks());
  append(all, acoustics_checks());
  append(all, acoustics_paper_checks());
  append(all, acoustics_decay_checks());
  append(all, acoustics_fe_checks());
  append(all, paper_checks());
  append(all, paper_contact_checks());
  append(all, measured_checks());
  validate(all);
  return all;
}

}  // namespace bearing::verify
