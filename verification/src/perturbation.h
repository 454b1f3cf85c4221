#pragma once
// Deliberate bugs, for `bearing-verify mutate` only. A Perturbation is applied by the Context
// (context.h) where a check takes the toolkit's values — geometry, contact constants, model inputs,
// the air, the FE meshes — so a mutation is a bug in the toolkit as the checks see it, while the
// references stay untouched. bearing-sim has no way to set one: this is a test-only hook, not an
// option. The identity Perturbation (the default) changes nothing.

namespace bearing::verify {

/// The knobs as bits: which ones a check read (Context records it) and which a mutation turns.
enum Knob : unsigned {
  kContact = 1u << 0,     ///< contact_constant, contact_exponent, ellipse_minor
  kTvds = 1u << 1,        ///< drop_tvds
  kWaviness = 1u << 2,    ///< waviness_sign
  kCageSlip = 1u << 3,    ///< cage_slip
  kPitch = 1u << 4,       ///< pitch_diameter
  kMass = 1u << 5,        ///< mass
  kDamping = 1u << 6,     ///< damping
  kSoundSpeed = 1u << 7,  ///< sound_speed
  kMicrophone = 1u << 8,  ///< microphone_distance
  kFeCells = 1u << 9,     ///< fe_cells
  kDefect = 1u << 10,     ///< defect_width
  kAnalysis = 1u << 11,   ///< analysis_speed, drop_prewhitening, false_alarm
  kStructure = 1u << 12,  ///< structure_young, modal_shapes
  kFeDegree = 1u << 13,   ///< fe_degree
};

struct Perturbation {
  double contact_constant = 1.0;     ///< × K of both races and of the ball's series law [-]
  double contact_exponent = 0.0;     ///< + load–deflection exponent n of every lumped law [-]
  double ellipse_minor = 1.0;        ///< × b*, the contact ellipse's minor semi-axis [-]
  bool drop_tvds = false;            ///< TVDS (curvature-dependent stiffness) switched off
  bool waviness_sign = false;        ///< every waviness harmonic turned over (ψ + π)
  double cage_slip = 0.0;            ///< + s_c in the ball-DOF model (0.01: cage 1 % slower) [-]
  double pitch_diameter = 1.0;       ///< × d_m of every bearing the checks build [-]
  double mass = 1.0;                 ///< × inner-ring mass m of the dynamic models [-]
  double damping = 1.0;              ///< × radial damping c [-]
  double sound_speed = 1.0;          ///< × c₀ in the lumped acoustics [-]
  double microphone_distance = 1.0;  ///< × every lumped microphone's distance [-]
  double fe_cells = 1.0;             ///< × cells across the FE contact patch / per radius [-]
  double defect_width = 1.0;         ///< × the width of every local defect the models see [-]
  double analysis_speed = 1.0;       ///< × the shaft speed a record's analysis is given [-]
  bool drop_prewhitening = false;    ///< a record analysed without its cepstral pre-whitening
  double false_alarm = 1.0;      ///< × the false-alarm rate the fault-line threshold is for [-]
  double structure_young = 1.0;  ///< × Young's modulus of a structure bearing-fem modes reads [-]
  double modal_shapes = 1.0;     ///< × every shape value read from modes.json (seat, sensors) [-]
  int fe_degree = 0;             ///< + the FE degree asked of bearing-fem modes (-1: P1 for P2) [-]

  /// The knobs this perturbation turns away from the identity.
  unsigned changed() const {
    unsigned k = 0;
    if (contact_constant != 1.0 || contact_exponent != 0.0 || ellipse_minor != 1.0) k |= kContact;
    if (drop_tvds) k |= kTvds;
    if (waviness_sign) k |= kWaviness;
    if (cage_slip != 0.0) k |= kCageSlip;
    if (pitch_diameter != 1.0) k |= kPitch;
    if (mass != 1.0) k |= kMass;
    if (damping != 1.0) k |= kDamping;
    if (sound_speed != 1.0) k |= kSoundSpeed;
    if (microphone_distance != 1.0) k |= kMicrophone;
    if (fe_cells != 1.0) k |= kFeCells;
    if (defect_width != 1.0) k |= kDefect;
    if (analysis_speed != 1.0 || drop_prewhitening || false_alarm != 1.0) k |= kAnalysis;
    if (structure_young != 1.0 || modal_shapes != 1.0) k |= kStructure;
    if (fe_degree != 0) k |= kFeDegree;
    return k;
  }
};

}  // namespace bearing::verify
