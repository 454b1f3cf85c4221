#pragma once
// The 3-DOF model with axial load / preload (seed 001, docs/model.md §4): the inner-ring centre
// (x, y) and its axial position z on Z Hertzian balls, outer ring fixed.
//
// Geometry. The groove curvature centres of one ball are A₀ = (f_i + f_o − 1) D apart. With the
// rings concentric and the ball touching both grooves they lie on the free contact line, at the
// free contact angle α₀, cos α₀ = 1 − P_d/(2A₀) (P_d the diametral clearance): radial offset
// u₀ = A₀ cos α₀ = A₀ − P_d/2, axial offset w₀ = A₀ sin α₀ = sqrt((P_d/2)(2A₀ − P_d/2)).
// z = 0 is that touching position (shifted axially by w₀ from the centred one). Moving the inner
// ring by (x, y, z) moves ball j's inner-groove centre by r_j = x cos θ_j + y sin θ_j + e_j
// radially (e_j: waviness on both races and the size error, docs/model.md §1) and by z axially, so
//     L_j = sqrt((w₀ + z)² + (u₀ + r_j)²),   δ_j = L_j − A₀,   Q_j = K_j [δ_j]_+^n,
// (n the exponent of the contact law: 3/2 for Hertz, the fitted one for an FE-calibrated law)
// and the loaded contact angle follows from the same triangle:
//     sin α_j = (w₀ + z)/L_j,  cos α_j = (u₀ + r_j)/L_j   (L_j = A₀ + δ_j).
// The contact force acts along the loaded contact line: on the inner ring
//     f_x = F_x + F_u cos ω_i t − c ẋ − Σ Q_j cos α_j cos θ_j
//     f_y = F_y + F_u sin ω_i t − c ẏ − Σ Q_j cos α_j sin θ_j  (− m g with gravity)
//     f_z = F_z − c_z ż − Σ Q_j sin α_j,
// which is −∇ of the contact energy Σ K_j/(n+1) [δ_j]_+^{n+1} (∂δ_j/∂r_j = cos α_j,
// ∂δ_j/∂z = sin α_j). The geometry is symmetric about the centred position z = −w₀, so a
// negative axial load loads the other groove shoulder (α < 0) with the same formulas.
//
// Approximations: K_j is the constant of the case (ModelInputs::contact, i.e. the curvatures at
// the bearing's free contact angle), not recomputed for the loaded contact angle; with
// waviness_stiffness it varies with the waviness curvature exactly as in the 2-DOF model. The cage
// speed is cage_speed() at the contact angle of the axial static state (solve_axial_preload), so
// the ball-pass frequencies move with the preload; ball angles θ_j = φ₀ + 2πj/Z + ω_c t.
//
// Reductions to the 2-DOF model (tests/lumped/test_models.cc checks each):
//  (a) P_d = 0 (α₀ = 0) and z = 0: L_j = A₀ + r_j, so δ_j = r_j and α_j = 0 exactly: the radial
//      forces are those of the 2-DOF model with zero clearance, and f_z = F_z.
//  (b) P_d > 0 at the axially centred position z = −w₀: L_j = u₀ + r_j, so
//      δ_j = r_j − (A₀ − u₀) = r_j − P_d/2 and α_j = 0 — exactly the 2-DOF model with γ = P_d/2
//      (not only to first order), and no axial contact force.
//  (c) Near it, z = −w₀ + ζ: δ_j = δ_j^{2DOF} + ζ²/(2 L_j) + O(ζ⁴), so the radial force differs
//      from the 2-DOF one at second order in ζ, and f_z = F_z − ζ Σ Q_j/L_j + O(ζ³): a radially
//      loaded bearing has the axial stiffness Σ Q_j/(A₀ + δ_j) there, an unloaded one none.
//  (d) At z = 0 with clearance (balls just touching at α₀): δ_j = r_j cos α₀ + O(r_j²/A₀), so to
//      first order the radial force is the zero-clearance 2-DOF one with K cos^{n+1} α₀.
//
// With a lubricant (issue 43) each ball's force along its contact line n_j = (cos α_j cos θ_j,
// cos α_j sin θ_j, sin α_j) is FilmLaw{K_j, n, C_i + C_o}.load(δ_j) + c_j δ̇_j with δ̇_j = n_j · v
// (the ring's velocity along the line), c_j the two squeeze films in series, as in the 2-DOF
// model (two_dof.h; film_contacts.h): no contact opens, the energy is Σ_j U(Q_j), the static state
// is the film's (Newton from the dry one), and the Jacobian the film law's tangent with the same
// geometric stiffness Q_j/L_j, plus −Σ c_j n_j n_jᵀ on v.
//
// DOFs {"x", "y", "z"} [m]; the analytic Jacobian is provided.

#include <memory>
#include <vector>

#include "bearing/models/bearing_model.h"
#include "bearing/models/model_inputs.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// The axial static state: x = y = 0, every ball equally loaded.
struct AxialPreload {
  double z = 0;              ///< axial position of the inner ring [m] (z = 0: balls just touch)
  double contact_angle = 0;  ///< loaded contact angle α [rad] (negative for F_z < 0)
  double ball_load = 0;      ///< normal load of each ball Q [N]
};

/// Solves Z K δ^n sin α = F_z (with δ = L − A₀, sin α = (w₀ + z)/L, L = sqrt((w₀ + z)² + u₀²))
/// for the axial load `inputs.axial_load` by a bracketed scalar root search on δ (monotone).
/// For F_z = 0 the balls carry no load anywhere in the dead band −2w₀ ≤ z ≤ 0; the centred
/// position z = −w₀ (α = 0, where the model is the 2-DOF model) is returned. The equivalent
/// closed form, Harris's F_z = Z K [A₀ (cos α₀ / cos α − 1)]^n sin α (seed 001 eq. 2.21 is
/// its α₀ = 0 case), is checked by the tests. Throws InputError for invalid geometry
/// (P_d ≥ 2A₀) or loads, SolverError if the root search fails.
AxialPreload solve_axial_preload(const ModelInputs& inputs);

/// The cage speed the 3-DOF model uses [rad/s]: cage_speed() at |α| of solve_axial_preload().
double three_dof_cage_speed(const ModelInputs& inputs);

/// Builds the 3-DOF model. Validation as make_two_dof_model(), plus the axial fields
/// (axial_mass ≥ 0, 0 meaning `mass`; axial_damping ≥ 0; axial_load finite).
///
/// initial_displacement() is the static state under the constant loads (radial with gravity if
/// on, and axial), without waviness or size errors: for F_z = 0 the centred position z = −w₀
/// with (x, y) from solve_static_load at γ = P_d/2 (by (b) an exact equilibrium, and with a
/// radial load a stable one, by (c)); otherwise Newton's method on the convex contact potential
/// from the axial state of solve_axial_preload().
std::unique_ptr<BearingModel> make_three_dof_model(const ModelInputs& inputs);

/// RK4 with the 3-DOF model's force inlined in its stages, as make_two_dof_rk4 (two_dof.h) for
/// the 2-DOF model: the same bits as make_integrator(settings); it integrates only a model of
/// make_three_dof_model (std::logic_error for any other system).
std::unique_ptr<Integrator> make_three_dof_rk4(const IntegratorSettings& settings);

/// The 3-DOF model of `bearing_only` (the inputs without the ring loads) on the housing
/// (housing.h: make_housing_model's model, with this kind's force statically dispatched).
std::unique_ptr<BearingModel> make_three_dof_housed(const ModelInputs& bearing_only,
                                                    const RingLoad& load, const Housing& housing,
                                                    std::vector<double> start);

/// RK4 with that model's force inlined (static_rk4.h); its integrate() takes only a model of
/// make_three_dof_housed.
std::unique_ptr<Integrator> make_three_dof_housed_rk4(const IntegratorSettings& settings);

}  // namespace bearing
