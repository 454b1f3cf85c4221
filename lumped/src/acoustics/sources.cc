// Transfer functions of the bearing's sound sources (sources.h has the derivations).

#include "bearing/acoustics/sources.h"

#include <gsl/gsl_sf_bessel.h>

#include <cmath>
#include <string>

#include "../core/edit_distance.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/units.h"

namespace bearing {

namespace {

using cd = std::complex<double>;
constexpr cd kI{0.0, 1.0};
// Outgoing Hankel functions of the second kind, H_n = J_n − i Y_n, h_n = j_n − i y_n.
cd hankel0(double x) {
  return {gsl_sf_bessel_J0(x), -gsl_sf_bessel_Y0(x)};
}
cd hankel1(double x) {
  return {gsl_sf_bessel_J1(x), -gsl_sf_bessel_Y1(x)};
}
cd spherical_hankel0(double x) {
  return {gsl_sf_bessel_j0(x), -gsl_sf_bessel_y0(x)};
}
cd spherical_hankel1(double x) {
  return {gsl_sf_bessel_j1(x), -gsl_sf_bessel_y1(x)};
}

void check_arguments(const AcousticSource& s, double omega, double r, double cos_angle) {
  if (!(std::isfinite(omega) && omega >= 0))
    throw InputError(std::string(s.name()) + ": angular frequency = " + format_number(omega) +
                     " rad/s: must be finite and ≥ 0");
  if (!(std::isfinite(r) && r >= s.radius()))
    throw InputError(std::string(s.name()) + ": distance = " + format_number(r) +
                     " m: must be finite and at least the radius " + format_number(s.radius()) +
                     " m (the point must lie outside the body)");
  if (!std::isfinite(cos_angle))
    throw InputError(std::string(s.name()) + ": cos(angle) = " + format_number(cos_angle) +
                     ": must be finite");
}

double direction_factor(Pattern p, double cos_angle) {
  return p == Pattern::translating ? cos_angle : 1.0;
}

// The fields below share ρ₀c₀ as `z`.
class Source : public AcousticSource {
 public:
  using AcousticSource::AcousticSource;

 protected:
  double z() const { return air().impedance(); }
};

// Infinite cylinder, breathing: p = −iρc u H₀(kr)/H₀'(ka) = iρc u H₀(kr)/H₁(ka).
class CylinderMonopole final : public Source {
 public:
  using Source::Source;
  double ramp_pressure(double, double) const override { return 0.0; }
  bool cylindrical() const override { return true; }
  Pattern pattern() const override { return Pattern::breathing; }
  cd transfer(double omega, double r, double c) const override {
    check_arguments(*this, omega, r, c);
    if (omega == 0) return 0.0;
    const double k = wavenumber(omega);
    return kI * z() * hankel0(k * r) / hankel1(k * radius());
  }
};

// Hankel functions for the cylinder dipole: the exact H₁⁽²⁾ and H₁⁽²⁾' = H₀ − H₁/x, or seed 000's
// small-argument forms H₁ ≈ x/2 + 2i/(πx), H₁' ≈ 1/2 − 2i/(πx²) (its eq. 19 as derived).
struct ExactHankel {
  static cd value(double x) { return hankel1(x); }
  static cd derivative(double x) { return hankel0(x) - hankel1(x) / x; }
};
struct SmallArgumentHankel {
  static cd value(double x) { return x / 2 + kI * 2.0 / (pi * x); }
  static cd derivative(double x) { return 0.5 - kI * 2.0 / (pi * x * x); }
};

// Infinite cylinder translating transversely: p = −iρc u cos ψ H₁(kr)/H₁'(ka).
template <class Hankel>
class CylinderDipole final : public Source {
 public:
  using Source::Source;
  bool cylindrical() const override { return true; }
  Pattern pattern() const override { return Pattern::translating; }
  cd transfer(double omega, double r, double c) const override {
    check_arguments(*this, omega, r, c);
    if (omega == 0) return 0.0;
    const double ka = wavenumber(omega) * radius(), kr = wavenumber(omega) * r;
    return -kI * z() * c * Hankel::value(kr) / Hankel::derivative(ka);
  }
  void transfer(double omega, const std::vector<double>& r, const std::vector<double>& c,
                std::vector<cd>& out) const override {
    for (std::size_t i = 0; i < r.size(); ++i) check_arguments(*this, omega, r[i], c[i]);
    out.assign(r.size(), 0.0);
    if (omega == 0) return;
    const cd body = Hankel::derivative(wavenumber(omega) * radius());  // once for all points
    for (std::size_t i = 0; i < r.size(); ++i)
      out[i] = -kI * z() * c[i] * Hankel::value(wavenumber(omega) * r[i]) / body;
  }
};

class SphereSource : public RadialSeriesSource {
 public:
  using RadialSeriesSource::RadialSeriesSource;
  bool cylindrical() const override { return false; }

 protected:
  double z() const { return air().impedance(); }
};

// Pulsating sphere: p = −iρc u h₀(kr)/h₀'(ka) = iρc u h₀(kr)/h₁(ka)
//                     = ρc u (a/r) ika/(1 + ika) e^{−ik(r−a)}.
class PulsatingSphere final : public SphereSource {
 public:
  PulsatingSphere(std::string name, double radius, const Air& air, bool delayed)
      : SphereSource(std::move(name), radius, air), delayed_(delayed) {}
  Pattern pattern() const override { return Pattern::breathing; }
  std::vector<int> powers() const override { return {1}; }
  bool delayed() const override { return delayed_; }
  cd factor(std::size_t, double omega) const override {
    const double ka = wavenumber(omega) * radius();
    return z() * kI * ka / (1.0 + kI * ka);
  }
  cd transfer(double omega, double r, double c) const override {
    check_arguments(*this, omega, r, c);
    if (omega == 0) return 0.0;
    if (!delayed_) return series(omega, r, c);  // seed 000 eq. (23) has no Bessel form
    const double k = wavenumber(omega);
    return kI * z() * spherical_hankel0(k * r) / spherical_hankel1(k * radius());
  }

 private:
  bool delayed_;
};

// Oscillating (rigidly translating) sphere: p = −iρc u cos ψ h₁(kr)/h₁'(ka).
class OscillatingSphere final : public SphereSource {
 public:
  using SphereSource::SphereSource;
  Pattern pattern() const override { return Pattern::translating; }
  std::vector<int> powers() const override { return {1, 2}; }
  bool delayed() const override { return true; }
  cd factor(std::size_t i, double omega) const override {
    const double x = wavenumber(omega) * radius();
    if (x == 0) return 0.0;
    const cd C = -kI * z() * x * x * x / (2 * x + kI * (x * x - 2));
    return i == 0 ? -C / x : kI * C / (x * x);
  }
  cd transfer(double omega, double r, double c) const override {
    check_arguments(*this, omega, r, c);
    if (omega == 0) return 0.0;
    const double ka = wavenumber(omega) * radius(), kr = wavenumber(omega) * r;
    const cd derivative = spherical_hankel0(ka) - 2.0 * spherical_hankel1(ka) / ka;
    return -kI * z() * c * spherical_hankel1(kr) / derivative;
  }
};

struct Entry {
  const char* name;
  const char* canonical;  // the name the object reports
};
constexpr Entry kSources[] = {
    {"cylinder-monopole", "cylinder-monopole"},
    {"cylinder-dipole", "cylinder-dipole"},
    {"cylinder-dipole-paper", "cylinder-dipole-paper"},
    {"pulsating-sphere", "pulsating-sphere"},
    {"sphere-monopole", "pulsating-sphere"},
    {"oscillating-sphere", "oscillating-sphere"},
    {"sphere-dipole", "oscillating-sphere"},
    {"pulsating-sphere-paper", "pulsating-sphere-paper"},
};

[[noreturn]] void unknown(std::string_view name, const std::string& key) {
  std::string allowed, nearest;
  std::size_t best = 1000;
  for (const Entry& e : kSources) {
    allowed += std::string(allowed.empty() ? "" : ", ") + e.name;
    const std::size_t d = detail::edit_distance(name, e.name);
    if (d < best) best = d, nearest = e.name;
  }
  std::string msg = key + " = \"" + std::string(name) + "\": unknown source; allowed: " + allowed;
  if (best <= 4) msg += " (did you mean \"" + nearest + "\"?)";
  throw InputError(msg);
}

std::string canonical(std::string_view name, const std::string& key) {
  for (const Entry& e : kSources)
    if (name == e.name) return e.canonical;
  unknown(name, key);
}

void check_body(double radius, const Air& air, const std::string& key) {
  if (!(std::isfinite(radius) && radius > 0))
    throw InputError(key + ": radius = " + format_number(radius) + " m: must be positive");
  if (!(std::isfinite(air.density) && air.density > 0))
    throw InputError(key + ": air density = " + format_number(air.density) +
                     " kg/m^3: must be positive");
  if (!(std::isfinite(air.sound_speed) && air.sound_speed > 0))
    throw InputError(key + ": sound speed = " + format_number(air.sound_speed) +
                     " m/s: must be positive");
}

// The angular frequency at which ka = 1e-7, for the ω → 0 limits.
double small_omega(const AcousticSource& s) {
  return 1e-7 * s.air().sound_speed / s.radius();
}

}  // namespace

void AcousticSource::transfer(double omega, const std::vector<double>& r,
                              const std::vector<double>& cos_angle, std::vector<cd>& out) const {
  out.resize(r.size());
  for (std::size_t i = 0; i < r.size(); ++i) out[i] = transfer(omega, r[i], cos_angle[i]);
}

double AcousticSource::ramp_pressure(double r, double cos_angle) const {
  const double w = small_omega(*this);
  return (transfer(w, r, cos_angle) / cd(0.0, w)).real();
}

double RadialSeriesSource::ramp_factor(std::size_t i) const {
  const double w = small_omega(*this);
  return (factor(i, w) / cd(0.0, w)).real();
}

std::complex<double> RadialSeriesSource::series(double omega, double r, double cos_angle) const {
  check_arguments(*this, omega, r, cos_angle);
  if (omega == 0) return 0.0;
  const std::vector<int> m = powers();
  cd sum = 0;
  for (std::size_t i = 0; i < m.size(); ++i) sum += std::pow(radius() / r, m[i]) * factor(i, omega);
  if (delayed()) sum *= std::polar(1.0, -wavenumber(omega) * (r - radius()));
  return direction_factor(pattern(), cos_angle) * sum;
}

std::vector<std::string> source_names() {
  std::vector<std::string> names;
  for (const Entry& e : kSources) names.push_back(e.name);
  return names;
}

std::unique_ptr<RadialSeriesSource> make_series_source(std::string_view name, double radius,
                                                       const Air& air, const std::string& key) {
  const std::string c = canonical(name, key);
  check_body(radius, air, key);
  if (c == "pulsating-sphere") return std::make_unique<PulsatingSphere>(c, radius, air, true);
  if (c == "pulsating-sphere-paper")
    return std::make_unique<PulsatingSphere>(c, radius, air, false);
  if (c == "oscillating-sphere") return std::make_unique<OscillatingSphere>(c, radius, air);
  throw InputError(key + " = \"" + std::string(name) +
                   "\": a cylinder's field is not a finite radial series; a moving source must be "
                   "a sphere");
}

std::unique_ptr<AcousticSource> make_source(std::string_view name, double radius, const Air& air,
                                            const std::string& key) {
  const std::string c = canonical(name, key);
  check_body(radius, air, key);
  if (c == "cylinder-monopole") return std::make_unique<CylinderMonopole>(c, radius, air);
  if (c == "cylinder-dipole") return std::make_unique<CylinderDipole<ExactHankel>>(c, radius, air);
  if (c == "cylinder-dipole-paper")
    return std::make_unique<CylinderDipole<SmallArgumentHankel>>(c, radius, air);
  return make_series_source(name, radius, air, key);
}

double sound_pressure_level(double p_rms) {
  if (!(std::isfinite(p_rms) && p_rms > 0))
    throw InputError("sound pressure level of p_rms = " + format_number(p_rms) +
                     " Pa: needs a positive, finite RMS pressure (a silent signal has no level)");
  return 20.0 * std::log10(p_rms / kReferencePressure);
}

}  // namespace bearing
