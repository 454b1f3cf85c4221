// A case's operating point through the 5-DOF static solution (stiffness.h).

#include "bearing/stiffness.h"

#include <algorithm>

#include "bearing/errors.h"
#include "bearing/kinematics.h"
#include "bearing/simulation.h"

namespace bearing {

std::string stiffness_unit(int i, int j) {
  const bool moment = i >= 3, tilt = j >= 3;
  if (moment && tilt) return "N*m/rad";
  if (moment) return "N";  // N m per m
  return tilt ? "N/rad" : "N/m";
}

std::string stiffness_name(int i, int j) {
  const std::string a = kStiffnessDofs[i], b = kStiffnessDofs[j];
  return "k_" + a + (a.size() == 1 && b.size() == 1 ? "" : "_") + b;
}

namespace {

// Both from one mapping of the case (model_inputs computes the contact constants).
Vector5 load_of(const Case& c, const ModelInputs& in) {
  const Eigen::Vector2d radial = in.radial_load();
  Vector5 f;
  f << radial.x(), radial.y(), c.operation.axial_load, c.operation.moment.x(),
      c.operation.moment.y();
  return f;
}

// At the case's speed each ball carries its centrifugal load when ball.centrifugal is on (the
// default), so K changes with operation.speed; at rest, or with it off, it does not.
// With [lubricant], each contact's EHL film at the case's speed, the cage at its pure-rolling
// speed (ehl_film.h): at rest there is no entrainment, and the contacts stay dry.
FiveDofBearing bearing_of(const ModelInputs& in) {
  const double Fc = in.centrifugal ? ball_centrifugal_load(in.bearing, in.inner_speed) : 0.0;
  FiveDofBearing b = five_dof_bearing(in.bearing, in.contact, in.cage_phase, Fc);
  if (in.lubricated)
    add_films(b, ball_films(in.bearing, in.contact, in.lubricant, in.inner_speed,
                            cage_speed(in.bearing, in.inner_speed)));
  return b;
}

}  // namespace

Vector5 five_dof_load_of(const Case& c) {
  return load_of(c, model_inputs(c));
}

FiveDofBearing five_dof_bearing_of(const Case& c) {
  return bearing_of(model_inputs(c));
}

double StiffnessPoint::q_max() const {
  const auto& q = solution.at.ball_loads;
  return q.empty() ? 0.0 : *std::max_element(q.begin(), q.end());
}

double StiffnessPoint::outer_q_max() const {
  const auto& q = solution.at.outer_loads;
  return q.empty() ? 0.0 : *std::max_element(q.begin(), q.end());
}

int StiffnessPoint::loaded_balls() const {
  // δ_j > 0 as well: with a film every ball carries some load, and a ball counts where its Hertz
  // deflection exceeds its film (dry, Q_j > 0 implies δ_j > 0: the count is Q_j > 0's).
  const auto& q = solution.at.ball_loads;
  const auto& d = solution.at.approaches;
  int n = 0;
  for (std::size_t j = 0; j < q.size(); ++j) n += q[j] > 0 && d[j] > 0;
  return n;
}

bool StiffnessPoint::elastic() const {
  return !(std::max(inner_peak_pressure, outer_peak_pressure) > kElasticPressureLimit);
}

StiffnessPoint stiffness_point(const Case& c, int ball_pass_samples) {
  if (ball_pass_samples != 0 && (ball_pass_samples < 4 || ball_pass_samples > kMaxBallPassSamples))
    throw InputError("ball-pass samples = " + std::to_string(ball_pass_samples) +
                     ": allowed 4 to " + std::to_string(kMaxBallPassSamples) +
                     " cage angles a pitch, or 0 for none");
  const ModelInputs in = model_inputs(c);
  const FiveDofBearing b = bearing_of(in);
  StiffnessPoint p;
  p.load = load_of(c, in);
  p.cage_angle = b.phase;
  p.solution = solve_five_dof(b, p.load);
  // At speed the outer contacts carry the centrifugal load as well: each race's pressure from its
  // own largest load.
  p.inner_peak_pressure = in.contact.inner.peak_pressure(p.q_max());
  p.outer_peak_pressure = in.contact.outer.peak_pressure(p.outer_q_max());
  // The outer ring is fixed (ModelInputs::inner_speed): BPFO = Z f_c, the rate the cage turns
  // one pitch at.
  p.bpfo = bearing_frequencies(in.bearing, in.inner_speed).bpfo;
  if (ball_pass_samples > 0) {
    p.ball_pass = ball_pass_stiffness(b, p.load, ball_pass_samples);
    p.rotor = rotor_coefficients(*p.ball_pass);
  }
  return p;
}

}  // namespace bearing
