#pragma once
// The 2-DOF model of seeds 001–003 (docs/model.md §4): the inner-ring centre (x, y) on Z Hertzian
// balls, outer ring fixed, inner ring turning at ω_i.
//
//   m ẍ + c ẋ + Σ_j Q_j cos θ_j = F_x + F_u cos ω_i t
//   m ÿ + c ẏ + Σ_j Q_j sin θ_j = F_y + F_u sin ω_i t − m g   (−m g only with gravity)
//
//   Q_j = K_j [δ_j]_+^{3/2},  δ_j = x cos θ_j + y sin θ_j − γ + Π_i(θ_j − ω_i t) + Π_o(θ_j) − ΔD_j,
//   θ_j = φ₀ + 2πj/Z + ω_c t,  ω_c = cage_speed(bearing, ω_i),  γ = P_d/2,  F_u = m_u e ω_i².
//
// K_j = K (TVD) or, with waviness_stiffness (TVDS, seed 002), the series constant of the ball
// recomputed from each race's waviness-modified rolling-direction curvature. DOFs {"x", "y"} [m];
// forces [N]. The analytic Jacobian is provided (∂f/∂q from the contacts, ∂f/∂v = −c I).
//
// With a lubricant (ModelInputs::lubricated, issue 43) each ball's two EHL films stand in series
// with its Hertz contacts (film_law.h, src/models/film_contacts.h): Q_j [δ_j]_+^{3/2} becomes
//   Q_j = FilmLaw{K_j, n, H}.load(δ_j) + c_j(Q_j) δ̇_j,   H = C_i + C_o,   δ̇_j = ẋ cos θ_j + ẏ sin θ_j,
//   c_j = c_i c_o/(c_i + c_o),  c_r = the squeeze film of race r at Q_j (ehl_film.h),
// for every ball (the film law is positive for all δ: no contact opens, so no switching
// functions); C_r and c_r at the entrainment of ω_i and this model's ω_c. The energy is
// Σ_j U(Q_j) (film_law.h), the static state the film's, ∂f/∂q uses dQ/dδ = the law's tangent,
// ∂f/∂v adds −Σ c_j e_j e_jᵀ (∂c/∂q neglected). The rates of the turning geometry and of the
// excitation are left out of δ̇_j (film_contacts.h). Without a lubricant, all as above.

#include <memory>
#include <vector>

#include "bearing/models/bearing_model.h"
#include "bearing/models/model_inputs.h"
#include "bearing/solvers/integrator.h"

namespace bearing {

/// Builds the 2-DOF model. Throws InputError naming the case key for invalid inputs (mass ≤ 0,
/// negative damping, a waviness order < 1, a ball-error list of the wrong length, ...).
/// initial_displacement() is the static solution (solve_static_load) under the constant radial
/// load (with gravity if on), without waviness or size errors.
std::unique_ptr<BearingModel> make_two_dof_model(const ModelInputs& inputs);

/// RK4 (`settings`: method rk4, dt, max_displacement) with the 2-DOF model's force inlined in its
/// stages (static_rk4.h): the same steps and bits as make_integrator(settings), faster. Its
/// integrate() takes only a model of make_two_dof_model (std::logic_error for any other system).
std::unique_ptr<Integrator> make_two_dof_rk4(const IntegratorSettings& settings);

/// The 2-DOF model of `bearing_only` (the inputs without the ring loads) on the housing
/// (housing.h: make_housing_model's model, with this kind's force statically dispatched).
std::unique_ptr<BearingModel> make_two_dof_housed(const ModelInputs& bearing_only,
                                                  const RingLoad& load, const Housing& housing,
                                                  std::vector<double> start);

/// RK4 with that model's force inlined (static_rk4.h); its integrate() takes only a model of
/// make_two_dof_housed.
std::unique_ptr<Integrator> make_two_dof_housed_rk4(const IntegratorSettings& settings);

}  // namespace bearing
