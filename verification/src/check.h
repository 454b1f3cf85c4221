#pragma once
// One verification check: what the toolkit computes, what it is compared with, how close it must
// be and why, and which deliberate bugs (mutations) it must catch. The checks are rows of tables
// (checks/*.cc, one file per family); the runner (runner.h) turns each into a CheckResult.

#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "figure.h"

namespace bearing::verify {

class Context;

/// How far a run goes: quick (CI, a few minutes on 2 cores) ⊂ standard (the default, FE at the
/// meshes fem/README.md calls accurate) ⊂ full (adds the convergence studies).
enum class Level { quick, standard, full };

/// What the value is compared with.
enum class ReferenceKind {
  closed_form,   ///< a formula or table written independently of the code under test
  fe,            ///< a finite-element reference (bearing-fem)
  convergence,   ///< an observed order of convergence against the method's theoretical order
  conservation,  ///< a conserved quantity (energy) that must not drift
  limit,         ///< a limit the model must reach (static limit, reduction of a model to another)
  cross_model,   ///< two independent models of the same physics
  paper,         ///< a value printed in a source paper (docs/model.md, Sources)
  measurement,   ///< a measured record and its known condition (the CWRU test rig)
  unit_test,     ///< a suite of the project's unit tests (each test derives its own bound)
};

/// |value − reference| ≤ bound (absolute) or |value / reference − 1| ≤ bound (relative).
/// A bound is `derived` (a truncation or discretisation bound, a root tolerance, a published
/// accuracy: it bounds the error) or a `pin` (the error measured once, rounded up: it holds past
/// output and bounds nothing; counted apart from the verified checks). A derived bound that is
/// justified by the error it judges is refused when the table is built (validate_checks()).
struct Tolerance {
  enum class Kind { absolute, relative };
  enum class Basis { derived, pin };
  Kind kind = Kind::relative;
  double bound = 0.0;  ///< in the check's unit (absolute) or as a fraction (relative)
  std::string why;     ///< the justification: where the bound comes from
  Basis basis = Basis::derived;
};
inline Tolerance relative(double bound, std::string why) {
  return {Tolerance::Kind::relative, bound, std::move(why)};
}
inline Tolerance absolute(double bound, std::string why) {
  return {Tolerance::Kind::absolute, bound, std::move(why)};
}
/// `t` as a regression pin: its `why` then starts "regression pin: ".
inline Tolerance pin(Tolerance t) {
  t.basis = Tolerance::Basis::pin;
  t.why = "regression pin: " + t.why;
  return t;
}

/// A paper check's printed number; when `disagreement` is set the check's reference is the
/// corrected value (docs/model.md) and the paper's number is shown beside it, never used to pass.
/// The verdict is "agree", "disagree-tested" (`explanation_tested` and the check passed) or
/// "disagree-untested" (the explanation is a reading of the paper that no comparison in the
/// report tests), counted apart in the summary.
struct PaperValue {
  double value = 0.0;        ///< the paper's number, in the check's unit
  std::string source;        ///< seed file and table/figure/equation, e.g. "seed000 Table 2"
  std::string disagreement;  ///< empty: we agree; else why our (correct) value differs
  /// true only when this check's own comparison tests the explanation: its reference is the
  /// physics the explanation appeals to (an FE field, an exact stiffness), so a pass confirms it.
  bool explanation_tested = false;
};

/// What one measurement produced.
struct Outcome {
  double value = 0.0;           ///< the toolkit's value, in the check's unit
  double reference = 0.0;       ///< the reference value, in the check's unit
  std::string detail;           ///< optional one line (mesh, step size, fitted points …)
  std::vector<Figure> figures;  ///< optional; shown under the check in the report
};

/// A check cannot run here (e.g. the FE program was not built); reported as skipped, with why.
struct Skipped : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// One row of a check table.
struct Check {
  std::string id;  ///< unique, dot-separated, lower case: "hertz.exact-vs-hamrock-brewe.6308.inner"
  std::string family;  ///< one of kFamilies (report.h): "hertz", "dynamics", …
  ReferenceKind reference = ReferenceKind::closed_form;
  std::string compares;  ///< "value: … ; reference: …" in words a reviewer understands
  std::string quantity;  ///< what is compared, e.g. "K_inner"
  std::string unit;      ///< SI unit of value/reference ("N/m^1.5", "Hz", "-", "dB")
  Tolerance tolerance;
  Level level = Level::quick;        ///< the lowest level that runs it
  double cost = 0.1;                 ///< expected wall time [s] on 2 cores
  std::vector<std::string> catches;  ///< mutation ids (mutations.cc) that must make it fail
  std::function<Outcome(const Context&)> measure;
  std::optional<PaperValue> paper;  ///< paper checks only
  /// false: measured and shown with its evidence, never judged (status "reported", counted
  /// apart): for what the method is not expected to establish, e.g. a fault that the record does
  /// not clearly show. Such a check names no mutation.
  bool judged = true;
};

}  // namespace bearing::verify
