#pragma once
// The files and tables of `bearing-sim stiffness` (docs/bearing-sim.md, "stiffness"): one row per
// operating point in stiffness.csv, everything in stiffness.json, a readable table, the table
// ROSS's BearingElement reads (stiffness_ross.csv) and the ball pass (ball_pass_output.h). Written
// all or nothing (atomic_file_set.h).

#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "bearing/stiffness.h"

namespace bearing {

/// A varied key of the operating points: its case-file key and SI unit ("" dimensionless).
struct StiffnessKey {
  std::string key;   ///< "operation.axial_load"
  std::string unit;  ///< "N"
};

/// One operating point: the varied keys' values (SI), the case's speed and its solution.
struct StiffnessRow {
  std::vector<double> values;  ///< one per StiffnessTable::keys [SI]
  double speed = 0;            ///< operation.speed [rad/s] (its centrifugal ball load enters K)
  StiffnessPoint point;
};

/// The operating points of one `bearing-sim stiffness` call.
struct StiffnessTable {
  std::string source;              ///< the case file, or "built-in default case"
  std::string bearing;             ///< its designation ("6308")
  std::vector<StiffnessKey> keys;  ///< the varied keys, in column order (none: one point)
  std::vector<StiffnessRow> rows;  ///< the points, the first key varying slowest
  /// Cage angles a pitch of every row's ball pass (StiffnessPoint::ball_pass, each row has one);
  /// 0: none, the rows are static points alone.
  int ball_pass_samples = 0;
  /// The case has [lubricant]: the files carry the damping C (five_dof_static.h) beside K;
  /// without it they are as they were before the film (no damping columns, C = 0).
  bool lubricated = false;
};

/// The unit of C_ij = ∂F_i/∂q̇_j: stiffness_unit(i, j) times s ("N*s/m", "N*s/rad", "N*s",
/// "N*m*s/rad").
std::string damping_unit(int i, int j);

/// The name of C_ij for i ≤ j: stiffness_name's with "c_" ("c_xx", "c_x_gx").
std::string damping_name(int i, int j);

/// The shortest "%.*g" text that reads back as exactly `v` ("0" for −0): the stiffness files hold
/// the solver's doubles bit for bit.
std::string stiffness_number(double v);

/// K as a JSON array of its 5 rows (rows F, columns q).
nlohmann::json stiffness_matrix_json(const Matrix5& K);

/// stiffness.csv: per point the varied keys ("operation.axial_load [N]"), the 15 K_ij with
/// i ≤ j ("k_xx [N/m]", …, "k_x_gx [N/rad]", …, "k_gy_gy [N*m/rad]"), the displacement ("x [m]",
/// …, "gy [rad]"), "q_max [N]", "loaded_balls", then the load ("Fx [N]", …, "My [N*m]"); with
/// [lubricant] (t.lubricated) then the 15 C_ij ("c_xx [N*s/m]", …, "c_gy_gy [N*m*s/rad]"); every
/// one the equilibrium at the case's cage angle (the rotor's K and C, averaged over one ball pass:
/// the "mean" of stiffness_ball_pass.csv, stiffness.json's rotor); shortest round-trip numbers.
std::string stiffness_csv(const StiffnessTable& t);

/// stiffness.json: the case, what the model assumes, the DOFs and units, and per point the
/// varied values, load, the case's cage angle and at it the displacement, the full 5×5 matrix
/// ("stiffness_at_cage_angle"), each ball's angle, load and contact angle, the peak Hertz
/// pressures and whether they are within the elastic limit; with [lubricant]
/// "damping_at_cage_angle" (5×5 C) and units.damping; with a ball pass its object (ball_pass_json,
/// with [lubricant] its "damping_mean") and "rotor": the rotor coefficients (rotor_coefficients.h:
/// "samples", "stiffness" and with [lubricant] "damping", the ball-pass means, "warnings"). Throws
/// SolverError naming the first non-finite value.
nlohmann::json stiffness_json(const StiffnessTable& t);

/// The matrix K with row (Fx [N] … My [N*m]) and column (x [m] … gy [rad]) labels and the units of
/// its blocks, each line started by `indent` (also `info`'s).
std::string stiffness_matrix_text(const Matrix5& K, const std::string& indent = "  ");

/// The damping C = ∂F/∂q̇ as stiffness_matrix_text shows K, with its units (also `info`'s).
std::string damping_matrix_text(const Matrix5& C, const std::string& indent = "  ");

/// What the reader of the matrix at the case's cage angle must know when it is singular, as a
/// line started by `indent`: no ball loaded (K = 0), or fewer than 3 (each ball stiffens the ring
/// in two directions only); "" otherwise.
std::string stiffness_note(const StiffnessPoint& p, const std::string& indent = "  ");

/// The warning `stiffness` gives when the rotor's K (the ball-pass mean, StiffnessPoint::rotor) is
/// singular or near it at some points: how many, the first one's varied values, then that
/// point's reasons (rotor_stiffness_warnings), one indented line each; "" when none is.
std::string stiffness_rotor_warning(const StiffnessTable& t);

/// The warning `stiffness` gives when points pass the elastic limit (StiffnessPoint::elastic):
/// how many, the first one's varied values and pressure; "" when none does.
std::string stiffness_elastic_warning(const StiffnessTable& t);

/// The readable table: for one point its load, displacement, balls and matrix at the case's cage
/// angle, and with a ball pass the rotor's matrix (the mean); for several, the main terms
/// (diagonal, q_max, loaded balls) at the cage angle per point; then, with a ball pass, its table
/// (ball_pass_text: with the mean of the main diagonal terms).
std::string stiffness_text(const StiffnessTable& t);

/// stiffness_ross.csv, the table ROSS's BearingElement reads (its from_table column names):
/// frequency [rad/s] (operation.speed), kxx, kxy, kyx, kyy [N/m]: the radial block of K AVERAGED
/// OVER ONE BALL PASS (StiffnessPoint::rotor, the ball pass's mean), not K at the case's cage
/// angle; cxx, cxy, cyx, cyy [N s/m], the damping columns 0 (the model has none); rows by
/// ascending speed. ROSS interpolates over the speed, so the points may vary operation.speed
/// only. Throws InputError naming --format ross and the varied keys, the repeated speed, or
/// --ball-pass 0 (no mean) otherwise.
std::string stiffness_ross_csv(const StiffnessTable& t);

/// Writes dir/stiffness.csv and stiffness.json, with a ball pass (t.ball_pass_samples > 0)
/// stiffness_ball_pass.csv, with `ross` stiffness_ross.csv, all or nothing (the folder is
/// created only once every file's text is made); removes the ball-pass and ROSS files an earlier
/// call left that this one does not write. Throws InputError (the folder cannot be made, ROSS's
/// table impossible), SolverError (a non-finite value) or OutputError.
void write_stiffness(const std::string& dir, const StiffnessTable& t, bool ross);

}  // namespace bearing
