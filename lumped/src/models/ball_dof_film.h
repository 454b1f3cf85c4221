#pragma once
// Private to the lumped models (not installed): the EHL film in the ball-DOF kind (issue 43;
// film_contacts.h, film_law.h). Each of a ball's two contacts has its own film law Q(δ) and its
// own squeeze damper c(Q) on its own approach rate: δ̇_i = n_j · v_ring − ṡ_j at the inner contact
// and δ̇_o = ṡ_j at the outer (ball_dofs.h). ball_dofs.cc calls this only when lubricated; its dry
// path never does.

#include <functional>

#include "ball_set.h"
#include "film_contacts.h"

namespace bearing::detail {

/// One ball's two contacts in the ball-DOF kind (ball_dofs.cc).
struct BallContacts {
  double delta_i, delta_o;  ///< approaches [m], signed
  double load_i, load_o;    ///< Q_i, Q_o [N]
  double ca = 1, sa = 0;    ///< cos α_j, sin α_j of the contact line (planar: 1, 0)
  double inv_length = 0;    ///< 1/L_j [1/m] (planar: 0)
};

/// The ball-DOF kind's films, each contact's at the model's cage speed (with cage slip).
struct BallDofFilm {
  RaceFilms races;

  /// k's loads Q_i, Q_o [N] from each contact's film law at k's approaches, with ball j's race
  /// constants K_i, K_o [N/m^n] of the frame.
  void set_loads(const RaceFrame& fr, int j, BallContacts& k) const {
    k.load_i = races.inner.load(fr.inner_stiffness[j], k.delta_i);
    k.load_o = races.outer.load(fr.outer_stiffness[j], k.delta_o);
  }
  /// Ball j's loads Q_i, Q_o [N] at the approaches δ_i, δ_o [m] and its contacts' normal
  /// forces with their squeeze dampers, push_i = Q_i + c_i (δ̇_ring − ṡ) and push_o = Q_o + c_o ṡ
  /// [N], for the ring's rate δ̇_ring = n_j · v_ring along the contact normal and the ball's ṡ
  /// [m/s]. Inline: the force loop's.
  void pushes(const RaceFrame& fr, int j, double delta_i, double delta_o, double ring_rate,
              double ball_rate, double& load_i, double& load_o, double& push_i,
              double& push_o) const {
    load_i = races.inner.load(fr.inner_stiffness[j], delta_i);
    load_o = races.outer.load(fr.outer_stiffness[j], delta_o);
    push_i = load_i + races.inner.damping(load_i) * (ring_rate - ball_rate);
    push_o = load_o + races.outer.damping(load_o) * ball_rate;
  }
  /// Each contact's tangent dQ/dδ at k's loads [N/m].
  void tangents(const RaceFrame& fr, int j, const BallContacts& k, double& ki, double& ko) const;
  /// U_i(Q_i) + U_o(Q_o), the energy stored in both contacts' film laws [J].
  double energy(const RaceFrame& fr, int j, const BallContacts& k) const;
  /// Each contact's central film thickness h_r = C_r Q_r^−0.067 at k's loads [m].
  void thickness(const RaceFrame& fr, int j, const BallContacts& k, double& inner,
                 double& outer) const;
  /// Adds the squeeze films' −∂f/∂v of ball j to dfdv (n×n row-major, n DOFs; the ring's first
  /// `ring`, the ball's at S) with the ring's contact normal nv: push_i = Q_i + c_i (n·v − ṡ) on
  /// the ring (−n) and the ball (+1), push_o = Q_o + c_o ṡ on the ball (−1); ∂c/∂q neglected.
  void add_damping(const BallContacts& k, const double* nv, int ring, int S, int n,
                   double* dfdv) const;
};

/// A ball's DOF s [m] where Q_o − Q_i − F_c changes sign, with the film: the excess rises in s
/// and every contact carries some load, so the root is bracketed outward from s0 (where the outer
/// contact's geometric overlap is 0) in doubling steps from 0.1 µm, then bisected to 1e-16 m.
/// below(s): Q_o − Q_i − F_c < 0 at s.
double film_ball_equilibrium(const std::function<bool(double)>& below, double s0);

}  // namespace bearing::detail
