#pragma once
// Case files: TOML with units (docs/case-files.md), resolved into SI values.
//
// Precedence, lowest first: built-in defaults, the `bearing.preset` catalogue entry, the keys in
// the file, then `--set table.key=value` overrides. Unknown tables and keys are errors that suggest
// the nearest valid name; every error names the key, the value and what is allowed.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Dense>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/bearing.h"
#include "bearing/calibration.h"
#include "bearing/choice.h"
#include "bearing/contact.h"
#include "bearing/excitation.h"
#include "bearing/local_defect.h"
#include "bearing/lubricant.h"
#include "bearing/models/housing.h"
#include "bearing/models/model_kind.h"
#include "bearing/models/random_slip.h"
#include "bearing/signal/envelope.h"
#include "bearing/signal/spectrum.h"
#include "bearing/solvers/integrator.h"
#include "bearing/units.h"

namespace bearing {

/// Inner ring and shaft. Defaults: m = 0.6 kg, c = 200 N s/m, the values seeds 001–003 use.
struct Rotor {
  double mass = 0.6;             ///< inner ring + shaft mass m [kg]
  double damping = 200.0;        ///< radial viscous damping c [N s/m]
  double axial_mass = 0.6;       ///< axial mass (3-DOF) [kg]; defaults to `mass`
  double axial_damping = 200.0;  ///< axial damping (3-DOF) [N s/m]; defaults to `damping`
};

/// Operating conditions. Outer ring fixed; x horizontal, y vertical (up).
struct Operation {
  double speed = 0.0;                              ///< inner-ring speed ω_i [rad/s]
  Eigen::Vector2d load = Eigen::Vector2d::Zero();  ///< radial load (F_x, F_y) on the inner ring [N]
  double axial_load = 0.0;                         ///< axial load F_z on the inner ring [N] (3-DOF)
  /// Moments (M_x, M_y) on the inner ring [N m], about +x and +y. Only the 5-DOF static solution
  /// (`stiffness`, `info`) carries them; `run` refuses a nonzero one (check_run_loads).
  Eigen::Vector2d moment = Eigen::Vector2d::Zero();
  double unbalance = 0.0;  ///< m_u e [kg m]; F_u = m_u e ω_i², rotating with the shaft
  bool gravity = false;    ///< add the rotor weight −m g to F_y
};

/// Waviness, ball-size errors and local defects, resolved (tables read, band drawn).
struct Excitations {
  std::vector<WavinessHarmonic> inner_waviness;
  std::vector<WavinessHarmonic> outer_waviness;
  std::vector<double> ball_size_errors;  ///< ΔD_j = D − D_j [m], empty or one per ball
  double ball_error_band = 0.0;          ///< band the errors were drawn from [m] (0: given/none)
  std::uint64_t ball_error_seed = 0;     ///< seed of the draw
  std::vector<LocalDefect> defects;      ///< [[defects]]: spalls (dynamic model kinds only)
};

/// The cage and the traction at the ball contacts (model.kind = "balls"; seed 004). Seed 004
/// gives no Δv_m; 0.1 m/s (μ saturates at about 4 % slide-to-roll at the default case's speed) is
/// this toolkit's assumption.
struct CageOptions {
  double slip = 0.0;         ///< s_c in [0, 1): the cage turns at (1 − s_c) ω_c [-]
  double friction = 0.01;    ///< μ_m, the traction coefficient beyond Δv_m [-] (seed 004 §4.3)
  double slide_speed = 0.1;  ///< Δv_m, the sliding speed where traction saturates [m/s]
};

/// Each ball's dynamics (model.kind = "balls"), resolved: defaults filled in when read.
struct BallOptions {
  double mass = 0.0;        ///< m_b [kg] (default ρ_ball π D³/6)
  double inertia = 0.0;     ///< J [kg m²] about the spin axis (default m_b D²/10)
  double damping = 0.0;     ///< c_b on the ball's radial velocity [N s/m] (default rotor.damping,
                            ///< as seed 004 eq. 24)
  bool centrifugal = true;  ///< the centrifugal load m_b ω_ca² d_m/2 on each ball
};

/// [lubricant]: the oil between the balls and the races (lubricant.h); present: every contact
/// has its EHL film (ehl_film.h), absent: the contacts are dry.
struct LubricantOptions : Lubricant {
  bool enabled = false;
};

/// Model choices.
struct ModelOptions {
  ModelKind kind = ModelKind::two_dof;  ///< quasi_static: no integrator ([solver] method, dt,
                                        ///< tolerance unused)
  /// Contact law: a Hertz method, or calibrated (the FE constants of `calibration`).
  ContactLaw contact = ContactLaw::exact;
  /// `model.calibration`, read and checked against the bearing when the case is parsed: present
  /// exactly when contact is ContactLaw::calibrated. Its path is absolute.
  std::optional<ContactCalibration> calibration;
  bool waviness_stiffness = false;  ///< TVDS (seed 002): K follows the waviness curvature
};

/// [solver]: the integration and the output times (solvers/integrator.h).
using SolverOptions = SolverSettings;

/// How `run` writes its tables (response, spectrum, pressure, envelope): CSV text with 12
/// significant digits, or NumPy .npy files of full doubles with columns.json naming their columns
/// and units.
enum class OutputFormat { csv, npy };
inline constexpr Named<OutputFormat> kOutputFormats[] = {{OutputFormat::csv, "csv"},
                                                         {OutputFormat::npy, "npy"}};

/// What `run` writes besides the ring's channels.
struct OutputOptions {
  bool ball_loads = false;     ///< add each ball's load Q1…QZ to response.csv
  bool ball_motion = false;    ///< add each ball centre's radial r1…rZ [m] and vr1…vrZ [m/s]
  bool ball_approach = false;  ///< add each ball's signed approach d1…dZ [m]
  /// add, per ball, the spin wb1… [rad/s], the outer-race load Qo1… [N] and the friction forces
  /// on the ball at its inner and outer contact Fi1…, Fo1… [N] (model.kind = "balls" only)
  bool ball_dynamics = false;
  /// add each ball's central EHL film thickness at its inner and outer contact hi1…, ho1… [m]
  /// (a [lubricant] table and a dynamic kind only)
  bool ball_film = false;
  Window window = Window::hann;  ///< spectrum window
  int peaks = 10;                ///< spectrum peaks listed per channel in summary.json
  /// envelope spectra of the ring accelerations and a diagnosis: none (default), a given band
  /// [Hz] or the fast kurtogram's (envelope.csv, summary.json envelope and diagnosis)
  EnvelopeBandSetting envelope_band;
  OutputFormat format = OutputFormat::csv;  ///< the tables as CSV (default) or .npy
};

struct Case {
  std::string source;  ///< file the case was read from, or "built-in default case"
  std::string preset;  ///< bearing.preset, empty if none
  Bearing bearing;
  Rotor rotor;
  Operation operation;
  Excitations excitation;
  ModelOptions model;
  CageOptions cage;  ///< model.kind = "balls" only
  BallOptions ball;  ///< model.kind = "balls" only
  SolverOptions solver;
  OutputOptions output;
  AcousticsOptions acoustics;  ///< on when the case has an [acoustics] table
  Housing housing;             ///< the outer ring's support and sensor: on with a [housing] table
  RandomSlip slip;             ///< the cage's random slip: on with [slip] rms > 0
  LubricantOptions lubricant;  ///< the EHL film of every contact: on with a [lubricant] table
};

/// The contact constants of the case's law (the one place models, the static solution and `info`
/// get them from): contact_constants(bearing, Hertz method) for a Hertz method,
/// calibrated_contact_constants(bearing, calibration) for "calibrated".
ContactConstants contact_constants(const Case& c);

/// The Hertz method behind the curvatures and ellipse shape of the case's law (for TVDS): the
/// method itself, or exact for calibrated.
HertzMethod hertz_shape_method(const ModelOptions& m);

/// One command-line override `table.key=value` (the value is TOML, or else taken as a string, so
/// `operation.speed=3000 rpm` and `model.contact=exact` need no quotes). A numeric path part
/// indexes an array of tables: `waviness.inner.0.amplitude=1um`.
struct Override {
  std::string key;    ///< dotted path, e.g. "material.ball.young"
  std::string value;  ///< the text after '='
};

/// Parses "table.key=value"; throws InputError if there is no '=' or no dotted key.
Override parse_override(std::string_view text);

/// Reads and resolves a case file. Throws InputError ("<path>: <key> = <value>: <what is
/// allowed>"). Waviness tables and model.calibration are found relative to the case file's
/// folder; a model.calibration given by an override relative to the working directory.
Case read_case_file(const std::string& path, const std::vector<Override>& overrides = {});

/// Resolves a case from TOML text; `source` names it in messages; relative table paths are taken
/// from `base_dir` (empty: the working directory).
Case parse_case(std::string_view toml_text, const std::string& source,
                const std::vector<Override>& overrides = {}, const std::string& base_dir = "");

/// TOML of the built-in default case: the 6308 of seed 003 at 2000 rpm under seed 002's 20 N
/// radial load, pointing down.
std::string_view default_case_toml();

/// The built-in default case with overrides applied.
Case default_case(const std::vector<Override>& overrides = {});

/// The fully resolved case as TOML, every number in SI with 17 significant digits, waviness and
/// ball errors written out: parse_case(case_to_toml(c)) gives back c exactly.
std::string case_to_toml(const Case& c);

/// The dimension of a numeric case-file key ("operation.speed" → angular speed; an array index
/// may appear: "waviness.inner.0.amplitude"), for sweeps. Throws InputError for other keys (an
/// unknown one with the nearest known key).
Dimension key_dimension(const std::string& key);

/// Whether a key takes a whole number (bearing.balls, waviness orders, ...).
bool key_is_integer(const std::string& key);

/// The names of every key the case reader accepts, as "table.key" (for --help and suggestions).
std::vector<std::string> known_keys();

/// One line per key: name, what it is and the units it accepts (for --help).
std::string case_keys_help();

}  // namespace bearing
