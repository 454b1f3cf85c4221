#pragma once
// Private to the lumped models (not installed): the ball set at one instant — each ball's angle,
// its excitation e_j (waviness on both races and its size error) and its contact constant K_j —
// evaluated without allocation and without one sin() per ball or per harmonic.
//
// Ball angles (docs/model.md §1): θ_j(t) = φ₀ + 2πj/Z + ω_c t, j = 0…Z−1. (cos θ_j, sin θ_j) is the
// precomputed (cos, sin) of φ₀ + 2πj/Z rotated by the one (cos, sin) of ω_c t per instant. With
// random slip (random_slip.h) the cage angle is ω_c t + φ(t), the slip path's error added, and
// every ball, defect and rate follows it; without, nothing is added.
//
// Each race's waviness at the balls: race_excitation.h (folded by order mod Z, so no sin() per
// ball or harmonic). TVDS: each race's constant K from its curvature change (race_stiffness.h,
// curvature_compliance_table.h), and the ball between both races has
//     K_j = (K_i^{−2/3} + K_o^{−2/3})^{−3/2}.

#include <algorithm>
#include <cassert>
#include <cmath>
#include <memory>
#include <vector>

#include "bearing/constants.h"
#include "bearing/contact.h"
#include "bearing/excitation.h"
#include "bearing/hertz.h"
#include "bearing/local_defect.h"
#include "bearing/models/model_inputs.h"
#include "bearing/models/random_slip.h"
#include "bearing/solvers/mechanical_system.h"
#include "contact_kernels.h"
#include "defect_excitation.h"
#include "frame_workspace.h"
#include "inline_contacts.h"
#include "max_balls.h"
#include "model_input_checks.h"
#include "phasor.h"
#include "race_excitation.h"
#include "race_stiffness.h"

namespace bearing::detail {

/// The ball set at one instant (filled by BallSet::evaluate; lives on the caller's stack).
struct BallFrame {
  double cos_theta[kMaxBalls];
  double sin_theta[kMaxBalls];
  double excitation[kMaxBalls];  ///< e_j = Π_i(θ_j − ω_i t) + Π_o(θ_j) − ΔD_j [m]
  double stiffness[kMaxBalls];   ///< K_j [N/m^n] (all equal to K unless TVDS)
  double cos_shaft = 1;          ///< cos ω_i t
  double sin_shaft = 0;          ///< sin ω_i t
  double slip_rate = 0;          ///< φ̇(t), the cage speed's random slip [rad/s] (0: none)
};

/// The ball set at one instant with the two races kept apart (BallSet::evaluate), for the
/// ball-DOF model, where each ball has a contact of its own on each race.
struct RaceFrame {
  double cos_theta[kMaxBalls];
  double sin_theta[kMaxBalls];
  double inner_excitation[kMaxBalls];  ///< e_i,j = Π_i(θ_j − ω_i t) − ΔD_j/2 [m]
  double outer_excitation[kMaxBalls];  ///< e_o,j = Π_o(θ_j) − ΔD_j/2 [m]
  double inner_stiffness[kMaxBalls];   ///< K_i,j [N/m^n_i] (all K_i unless TVDS)
  double outer_stiffness[kMaxBalls];   ///< K_o,j [N/m^n_o] (all K_o unless TVDS)
  double cos_shaft = 1;                ///< cos ω_i t
  double sin_shaft = 0;                ///< sin ω_i t
  double slip_rate = 0;                ///< φ̇(t), the cage speed's random slip [rad/s] (0: none)
};

/// Q = K δ^n for δ > 0 (fast path for n = 3/2).
inline double contact_load(double K, double n, double delta) {
  return n == 1.5 ? K * delta * std::sqrt(delta) : K * std::pow(delta, n);
}

/// Time derivatives of the ball set at one instant and the outer race's share of it, for the
/// output instants (libm per ball and harmonic: never in the hot loop).
struct BallRates {
  double excitation_rate[kMaxBalls];       ///< de_j/dt [m/s]
  double stiffness_rate[kMaxBalls];        ///< dK_j/dt [N/(m^n s)] (0 unless TVDS)
  double outer_profile[kMaxBalls];         ///< Π_o(θ_j) [m]
  double outer_profile_rate[kMaxBalls];    ///< dΠ_o(θ_j)/dt [m/s]
  double outer_stiffness[kMaxBalls];       ///< K_o,j of the ball on the outer race [N/m^n_o]
  double outer_stiffness_rate[kMaxBalls];  ///< dK_o,j/dt (0 unless TVDS)
  double cage_rate = 0;                    ///< dθ_j/dt = ω_c (+ φ̇ with random slip) [rad/s]
};

/// Geometry, excitation and contact constants of the ball set, evaluated per instant.
class BallSet {
 public:
  /// `cage_speed` ω_c [rad/s] and `contact_angle` [rad] (the model's kinematics: a ball defect
  /// turns at the rolling spin they give); the inputs must have passed validate_common_inputs.
  BallSet(const ModelInputs& in, double cage_speed, double contact_angle)
      : balls_(in.bearing.balls),
        cage_speed_(cage_speed),
        inner_speed_(in.inner_speed),
        defects_(in, cage_speed, contact_angle),
        // Only the inner-race waviness and the unbalance turn with the shaft.
        needs_shaft_(!in.inner_waviness.empty() || in.unbalance != 0.0),
        K_(in.contact.K),
        exponent_(in.contact.exponent),
        cage_phase_(in.cage_phase),
        kernels_(contact_kernels(in.contact_loop, in.bearing.balls)),
        inner_K_(in.contact.inner.K),
        outer_K_(in.contact.outer.K),
        outer_exponent_(in.contact.outer.exponent),
        inner_waviness_(in.inner_waviness),
        outer_waviness_(in.outer_waviness) {
    const int Z = balls_;
    base_cos_.assign(padded_balls(Z), 0.0);  // read by the kernels in whole vectors
    base_sin_.assign(padded_balls(Z), 0.0);
    for (int j = 0; j < Z; ++j) {
      base_cos_[j] = std::cos(in.cage_phase + two_pi * j / Z);
      base_sin_[j] = std::sin(in.cage_phase + two_pi * j / Z);
    }
    size_error_.assign(Z, 0.0);
    if (!in.ball_size_errors.empty()) size_error_ = in.ball_size_errors;

    const bool tvds = in.waviness_stiffness;
    inner_ = RaceExcitation(in.inner_waviness, Z, tvds);
    outer_ = RaceExcitation(in.outer_waviness, Z, tvds);
    if (!inner_.empty() || !outer_.empty()) {
      table_cos_.resize(Z * Z);
      table_sin_.resize(Z * Z);
      for (int j = 0; j < Z; ++j)
        for (int k = 0; k < Z; ++k) {
          const int m = (k * j) % Z;  // 2πkj/Z reduced exactly
          table_cos_[j * Z + k] = std::cos(two_pi * m / Z);
          table_sin_[j * Z + k] = std::sin(two_pi * m / Z);
        }
    }
    if (tvds && (!inner_.empty() || !outer_.empty())) setup_tvds(in);
    // The slip's default correlation time is one ball pass of the cage (random_slip.h).
    if (in.slip.enabled() && cage_speed != 0.0) {
      const double tau = in.slip.correlation_time > 0.0 ? in.slip.correlation_time
                                                        : two_pi / (Z * std::abs(cage_speed));
      slip_ = std::make_shared<const SlipPath>(in.slip.rms, tau, in.slip.seed, cage_speed,
                                               in.slip_span);
    }
  }

  int balls() const { return balls_; }
  /// The per-ball kernels (contact_kernels.h) of the case's contact loop.
  const ContactKernels& kernels() const { return kernels_; }
  double cage_speed() const { return cage_speed_; }
  double K() const { return K_; }
  double exponent() const { return exponent_; }
  /// The ball set at t = 0 without excitation, ball 0 at `phase` [rad]: the static solutions'
  /// frame (each ball at its nominal angle, K_j = K).
  BallFrame rest_frame(double phase) const {
    BallFrame fr;
    for (int j = 0; j < balls_; ++j) {
      fr.cos_theta[j] = std::cos(phase + two_pi * j / balls_);
      fr.sin_theta[j] = std::sin(phase + two_pi * j / balls_);
      fr.excitation[j] = 0.0;
      fr.stiffness[j] = K_;
    }
    return fr;
  }
  bool tvds() const { return inner_stiffness_.varies || outer_stiffness_.varies; }
  /// Whether e_j or K_j depend on t (waviness on a race, or a local defect).
  bool excitation_varies() const { return !inner_.empty() || !outer_.empty() || !defects_.empty(); }
  /// Load–deflection exponent n_o of a ball on the outer race [-].
  double outer_exponent() const { return outer_exponent_; }
  /// ΔD_j = D − D_j [m].
  double size_error(int j) const { return size_error_[j]; }
  /// The random slip's path, or nullptr (random_slip.h).
  const SlipPath* slip() const { return slip_.get(); }

  /// Fills `br` for time t [s]: with φ_o = θ_j (dφ_o/dt = ω_c) and φ_i = θ_j − ω_i t
  /// (dφ_i/dt = ω_c − ω_i), de_j/dt = Π_i'(φ_i)(ω_c − ω_i) + Π_o'(φ_o) ω_c; with TVDS,
  /// K_j = (c_i + c_o)^{−3/2} (c = K_race^{−2/3}) gives dK_j/dt = −(3/2) K_j (ċ_i + ċ_o)/(c_i +
  /// c_o).
  void rates(double t, BallRates& br) const {
    // With random slip dθ_j/dt = ω_c + φ̇ and θ_j has φ added (random_slip.h).
    const SlipPath::AngleRate slip = slip_ ? slip_->at(t) : SlipPath::AngleRate{0.0, 0.0};
    const double wo = slip_ ? cage_speed_ + slip.rate : cage_speed_, wi = wo - inner_speed_;
    br.cage_rate = wo;
    for (int j = 0; j < balls_; ++j) {
      double theta = cage_phase_ + two_pi * j / balls_ + cage_speed_ * t;
      if (slip_) theta += slip.angle;
      const ProfileDerivatives o = profile_derivatives(outer_waviness_, theta);
      const ProfileDerivatives i = profile_derivatives(inner_waviness_, theta - inner_speed_ * t);
      br.excitation_rate[j] = i.slope * wi + o.slope * wo;
      br.outer_profile[j] = o.profile;
      br.outer_profile_rate[j] = o.slope * wo;
      br.stiffness_rate[j] = 0.0;
      br.outer_stiffness[j] = outer_K_;
      br.outer_stiffness_rate[j] = 0.0;
      if (!defects_.empty()) {
        DefectDrop di, d_o;
        defects_.at_ball(j, theta, inner_speed_ * t, t, slip.angle, slip.rate, di, d_o);
        br.excitation_rate[j] -= di.rate + d_o.rate;
        br.outer_profile[j] -= d_o.drop;
        br.outer_profile_rate[j] -= d_o.rate;
      }
      if (!tvds()) continue;
      const RaceStiffness &ri = inner_stiffness_, &ro = outer_stiffness_;
      const double ci = ri.varies ? ri.compliance(i.curv) : ri.k0;
      const double co = ro.varies ? ro.compliance(o.curv) : ro.k0;
      const double ci_rate = ri.varies ? ri.compliance_rate(i.curv, i.curv_slope * wi) : 0.0;
      const double co_rate = ro.varies ? ro.compliance_rate(o.curv, o.curv_slope * wo) : 0.0;
      const double K = 1.0 / ((ci + co) * std::sqrt(ci + co));
      br.stiffness_rate[j] = -1.5 * K * (ci_rate + co_rate) / (ci + co);
      br.outer_stiffness[j] = 1.0 / (co * std::sqrt(co));
      br.outer_stiffness_rate[j] = -1.5 * br.outer_stiffness[j] * co_rate / co;
    }
  }

  /// The trigonometry of t that a frame needs: the phasors of the cage angle ω_c t and, where the
  /// frame uses it (inner-race waviness, unbalance), of the shaft angle ω_i t (phasor.h). It
  /// depends on t alone, so a caller that knows the coming times may compute it ahead for
  /// several at once (static_rk4.h), which overlaps their latency.
  struct TimeAngles {
    Phasor cage;
    Phasor shaft;
    double slip = 0.0;       ///< φ(t), the random slip's angle [rad] (0: none)
    double slip_rate = 0.0;  ///< φ̇(t) [rad/s]
  };
  TimeAngles time_angles(double t) const {
    const Phasor shaft = needs_shaft_ ? phasor(inner_speed_ * t) : Phasor{1.0, 0.0};
    if (!slip_) return {phasor(cage_speed_ * t), shaft};
    const SlipPath::AngleRate slip = slip_->at(t);
    return {phasor(cage_speed_ * t + slip.angle), shaft, slip.angle, slip.rate};
  }

  /// time_angles() of the n times t[i] [s] at once, into out[i]: the same bits, computed several
  /// to a vector (the kernels' phasors). `scratch` is resized as needed.
  void time_angles(const double* t, int n, TimeAngles* out, std::vector<double>& scratch) const {
    const int padded = padded_balls(n);
    scratch.resize(3 * static_cast<std::size_t>(padded));  // lanes past n: never used
    double* const theta = scratch.data();
    double* const c = theta + padded;
    double* const s = c + padded;
    for (int i = 0; i < n; ++i) theta[i] = cage_speed_ * t[i];
    if (slip_) {
      for (int i = 0; i < n; ++i) {
        const SlipPath::AngleRate slip = slip_->at(t[i]);
        theta[i] += slip.angle;
        out[i].slip = slip.angle;
        out[i].slip_rate = slip.rate;
      }
    }
    kernels_.phasors(theta, n, c, s);
    for (int i = 0; i < n; ++i) {
      out[i].cage = {c[i], s[i]};
      out[i].shaft = {1.0, 0.0};
      if (!slip_) out[i].slip = out[i].slip_rate = 0.0;
    }
    if (!needs_shaft_) return;
    for (int i = 0; i < n; ++i) theta[i] = inner_speed_ * t[i];
    kernels_.phasors(theta, n, c, s);
    for (int i = 0; i < n; ++i) out[i].shaft = {c[i], s[i]};
  }

  /// The frame at time t [s] in `workspace` (a FrameWorkspace<Frame> from the model's
  /// make_workspace()), evaluated only when t differs from the last t asked of it
  /// (frame_workspace.h); `ahead`: time_angles(t) computed ahead, or nullptr. The reference is
  /// valid until the next call with this workspace. kInline: the balls rotated by the inline
  /// loop (inline_contacts.h; the same bits), for the kinds' own RK4.
  template <class Frame, bool kInline = false>
  const Frame& frame(double t, MechanicalSystem::Workspace& workspace,
                     const TimeAngles* ahead = nullptr) const {
    assert(dynamic_cast<FrameWorkspace<Frame>*>(&workspace));
    auto& w = static_cast<FrameWorkspace<Frame>&>(workspace);
    if (w.t != t) {
      const TimeAngles a = ahead ? *ahead : time_angles(t);
      // Without waviness and defects e_j and K_j do not depend on t: only the angles move.
      if (std::isnan(w.t) || excitation_varies())
        evaluate(t, a, w.frame);
      else
        angles<kInline>(a, w.frame);
      w.t = t;
    }
    return w.frame;
  }

  /// Each ball's load Q_j = K_j [δ_j]_+^n at time t [N], with δ_j = approach(j, frame) [m] the
  /// model's own geometry (shared by the models' ball_loads()).
  template <class Approach>
  void ball_loads(double t, const Approach& approach, double* loads) const {
    BallFrame fr;
    evaluate(t, fr);
    for (int j = 0; j < balls_; ++j) {
      const double delta = approach(j, fr);
      loads[j] = delta > 0 ? contact_load(fr.stiffness[j], exponent_, delta) : 0.0;
    }
  }

  /// Each ball's approach δ_j = approach(j, frame) at time t [m], signed (negative: the gap left
  /// to contact), the δ_j of ball_loads().
  template <class Approach>
  void ball_approaches(double t, const Approach& approach, double* out) const {
    BallFrame fr;
    evaluate(t, fr);
    for (int j = 0; j < balls_; ++j) out[j] = approach(j, fr);
  }

  /// The contact potential Σ_j K_j/(n+1) [δ_j]_+^{n+1} at time t [J], δ_j as in ball_loads().
  template <class Approach>
  double potential_energy(double t, const Approach& approach) const {
    BallFrame fr;
    evaluate(t, fr);
    double energy = 0;
    for (int j = 0; j < balls_; ++j) {
      const double delta = approach(j, fr);
      if (delta > 0)
        energy += fr.stiffness[j] / (exponent_ + 1.0) * std::pow(delta, exponent_ + 1.0);
    }
    return energy;
  }

  /// Fills `fr` for time t [s].
  void evaluate(double t, BallFrame& fr) const { evaluate(t, time_angles(t), fr); }
  /// The same with time_angles(t) given.
  void evaluate(double t, const TimeAngles& ta, BallFrame& fr) const {
    const int Z = balls_;
    angles(ta, fr);
    for (int j = 0; j < Z; ++j) fr.excitation[j] = -size_error_[j];
    double curv_i[kMaxBalls], curv_o[kMaxBalls];
    add_waviness(fr, fr.excitation, fr.excitation, curv_i, curv_o);
    defects_.apply(t, ta.slip, fr.excitation, fr.excitation);

    if (!tvds()) {
      std::fill(fr.stiffness, fr.stiffness + Z, K_);
      return;
    }
    for (int j = 0; j < Z; ++j) {
      const double s = inner_compliance(curv_i[j]) + outer_compliance(curv_o[j]);  // K_j^{−2/3}
      fr.stiffness[j] = 1.0 / (s * std::sqrt(s));
    }
  }

  /// Fills `fr` for time t [s] with each race's excitation and constant apart; a ball-size error
  /// ΔD_j takes ΔD_j/2 from each contact.
  void evaluate(double t, RaceFrame& fr) const { evaluate(t, time_angles(t), fr); }
  /// The same with time_angles(t) given.
  void evaluate(double t, const TimeAngles& ta, RaceFrame& fr) const {
    const int Z = balls_;
    angles(ta, fr);
    for (int j = 0; j < Z; ++j)
      fr.inner_excitation[j] = fr.outer_excitation[j] = -0.5 * size_error_[j];
    double curv_i[kMaxBalls], curv_o[kMaxBalls];
    add_waviness(fr, fr.inner_excitation, fr.outer_excitation, curv_i, curv_o);
    defects_.apply(t, ta.slip, fr.inner_excitation, fr.outer_excitation);
    if (!tvds()) {
      std::fill(fr.inner_stiffness, fr.inner_stiffness + Z, inner_K_);
      std::fill(fr.outer_stiffness, fr.outer_stiffness + Z, outer_K_);
      return;
    }
    for (int j = 0; j < Z; ++j) {
      const double ki = inner_compliance(curv_i[j]), ko = outer_compliance(curv_o[j]);
      fr.inner_stiffness[j] = 1.0 / (ki * std::sqrt(ki));
      fr.outer_stiffness[j] = 1.0 / (ko * std::sqrt(ko));
    }
  }

 private:
  // θ_j and the shaft angle at t from time_angles(t): the precomputed (cos, sin) of φ₀ + 2πj/Z
  // rotated by the one phasor of ω_c t (Frame: BallFrame or RaceFrame); kInline: frame().
  template <bool kInline = false, class Frame>
  void angles(const TimeAngles& ta, Frame& fr) const {
    const double cc = ta.cage.c, sc = ta.cage.s;
    fr.cos_shaft = ta.shaft.c;
    fr.sin_shaft = ta.shaft.s;
    fr.slip_rate = ta.slip_rate;
    static_assert(kMaxBalls % kKernelPad == 0, "the frame's arrays hold whole vectors");
    if constexpr (kInline)
      rotate_balls_inline(base_cos_.data(), base_sin_.data(), cc, sc, balls_, fr.cos_theta,
                          fr.sin_theta);
    else
      kernels_.rotate(base_cos_.data(), base_sin_.data(), cc, sc, balls_, fr.cos_theta,
                      fr.sin_theta);
  }

  // Adds each race's waviness at the balls of `fr` (angles set) to `inner` and `outer` (one array
  // for the combined excitation) and writes Π + Π'' per race (TVDS). Outer race: φ_j = θ_j,
  // reference θ_0; inner race: φ_j = θ_j − ω_i t.
  template <class Frame>
  void add_waviness(const Frame& fr, double* inner, double* outer, double* curv_i,
                    double* curv_o) const {
    const double c0 = fr.cos_theta[0], s0 = fr.sin_theta[0];
    outer_.evaluate(c0, s0, table_cos_.data(), table_sin_.data(), outer, curv_o);
    const double ci = c0 * fr.cos_shaft + s0 * fr.sin_shaft;
    const double si = s0 * fr.cos_shaft - c0 * fr.sin_shaft;
    inner_.evaluate(ci, si, table_cos_.data(), table_sin_.data(), inner, curv_i);
  }

  // K^{−2/3} of a ball on each race with TVDS, from the race's Π + Π'' at the contact.
  double inner_compliance(double curv) const {
    return inner_stiffness_.varies ? inner_stiffness_.compliance(curv) : inner_stiffness_.k0;
  }
  double outer_compliance(double curv) const {
    return outer_stiffness_.varies ? outer_stiffness_.compliance(curv) : outer_stiffness_.k0;
  }

  void setup_tvds(const ModelInputs& in) {
    validate_tvds_contact(in);
    const std::unique_ptr<HertzSolution> method = make_hertz_solution(in.hertz_method);
    inner_stiffness_ = race_stiffness(in, Race::inner, in.inner_waviness, *method);
    outer_stiffness_ = race_stiffness(in, Race::outer, in.outer_waviness, *method);
  }

  int balls_;
  double cage_speed_;
  double inner_speed_;
  DefectExcitation defects_;
  bool needs_shaft_;
  double K_;
  double exponent_;
  double cage_phase_;
  ContactKernels kernels_;
  double inner_K_;
  double outer_K_;
  double outer_exponent_;
  Waviness inner_waviness_, outer_waviness_;  // for rates(): direct sums
  std::vector<double> base_cos_, base_sin_, size_error_;
  std::vector<double> table_cos_, table_sin_;
  RaceExcitation inner_, outer_;
  RaceStiffness inner_stiffness_, outer_stiffness_;
  std::shared_ptr<const SlipPath> slip_;  // the random slip's path; null: none (shared: copies
                                          // of the set, e.g. a housed model's, share one path)
};

}  // namespace bearing::detail
