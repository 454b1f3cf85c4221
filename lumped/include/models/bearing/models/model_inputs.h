#pragma once
// Everything a lumped bearing model is built from, in SI units, independent of the case file.

#include <string>
#include <vector>

#include <Eigen/Dense>

#include "bearing/bearing.h"
#include "bearing/constants.h"
#include "bearing/contact.h"
#include "bearing/contact_loop.h"
#include "bearing/excitation.h"
#include "bearing/local_defect.h"
#include "bearing/lubricant.h"
#include "bearing/models/housing.h"
#include "bearing/models/random_slip.h"
#include "bearing/traction.h"

namespace bearing {

struct ModelInputs {
  Bearing bearing;           ///< geometry and materials
  ContactConstants contact;  ///< constants per race and in series (the case's contact law)
  /// TVDS: the Hertz method of the curvature–compliance table (exact for an FE-calibrated law)
  HertzMethod hertz_method = HertzMethod::exact;
  ContactLoop contact_loop = ContactLoop::simd;  ///< per-ball loop: SIMD or scalar (same bits)

  double inner_speed = 0.0;                        ///< ω_i [rad/s], outer ring fixed
  double cage_phase = 0.0;                         ///< φ₀, angle of ball 0 at t = 0 [rad]
  Eigen::Vector2d load = Eigen::Vector2d::Zero();  ///< constant radial load (F_x, F_y) [N]
  double axial_load = 0.0;  ///< F_z on the inner ring [N] (kinds that carry it: model_registry.h)
  double unbalance = 0.0;   ///< m_u e [kg m]; F_u = m_u e ω_i², rotating with the shaft
  bool gravity = false;     ///< add −m g to F_y (g = standard_gravity = 9.80665 m/s²)

  double mass = 0.0;           ///< inner ring + shaft mass m [kg]
  double damping = 0.0;        ///< radial viscous damping c [N s/m]
  double axial_mass = 0.0;     ///< axial mass [kg] (3-DOF; 0 → same as mass)
  double axial_damping = 0.0;  ///< axial damping [N s/m] (3-DOF)
  /// The outer ring's support and the sensor on it (housing.h); off: the outer ring is fixed.
  Housing housing;
  /// The cage's random slip (random_slip.h); off: the balls turn at exactly the cage speed.
  RandomSlip slip;
  /// The lubricant: with `lubricated`, every contact carries its EHL film in series with Hertz
  /// and its squeeze-film damping (ehl_film.h, film_law.h); off, the contacts are dry and the
  /// model the same as without it.
  bool lubricated = false;
  Lubricant lubricant;
  /// The last time a run evaluates the model [s] (solver.duration): the slip's path covers
  /// [0, slip_span].
  double slip_span = 0.0;

  /// The constant radial load on the inner ring [N]: `load`, with the weight −m g on F_y when
  /// `gravity` is on.
  Eigen::Vector2d radial_load() const {
    return {load.x(), load.y() - (gravity ? mass * standard_gravity : 0.0)};
  }

  Waviness inner_waviness;               ///< on the inner race (φ = θ_j − ω_i t)
  Waviness outer_waviness;               ///< on the outer race (φ = θ_j)
  std::vector<double> ball_size_errors;  ///< ΔD_j [m], empty or Z entries
  bool waviness_stiffness = false;       ///< TVDS: K varies with the waviness curvature (seed 002)
  std::vector<LocalDefect> defects;      ///< spalls on the races and balls (local_defect.h)

  // The ball-DOF model (model.kind = "balls", seed 004); unused by the others.
  double cage_slip = 0.0;     ///< s_c in [0, 1): the cage turns at ω_ca = (1 − s_c) ω_c [-]
  TractionCurve traction;     ///< μ(Δv) at both contacts of every ball (μ_m = 0: no friction)
  double ball_mass = 0.0;     ///< m_b [kg]; 0: from the ball density, ρ π D³/6
  double ball_inertia = 0.0;  ///< J [kg m²] about the spin axis; 0: m_b D²/10 (solid sphere)
  double ball_damping = 0.0;  ///< c_b [N s/m] on each ball's radial velocity (seed 004 eq. 24)
  bool centrifugal = false;   ///< add the centrifugal load m_b ω_ca² d_m/2 on each ball (the case
                              ///< file's ball.centrifugal defaults to true)
};

}  // namespace bearing
