#pragma once
// The deliberate bugs `bearing-verify mutate` plants, one row each. Every check names at least one
// of these in Check::catches; a mutation no check catches is a gap in the verification.

#include <string>
#include <vector>

#include "perturbation.h"

namespace bearing::verify {

struct Mutation {
  std::string id;           ///< e.g. "contact-constant-x1.03"
  std::string description;  ///< the bug it stands for
  Perturbation perturbation;
};

/// The mutation table (mutations.cc).
const std::vector<Mutation>& mutations();

/// The row with this id, or nullptr.
const Mutation* find_mutation(const std::string& id);

}  // namespace bearing::verify
