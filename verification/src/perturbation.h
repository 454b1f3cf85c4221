#pragma once
// Deliberate bugs, for `bearing-verify mutate` only. A Perturbation is applied by the Context
// (context.h) where a check takes the toolkit's values — geometry, contact constants, model inputs,
// the air, the FE meshes — so a mutation is a bug in the toolkit as the checks see it, while the
// references stay untouched. bearing-sim has no way to set one: this is a test-only hook, not an
// option. The identity Perturbation (the default) changes nothing.

namespace bearing::verify {

struct Perturbation {
  double contact_constant = 1.0;     ///< × K of both races and of the ball's series law [-]
  double contact_exponent = 0.0;     ///< + load–deflection exponent n of every lumped law [-]
  bool drop_tvds = false;            ///< TVDS (curvature-dependent stiffness) switched off
  bool waviness_sign = false;        ///< every waviness harmonic turned over (ψ + π)
  double cage_slip = 0.0;            ///< + s_c in the ball-DOF model (0.01: cage 1 % slower) [-]
  double pitch_diameter = 1.0;       ///< × d_m of every bearing the checks build [-]
  double mass = 1.0;                 ///< × inner-ring mass m of the dynamic models [-]
  double damping = 1.0;              ///< × radial damping c [-]
  double sound_speed = 1.0;          ///< × c₀ in the lumped acoustics [-]
  double microphone_distance = 1.0;  ///< × every lumped microphone's distance [-]
  double fe_cells = 1.0;             ///< × cells across the FE contact patch / per radius [-]
};

}  // namespace bearing::verify
