// Microphone positions and the sources' paths seen from them.

#include "bearing/acoustics/microphones.h"

#include <cmath>
#include <string>

#include "bearing/errors.h"
#include "bearing/target_clones.h"

namespace bearing {

Eigen::Vector2d microphone_position(const Microphone& m) {
  return m.radius * Eigen::Vector2d(std::cos(m.angle), std::sin(m.angle));
}

SourcePath ball_path(const Eigen::Vector2d& at, double pitch_radius, double theta0,
                     double cage_speed, const std::vector<double>& times,
                     const std::vector<double>& radial) {
  if (times.size() != radial.size())
    throw InputError("ball path: " + std::to_string(times.size()) + " times and " +
                     std::to_string(radial.size()) + " radial positions");
  SourcePath path;
  ball_path(at, pitch_radius, ball_orbit(theta0, cage_speed, times), radial, path);
  return path;
}

BallOrbit ball_orbit(double theta0, double cage_speed, const std::vector<double>& times,
                     const std::vector<double>& slip) {
  if (!slip.empty() && slip.size() != times.size())
    throw InputError("ball orbit: " + std::to_string(times.size()) + " times and " +
                     std::to_string(slip.size()) + " slip angles");
  BallOrbit o;
  o.cos.resize(times.size());
  o.sin.resize(times.size());
  for (std::size_t n = 0; n < times.size(); ++n) {
    double theta = theta0 + cage_speed * times[n];
    if (!slip.empty()) theta += slip[n];
    o.cos[n] = std::cos(theta);
    o.sin[n] = std::sin(theta);
  }
  return o;
}

BallOrbit rotate_orbit(const BallOrbit& orbit, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  BallOrbit o;
  o.cos.resize(orbit.cos.size());
  o.sin.resize(orbit.sin.size());
  for (std::size_t n = 0; n < orbit.cos.size(); ++n) {
    o.cos[n] = orbit.cos[n] * c - orbit.sin[n] * s;
    o.sin[n] = orbit.sin[n] * c + orbit.cos[n] * s;
  }
  return o;
}

namespace {

// d = at − (R + r_k) e_k, |d|, e_k · d / |d| for every sample, in the order Eigen's norm() and
// dot() use. Compiled per instruction set (bearing/target_clones.h; no fused multiply-adds on
// this file): square roots and divisions are correctly rounded in every one, so every clone gives
// the same bits.
BEARING_TARGET_CLONES void path_arrays(double ax, double ay, double pitch_radius, std::size_t n,
                                       const double* cosine, const double* sine,
                                       const double* radial, double* distance, double* cos_angle) {
  for (std::size_t k = 0; k < n; ++k) {
    const double c = cosine[k], s = sine[k], R = pitch_radius + radial[k];
    const double dx = ax - R * c, dy = ay - R * s;
    const double r = std::sqrt(dx * dx + dy * dy);
    distance[k] = r;
    cos_angle[k] = r > 0 ? (c * dx + s * dy) / r : 0.0;
  }
}

}  // namespace

void ball_path(const Eigen::Vector2d& at, double pitch_radius, const BallOrbit& orbit,
               const std::vector<double>& radial, SourcePath& path) {
  const std::size_t n = radial.size();
  if (orbit.cos.size() != n || orbit.sin.size() != n)
    throw InputError("ball path: an orbit of " + std::to_string(orbit.cos.size()) +
                     " samples and " + std::to_string(n) + " radial positions");
  path.distance.resize(n);
  path.cos_angle.resize(n);
  path_arrays(at.x(), at.y(), pitch_radius, n, orbit.cos.data(), orbit.sin.data(), radial.data(),
              path.distance.data(), path.cos_angle.data());
}

Eigen::Vector2d ball_annulus(const Bearing& b) {
  return {0.5 * (b.pitch_diameter - b.ball_diameter), 0.5 * (b.pitch_diameter + b.ball_diameter)};
}

}  // namespace bearing
