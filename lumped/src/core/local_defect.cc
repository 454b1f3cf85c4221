#include "bearing/local_defect.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

void check_size(const std::string& key, double value) {
  if (!(std::isfinite(value) && value >= 0))
    throw InputError(key + " = " + format_number(value) + " m: must be finite and not negative");
}

// The pivot geometry of the header: the slotted surface (radius r_s, sign σ_s) and the body
// rolling over it (r_p, σ_p); σ = +1 convex, −1 concave.
struct Pivot {
  double r_s, sigma_s, r_p, sigma_p, depth;

  double drop(double phi) const {
    const double a = r_s * std::sin(phi);
    if (a >= r_p) return depth;  // the ball reaches the floor
    return std::min(std::max(sag(a, phi), 0.0), depth);
  }
  // Without cancellation: r − √(r² − a²) = a²/(r + √(r² − a²)), 1 − cos φ = 2 sin²(φ/2).
  double sag(double a, double phi) const {
    const double half = std::sin(0.5 * phi);
    return sigma_p * a * a / (r_p + std::sqrt(r_p * r_p - a * a)) + sigma_s * 2 * r_s * half * half;
  }
  double slope(double phi) const {
    const double a = r_s * std::sin(phi);
    if (a >= r_p) return 0.0;
    const double root = std::sqrt(r_p * r_p - a * a), s = sag(a, phi);
    if (s <= 0 || s >= depth) return 0.0;
    return sigma_p * a * r_s * std::cos(phi) / root + sigma_s * r_s * std::sin(phi);
  }
};

double race_radius(const Bearing& b, Race race) {
  return 0.5 * (race == Race::inner ? b.inner_raceway_diameter() : b.outer_raceway_diameter());
}

double sign_of(Race race) {
  return race == Race::inner ? 1.0 : -1.0;  // the inner race is convex, the outer concave
}

}  // namespace

void check_defects(const std::vector<LocalDefect>& defects, const Bearing& b) {
  const double D = b.ball_diameter;
  for (std::size_t i = 0; i < defects.size(); ++i) {
    const LocalDefect& d = defects[i];
    const std::string key = "defects[" + std::to_string(i) + "].";
    if (!(d.width > 0 && d.width <= D))
      throw InputError(key + "width = " + format_quantity(d.width, "mm", Dimension::length) +
                       ": must lie in (0, D = " + format_quantity(D, "mm", Dimension::length) +
                       "] (a spall longer than the ball is a damaged band, not a local defect)");
    if (!(d.depth > 0 && d.depth <= 0.25 * D))
      throw InputError(
          key + "depth = " + format_quantity(d.depth, "mm", Dimension::length) +
          ": must lie in (0, D/4 = " + format_quantity(0.25 * D, "mm", Dimension::length) + "]");
    if (!std::isfinite(d.position))
      throw InputError(key + "position = " + format_number(d.position) + " rad: must be finite");
    if (d.location == DefectLocation::ball && !(d.ball >= 0 && d.ball < b.balls))
      throw InputError(key + "ball = " + std::to_string(d.ball) + ": must lie in [0, " +
                       std::to_string(b.balls - 1) +
                       "] (bearing.balls = " + std::to_string(b.balls) + ")");
  }
}

double defect_surface_radius(const LocalDefect& d, const Bearing& b) {
  switch (d.location) {
    case DefectLocation::outer:
      return race_radius(b, Race::outer);
    case DefectLocation::inner:
      return race_radius(b, Race::inner);
    case DefectLocation::ball:
      break;
  }
  return 0.5 * b.ball_diameter;
}

DefectPath::DefectPath(const Bearing& b, const LocalDefect& d, Race contact)
    : width_(d.width), depth_(d.depth), profile_(d.profile) {
  check_defects({d}, b);
  const double R = 0.5 * b.ball_diameter;
  if (d.location == DefectLocation::ball) {
    surface_ = R, surface_sign_ = 1.0;
    pivot_radius_ = race_radius(b, contact), pivot_sign_ = sign_of(contact);
  } else {
    const Race race = d.location == DefectLocation::inner ? Race::inner : Race::outer;
    if (race != contact)
      throw std::logic_error("DefectPath: a race defect seen from the other race");
    surface_ = race_radius(b, race), surface_sign_ = sign_of(race);
    pivot_radius_ = R, pivot_sign_ = 1.0;
  }
  max_drop_ = pivot(0.5 * width_ / surface_);
}

double DefectPath::pivot(double phi) const {
  return Pivot{surface_, surface_sign_, pivot_radius_, pivot_sign_, depth_}.drop(phi);
}

double DefectPath::pivot_slope(double phi) const {
  return Pivot{surface_, surface_sign_, pivot_radius_, pivot_sign_, depth_}.slope(phi);
}

double DefectPath::drop(double u) const {
  if (!(u > 0 && u < width_)) return 0.0;
  if (profile_ == DefectProfile::smooth) return max_drop_ * std::sin(pi * u / width_);
  return pivot(std::min(u, width_ - u) / surface_);  // s grows with φ: the nearer edge holds
}

double DefectPath::slope(double u) const {
  if (!(u >= 0 && u < width_)) return 0.0;
  if (profile_ == DefectProfile::smooth) return max_drop_ * pi / width_ * std::cos(pi * u / width_);
  if (u < 0.5 * width_) return pivot_slope(u / surface_) / surface_;
  return -pivot_slope((width_ - u) / surface_) / surface_;
}

double ball_spin_speed(const Bearing& b, double cage_speed, double contact_angle) {
  const double g = b.ball_diameter * std::cos(contact_angle) / b.pitch_diameter;
  return b.pitch_diameter / b.ball_diameter * (1.0 + g) * cage_speed;
}

double defect_transit_time(const LocalDefect& d, const Bearing& b, double inner_speed,
                           double cage_speed, double contact_angle) {
  double speed = 0;  // of the contact point along the slotted surface [m/s]
  switch (d.location) {
    case DefectLocation::outer:
      speed = std::abs(cage_speed) * race_radius(b, Race::outer);
      break;
    case DefectLocation::inner:
      speed = std::abs(inner_speed - cage_speed) * race_radius(b, Race::inner);
      break;
    case DefectLocation::ball:
      speed = std::abs(ball_spin_speed(b, cage_speed, contact_angle)) * 0.5 * b.ball_diameter;
      break;
  }
  return speed > 0 ? d.width / speed : std::numeric_limits<double>::infinity();
}

double defect_drop(double ball_diameter, Race race, double race_radius, double width, double depth,
                   double u) {
  check_size("bearing.ball_diameter", ball_diameter);
  check_size("race radius", race_radius);
  check_size("defects.width", width);
  check_size("defects.depth", depth);
  if (race == Race::outer && !(race_radius > 0.5 * ball_diameter))
    throw InputError("race radius = " + format_number(race_radius) +
                     " m: an outer race must be larger than the ball (D/2 = " +
                     format_number(0.5 * ball_diameter) + " m)");
  if (!(u > 0 && u < width)) return 0.0;
  const Pivot p{race_radius, sign_of(race), 0.5 * ball_diameter, 1.0, depth};
  return p.drop(std::min(u, width - u) / race_radius);
}

double defect_max_drop(double ball_diameter, Race race, double race_radius, double width,
                       double depth) {
  if (width <= 0) {
    defect_drop(ball_diameter, race, race_radius, width, depth, 0.0);  // the checks
    return 0.0;
  }
  return defect_drop(ball_diameter, race, race_radius, width, depth, 0.5 * width);
}

}  // namespace bearing
