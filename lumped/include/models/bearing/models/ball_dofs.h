#pragma once
// The ball-DOF model with cage slip and traction friction (seed 004; docs/model.md §4, "Ball DOFs,
// cage slip and friction"): model.kind = "balls". DOFs (2Z + 2; with an axial load 2Z + 3,
// below), in this order:
//   q = [x, y, r_1 … r_Z, φ_1 … φ_Z]
// x, y the inner-ring centre [m]; r_j ball j's centre, radially outward from the position where a
// nominal ball touches the perfect outer race [m] (the r_j of bearing_model.h's ball_motion);
// φ_j its spin angle relative to the cage [rad], cyclic (no force depends on it), so v = φ̇_j =
// ω_b,j.
//
// Contacts. The ball sits between two Hertz contacts of its own, with each race's constant:
//     δ_o,j = r_j + Π_o(θ_j) − ΔD_j/2,
//     δ_i,j = x cos θ_j + y sin θ_j − r_j − γ + Π_i(θ_j − ω_i t) − ΔD_j/2,
//     Q_o,j = K_o [δ_o,j]_+^{n_o},   Q_i,j = K_i [δ_i,j]_+^{n_i}   (TVDS: K per race and ball).
// Their sum is the 2-DOF model's approach (docs/model.md §1). Clearance split: all of the per-ball
// gap γ = P_d/2 (bearing.clearance, the ISO diametral clearance) sits on the inner side, the
// convention every model of the toolkit uses (outer raceway diameter d_m + D). Any other split
// g_in + g_out = γ is the shift r_j → r_j − g_out of the ball coordinate: the equations, and so the
// motion, are the same, with or without ball mass. Seed 004 subtracts its P_d/2 at each contact
// (eqs. 13–14), so its per-ball gap is its whole P_d: clearance = 2 P_d maps it
// (examples/seed004_6304.toml).
//
// Kinematics. θ_j = φ₀ + 2πj/Z + ω_ca t with ω_ca = (1 − s_c) ω_c (seed 004 eq. 3). Sliding speeds
// (traction.h, seed 004 eqs. 7–8), with g = D cos α / d_m and the lever arm L = (D/2) cos α:
//     Δv_i = ½ (ω_i − ω_ca) d_m (1 − g) − L ω_b + u_t,   u_t = −ẋ sin θ_j + ẏ cos θ_j,
//     Δv_o = ½ ω_ca d_m (1 + g) − L ω_b.
// u_t, the inner ring's translation along the rolling direction at the contact, is not in seed 004.
// Without it the friction on the ring would do work that no sliding accounts for, and the power
// balance below would not close. It is mm/s, but on the linear part of the traction curve it makes
// each loaded ball a damper of about (μ_m/Δv_m) Q_i/2 on the ring's tangential motion (spin in
// equilibrium; 370 N s/m for the seed 004 case at μ_m = 0.05: examples/README.md, §6).
//
// Equations of motion (friction forces as derived in traction.h; seed 004's eqs. 20–23 apply the
// ring's friction with inconsistent signs, sin θ for x and cos θ for y, subtracted in both):
//     m ẍ + c ẋ = F_x + F_u cos ω_i t − Σ_j [Q_i,j cos θ_j − μ(Δv_i,j) Q_i,j sin θ_j]
//     m ÿ + c ẏ = F_y + F_u sin ω_i t (− m g) − Σ_j [Q_i,j sin θ_j + μ(Δv_i,j) Q_i,j cos θ_j]
//     m_b r̈_j + c_b ṙ_j = Q_i,j − Q_o,j (+ F_c = m_b ω_ca² d_m/2, centrifugal)   (seed 004 eq. 24)
//     J ω̇_b,j = L [μ(Δv_i,j) Q_i,j + μ(Δv_o,j) Q_o,j]                           (seed 004 eq. 25)
// The friction on the ring acts along −t_j, t_j = (−sin θ_j, cos θ_j) the direction of rotation, as
// the reaction of +μ(Δv_i) Q_i on the ball. The spin torque: the ball's absolute angular speed is
// ω_ca − ω_b (seed 004's ω_b is counted against the rotation), and the tangential forces F_bi at
// its inner and F_bo = −μ(Δv_o) Q_o at its outer contact turn it by (D/2)(F_bo − F_bi) cos α.
// Seed 004's eq. 25 with its eq. 9–10 forces has the opposite sign: a ball spinning too slowly
// would be braked further instead of being brought back to rolling. The cage carries the balls at
// ω_ca whatever the forces (seed 004's assumption 4): the tangential forces' net pull on each ball
// is taken by the cage, the inner ring's friction torque by the drive.
//
// Power. Friction on the model's DOFs does P_f = Σ_j −μ(Δv_i) Q_i u_t + L ω_b [μ(Δv_i) Q_i +
// μ(Δv_o) Q_o]; the prescribed rotations (the inner ring, and the cage, in whose frame ω_b is
// counted) give the contacts P_d = −Σ_j [μ(Δv_i) Q_i ½ (ω_i − ω_ca) d_m (1 − g) + μ(Δv_o) Q_o ½
// ω_ca d_m (1 + g)]; and P_f + P_d = −Σ_j [μ(Δv_i) Q_i Δv_i + μ(Δv_o) Q_o Δv_o], minus what the
// contacts dissipate. The DOFs' energy E = ½ vᵀMv + Σ_j [K_i δ_i^{n_i+1}/(n_i+1) + K_o
// δ_o^{n_o+1}/(n_o+1)] − F_x x − F_y y − F_c Σ_j r_j (constant loads, no unbalance) changes at
// dE/dt = P_f − c (ẋ² + ẏ²) − c_b Σ_j ṙ_j² + ∂E/∂t, the last the work of the turning contact
// geometry (0 at zero speed, where the energy decays exactly by what the contacts dissipate).
//
// Axial load / preload (operation.axial_load ≠ 0). The ring gets its axial DOF z, and each ball
// sits on the contact line of the 3-DOF model (three_dof.h): the groove curvature centres are
// L_j = sqrt((w₀ + z)² + (u₀ + ρ_j)²) apart, ρ_j = x cos θ_j + y sin θ_j + e_i,j + e_o,j, and the
// ball between them, at s_j along the line from where it touches the outer groove:
//     δ_o,j = s_j,   δ_i,j = L_j − A₀ − s_j,
// so δ_i + δ_o is the 3-DOF model's δ_j, and a massless ball in equilibrium gives its forces. The
// inner contact pushes the ring by −Q_i,j n_j, n_j = (cos α_j cos θ_j, cos α_j sin θ_j, sin α_j)
// with the loaded angle of the same triangle; the ball moves along the line (its inertia m_b along
// it, the motion across it neglected: a ball held by two contacts on one line), m_b s̈_j + c_b ṡ_j =
// Q_i − Q_o + F_c cos α_p. The kinematics (ω_c, the sliding speeds, the lever arm) use the loaded
// contact angle α_p of the axial static state, as the 3-DOF model's cage speed does. DOFs
// [x, y, z, s_1 … s_Z, φ_1 … φ_Z], 2Z + 3 of them.
//
// Lubricated (issue 43): each contact carries its own EHL film in series with its Hertz law and its
// own squeeze damper (film_law.h, ehl_film.h, src/models/film_contacts.h): Q_r,j =
// FilmLaw{K_r,j, n_r, C_r}.load(δ_r,j) (positive for every δ: no contact opens), and the normal
// force of contact r is Q_r,j + c_r(Q_r,j) δ̇_r,j on its own approach rate, δ̇_o,j = ṡ_j and
// δ̇_i,j = n_j · v_ring − ṡ_j (the excitation's and the turning geometry's rates left out). The
// ring takes −(Q_i + c_i δ̇_i) n_j, the ball (Q_i + c_i δ̇_i) − (Q_o + c_o δ̇_o); the traction
// stays μ Q. The films' entrainment is at this model's cage speed ω_ca (cage slip included); the
// energy is Σ U(Q_i) + U(Q_o); the ring starts at the 2-DOF (3-DOF) film static state.
//
// Ball mass m_b = ρ π D³/6 (material.ball.density) and J = m_b D²/10 unless given. The analytic
// Jacobian is provided.

#include <memory>

#include "bearing/models/bearing_model.h"
#include "bearing/models/model_inputs.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// Powers of the traction at one instant [W] (see the header comment).
struct FrictionPower {
  double dissipated = 0.0;  ///< Σ_j μ(Δv_i) Q_i Δv_i + μ(Δv_o) Q_o Δv_o ≥ 0
  double on_dofs = 0.0;     ///< P_f: friction power on the ring's translation and the balls' spin
  double drives = 0.0;      ///< P_d: friction power on the ring's rotation and the cage's
};

class BallDofModel : public BearingModel {
 public:
  /// The cage slip s_c [-].
  virtual double cage_slip() const = 0;
  /// The constant radial force on each ball [N]: m_b ω_ca² d_m/2 with centrifugal, else 0.
  virtual double centrifugal_force() const = 0;
  /// The traction powers at (t, q, v).
  virtual FrictionPower friction_power(double t, const double* q, const double* v) const = 0;
};

/// A steel ball's mass from its material, ρ π D³/6 [kg] (ball.mass's default).
double default_ball_mass(const Bearing& b);
/// A solid sphere's moment of inertia m D²/10 [kg m²] (ball.inertia's default).
double default_ball_inertia(double mass, double diameter);

/// Builds the ball-DOF model: planar (2Z + 2 DOFs), or with the ring's z (2Z + 3) when
/// inputs.axial_load ≠ 0. Throws InputError naming the case key for invalid inputs (those of the
/// 2-DOF and, with an axial load, the 3-DOF model, and cage.slip outside [0, 1), a negative
/// ball.mass, ball.inertia or ball.damping).
std::unique_ptr<BallDofModel> make_ball_dof_model(const ModelInputs& inputs);

/// RK4 with the ball-DOF model's force inlined in its stages, as make_two_dof_rk4 (two_dof.h) for
/// the 2-DOF model: the same bits as make_integrator(settings); it integrates only a model of
/// make_ball_dof_model (std::logic_error for any other system).
std::unique_ptr<Integrator> make_ball_dof_rk4(const IntegratorSettings& settings);

}  // namespace bearing
