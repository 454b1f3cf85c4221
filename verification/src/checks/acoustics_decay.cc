// Decay with distance in the far field (docs/model.md §8): a ball's field as 1/r from the ball (not
// from the bearing centre: microphones are placed from the centre, distances are taken from each
// source), the ring's as 1/√r towards the large-argument asymptote of H₁⁽²⁾. The 6308's ring and
// ball at 20 kHz, microphones 0.2–2 m from the centre.

#include <cmath>
#include <complex>
#include <string>
#include <vector>

#include <Eigen/Dense>

#include "../context.h"
#include "../families.h"
#include "acoustics_reference.h"
#include "acoustics_shared.h"
#include "bearing/acoustics/microphones.h"
#include "bearing/constants.h"
#include "check_util.h"

namespace bearing::verify {

namespace {

namespace ref = acoustic_reference;
using cd = std::complex<double>;

constexpr double kFrequency = 20000.0;             // Hz
constexpr int kPoints = 11;                        // microphones, geometric in R
constexpr double kNearest = 0.2, kFarthest = 2.0;  // from the bearing centre [m]

double distance(int i) {
  return kNearest * std::pow(kFarthest / kNearest, static_cast<double>(i) / (kPoints - 1));
}

double wavenumber() {
  return 2 * pi * kFrequency / ref::kSoundSpeed;
}

Figure level_figure(const std::string& name, const std::string& title, const std::string& label,
                    const std::vector<double>& r, const std::vector<double>& level,
                    const std::vector<double>& law, const std::string& law_label) {
  Figure fig;
  fig.name = name;
  fig.title = title;
  fig.x_label = "distance r [m]";
  fig.y_label = "SPL of a 1 m/s tone [dB re 20 µPa]";
  fig.log_x = true;
  fig.series = {{label, r, level, "marker"}, {law_label, r, law, "line"}};
  return fig;
}

// A 6308 ball (oscillating sphere, the default ball source) on the pitch circle at angle 0,
// microphones on its radial line at R from the bearing centre: the fitted exponent of |p|
// against the true distance R − d_m/2 from the ball.
Check ball_decay() {
  const Bearing b = preset("6308");
  const double a = 0.5 * b.ball_diameter, pitch_radius = 0.5 * b.pitch_diameter;
  const double x_min = wavenumber() * (kNearest - pitch_radius);
  Check c;
  c.id = "acoustics.decay.ball-sphere";
  c.family = "acoustics";
  c.reference = ReferenceKind::limit;
  c.compares =
      "value: exponent n of |p| ∝ d^n fitted to the toolkit's oscillating sphere (6308 ball, a = "
      "7.54 mm, 20 kHz) at microphones 0.2–2 m from the bearing centre on the ball's radius, d the "
      "true distance from the ball (ball_path); reference: −1, the far field of a sphere";
  c.quantity = "decay exponent";
  c.unit = "-";
  c.tolerance = absolute(
      1 / (x_min * x_min),
      "|h₁(x)| = √(1 + x²)/x² has the local exponent −1 − 1/(1 + x²): the fit departs from −1 by "
      "less than 1/(kd_min)² = " +
          fmt(1 / (x_min * x_min)) + " (kd_min = " + fmt(x_min) + ")");
  c.level = Level::quick;
  c.cost = 0.01;
  // Both move the microphones relative to the ball, not only away from the centre.
  c.catches = {"microphone-distance-x1.05", "pitch-diameter-x1.01"};
  c.measure = [=](const Context& ctx) {
    const Bearing tb = ctx.bearing("6308");
    const auto source = make_source("oscillating-sphere", a, ctx.air());
    std::vector<double> d, log_d, log_p, level, law;
    for (int i = 0; i < kPoints; ++i) {
      const Eigen::Vector2d at = microphone_position(ctx.microphone(distance(i), 0.0));
      const SourcePath path = ball_path(at, 0.5 * tb.pitch_diameter, 0.0, 0.0, {0.0}, {0.0});
      const cd p = source->transfer(2 * pi * kFrequency, path.distance[0], path.cos_angle[0]);
      d.push_back(distance(i) - pitch_radius);
      log_d.push_back(std::log(d.back()));
      log_p.push_back(std::log(std::abs(p)));
      level.push_back(tone_level(p));
    }
    const double ka = wavenumber() * a;
    for (double di : d)  // the far field of the reference: |h₁(x)| → 1/x
      law.push_back(tone_level(ref::kImpedance / (di * wavenumber()) /
                               std::abs(ref::spherical_hankel_derivative(1, ka))));
    Outcome o{least_squares_slope(log_d, log_p),
              -1.0,
              "kd = " + fmt(wavenumber() * d.front()) + " … " + fmt(wavenumber() * d.back()),
              {}};
    o.figures.push_back(level_figure("acoustics-decay-ball",
                                     "6308 ball (oscillating sphere) at 20 kHz, on its radius",
                                     "toolkit", d, level, law, "far field ρ₀c₀/(kd |h₁'(ka)|)"));
    o.figures.back().x_label = "distance d from the ball [m]";
    return o;
  };
  return c;
}

// The 6308 ring (cylinder dipole) at the centre: the toolkit's level against the 1/√r law
// ρ₀c₀ |cos ψ| √(2/(πkr)) / |H₁'(ka)| (H₁' from the check's quadrature).
Check ring_decay() {
  const Bearing b = preset("6308");
  const double a = 0.5 * (b.pitch_diameter - b.ball_diameter);
  const double x_min = wavenumber() * kNearest;
  const double bound = 10 * std::log10(1 + 3 / (8 * x_min * x_min));
  Check c;
  c.id = "acoustics.decay.ring-cylinder";
  c.family = "acoustics";
  c.reference = ReferenceKind::limit;
  c.compares =
      "value: largest |L − L_∞| over microphones 0.2–2 m, L the toolkit's cylinder dipole (6308 "
      "ring, a = 24.96 mm, 20 kHz, ψ = 30°); reference: 0, L_∞ the 1/√r far-field law ρ₀c₀ cos ψ "
      "√(2/(πkr))/|H₁'(ka)| (the fitted exponent is in the detail)";
  c.quantity = "max |L − L_∞|";
  c.unit = "dB";
  c.tolerance = absolute(
      bound,
      "|H₁(x)|² = (2/(πx))(1 + 3/(8x²) − 45/(128x⁴) + …) (Nicholson's asymptotic series, "
      "A&S 9.2.28; for ν > 1/2 the remainder is smaller than the first neglected term, Watson "
      "§13.75): |L − L_∞| ≤ 10 log₁₀(1 + 3/(8x²)) = " +
          fmt(bound) + " dB at x = kr_min = " + fmt(x_min));
  c.level = Level::quick;
  c.cost = 0.05;
  c.catches = {"sound-speed-x1.02", "microphone-distance-x1.05"};
  c.measure = [=](const Context& ctx) {
    const auto source = make_source("cylinder-dipole", a, ctx.air());
    const double k = wavenumber(), psi = pi / 6;
    const double far = ref::kImpedance * std::cos(psi) / std::abs(ref::hankel_derivative(1, k * a));
    std::vector<double> r, log_r, log_p, level, law;
    double worst = 0;
    for (int i = 0; i < kPoints; ++i) {
      const Microphone m = ctx.microphone(distance(i), psi);
      const cd p = source->transfer(2 * pi * kFrequency, m.radius, std::cos(psi));
      r.push_back(distance(i));
      log_r.push_back(std::log(r.back()));
      log_p.push_back(std::log(std::abs(p)));
      level.push_back(tone_level(p));
      law.push_back(tone_level(far * std::sqrt(2 / (pi * k * r.back()))));
      worst = std::max(worst, std::abs(level.back() - law.back()));
    }
    Outcome o{worst,
              0.0,
              "fitted exponent of |p| ∝ r^n: n = " + fmt(least_squares_slope(log_r, log_p)) +
                  " (far field −1/2); kr = " + fmt(k * r.front()) + " … " + fmt(k * r.back()),
              {}};
    o.figures.push_back(level_figure("acoustics-decay-ring",
                                     "6308 ring (cylinder dipole) at 20 kHz, ψ = 30°", "toolkit", r,
                                     level, law, "far field 1/√r (Hankel asymptote)"));
    return o;
  };
  return c;
}

}  // namespace

std::vector<Check> acoustics_decay_checks() {
  return {ball_decay(), ring_decay()};
}

}  // namespace bearing::verify
