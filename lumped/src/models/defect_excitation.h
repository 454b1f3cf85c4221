#pragma once
// Private to the lumped models (not installed): the local defects ([[defects]], local_defect.h)
// at the balls — each defect lowers the excitation of the contact that is over it by its drop,
// e → e − drop(u), on the inner or the outer contact of the ball (a race defect: the contact on
// that race; a ball defect: the ball's contact on either race), so every model that reads the
// ball set's excitation (2-DOF, 3-DOF, ball DOFs) sees them. The contact constants K stay those
// of the intact surfaces.
//
// Where the contact is on the defect (local_defect.h): race defects from the ball angles
// θ_j = φ₀ + 2πj/Z + ω_c t relative to the defect's angle (housing-fixed φ_d for the outer race,
// φ_d + ω_i t for the inner race); ball defects from the ball's rolling spin ψ = ψ₀ + ω_s t
// (kinematic, also in the ball-DOF model, whose spin DOF stays cyclic: the defect turns at the
// rolling spin, not at the DOF's, which departs from it by the traction's sliding). With random
// slip (random_slip.h) the cage angle gains φ(t), and the spin follows it as a ball rolling on
// the outer race does: ψ = ψ₀ + ω_s (t + φ(t)/ω_c).
//
// Cost: the balls are evenly spaced, so the ball nearest a race defect is found from one angle,
// x = φ₀ − φ_d + (ω_c [− ω_i]) t: with k the integer nearest x/(2π/Z), the ball m − k (mod Z) is at
// x − k·2π/Z + m·2π/Z from the defect, and only m = 0 (± 1 for a defect wider than half a ball
// spacing) can be over it. A few flops per defect and instant, whatever Z.

#include <cmath>
#include <vector>

#include "bearing/constants.h"
#include "bearing/local_defect.h"
#include "bearing/models/model_inputs.h"

namespace bearing::detail {

/// One contact's drop and its rate at one instant.
struct DefectDrop {
  double drop = 0;  ///< [m]
  double rate = 0;  ///< d drop/dt [m/s]
};

class DefectExcitation {
 public:
  DefectExcitation() = default;
  /// `cage_speed` ω_c and `contact_angle` [rad/s, rad] are the model's kinematics.
  DefectExcitation(const ModelInputs& in, double cage_speed, double contact_angle) {
    const Bearing& b = in.bearing;
    check_defects(in.defects, b);
    count_ = b.balls;
    for (const LocalDefect& d : in.defects) {
      if (d.location == DefectLocation::ball) {
        BallDefect bd{d.ball,
                      d.position,
                      ball_spin_speed(b, cage_speed, contact_angle),
                      DefectPath(b, d, Race::inner),
                      DefectPath(b, d, Race::outer),
                      0.0};
        bd.half_angle = 0.5 * d.width / bd.outer.surface_radius();
        bd.spin_per_cage = cage_speed != 0.0 ? bd.spin / cage_speed : 0.0;
        balls_.push_back(bd);
        continue;
      }
      const bool inner = d.location == DefectLocation::inner;
      RaceDefect rd{inner, DefectPath(b, d, inner ? Race::inner : Race::outer), d.position,
                    in.cage_phase - d.position, inner ? cage_speed - in.inner_speed : cage_speed};
      rd.half_angle = 0.5 * d.width / rd.path.surface_radius();
      rd.spacing = two_pi / b.balls;
      rd.reach = static_cast<int>(std::ceil(rd.half_angle / rd.spacing - 0.5));
      races_.push_back(rd);
    }
  }

  bool empty() const { return races_.empty() && balls_.empty(); }

  /// Subtracts the drops at time t [s] from inner[j] and outer[j], the excitations of ball j's
  /// inner and outer contact [m] (one array for both: the ball's combined excitation); `slip`:
  /// the random slip's cage angle φ(t) [rad] (random_slip.h), which the balls' angles and spins
  /// carry too.
  void apply(double t, double slip, double* inner, double* outer) const {
    for (const RaceDefect& d : races_) {
      double x = d.phase + d.relative_speed * t;
      if (slip != 0.0) x += slip;
      // k = round(x / spacing) by the 1.5·2^52 shifter (std::nearbyint is a libm call here)
      constexpr double kShifter = 6755399441055744.0;
      const double k = (x / d.spacing + kShifter) - kShifter;
      const double r0 = x - k * d.spacing;
      double* e = d.inner ? inner : outer;
      for (int m = -d.reach; m <= d.reach; ++m) {
        const double r = r0 + m * d.spacing;
        if (std::abs(r) >= d.half_angle) continue;
        long long j = (static_cast<long long>(m) - static_cast<long long>(k)) % count_;
        if (j < 0) j += count_;
        e[j] -= d.path.drop(d.path.surface_radius() * r + 0.5 * d.path.width());
      }
    }
    for (const BallDefect& d : balls_) {
      double psi = d.position + d.spin * t;
      if (slip != 0.0) psi += d.spin_per_cage * slip;
      outer[d.ball] -= d.at(d.outer, psi).drop;
      inner[d.ball] -= d.at(d.inner, psi - pi).drop;
    }
  }

  /// The drops and their rates at ball j, angle θ_j [rad] (the slip's included), shaft angle
  /// ω_i t [rad], time t [s], the random slip's φ(t) [rad] and φ̇(t) [rad/s] (for output
  /// instants: libm, no phasors).
  void at_ball(int j, double theta, double shaft_angle, double t, double slip, double slip_rate,
               DefectDrop& inner, DefectDrop& outer) const {
    inner = outer = DefectDrop{};
    for (const RaceDefect& d : races_) {
      const double delta =
          std::remainder(theta - d.position - (d.inner ? shaft_angle : 0.0), two_pi);
      if (std::abs(delta) >= d.half_angle) continue;
      const double r = d.path.surface_radius(), u = r * delta + 0.5 * d.path.width();
      DefectDrop& out = d.inner ? inner : outer;
      out.drop += d.path.drop(u);
      out.rate += d.path.slope(u) * r * (d.relative_speed + slip_rate);
    }
    for (const BallDefect& d : balls_) {
      if (d.ball != j) continue;
      const double psi = d.position + d.spin * t + d.spin_per_cage * slip;
      const double spin = d.spin + d.spin_per_cage * slip_rate;
      const DefectDrop o = d.at(d.outer, psi, spin), i = d.at(d.inner, psi - pi, spin);
      outer.drop += o.drop, outer.rate += o.rate;
      inner.drop += i.drop, inner.rate += i.rate;
    }
  }

 private:
  struct RaceDefect {
    bool inner;
    DefectPath path;
    double position;        // φ_d [rad]
    double phase;           // φ₀ − φ_d [rad]
    double relative_speed;  // dx/dt: ω_c, or ω_c − ω_i on the inner race [rad/s]
    double half_angle = 0, spacing = 0;
    int reach = 0;  // the neighbours of the nearest ball that can be over the defect
  };
  struct BallDefect {
    int ball;
    double position, spin;  // ψ₀ [rad], ω_s [rad/s]
    DefectPath inner, outer;
    double half_angle;
    double spin_per_cage = 0;  // ω_s/ω_c: the spin follows the cage's slip (random_slip.h)
    // The drop at the contact `psi` [rad] of the ball's turn past it, turning at `speed` [rad/s].
    DefectDrop at(const DefectPath& path, double psi, double speed) const {
      const double delta = std::remainder(psi, two_pi);
      if (std::abs(delta) >= half_angle) return {};
      const double r = path.surface_radius(), u = r * delta + 0.5 * path.width();
      return {path.drop(u), path.slope(u) * r * speed};
    }
    DefectDrop at(const DefectPath& path, double psi) const { return at(path, psi, spin); }
  };

  int count_ = 0;  // Z
  std::vector<RaceDefect> races_;
  std::vector<BallDefect> balls_;
};

}  // namespace bearing::detail
