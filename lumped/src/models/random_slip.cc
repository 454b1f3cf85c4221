// The cage's random slip path (random_slip.h): the Ornstein–Uhlenbeck speed sampled exactly on its
// grid, and the angle error integrated from it.

#include "bearing/models/random_slip.h"

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/limits.h"
#include "bearing/units.h"

namespace bearing {

namespace {

// Standard normal deviates by the Box–Muller transform of two uniforms in (0, 1], written here so
// that a seed gives the same numbers with any standard library (its distributions' algorithms are
// unspecified; the engine's are specified).
class Normal {
 public:
  explicit Normal(std::uint64_t seed) : engine_(seed) {}
  double operator()() {
    if (has_spare_) {
      has_spare_ = false;
      return spare_;
    }
    // 53 random bits, shifted into (0, 1]: log() never sees 0.
    const double u1 = (static_cast<double>(engine_() >> 11) + 1.0) * 0x1.0p-53;
    const double u2 = static_cast<double>(engine_() >> 11) * 0x1.0p-53;
    const double r = std::sqrt(-2.0 * std::log(u1));
    spare_ = r * std::sin(two_pi * u2);
    has_spare_ = true;
    return r * std::cos(two_pi * u2);
  }

 private:
  std::mt19937_64 engine_;
  double spare_ = 0.0;
  bool has_spare_ = false;
};

}  // namespace

SlipPath::SlipPath(double rms, double correlation_time, int seed, double cage_speed, double end)
    : cage_speed_(cage_speed) {
  limits::slip_rms.check(rms);
  limits::slip_correlation_time.check(correlation_time);
  if (!(std::isfinite(end) && end >= 0.0))
    throw std::logic_error("SlipPath: the span's end must be finite and >= 0");
  step_ = correlation_time / kStepsPerCorrelationTime;
  inv_step_ = 1.0 / step_;
  end_ = end;
  const double points = std::ceil(end / step_) + 2.0;
  if (points > kMaxPoints)
    throw InputError("slip.correlation_time = " + format_number(correlation_time) +
                     " s: the slip's path over the run's " + format_number(end) + " s needs " +
                     format_number(points) + " points of step " + format_number(step_) +
                     " s, more than " + format_number(kMaxPoints) +
                     "; lengthen the correlation time or shorten the run");
  const auto n = static_cast<std::size_t>(points);
  u_.resize(n);
  phi_.resize(n);
  const double a = std::exp(-step_ / correlation_time), b = rms * std::sqrt(1.0 - a * a);
  Normal normal(static_cast<std::uint64_t>(seed));
  u_[0] = rms * normal();  // stationary from t = 0
  phi_[0] = 0.0;
  for (std::size_t k = 0; k + 1 < n; ++k) {
    u_[k + 1] = a * u_[k] + b * normal();
    phi_[k + 1] = phi_[k] + cage_speed * step_ * 0.5 * (u_[k] + u_[k + 1]);
  }
}

std::size_t SlipPath::index(double t, double& s) const {
  if (!(t >= 0.0 && t <= end_ + step_))
    throw std::logic_error("SlipPath: t = " + std::to_string(t) + " s outside its span [0, " +
                           std::to_string(end_) + "] s");
  const auto k = std::min(static_cast<std::size_t>(t * inv_step_), u_.size() - 2);
  s = t - static_cast<double>(k) * step_;
  return k;
}

double SlipPath::angle(double t) const {
  double s;
  const std::size_t k = index(t, s);
  const double slope = (u_[k + 1] - u_[k]) * inv_step_;
  return phi_[k] + cage_speed_ * s * (u_[k] + 0.5 * slope * s);
}

SlipPath::AngleRate SlipPath::at(double t) const {
  double s;
  const std::size_t k = index(t, s);
  const double slope = (u_[k + 1] - u_[k]) * inv_step_;
  return {phi_[k] + cage_speed_ * s * (u_[k] + 0.5 * slope * s), cage_speed_ * (u_[k] + slope * s)};
}

double SlipPath::rate(double t) const {
  double s;
  const std::size_t k = index(t, s);
  return cage_speed_ * (u_[k] + (u_[k + 1] - u_[k]) * inv_step_ * s);
}

}  // namespace bearing
