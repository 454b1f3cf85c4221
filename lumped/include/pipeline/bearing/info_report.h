#pragma once
// `bearing-sim info`: the numbers that follow from a case's geometry and load alone — contact
// constants, bearing frequencies and the static load distribution — as text and as JSON.

#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/film_report.h"
#include "bearing/kinematics.h"
#include "bearing/models/housing.h"
#include "bearing/static_load.h"
#include "bearing/stiffness.h"

namespace bearing {

/// One local defect as the contacts see it (pure-rolling kinematics at the free contact angle).
struct DefectInfo {
  double inner_drop = 0;  ///< largest extra clearance at the inner contact [m] (0: none there)
  double outer_drop = 0;  ///< at the outer contact [m]
  double crossing = 0;    ///< time a contact takes to cross it [s] (infinite at rest)
  double max_step = 0;    ///< the largest fixed step a run accepts [s] (crossing / 10)
};

/// The axial static state of a kind that carries operation.axial_load (model_registry.h).
struct AxialStaticInfo {
  double contact_angle = 0;  ///< loaded contact angle α under the axial load alone [rad]
  double ball_load = 0;      ///< each ball's load under the axial load alone [N]
  double z = 0;              ///< the inner ring's axial position (0: balls just touch) [m]
};

struct InfoReport {
  Case input;
  ContactConstants contact;
  BearingFrequencies frequencies;
  StaticLoadResult static_load;  ///< under the radial load, as the 2-DOF model sees it
  /// With an axial load on a kind that carries it: its state under the axial load alone.
  std::optional<AxialStaticInfo> axial;
  /// The most loaded ball's load in the kind's static state, radial and axial loads together
  /// (the model's initial_displacement, without waviness, size errors or defects) [N]; the peak
  /// pressures are at this load.
  double peak_load = 0;
  double inner_peak_pressure = 0;  ///< peak Hertz pressure of the most loaded ball, inner race [Pa]
  double outer_peak_pressure = 0;  ///< the same on the outer race [Pa]
  std::vector<DefectInfo> defects;  ///< one per [[defects]] entry
  /// With [housing]: the undamped modes of the bearing on the housing at the static state
  /// (housing_modes, housing.h), ascending.
  std::vector<HousingMode> housing_modes;
  /// The 5-DOF static state and stiffness at the case's loads, radial, axial and moments
  /// together, whatever the model kind (stiffness.h); empty when it has none, with the reason in
  /// stiffness_error (a clearance beyond the 5-DOF geometry, no equilibrium reached).
  /// Its ball pass at kInfoBallPassSamples cage angles (StiffnessPoint::ball_pass) too, or,
  /// when an equilibrium at another cage angle is not reached, none, with the reason in
  /// ball_pass_error.
  std::optional<StiffnessPoint> stiffness;
  std::string stiffness_error;
  std::string ball_pass_error;
  /// With [lubricant]: each race's EHL film at the most loaded contact of `stiffness` (its
  /// largest inner and outer loads; without it, at peak_load).
  std::optional<FilmInfo> film;
};

/// Cage angles a pitch of info's ball pass: a few, so that info stays fast (`bearing-sim
/// stiffness --ball-pass N` for more).
constexpr int kInfoBallPassSamples = 16;

/// The warning `info` and `run` give when the static load's peak Hertz pressure passes
/// kElasticPressureLimit (contact.h), naming both pressures; empty otherwise.
std::string elastic_limit_warning(const InfoReport& report);

/// What compute_info leaves out: `run` asks for the elastic-limit warning only, and the 5-DOF
/// stiffness and its ball pass (a Newton solve per ball at speed, at each cage angle) are no part
/// of a run's cost.
enum class InfoParts { all, without_stiffness };

/// Computes everything `info` shows (`parts`: all, or all but the stiffness section). Throws
/// InputError / SolverError.
InfoReport compute_info(const Case& c, InfoParts parts = InfoParts::all);

/// JSON with the keys docs/bearing-sim.md documents: kinematics.{shaft,ftf,bpfo,bpfi,bsf} [Hz],
/// contact.{inner,outer}.{sum_rho [1/m], f_rho, ellipticity, delta_star, K [N/m^n], exponent n},
/// contact.K, contact.exponent, static.{deflection [m, m], ball_loads [N], q_max [N],
/// peak_load [N], peak_pressure.{inner, outer} [Pa], pressure_limit [Pa], elastic (bool), and
/// with an axial load axial.{contact_angle [rad], ball_load [N], z [m]}}; plus
/// contact.method, static.ball_angles [rad] and a `units` object; for a calibrated law
/// contact.calibration (calibration_json, json_helpers.h); with [[defects]], defects[] with
/// location, width, depth [m], inner_drop, outer_drop [m], crossing, max_step [s] (null at rest);
/// with [housing], housing.{mass [kg], frequency [Hz], damping_ratio, stiffness [N/m], damping
/// [N s/m], modes[].{frequency [Hz], housing_share}}; stiffness.{dofs, load [N, N m],
/// displacement [m, rad], matrix (5×5 K = dF/dq) [N/m, N/rad, N m/rad], q_max [N],
/// loaded_balls, ball_pass (ball_pass_json, at kInfoBallPassSamples cage angles; {error} when it
/// could not be solved)} (stiffness.h), or {error} saying why; with [lubricant] also
/// stiffness.damping (5×5 C = dF/dq̇) [N s/m, N s/rad, N s, N m s/rad] and film.{inner,
/// outer}.{load [N], entrainment_speed [m/s], central_thickness [m], minimum_thickness [m],
/// lambda, stiffness [N/m], damping [N s/m], ellipticity_within_fit} (film_report.h).
/// Throws SolverError if any value is not finite.
nlohmann::json info_json(const InfoReport& report);

/// Human-readable report with units.
std::string info_text(const InfoReport& report);

}  // namespace bearing
