#pragma once
// What a check measures with. Checks take the toolkit's values only through a Context, which
// applies the run's Perturbation (identity except under `bearing-verify mutate`) where the values
// enter: the bearing's geometry, the contact constants, the model inputs, the air and
// microphones, the FE meshes. References (closed forms written in the check, papers' numbers)
// never pass through it.

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/acoustics/sources.h"
#include "bearing/bearing.h"
#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/hertz.h"
#include "bearing/kinematics.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/model_kind.h"
#include "bearing/record_analysis.h"
#include "bearing/simulation.h"
#include "bearing/static_load.h"
#include "check.h"
#include "perturbation.h"

namespace bearing::verify {

class FemRunner;

/// Records, on this thread, which perturbation knobs the Context methods read while it lives
/// (runner.cc: a mutation that turns none of a check's knobs cannot change its result, so
/// `mutate` does not rerun it). Sound because checks take the toolkit's values only from a Context.
class KnobRecorder {
 public:
  KnobRecorder();
  ~KnobRecorder();
  KnobRecorder(const KnobRecorder&) = delete;
  KnobRecorder& operator=(const KnobRecorder&) = delete;
  unsigned knobs() const { return knobs_; }

 private:
  unsigned knobs_ = 0;
  unsigned* previous_;
};

class Context {
 public:
  Context(Level level, Perturbation perturbation, FemRunner* fem, std::string source_dir);

  Level level() const { return level_; }
  const Perturbation& perturbation() const { return perturbation_; }
  /// True when this run's level includes `l` (quick ⊂ standard ⊂ full).
  bool at_least(Level l) const { return static_cast<int>(level_) >= static_cast<int>(l); }

  // --- geometry, contact ------------------------------------------------------------------
  /// A preset bearing ("608", "6304", "6308", "6205", "6203", "209") as the toolkit builds it.
  Bearing bearing(const std::string& designation) const;
  /// Any bearing as the toolkit sees it (the perturbation's geometry applied).
  Bearing bearing(Bearing b) const;
  /// One race's constants by a Hertz method (K and n perturbed).
  RaceContact race_contact(const Bearing& b, Race race, HertzMethod method) const;
  /// Both races and the series law by a Hertz method (K and n perturbed).
  ContactConstants contact(const Bearing& b, HertzMethod method) const;
  /// Frequencies of the rolling elements (pitch diameter perturbed through bearing()).
  BearingFrequencies frequencies(const Bearing& b, double inner_speed) const;
  /// The static load distribution (solve_static_load) with the contact's K and n as given.
  StaticLoadResult static_load(int balls, const ContactConstants& k, double gap,
                               const Eigen::Vector2d& load, double phase = 0.0) const;

  // --- cases and dynamics -----------------------------------------------------------------
  /// A case file of examples/ ("seed003_6308.toml"), with overrides.
  Case example(const std::string& file, const std::vector<Override>& overrides = {}) const;
  /// The built-in default case with overrides.
  Case default_case(const std::vector<Override>& overrides = {}) const;
  /// model_inputs(c) as the toolkit builds them, perturbed (contact, mass, damping, waviness,
  /// TVDS, cage slip, geometry).
  ModelInputs inputs(const Case& c) const;
  /// Perturbs inputs a check assembled itself (from inputs() or by hand).
  ModelInputs perturbed(ModelInputs in) const;
  /// simulate() of the pipeline; `in` is used as given (take it from inputs() or perturbed()).
  SimulationResult simulate(ModelKind kind, const ModelInputs& in, const SolverSettings& solver,
                            const OutputRequest& output) const;
  /// run_settings(c) with its model inputs perturbed and acoustics perturbed.
  RunSettings settings(const Case& c) const;

  // --- acoustics --------------------------------------------------------------------------
  /// The air the lumped acoustics uses (sound speed perturbed).
  Air air(double density = 1.204, double sound_speed = 343.2) const;
  /// A microphone as the lumped acoustics places it (distance perturbed).
  Microphone microphone(double radius, double angle) const;
  /// An AcousticsOptions with the perturbation applied (air, microphones).
  AcousticsOptions acoustics(AcousticsOptions a) const;

  // --- measured records ------------------------------------------------------------------
  /// analyse_record() of the pipeline with the perturbation's analysis knobs: the speed scaled,
  /// the pre-whitening dropped, the false-alarm rate scaled.
  RecordAnalysis analyse_record(const std::vector<double>& samples, double rate, const Bearing& b,
                                SpeedSetting speed, RecordAnalysisSettings settings) const;

  // --- finite elements --------------------------------------------------------------------
  /// Runs `bearing-fem ARGS --out DIR` (under mpirun -np N when asked; the same arguments run
  /// once per report, memoised) and returns the JSON file it wrote (`json_name` in DIR) with
  /// "dir" added. The perturbation's FE mesh factor is applied to --cells and
  /// --cells-per-radius by the caller through fe_cells(). Throws Skipped when bearing-fem was not
  /// built, SolverError when it fails.
  nlohmann::json fem(const std::vector<std::string>& args, const std::string& json_name) const;
  /// A mesh-resolution argument as the perturbation makes it (at least 1).
  int fe_cells(int cells) const;
  /// The FE degree asked of bearing-fem modes as the perturbation makes it (at least 1).
  int fe_degree(int degree) const;
  /// A structure's Young's modulus as bearing-fem modes is to read it [Pa] (perturbed).
  double structure_young(double young) const;
  /// modes.json as the toolkit's modal model reads it: every shape value (seat, sensors) and the
  /// effective masses (quadratic in the shapes) scaled by the perturbation.
  nlohmann::json modal(nlohmann::json modes) const;
  /// Writes `text` once to the FE runs' folder under a name made of `stem`, a hash of the text
  /// and `extension` (the same text: the same file, so memoised runs stay right) and returns its
  /// path. Throws Skipped without an FE runner.
  std::string fem_input(const std::string& stem, const std::string& extension,
                        const std::string& text) const;

  /// The repository root (examples/, meshes/).
  const std::string& source_dir() const { return source_dir_; }

 private:
  void perturb_model(ModelInputs& in) const;

  Level level_;
  Perturbation perturbation_;
  FemRunner* fem_;
  std::string source_dir_;
};

}  // namespace bearing::verify
