#pragma once
// Private to the lumped models (not installed): the local defects ([[defects]], local_defect.h)
// at the balls — each defect lowers the excitation of the contact that is over it by its drop,
// e → e − drop(u), on the inner or the outer contact of the ball (a race defect: the contact on
// that race; a ball defect: the ball's contact on either race), so every model that reads the
// ball set's excitation (2-DOF, 3-DOF, ball DOFs) sees them. The contact constants K stay those
// of the intact surfaces.
//
// Where the contact is on the defect (local_defect.h): race defects from the ball angle θ_j
// relative to the defect's angle (housing-fixed φ_d for the outer race, φ_d + ω_i t for the inner
// race); ball defects from the ball's rolling spin ψ = ψ₀ + ω_s t (kinematic, also in the
// ball-DOF model, whose spin DOF stays cyclic: the defect turns at the rolling spin, not at the
// DOF's, which departs from it by the traction's sliding). In the hot loop each race defect costs
// one rotated phasor per ball (cos(θ_j − φ_d) against cos(w/2ρ) rejects the balls away from it);
// only a ball over the defect takes an atan2.

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
        balls_.push_back(bd);
        continue;
      }
      const bool inner = d.location == DefectLocation::inner;
      RaceDefect rd{inner,
                    DefectPath(b, d, inner ? Race::inner : Race::outer),
                    std::cos(d.position),
                    std::sin(d.position),
                    d.position,
                    inner ? cage_speed - in.inner_speed : cage_speed,
                    0.0,
                    0.0};
      rd.half_angle = 0.5 * d.width / rd.path.surface_radius();
      rd.cos_half = std::cos(rd.half_angle);
      races_.push_back(rd);
    }
  }

  bool empty() const { return races_.empty() && balls_.empty(); }
  /// Whether a defect turns with the shaft (the ball set must then track the shaft angle).
  bool turns_with_shaft() const {
    for (const RaceDefect& d : races_)
      if (d.inner) return true;
    return false;
  }

  /// Subtracts the drops at time t [s] from inner[j] and outer[j], the excitations of ball j's
  /// inner and outer contact [m] (one array for both: the ball's combined excitation), with the
  /// ball and shaft phasors of `fr` (BallFrame or RaceFrame).
  template <class Frame>
  void apply(double t, const Frame& fr, double* inner, double* outer) const {
    for (const RaceDefect& d : races_) {
      double cd = d.cos, sd = d.sin;  // the defect's direction now
      if (d.inner) {
        cd = d.cos * fr.cos_shaft - d.sin * fr.sin_shaft;
        sd = d.sin * fr.cos_shaft + d.cos * fr.sin_shaft;
      }
      double* e = d.inner ? inner : outer;
      for (int j = 0; j < count_; ++j) {
        const double c = fr.cos_theta[j] * cd + fr.sin_theta[j] * sd;  // cos(θ_j − φ)
        if (c <= d.cos_half) continue;
        const double s = fr.sin_theta[j] * cd - fr.cos_theta[j] * sd;
        e[j] -= d.path.drop(d.path.surface_radius() * std::atan2(s, c) + 0.5 * d.path.width());
      }
    }
    for (const BallDefect& d : balls_) {
      const double psi = d.position + d.spin * t;
      outer[d.ball] -= d.at(d.outer, psi).drop;
      inner[d.ball] -= d.at(d.inner, psi - pi).drop;
    }
  }

  /// The drops and their rates at ball j, angle θ_j [rad], shaft angle ω_i t [rad], time t [s]
  /// (for output instants: libm, no phasors).
  void at_ball(int j, double theta, double shaft_angle, double t, DefectDrop& inner,
               DefectDrop& outer) const {
    inner = outer = DefectDrop{};
    for (const RaceDefect& d : races_) {
      const double delta =
          std::remainder(theta - d.position - (d.inner ? shaft_angle : 0.0), two_pi);
      if (std::abs(delta) >= d.half_angle) continue;
      const double r = d.path.surface_radius(), u = r * delta + 0.5 * d.path.width();
      DefectDrop& out = d.inner ? inner : outer;
      out.drop += d.path.drop(u);
      out.rate += d.path.slope(u) * r * d.relative_speed;
    }
    for (const BallDefect& d : balls_) {
      if (d.ball != j) continue;
      const double psi = d.position + d.spin * t;
      const DefectDrop o = d.at(d.outer, psi), i = d.at(d.inner, psi - pi);
      outer.drop += o.drop, outer.rate += o.rate;
      inner.drop += i.drop, inner.rate += i.rate;
    }
  }

 private:
  struct RaceDefect {
    bool inner;
    DefectPath path;
    double cos, sin, position;  // φ_d [rad]
    double relative_speed;      // dΔ/dt of the ball relative to the defect [rad/s]
    double half_angle, cos_half;
  };
  struct BallDefect {
    int ball;
    double position, spin;  // ψ₀ [rad], ω_s [rad/s]
    DefectPath inner, outer;
    double half_angle;
    // The drop at the contact `psi` [rad] of the ball's turn past it.
    DefectDrop at(const DefectPath& path, double psi) const {
      const double delta = std::remainder(psi, two_pi);
      if (std::abs(delta) >= half_angle) return {};
      const double r = path.surface_radius(), u = r * delta + 0.5 * path.width();
      return {path.drop(u), path.slope(u) * r * spin};
    }
  };

  int count_ = 0;  // Z
  std::vector<RaceDefect> races_;
  std::vector<BallDefect> balls_;
};

}  // namespace bearing::detail
