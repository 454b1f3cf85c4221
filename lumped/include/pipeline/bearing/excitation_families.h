#pragma once
// Which families of spectral lines a simulated bearing can show, from what its case contains
// (docs/model.md §7), so a run's peaks are named only after lines its excitations make.
//
// Identical balls evenly spaced in the cage make every force a function of the ball set's angle
// that repeats each ball pass: lines at k·BPFO, and, when the response repeats only every m ball
// passes (period doubling once the balls lose contact, in a bearing with clearance), at (k/m)·BPFO.
// Nothing turns at the cage rate alone, so FTF lines need balls that differ: size errors, a ball
// defect, or each ball's own DOFs (model.kind = "balls": spin, radial motion and slip per ball).
// Features on the turning inner race (waviness, a defect) under the fixed load zone give k·BPFI
// and its shaft-rate sidebands; they and unbalance make a load that turns with the shaft: lines at
// k·f_r, and at k·BPFO ± f_r where it meets the varying compliance. A ball defect strikes at the
// spin rate.

#include "bearing/models/model_inputs.h"
#include "bearing/models/model_kind.h"
#include "bearing/signal/line_names.h"

namespace bearing {

/// The line families of a model of `kind` built from `inputs`:
///  - BPFO harmonics always (the ball set turns); its subharmonics (k/m)·BPFO with a dynamic kind
///    (a quasi-static equilibrium follows the ball set's angle, so it repeats every ball pass);
///  - FTF with ball-size errors (one not zero), a ball defect, or a kind with ball DOFs;
///  - BPFI and its ±f_r, ±2f_r sidebands with inner-race waviness (an amplitude not zero) or an
///    inner-race defect;
///  - f_r (and k·BPFO ± f_r) with unbalance (m_u e ≠ 0) or those inner-race features;
///  - BSF with a ball defect.
/// Outer-race waviness and defects make k·BPFO lines only: no family of their own.
LineFamilies excitation_families(ModelKind kind, const ModelInputs& inputs);

}  // namespace bearing
