#pragma once
// Where the microphones are, and where each source is as seen from one (docs/model.md §8: distances
// and angles from each source, not from the bearing centre).

#include <vector>

#include <Eigen/Dense>

#include "bearing/acoustics/acoustics_options.h"
#include "bearing/acoustics/pressure.h"
#include "bearing/bearing.h"

namespace bearing {

/// Position (x, y) of a microphone in the fixed frame, origin at the bearing centre [m].
Eigen::Vector2d microphone_position(const Microphone& microphone);

/// A ball's centre seen from the point `at` [m]: at sample n the ball is at angle
/// θ_n = theta0 + cage_speed · times[n] [rad] on the circle of radius pitch_radius + radial[n]
/// [m], vibrating along its radius e(θ_n) = (cos θ_n, sin θ_n). Distances [m] and cos ψ between
/// e(θ_n) and the direction from the ball to the point.
SourcePath ball_path(const Eigen::Vector2d& at, double pitch_radius, double theta0,
                     double cage_speed, const std::vector<double>& times,
                     const std::vector<double>& radial);

/// The part of a ball's path that does not depend on the point: its direction
/// e(θ_n) = (cos θ_n, sin θ_n), θ_n = theta0 + cage_speed · times[n] [rad]. One per ball serves
/// every microphone (the sines and cosines are most of a path's cost).
struct BallOrbit {
  std::vector<double> cos, sin;
};
/// With random slip (random_slip.h) the cage angle gains `slip`[n] [rad] at each sample (empty:
/// none).
BallOrbit ball_orbit(double theta0, double cage_speed, const std::vector<double>& times,
                     const std::vector<double>& slip = {});

/// The orbit of `orbit`'s ball turned by `angle` [rad] (θ_n + angle): each sine and cosine by
/// the angle-sum formulas, the same values as ball_orbit(theta0 + angle, …) to rounding, without
/// evaluating a sine or cosine per sample. The balls of one cage share one orbit so.
BallOrbit rotate_orbit(const BallOrbit& orbit, double angle);

/// ball_path from the ball's orbit, into `path` (its storage reused from call to call): the same
/// values, bit for bit.
void ball_path(const Eigen::Vector2d& at, double pitch_radius, const BallOrbit& orbit,
               const std::vector<double>& radial, SourcePath& path);

/// The radii [inner, outer] of the annulus the balls sweep, (d_m − D)/2 … (d_m + D)/2 [m]: a
/// microphone there would be inside a ball whenever one passes.
Eigen::Vector2d ball_annulus(const Bearing& bearing);

}  // namespace bearing
