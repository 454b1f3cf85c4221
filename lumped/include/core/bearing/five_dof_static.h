#pragma once
// The 5-DOF static solution of a deep-groove ball bearing's inner ring and its tangent stiffness
// (issue 32): at rest, each ball on the line of its groove centres; at speed (below), each ball
// its own centre between the races under its centrifugal load.
//
// Coordinates. The outer ring is fixed; the inner ring moves by q = (δx, δy, δz, γx, γy) [m, m, m,
// rad, rad] from the concentric, axially centred position, and carries the load vector
// F = (Fx, Fy, Fz, Mx, My) [N, N, N, N m, N m], the work-conjugate of q (Mx turns about +x, as γx).
//
// Geometry (docs/model.md §1, three_dof.h). The groove curvature centres of one ball are
// A₀ = (f_i + f_o − 1) D apart when it touches both races. In the centred position they lie at
// the same axial position, radially u = A₀ − P_d/2 apart (P_d the diametral clearance): each ball
// has a gap P_d/2. The inner groove centre lies on a circle of radius
//     ℜ_i = d_m/2 + (f_i − 1/2) D − P_d/4     (the inner groove bottom d_i/2 = d_m/2 − D/2 − P_d/4,
//                                              plus the groove radius f_i D).
// Moving the inner ring by q moves ball j's inner groove centre, at ψ_j = φ₀ + 2πj/Z, radially by
// r_j = δx cos ψ_j + δy sin ψ_j and axially by s_j = δz + ℜ_i (γx sin ψ_j − γy cos ψ_j) (a rotation
// γ × p of the point p = ℜ_i (cos ψ_j, sin ψ_j, 0); its radial part is of second order in γ and
// left out, as Jones and Harris do). So, with a_j = (u + r_j, s_j) = a₀ + B_j q,
//     B_j = [ cos ψ_j  sin ψ_j  0       0             0          ]
//           [ 0        0        1   ℜ_i sin ψ_j  −ℜ_i cos ψ_j ],
//     L_j = |a_j|,   δ_j = L_j − A₀,   Q_j = K [δ_j]_+^n,
// and the ball's contact angle follows the deflection: tan α_j = s_j/(u + r_j) (negative: the
// other shoulder). The contact energy V(q) = Σ_j K/(n+1) [δ_j]_+^{n+1} is convex in q (a norm of
// an affine map, through a convex increasing function), and in equilibrium
//     F = ∇V = Σ_j Q_j B_jᵀ e_j,   e_j = (cos α_j, sin α_j),
// i.e. Fx = Σ Q cos α cos ψ, Fz = Σ Q sin α, Mx = Σ Q sin α ℜ_i sin ψ, My = −Σ Q sin α ℜ_i cos ψ.
// The tangent stiffness is the Hessian (symmetric by construction):
//     K = ∂F/∂q = Σ_j n K δ_j^{n−1} g_j g_jᵀ + (Q_j / L_j) h_j h_jᵀ,
//     g_j = B_jᵀ e_j,   h_j = B_jᵀ t_j,   t_j = (−sin α_j, cos α_j),
// the first term the contact's own stiffness along its line, the second the turn of the contact
// line (the contact angle's change) under its load.
//
// Reductions (tests/lumped/test_five_dof_static.cc checks each): a radial load alone gives
// δz = γ = 0 and the 2-DOF static solution (solve_static_load with γ = P_d/2); a radial and an
// axial load with the tilts held at 0 give the 3-DOF model's static state (three_dof.h, whose z
// is δz − w₀; free to tilt, the ring does tilt, as the loaded side carries more of the axial
// load); a pure axial load gives Harris's F_z = Z K [A₀ (cos α₀ / cos α − 1)]^n sin α.
//
// At speed (races apart). A centrifugal load F_c = m_b ω_c² d_m/2 presses each ball outward, so
// its two contacts no longer lie on one line: the ball centre p (from the outer groove centre O,
// in the ball's radial–axial plane) is a DOF of its own, with the outer contact
// δ_o = |p| − (f_o − 1/2) D and the inner one δ_i = |a_j − p| − (f_i − 1/2) D, each with its
// race's constant and exponent, and the ball's energy
//     E_j(p; a_j) = K_o/(n_o+1) [δ_o]_+^{n_o+1} + K_i/(n_i+1) [δ_i]_+^{n_i+1} − F_c p_r,
// jointly convex in (p, a_j). Each ball settles where ∇_p E_j = 0 — Jones's ball equilibrium
//     Q_o cos α_o − Q_i cos α_i = F_c,   Q_o sin α_o = Q_i sin α_i
// (the gyroscopic moment neglected, so the race control does not enter the forces). The ring
// then feels V(q) = Σ_j min_p E_j, still convex, with F = Σ_j Q_i,j B_jᵀ e_i,j and the condensed
// stiffness
//     K = Σ_j B_jᵀ [H_i − H_i (H_o + H_i)⁻¹ H_i] B_j = Σ_j B_jᵀ (H_i⁻¹ + H_o⁻¹)⁻¹ B_j,
// H_x = n_x K_x δ_x^{n_x−1} e_x e_xᵀ + (Q_x/L_x) t_x t_xᵀ each contact's 2×2 Hessian: the two
// contacts in series. With F_c = 0 and equal exponents the ball lies on the line of centres,
// δ_i + δ_o = L − A₀, and this is the one-contact form above with the series constant
// (tests/lumped/test_five_dof_static.cc checks that the two agree).
//
// With the EHL film (issue 43; ehl_film.h, film_law.h). Each contact's film keeps the surfaces
// h_c(Q) = C Q^−e apart (e = 0.067), so the contact law becomes FilmLaw's
//     δ = (Q/K)^{1/n} − H Q^−e,   dQ/dδ = (1/k_H + 1/k_f)^−1,   U(Q) = Q δ_H/(n+1) + e/(1−e) Q h_c,
// with H = C_i + C_o for the one-contact form (the two films in series along the ball's line)
// and each race's C for the races apart: Q_j = Q(δ_j), the term n K δ^{n−1} of K is the tangent
// (Hertz and the film in series) and V = Σ U(Q_j). The law is smooth: every ball carries a load,
// the unloaded ones a vanishing one (a gap of 10 h_c leaves ~1e-15 of it); a ball counts as
// loaded where δ_j > 0, i.e. its Hertz deflection exceeds its film (for dry contacts the same as
// Q_j > 0). H = 0 (no lubricant, or no entrainment at rest) is Hertz's law, bit for bit.
// The squeeze film of each contact (ehl_film.h) damps its approach: c_x(Q) = S_x / h_c,x(Q),
// S_x = 12 π η₀ (R_x R_y)^{3/2} / (R_x + R_y) [N s], and the ring feels, C_ij = ∂F_i/∂q̇_j,
//     C = Σ_j c_j g_j g_jᵀ,   c_j = c_i c_o / (c_i + c_o) at Q_j     (one contact form)
// (film_law.h: the two dampers in series on the ball's δ). With the races apart each ball's
// centre follows the ring quasi-statically as its springs place it, ṗ = P ȧ,
// P = (H_o + H_i)⁻¹ H_i, and the two dampers D_x = c_x e_x e_xᵀ dissipate along their lines:
//     C = Σ_j B_jᵀ [(I − P)ᵀ D_i (I − P) + Pᵀ D_o P] B_j,
// symmetric and positive semi-definite; on one line it is c_i k_o² + c_o k_i² over (k_i + k_o)²,
// the series c_i c_o/(c_i + c_o) when the springs stand in the ratio of the dampers.
// C's units follow K's with a factor s: N s/m, N s/rad, N s, N m s/rad.
//
// Approximations: rigid rings, the contact constants of the case (the curvatures at the free
// contact angle, as the 3-DOF model), F_c from the kinematic cage speed at the free contact angle,
// no gyroscopic moment; the film's coefficients at the free contact angle and the pure-rolling
// cage speed (ehl_film.h), the squeeze film's damping its isoviscous lower estimate (ehl_film.h).

#include <array>
#include <vector>

#include <Eigen/Dense>

#include "bearing/bearing.h"
#include "bearing/contact.h"
#include "bearing/ehl_film.h"

namespace bearing {

using Vector5 = Eigen::Matrix<double, 5, 1>;
using Matrix5 = Eigen::Matrix<double, 5, 5>;

/// What the 5-DOF solution needs of a bearing.
struct FiveDofBearing {
  int balls = 0;             ///< Z
  double K = 0;              ///< series constant of one ball [N/m^n]
  double exponent = 1.5;     ///< n [-]
  double A0 = 0;             ///< groove-centre distance (f_i + f_o − 1) D [m]
  double clearance = 0;      ///< P_d [m]
  double groove_radius = 0;  ///< ℜ_i, radius of the inner groove centres [m]
  double phase = 0;          ///< φ₀, angle of ball 0 from +x toward +y [rad]
  /// The races apart (each ball its own centre, two contacts): set when centrifugal > 0.
  bool races_apart = false;
  double centrifugal = 0;                             ///< F_c on each ball, outward [N]
  double inner_K = 0, outer_K = 0;                    ///< each race's constant [N/m^n]
  double inner_exponent = 1.5, outer_exponent = 1.5;  ///< each race's n [-]
  double inner_offset = 0;  ///< (f_i − 1/2) D: ball centre to inner groove centre [m]
  double outer_offset = 0;  ///< (f_o − 1/2) D: outer groove centre to ball centre [m]
  /// The EHL films (above; set by add_films): all 0, dry contacts.
  double film_H = 0;                            ///< H = C_i + C_o of the ball [m N^0.067]
  double inner_film_H = 0, outer_film_H = 0;    ///< each race's C [m N^0.067]
  double inner_squeeze = 0, outer_squeeze = 0;  ///< S in c = S / h_c(Q) [N s]
};

/// Sets the films of `b` from both contacts' films (ball_films, ehl_film.h): H, C and S. A film
/// without entrainment (u = 0) is none: its contact stays dry.
void add_films(FiveDofBearing& b, const BallFilms& films);

/// The FiveDofBearing of `b` with the contact law `c`, ball 0 at `phase` [rad] and the
/// centrifugal load `centrifugal` [N] on each ball (0: at rest; ball_centrifugal_load() gives it
/// at a speed). Throws InputError naming bearing.clearance when P_d ≥ 2 A₀ (no contact angle
/// below 90°).
FiveDofBearing five_dof_bearing(const Bearing& b, const ContactConstants& c, double phase = 0,
                                double centrifugal = 0);

/// F_c = m_b ω_c² d_m/2 [N] of one ball (m_b from its diameter and density) at the inner ring's
/// speed `inner_speed` [rad/s], ω_c the cage speed at the free contact angle (kinematics.h).
double ball_centrifugal_load(const Bearing& b, double inner_speed);

/// The ball set at one inner-ring displacement q.
struct FiveDofPoint {
  Vector5 force = Vector5::Zero();      ///< ∇V: the load the balls hold the ring in [N, N m]
  Matrix5 stiffness = Matrix5::Zero();  ///< ∂force/∂q [N/m, N, N/rad, N m/rad]
  /// ∂force/∂q̇, the squeeze films' damping [N s/m, N s, N s/rad, N m s/rad]; 0 for dry contacts.
  Matrix5 damping = Matrix5::Zero();
  double energy = 0;                         ///< V [J]
  std::vector<double> ball_angles;           ///< ψ_j [rad]
  std::vector<double> approaches;            ///< δ_j, negative: the gap left [m]
  std::vector<double> ball_loads;            ///< Q_j ≥ 0 [N], of the inner contact
  std::vector<double> contact_angles;        ///< α_j [rad], of the inner contact
  std::vector<double> outer_loads;           ///< Q_o,j [N] (= Q_j at rest)
  std::vector<double> outer_contact_angles;  ///< α_o,j [rad] (= α_j at rest)
  /// With the film (film_H > 0): each ball's central film h_c at its inner and outer contact
  /// [m], C_i Q_j^−0.067 and C_o Q_o,j^−0.067 (ehl_film.h); empty for dry contacts.
  std::vector<double> inner_films, outer_films;
};

/// Force, stiffness and the balls at displacement q = (δx, δy, δz, γx, γy) [m, rad].
FiveDofPoint five_dof_point(const FiveDofBearing& b, const Vector5& q);

struct FiveDofSolution {
  Vector5 displacement = Vector5::Zero();  ///< q in equilibrium with the load [m, rad]
  FiveDofPoint at;                         ///< the ball set there
  double residual = 0;  ///< |force − F| / |F| with moments over ℜ_i [-] (0 for F = 0)
  int iterations = 0;
};

/// Which of the five DOFs are held at 0 (e.g. the tilts of a ring whose shaft cannot tilt: the
/// 3-DOF model); their load components are then reactions (FiveDofPoint::force there).
using HeldDofs = std::array<bool, 5>;

/// The displacement that carries `load` = (Fx, Fy, Fz, Mx, My) [N, N m] in the DOFs not `held`:
/// the minimum of V(q) − F·q over them, by Levenberg-damped Newton from the centred position (V
/// is convex, so it converges from there). A zero load gives q = 0 (the centred position, in the
/// dead band of the clearance). Throws SolverError if the balance is not reached to 1e-10 of
/// |F| (moments over ℜ_i).
FiveDofSolution solve_five_dof(const FiveDofBearing& b, const Vector5& load,
                               const HeldDofs& held = {});

}  // namespace bearing
