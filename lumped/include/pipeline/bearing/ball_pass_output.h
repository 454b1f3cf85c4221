#pragma once
// The ball-pass stiffness in the outputs (issue 32): K of each operating point over one ball pitch
// (ball_pass_stiffness.h, StiffnessPoint::ball_pass) — its mean, range and BPFO harmonics, the
// parametric excitation the dynamic models feel — as `bearing-sim stiffness` writes it
// (stiffness.json's points[].ball_pass, stiffness_ball_pass.csv, a table below the main one) and
// `info` shows it (the diagonal's range and first harmonic). docs/bearing-sim.md, "stiffness".

#include <string>

#include <nlohmann/json.hpp>

#include "bearing/stiffness.h"
#include "bearing/stiffness_output.h"

namespace bearing {

/// What stiffness.json's ball_pass holds, in a sentence (its "ball_pass_definition").
extern const char* const kBallPassDefinition;

/// The ball pass of `p` (which has one) as JSON: samples (the count N), cage_angles [rad], bpfo
/// [Hz], mean, min, max (5×5, the units of K), harmonics[] of {order m, frequency = m × bpfo
/// [Hz], amplitude (5×5, the units of K)}, every m < N/2.
nlohmann::json ball_pass_json(const StiffnessPoint& p);

/// The units of ball_pass_json's fields, as entries of a `units` object ("ball_pass.bpfo": "Hz",
/// "ball_pass.mean": "<k_units>, entry by entry", …); `k_units` names the 5×5 table of K's
/// units ("units.stiffness" in stiffness.json).
nlohmann::json ball_pass_units_json(const std::string& k_units);

/// stiffness_ball_pass.csv, long form: per operating point and per K_ij (i ≤ j, stiffness.csv's
/// order and names) the varied keys ("operation.speed [rad/s]"), "bpfo [Hz]", "entry" ("k_xx"),
/// "unit" ("N/m": of every K value on the row), "at_cage_angle" (K at the case's cage angle:
/// stiffness.csv's value), "mean" (over the pitch: the rotor's K, as in stiffness_ross.csv),
/// "min", "max", then "1xBPFO", "2xBPFO", … (each harmonic's amplitude); shortest round-trip
/// numbers. Needs t.ball_pass_samples > 0.
std::string ball_pass_csv(const StiffnessTable& t);

/// The readable table of the ball pass: per point the varied values, the BPFO [Hz], and for k_xx,
/// k_yy, k_zz the min, mean, max and 1×BPFO amplitude [N/m]; "" without a ball pass.
std::string ball_pass_text(const StiffnessTable& t);

/// `info`'s lines under the matrix, each started by `indent`: the sample count, the BPFO, and per
/// diagonal term K_ii its min and max over one pitch and its 1×BPFO amplitude, with units; "" when
/// `p` has no ball pass.
std::string ball_pass_diagonal_text(const StiffnessPoint& p, const std::string& indent = "  ");

}  // namespace bearing
