#pragma once
// The housing: the outer ring on its own support, a mass–spring–damper in the bearing plane, and
// the accelerometer on it (the case file's [housing] table; issue 29 §2). Off by default: the
// outer ring is then fixed to the ground, as every model kind's header says, and nothing here runs.
//
// Why. A measured bearing signal comes from an accelerometer on the housing, and carries a fault's
// impacts at the structure's resonances (2–4 kHz on the CWRU rig), which a model of the bearing
// alone, its outer ring on the ground, does not have. Sawalhi & Randall (MSSP 22, 2008, Part I)
// add them to their bearing model: beside the shaft (x_s, y_s) the pedestal that holds the outer
// ring has its own mass, spring and damper (x_p, y_p), and a mass–spring–damper y_b on the
// pedestal, tuned to a high-frequency resonance of the measured signals, stands for the "typical
// bearing response" the accelerometer sees.
//
// The model. The outer ring and what carries it (housing, pedestal, sensor mount) are one rigid
// body of mass m_h translating in the bearing plane, q_h = (x_h, y_h), held to the ground by an
// isotropic spring and damper:
//     k_h = m_h ω_h²,   c_h = 2 ζ_h m_h ω_h,   ω_h = 2π f_h,
// f_h (housing.frequency) the housing's natural frequency on its support with the inner ring
// taken out, ζ_h (housing.damping_ratio) its damping ratio. The accelerometer sits rigidly on it:
// the sensor channels are the housing's accelerations ax_housing, ay_housing [m/s²] (the DOFs
// x_housing, y_housing [m] follow the ring's DOFs in q and in response.csv).
//
// With q = (x, y[, z]) the inner ring and q_r = q − q_h its position relative to the outer ring
// (z unchanged: the housing does not move axially), the 2-DOF and 3-DOF equations become
//     m q̈     = F + F_u (cos ω_i t, sin ω_i t) (− m g ŷ) + f_b(t, q_r, q̇_r)
//     m_h q̈_h = −f_b,xy(t, q_r, q̇_r) − k_h q_h − c_h q̇_h
// f_b = −c q̇_r − Σ_j Q_j n_j (+ F_z − c_z ż in z, 3-DOF) is what the bearing exerts on the inner
// ring: the model's own force (two_dof.h, three_dof.h) with the applied loads left out, evaluated
// at the relative position. Every approach δ_j depends on the rings' relative position only (the
// outer raceway is a circle about the housing's centre, and its waviness and defects are fixed in
// it at the ground-frame angles θ_j: the housing translates, it does not turn), so the contact
// laws are the model's own. The housing takes −f_b: action and reaction across massless balls.
// With the housing at rest (q_h = 0) this is the model without the housing exactly.
//
// Choices, stated:
//  - rotor.damping c acts between the rings (on q̇_r): it is the bearing's damping. With the
//    housing at rest it is today's c q̇.
//  - x, y and their channels are the inner ring's absolute motion (ground frame); inside the
//    clearance the ring is at x − x_housing. The ball channels (loads, approaches, the balls'
//    radial motion) are relative to the housing, as the contacts are.
//  - The static start is the model's own static solution for q_r, the housing deflected by the
//    constant load that passes through it, k_h q_h = F (− m g ŷ) (unbalance left out, as the
//    models do).
//  - The housing's own weight is carried by its support and left out: it would only shift y_h
//    and y by the constant m_h g/k_h.
//  - f_h is the housing's frequency alone. Coupled to the inner ring through the bearing's
//    stiffness k_b, the mode the sensor sees lies higher, near sqrt((k_h + k_b)/m_h)/2π while
//    the ring is much heavier than m_h (`bearing-sim info` prints the coupled frequencies).
//
// Simplifications against Sawalhi & Randall, said plainly: one body per direction instead of
// their pedestal plus separate resonator, so the sensor's resonance and the support's compliance
// are one mode (tune f_h to the band of the measured signal; m_h is that mode's modal mass, not a
// weighed housing); the same k_h and c_h in x and y; no tilt, no rotation; the sensor reads the
// housing's own acceleration, not a further base-excited transducer resonance. The ball-DOF model
// is not carried (its balls' inertia would see the housing's acceleration: a mass matrix that is
// not diagonal), nor the quasi-static one (no inertia, no resonance): both refuse [housing]
// (ModelDescriptor::housing).
//
// The modal transfer path (issue 40 §3; docs/model.md, "The transfer path"). With
// `housing.modes = "DIR/modes.json"` (bearing-fem modes: the structure's natural modes from
// finite elements, structure_modes.h) the one body above becomes the structure's M modes. Their
// coordinates η_k [kg^½ m], mass-normalised (unit modal mass), are the support's DOFs; the seat,
// and with it the outer ring, moves by the sum of the modes, and each mode is driven by the
// bearing's reaction projected on its seat motion s_k = (s_k,x, s_k,y) [kg^-½]:
//     q_h = Σ_k s_k η_k,     η̈_k + 2 ζ_k ω_k η̇_k + ω_k² η_k = −s_k · f_b,xy(t, q_r, q̇_r)
// with ω_k = 2π f_k and ζ_k housing.damping_ratio (one for all modes, or one per mode). The
// resonator above is the case of two modes at f_h with s = (1/√m_h, 0) and (0, 1/√m_h), η = √m_h
// q_h (a modes file holding them reproduces it: tests/lumped/test_housing_modes.cc). A sensor
// ψ (a point of the structure) moves by u = Σ_k ψ_k η_k, and the run writes its x, y, z
// displacement, velocity and acceleration: x_<sensor>, vx_<sensor>, ax_<sensor>, …; and the
// seat's own x, y motion q_s as x_seat, y_seat (the outer ring's: "seat" names no sensor).
// Choices, stated: the seat moves in x and y only (its axial motion and tilts, in the file, are
// left out: the rings of the 2-DOF and 3-DOF models do not tilt, and the 3-DOF model's axial
// force includes the applied F_z, which a moving seat would have to carry statically); the outer
// ring's own mass is not added to the structure's (mesh the ring with the housing if it
// matters); the modes are truncated at the file's last one, without residual flexibility (the
// static start is the truncated modes' own equilibrium, η_k = s_k · F/ω_k²); a free-free
// structure cannot carry the bearing and is refused.
//
// Limits (tests/lumped/test_housing.cc): with the inner ring's force prescribed the housing is
// the single-DOF oscillator, peak displacement at f_h sqrt(1 − 2ζ²), free decay at
// f_h sqrt(1 − ζ²) with logarithmic decrement 2πζ/sqrt(1 − ζ²); its energy E_h = ½ m_h |q̇_h|² +
// ½ k_h |q_h|² changes at dE_h/dt = −f_b,xy·q̇_h − c_h |q̇_h|²; k_h → ∞ at fixed m_h brings back
// the model without the housing at O(1/k_h) = O(f_h⁻²). (m_h → 0 at fixed f_h does not: k_h
// vanishes with it, and the outer ring floats.)

#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bearing/models/bearing_model.h"
#include "bearing/structure_modes.h"

namespace bearing {

/// The [housing] table, in SI. Its presence turns it on: the resonator (mass, frequency) or the
/// structure's modes (modes), never both.
struct Housing {
  bool enabled = false;
  double mass = 0.0;            ///< m_h, the outer ring and its carrier [kg] (the resonator)
  double frequency = 0.0;       ///< f_h, natural frequency on the support alone [Hz] (resonator)
  double damping_ratio = 0.05;  ///< ζ_h [-], and every mode's unless damping_ratios: a bolted
                                ///< machine structure's few per cent
  /// The modal transfer path: housing.modes as given (relative to the case file), and the file.
  std::string modes_file;
  std::optional<StructureModes> modes;  ///< read when the case is read; empty: the resonator
  std::vector<double> damping_ratios;   ///< ζ_k per mode [-] (empty: damping_ratio for all)
  std::vector<std::string> sensors;     ///< the sensors a run writes (empty: all in the file)

  bool modal() const { return modes.has_value(); }
  /// k_h = m_h (2π f_h)² [N/m] (the resonator).
  double stiffness() const;
  /// c_h = 2 ζ_h m_h (2π f_h) [N s/m] (the resonator).
  double damping() const;
  /// ζ_k of mode k [-].
  double mode_damping_ratio(int k) const;
  /// The sensors a run writes, in the file's order (all when `sensors` is empty).
  std::vector<const StructureSensor*> written_sensors() const;
  /// The support's DOFs: 2 for the resonator, the modes' count.
  int support_dofs() const;
};

/// The loads applied to the inner ring alone, which the housing takes only through the bearing.
struct RingLoad {
  Eigen::Vector2d constant = Eigen::Vector2d::Zero();  ///< (F_x, F_y), gravity included [N]
  double unbalance_force = 0.0;                        ///< F_u = m_u e ω_i² [N]
  double shaft_speed = 0.0;                            ///< ω_i [rad/s]: F_u turns at ω_i t
};

/// Checks the [housing] values: the resonator's mass, frequency and damping ratio, or the
/// modes' damping ratios (one or one per mode), the sensors (named in the file) and a held
/// structure. Throws InputError naming the key, the value and the allowed range.
void check_housing(const Housing& housing);

/// The bearing model `bearing` carried by the housing. `bearing` must be built without the ring
/// loads (its force is f_b, what the bearing exerts on the inner ring), its DOFs the ring's only
/// (dof_names().size() == dofs() ≤ 8, x and y first); `start` is the relative static position
/// q_r, from the same model built with the loads. DOFs: the bearing's, then the support's:
/// x_housing, y_housing [m] (the resonator) or η_1 … η_M [kg^½ m] (the modes: not named, so not
/// written; the sensors are). Throws InputError as check_housing, std::logic_error for a model
/// it cannot carry.
std::unique_ptr<BearingModel> make_housing_model(std::unique_ptr<BearingModel> bearing,
                                                 const RingLoad& load, const Housing& housing,
                                                 std::vector<double> start);

/// One undamped mode of a bearing carried by the housing, linearised about a state.
struct HousingMode {
  double frequency = 0.0;      ///< natural frequency [Hz]
  double housing_share = 0.0;  ///< the housing's share of the mode's kinetic energy [0, 1]
};

/// The undamped natural modes of `model` (make_housing_model's, whose support has
/// `support_dofs` DOFs, the last ones) linearised at its static start (initial_displacement) at
/// t = 0, ascending: the eigenproblem K φ = ω² M φ with K = −∂f/∂q symmetrised. What a case's
/// f_h (or the structure's modes) become once the housing carries the bearing (its sensor's
/// resonance is the mode with the largest housing share). A mode of zero stiffness (a free DOF,
/// e.g. an unloaded ring) has frequency 0.
std::vector<HousingMode> housing_modes(const BearingModel& model, int support_dofs = 2);

}  // namespace bearing
