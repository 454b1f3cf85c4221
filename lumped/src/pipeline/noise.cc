// The bearing's sound at its microphones (noise.h).

#include "bearing/noise.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>

#include "bearing/acoustics/microphones.h"
#include "bearing/acoustics/pressure.h"
#include "bearing/acoustics/sources.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

std::string microphone_key(std::size_t i) {
  return "acoustics.microphones[" + std::to_string(i) + "]";
}

// A length in millimetres with 4 significant digits, for messages.
std::string mm(double metres) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g mm", metres * 1e3);
  return buf;
}

std::string shown(const Microphone& m) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g deg", m.angle * 180 / pi);
  return "[" + mm(m.radius) + ", " + buf + "]";
}

// The analysis window of a channel and the sample after it (at t = duration): what the
// pressure filters need to take out the record's trend (pressure.h).
std::vector<double> window_and_next(const Response& r, const std::string& name) {
  const auto& v = r.channel(name);
  return std::vector<double>(v.begin() + static_cast<std::ptrdiff_t>(r.first_steady), v.end());
}

double mean(const std::vector<double>& x) {
  double s = 0;
  for (double v : x) s += v;
  return x.empty() ? 0.0 : s / static_cast<double>(x.size());
}

std::optional<double> level(double p_rms, bool present) {
  if (!present || !(p_rms > 0)) return std::nullopt;
  return sound_pressure_level(p_rms);
}

}  // namespace

BearingNoise radiate(const Response& response, const AcousticsOptions& ac, const Bearing& bearing,
                     const RunKinematics& kinematics) {
  if (!ac.enabled) throw InputError("acoustics: the case has no [acoustics] table");
  const Air air{ac.density, ac.sound_speed};
  const Summation summation = ac.summation;
  const double rate = response.rate;
  const double cage_speed = kinematics.cage_speed;

  BearingNoise out;
  out.time.assign(response.time.begin() + static_cast<std::ptrdiff_t>(response.first_steady),
                  response.time.end() - 1);
  const std::size_t n = out.time.size();
  RealFft fft(n);
  out.band_low = rate / static_cast<double>(n);
  out.band_high = kPressureBandFraction * rate / 2;

  const bool ring_on = ac.ring_source != RingSource::none;
  const bool balls_on = ac.ball_source != BallSource::none;
  std::unique_ptr<AcousticSource> ring;
  std::vector<double> vx, vy;
  if (ring_on) {
    ring = make_source(source_model_name(ac.ring_source), ac.ring_radius, air,
                       "acoustics.ring_source");
    vx = window_and_next(response, "vx");
    vy = window_and_next(response, "vy");
    out.ring_centre = {mean(response.steady("x")), mean(response.steady("y"))};
  }
  std::unique_ptr<RadialSeriesSource> ball;
  std::optional<PeriodicInterpolator> interpolator;  // the balls' delays, one table for all
  const int Z = bearing.balls;
  std::vector<std::vector<double>> radial;
  std::vector<FilteredRecord> filtered;  // each ball's, for every microphone
  std::vector<BallOrbit> orbits;         // likewise
  SourcePath path;                       // one ball's, seen from one microphone
  std::vector<std::vector<double>> each(
      static_cast<std::size_t>(balls_on ? Z : 0));  // ball pressures
  if (balls_on) {
    ball = make_series_source(source_model_name(ac.ball_source), 0.5 * bearing.ball_diameter, air,
                              "acoustics.ball_source");
    interpolator.emplace();
    // The cage's random slip over the analysed samples (empty without).
    std::vector<double> slip;
    if (!response.cage_slip.empty())
      slip.assign(response.cage_slip.begin() + static_cast<std::ptrdiff_t>(response.first_steady),
                  response.cage_slip.end() - 1);
    const SeriesFactors factors(*ball, rate, n);  // F_m(ω_k): the balls are alike
    for (int j = 0; j < Z; ++j) {
      radial.push_back(response.steady("r" + std::to_string(j + 1)));
      filtered.push_back(
          filter_moving(factors, window_and_next(response, "vr" + std::to_string(j + 1)), fft));
      // Ball j is ball 1 turned by 2πj/Z: its sines and cosines by rotation.
      orbits.push_back(j == 0 ? ball_orbit(0.0, cage_speed, out.time, slip)
                              : rotate_orbit(orbits.front(), 2 * pi * j / Z));
    }
  }

  // The ring at every microphone at once (its Hankel functions of ka once per frequency).
  std::vector<std::vector<double>> p_rings;
  if (ring_on) {
    std::vector<std::vector<double>> un;
    std::vector<double> distance;
    for (std::size_t i = 0; i < ac.microphones.size(); ++i) {
      const Microphone& mic = ac.microphones[i];
      const Eigen::Vector2d d = microphone_position(mic) - out.ring_centre;
      const double r = d.norm();
      if (!(r > ring->radius()))
        throw InputError(microphone_key(i) + " = " + shown(mic) + ": the microphone is " + mm(r) +
                         " from the ring centre, inside the ring "
                         "source of radius acoustics.ring_radius = " +
                         mm(ring->radius()) + "; it must lie outside it");
      // The dipole's pattern is linear in the velocity: p = H(r, cos ψ = 1) · (v · d/r).
      un.emplace_back(n + 1);
      for (std::size_t k = 0; k <= n; ++k) un.back()[k] = (vx[k] * d.x() + vy[k] * d.y()) / r;
      distance.push_back(r);
    }
    p_rings = radiate_fixed(*ring, un, rate, distance, std::vector<double>(un.size(), 1.0), fft);
  }

  for (std::size_t i = 0; i < ac.microphones.size(); ++i) {
    const Microphone& mic = ac.microphones[i];
    MicrophoneLevels lv;
    lv.microphone = mic;
    lv.position = microphone_position(mic);

    std::vector<double> p_ring(n, 0.0);
    if (ring_on) {
      p_ring = std::move(p_rings[i]);
      lv.p_rms_ring = root_mean_square(p_ring);
    }

    std::vector<double> p_balls(n, 0.0);
    if (balls_on) {
      double nearest = std::numeric_limits<double>::infinity();
      const double a = ball->radius();
      for (int j = 0; j < Z; ++j) {
        ball_path(lv.position, 0.5 * bearing.pitch_diameter, orbits[j], radial[j], path);
        const auto closest = std::min_element(path.distance.begin(), path.distance.end());
        if (*closest <= a) {
          const auto k = static_cast<std::size_t>(closest - path.distance.begin());
          throw InputError(microphone_key(i) + " = " + shown(mic) +
                           ": the microphone is inside "
                           "ball " +
                           std::to_string(j + 1) + " at t = " + format_number(out.time[k]) +
                           " s (" + mm(*closest) + " from its centre, radius " + mm(a) +
                           "); the balls sweep radii " + mm(ball_annulus(bearing).x()) + " … " +
                           mm(ball_annulus(bearing).y()));
        }
        nearest = std::min(nearest, *closest - a);
        pressure_from(*ball, filtered[j], rate, path, *interpolator, each[j]);
      }
      p_balls = sum_pressures(each, summation);
      lv.p_rms_balls = root_mean_square(p_balls);
      lv.nearest_ball_surface = nearest;
    }

    std::vector<double> total = sum_pressures({p_ring, p_balls}, summation);
    lv.p_rms = root_mean_square(total);
    lv.spl_total = level(lv.p_rms, true);
    lv.spl_ring = level(lv.p_rms_ring, ring_on);
    lv.spl_balls = level(lv.p_rms_balls, balls_on);
    out.pressure.push_back(std::move(total));
    out.microphones.push_back(lv);
  }
  return out;
}

}  // namespace bearing
