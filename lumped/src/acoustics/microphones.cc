// Microphone positions and the sources' paths seen from them.

#include "bearing/acoustics/microphones.h"

#include <cmath>

#include "bearing/errors.h"

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
  path.distance.resize(times.size());
  path.cos_angle.resize(times.size());
  for (std::size_t n = 0; n < times.size(); ++n) {
    const double theta = theta0 + cage_speed * times[n];
    const Eigen::Vector2d e(std::cos(theta), std::sin(theta));
    const Eigen::Vector2d d = at - (pitch_radius + radial[n]) * e;
    const double r = d.norm();
    path.distance[n] = r;
    path.cos_angle[n] = r > 0 ? e.dot(d) / r : 0.0;
  }
  return path;
}

Eigen::Vector2d ball_annulus(const Bearing& b) {
  return {0.5 * (b.pitch_diameter - b.ball_diameter), 0.5 * (b.pitch_diameter + b.ball_diameter)};
}

}  // namespace bearing
