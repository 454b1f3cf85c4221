// The acoustic sources and the time-domain pressure (docs/model.md §8), each checked against
// something computed independently: elementary closed forms, low-ka limits, the outgoing phase, the
// power balance between the body's surface and the far field, seed 000's printed terms, and
// analytic tones through the filters.

#include <cmath>
#include <complex>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/acoustics/microphones.h"
#include "bearing/acoustics/pressure.h"
#include "bearing/acoustics/sources.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/fft.h"

namespace bearing {
namespace {

using cd = std::complex<double>;
constexpr cd kI{0, 1};
const Air kAir{};  // 1.204 kg/m^3, 343.2 m/s

double relative(cd a, cd b) {
  return std::abs(a - b) / std::abs(b);
}

// --- FFT ---------------------------------------------------------------------------------------

// A direct O(N²) DFT, the definition in fft.h.
std::vector<cd> direct_dft(const std::vector<double>& x) {
  const std::size_t n = x.size();
  std::vector<cd> X(n / 2 + 1);
  for (std::size_t k = 0; k < X.size(); ++k)
    for (std::size_t j = 0; j < n; ++j)
      X[k] += x[j] * std::polar(1.0, -two_pi * static_cast<double>(k * j % n) / n);
  return X;
}

TEST(RealFft, ForwardIsTheDftAndInverseUndoesItForAnyLength) {
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  // 96: mixed radix, even; 97, 194 and 211: Bluestein (prime factor > 64), odd and even.
  for (std::size_t n : {96u, 97u, 194u, 211u, 250u}) {
    std::vector<double> x(n);
    for (double& v : x) v = u(rng);
    RealFft fft(n);
    std::vector<double> scratch = x;
    const auto X = fft.forward(scratch);
    const auto ref = direct_dft(x);
    for (std::size_t k = 0; k < X.size(); ++k) EXPECT_LT(std::abs(X[k] - ref[k]), 1e-11) << n;
    const auto back = fft.inverse(X);
    for (std::size_t j = 0; j < n; ++j) EXPECT_NEAR(back[j], x[j], 1e-13) << n << " " << j;
  }
}

TEST(RealFft, InverseOfOneBinIsACosine) {
  // x_n = (1/N)(X_k e^{iθ_n} + conj) = (2/N)|X_k| cos(θ_n + arg X_k): the e^{+iωt} convention.
  const std::size_t n = 24001;  // prime: Bluestein
  RealFft fft(n);
  std::vector<cd> X(n / 2 + 1);
  X[37] = std::polar(n / 2.0, 0.4);
  const auto x = fft.inverse(X);
  for (std::size_t j = 0; j < n; j += 997)
    EXPECT_NEAR(x[j], std::cos(two_pi * 37.0 * j / n + 0.4), 1e-12);
}

// --- transfer functions ------------------------------------------------------------------------

TEST(Sources, PulsatingSphereEqualsItsElementaryClosedForm) {
  // p = ρc u (a/r) ika/(1 + ika) e^{−ik(r−a)}, docs/model.md §8.
  const double a = 1.9845e-3;
  const auto s = make_source("pulsating-sphere", a, kAir);
  for (double ka : {1e-4, 1e-2, 0.3, 1.0, 4.0, 30.0})
    for (double ratio : {1.0, 1.5, 10.0, 1000.0}) {
      const double k = ka / a, r = ratio * a, w = k * kAir.sound_speed;
      const cd expected =
          kAir.impedance() * (a / r) * (kI * ka) / (1.0 + kI * ka) * std::exp(-kI * k * (r - a));
      // The phase k(r − a) is rounded to ~k r ε: 7e-12 at kr = 3e4.
      EXPECT_LT(relative(s->transfer(w, r, 0.3), expected), 1e-15 * std::max(1e3, 2 * k * r))
          << ka << " " << ratio;
    }
}

TEST(Sources, SphereSeriesFormsEqualTheBesselForms) {
  const double a = 2e-3;
  for (const char* name : {"pulsating-sphere", "oscillating-sphere"}) {
    const auto s = make_series_source(name, a, kAir);
    for (double ka : {1e-3, 0.1, 1.0, 7.0, 50.0})
      for (double ratio : {1.0, 3.0, 200.0}) {
        const double w = ka / a * kAir.sound_speed;
        EXPECT_LT(relative(s->series(w, ratio * a, 0.6), s->transfer(w, ratio * a, 0.6)), 1e-11)
            << name << " ka " << ka << " r/a " << ratio;
      }
  }
}

TEST(Sources, SphereDipoleApproachesItsLowKaLimit) {
  // p → −(ρc k² a³ cos ψ / 2r)(1 − i/(kr)) e^{−ikr}; the exact form differs by O(ka) (the phase
  // e^{ika}) and O((ka)²): the error falls tenfold per decade of ka at fixed kr.
  const auto s = make_source("oscillating-sphere", 1e-3, kAir);
  for (double kr : {0.05, 1.0, 20.0}) {
    double previous = 1;
    for (double ka : {1e-1, 1e-2, 1e-3, 1e-4}) {
      const double a = 1e-3, k = ka / a, r = kr / k;
      if (r < a) continue;
      const cd limit = -(kAir.impedance() * k * k * a * a * a * 0.5 / r) * (1.0 - kI / kr) *
                       std::exp(-kI * kr) * 0.8;
      const double err = relative(s->transfer(k * kAir.sound_speed, r, 0.8), limit);
      EXPECT_LT(err, 1.5 * ka) << "kr " << kr << " ka " << ka;
      if (previous < 1) EXPECT_LT(err, 0.15 * previous);
      previous = err;
    }
  }
}

TEST(Sources, CylinderDipoleApproachesItsLowKaLimit) {
  // p → (π/2) ρc (ka)² cos ψ H₁⁽²⁾(kr); next term O((ka)² ln ka).
  const double a = 5.79e-3;
  const auto s = make_source("cylinder-dipole", a, kAir);
  for (double kr : {0.01, 1.0, 30.0}) {
    double previous = 1;
    for (double ka : {1e-2, 1e-3, 1e-4}) {
      const double k = ka / a, r = kr / k;
      if (r < a) continue;
      const cd h1(std::cyl_bessel_j(1.0, kr), -std::cyl_neumann(1.0, kr));  // libstdc++, not GSL
      const cd limit = 0.5 * pi * kAir.impedance() * ka * ka * 0.5 * h1;
      const double err = relative(s->transfer(k * kAir.sound_speed, r, 0.5), limit);
      EXPECT_LT(err, 2 * ka * ka * std::fabs(std::log(ka))) << "kr " << kr << " ka " << ka;
      if (previous < 1) EXPECT_LT(err, 0.05 * previous);
      previous = err;
    }
  }
}

TEST(Sources, FieldsAreOutgoing) {
  // The phase falls with distance everywhere (d arg p/dr < 0) and tends to −k far away:
  // e^{i(ωt − kr)}, a wave travelling out.
  for (const char* name :
       {"cylinder-monopole", "cylinder-dipole", "pulsating-sphere", "oscillating-sphere"}) {
    const double a = 3e-3;
    const auto s = make_source(name, a, kAir);
    for (double f : {100.0, 2000.0, 20000.0}) {
      const double w = two_pi * f, k = w / kAir.sound_speed;
      for (double r = a; r < 200 / k; r *= 1.3) {
        const double dr = 1e-4 * r;
        const double slope = std::arg(s->transfer(w, r + dr, 1) / s->transfer(w, r, 1)) / dr;
        EXPECT_LT(slope, 0) << name << " f " << f << " r " << r;
        if (k * r > 150) EXPECT_NEAR(slope / k, -1.0, 0.01) << name << " f " << f << " r " << r;
      }
    }
  }
}

// Power balance: what the surface puts in, ½ ∫ Re(p u*) dS, leaves through a far circle or
// sphere as ∫ |p|²/(2ρc) dS (exact as kr → ∞; O(1/kr) here at kr = 1e4).
TEST(Sources, SurfacePowerLeavesThroughTheFarField) {
  struct Body {
    const char* name;
    double pattern_integral_surface;  // ∫ Θ² dS / a^d on the body (d = 1 cylinder, 2 sphere)
  };
  // Cylinder per unit length: ∫ dφ = 2π, ∫ cos² = π. Sphere: ∫ dΩ = 4π, ∫ cos² dΩ = 4π/3.
  for (const Body& b : {Body{"cylinder-monopole", two_pi}, Body{"cylinder-dipole", pi},
                        Body{"pulsating-sphere", 4 * pi}, Body{"oscillating-sphere", 4 * pi / 3}}) {
    const double a = 4e-3;
    const auto s = make_source(b.name, a, kAir);
    const int d = s->cylindrical() ? 1 : 2;
    for (double ka : {0.05, 0.5, 3.0}) {
      const double w = ka / a * kAir.sound_speed, k = ka / a;
      const double surface =
          0.5 * s->transfer(w, a, 1).real() * std::pow(a, d) * b.pattern_integral_surface;
      const double R = 1e4 / k;
      const double far = std::norm(s->transfer(w, R, 1)) / (2 * kAir.impedance()) * std::pow(R, d) *
                         b.pattern_integral_surface;
      EXPECT_GT(surface, 0) << b.name;
      EXPECT_NEAR(far / surface, 1.0, 1e-3) << b.name << " ka " << ka;
    }
  }
}

TEST(Sources, SeedZeroRingFormCarriesEquation19sTermsAndItsSmallArgumentLimit) {
  // −iρc cos ψ h̃(kr)/h̃'(ka) with h̃(x) = x/2 + 2i/(πx), h̃'(x) = 1/2 − 2i/(πx²). Multiplied by
  // |h̃'(ka)|² = 1/4 + (2/(πk²a²))² (eq. 19's denominator) and divided by −iρc cos ψ, its real
  // part is eq. 19's first bracket kr/4 − 4/(π²k³a²r) exactly; its imaginary part is
  // r/(πka²) + 1/(πkr) (eq. 19 prints 4/(π²k³a²r) + r/(πka²)).
  const double a = 5.79e-3;
  const auto paper = make_source("cylinder-dipole-paper", a, kAir);
  const auto exact = make_source("cylinder-dipole", a, kAir);
  for (double f : {50.0, 500.0, 5000.0}) {
    const double w = two_pi * f, k = w / kAir.sound_speed, r = 10e-3;
    const double denominator = 0.25 + std::pow(2 / (pi * k * k * a * a), 2);
    const cd bracket = paper->transfer(w, r, 0.7) * denominator / (-kI * kAir.impedance() * 0.7);
    const double first = k * r / 4 - 4 / (pi * pi * k * k * k * a * a * r);
    EXPECT_NEAR(bracket.real(), first, 1e-12 * std::fabs(first)) << f;
    const double second = r / (pi * k * a * a) + 1 / (pi * k * r);
    EXPECT_NEAR(bracket.imag(), second, 1e-12 * second) << f;
  }
  // Both ka and kr small: it approaches the exact dipole; at kr ~ 1 it is off by tens of percent.
  const double r = 2 * a;
  double previous = 1;
  for (double kr : {1e-1, 1e-2, 1e-3}) {
    const double w = kr / r * kAir.sound_speed;
    const double err = relative(paper->transfer(w, r, 1), exact->transfer(w, r, 1));
    EXPECT_LT(err, kr) << kr;
    if (previous < 1) EXPECT_LT(err, 0.2 * previous);
    previous = err;
  }
  const double w1 = 1.0 / r * kAir.sound_speed;
  EXPECT_GT(relative(paper->transfer(w1, r, 1), exact->transfer(w1, r, 1)), 0.1);
}

TEST(Sources, SeedZeroBallFormIsEquation23) {
  // p = ρc k r₀² u / (√(1 + (kr₀)²) r) e^{iθ}, θ = arctan(1/(kr₀)): the pulsating sphere's
  // modulus, without its propagation phase.
  const double a = 1.98e-3;
  const auto paper = make_source("pulsating-sphere-paper", a, kAir);
  const auto exact = make_source("pulsating-sphere", a, kAir);
  for (double f : {30.0, 1000.0, 20000.0})
    for (double r : {a, 10e-3, 1.0}) {
      const double w = two_pi * f, k = w / kAir.sound_speed;
      const cd eq23 = kAir.impedance() * k * a * a / (std::sqrt(1 + k * a * k * a) * r) *
                      std::polar(1.0, std::atan(1 / (k * a)));
      EXPECT_LT(relative(paper->transfer(w, r, 0), eq23), 1e-12);
      EXPECT_NEAR(std::abs(paper->transfer(w, r, 0)), std::abs(exact->transfer(w, r, 0)),
                  1e-12 * std::abs(eq23));
      EXPECT_LT(relative(paper->transfer(w, r, 0) * std::exp(-kI * k * (r - a)),
                         exact->transfer(w, r, 0)),
                1e-12);
    }
}

TEST(Sources, RampPressureIsTheIncompressibleNearField) {
  // A steady acceleration β of a small body: p = ρ a² β / r (pulsating sphere), ρ a³ β cos ψ /
  // (2r²) (translating sphere), ρ a² β cos ψ / r (translating cylinder): potential flow.
  const double a = 2e-3, r = 7e-3, c = 0.4, rho = kAir.density;
  EXPECT_NEAR(make_source("pulsating-sphere", a, kAir)->ramp_pressure(r, c), rho * a * a / r,
              1e-6 * rho * a * a / r);
  EXPECT_NEAR(make_source("oscillating-sphere", a, kAir)->ramp_pressure(r, c),
              rho * a * a * a * c / (2 * r * r), 1e-6 * rho * a * a * a / (r * r));
  EXPECT_NEAR(make_source("cylinder-dipole", a, kAir)->ramp_pressure(r, c), rho * a * a * c / r,
              1e-6 * rho * a * a / r);
  EXPECT_EQ(make_source("cylinder-monopole", a, kAir)->ramp_pressure(r, c), 0.0);
}

TEST(Sources, BadArgumentsAreNamed) {
  try {
    make_source("sphere", 1e-3, kAir, "acoustics.ball_source");
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("acoustics.ball_source = \"sphere\""), std::string::npos) << m;
    EXPECT_NE(m.find("pulsating-sphere"), std::string::npos) << m;
  }
  EXPECT_THROW(make_source("cylinder-dipole", -1, kAir), InputError);
  EXPECT_THROW(make_series_source("cylinder-dipole", 1e-3, kAir), InputError);
  const auto s = make_source("oscillating-sphere", 2e-3, kAir);
  EXPECT_THROW(s->transfer(100, 1e-3, 1), InputError);  // inside the body
  EXPECT_THROW(s->transfer(-1, 1, 1), InputError);
  EXPECT_EQ(s->transfer(0, 1, 1), cd(0));
  EXPECT_THROW(sound_pressure_level(0), InputError);
  EXPECT_NEAR(sound_pressure_level(1.0), 93.9794, 1e-4);  // 1 Pa RMS
}

// --- time domain -------------------------------------------------------------------------------

// N + 1 samples of U cos(ωt + φ) at `rate` (the record and the sample after it).
std::vector<double> tone(std::size_t n, double rate, double f, double U, double phase) {
  std::vector<double> u(n + 1);
  for (std::size_t i = 0; i <= n; ++i) u[i] = U * std::cos(two_pi * f * i / rate + phase);
  return u;
}

// The steady pressure of that tone through H: Re(H U e^{i(ωt + φ)}).
double tone_pressure(cd H, double t, double f, double U, double phase) {
  return (H * U * std::polar(1.0, two_pi * f * t + phase)).real();
}

TEST(Pressure, FixedSourceTurnsAToneIntoItsTransferFunction) {
  const std::size_t n = 4000;
  const double rate = 20000;
  RealFft fft(n);
  for (const char* name : {"cylinder-dipole", "cylinder-dipole-paper", "oscillating-sphere"}) {
    const auto s = make_source(name, 5e-3, kAir);
    const double f = 35 * rate / n;  // on a bin: the record is whole periods
    const auto p = radiate_fixed(*s, tone(n, rate, f, 1e-3, 0.3), rate, 0.012, 0.9, fft);
    const cd H = s->transfer(two_pi * f, 0.012, 0.9);
    for (std::size_t i = 0; i < n; i += 37)
      EXPECT_NEAR(p[i], tone_pressure(H, i / rate, f, 1e-3, 0.3), 1e-12 * std::abs(H)) << name;
  }
}

TEST(Pressure, RecordThatIsNotWholePeriodsHasNoSpikeAtItsEnds) {
  // 1 s at 20 kHz holding 123.37 periods of a 123.37 Hz tone. Without the detrend the wrap's jump
  // would radiate a spike ~ rate/ω = 26 times the tone's amplitude (near field ∝ du/dt); with it,
  // what is left at the wrap is a kink: a jump J of p of the order of its amplitude, ringing as
  // J/(πn) at n samples from the ends (the band stops at 0.8 Nyquist: a sinc tail).
  const std::size_t n = 20000;
  const double rate = 20000, f = 123.37, U = 1e-4;
  RealFft fft(n);
  const auto s = make_source("cylinder-dipole", 5.79e-3, kAir);
  const auto p = radiate_fixed(*s, tone(n, rate, f, U, 1.1), rate, 0.01, 1, fft);
  const cd H = s->transfer(two_pi * f, 0.01, 1);
  const double amplitude = std::abs(H) * U;
  double err2 = 0, ref2 = 0, got2 = 0, worst = 0, worst_inside = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double expected = tone_pressure(H, i / rate, f, U, 1.1);
    const double e = p[i] - expected;
    err2 += e * e, ref2 += expected * expected, got2 += p[i] * p[i];
    worst = std::max(worst, std::fabs(e));
    if (i > 1000 && i < n - 1000) worst_inside = std::max(worst_inside, std::fabs(e));
  }
  // The kink makes p jump at the wrap by J = p(T) − p(0); the ringing of a band-limited jump
  // carries an energy of order J² (Σ 2/(πn)² = J²/3 for the sinc tails, plus the half-jump at the
  // two samples beside it), whatever N: measured 1.26 J² here.
  const double jump = tone_pressure(H, n / rate, f, U, 1.1) - tone_pressure(H, 0, f, U, 1.1);
  EXPECT_LT(worst, 1.5 * amplitude);                       // no spike
  EXPECT_LT(worst_inside, std::fabs(jump) / (pi * 1000));  // the tail: J/(πn)
  EXPECT_LT(err2, 2 * jump * jump);
  EXPECT_NEAR(10 * std::log10(got2 / ref2), 0.0, 0.01);  // the level within 0.01 dB
}

TEST(PeriodicInterpolator, IsExactOnSamplesAndBandLimitedBetween) {
  const std::size_t n = 1000;
  const PeriodicInterpolator at;
  for (double fraction : {0.1, 0.25, 0.4}) {  // of the sample rate (Nyquist = 0.5)
    const double cycles = std::round(fraction * n);
    std::vector<double> x(n);
    for (std::size_t i = 0; i < n; ++i) x[i] = std::sin(two_pi * cycles * i / n + 0.2);
    for (double s : {3.0, 17.37, -4.81, 999.5, 1500.25}) {
      const double expected = std::sin(two_pi * cycles * s / n + 0.2);
      // pressure.h's figures: ≤ 3e-5 up to 0.4 Nyquist, ≤ 2e-4 up to 0.84 Nyquist.
      EXPECT_NEAR(at(x, s), expected, fraction <= 0.2 ? 3e-5 : 2e-4) << fraction << " " << s;
    }
    EXPECT_NEAR(at(x, 12.0), x[12], 1e-15);  // sinc zeros at the other taps, to rounding
  }
}

TEST(Pressure, MovingSourceOnAFixedPathEqualsTheFixedSource) {
  const std::size_t n = 3000;
  const double rate = 20000;
  RealFft fft(n);
  for (const char* name : {"pulsating-sphere", "oscillating-sphere", "pulsating-sphere-paper"}) {
    const auto s = make_series_source(name, 2e-3, kAir);
    std::vector<double> u(n + 1);
    for (std::size_t i = 0; i <= n; ++i)
      u[i] =
          1e-4 * (std::sin(two_pi * 40.5 * i / rate) + 0.3 * std::cos(two_pi * 3210.0 * i / rate));
    SourcePath path{std::vector<double>(n, 0.0137), std::vector<double>(n, -0.6)};
    const auto moving = radiate_moving(*s, u, rate, path, fft);
    const auto fixed = radiate_fixed(*s, u, rate, 0.0137, -0.6, fft);
    double scale = 0;
    for (double v : fixed) scale = std::max(scale, std::fabs(v));
    // Interpolated delays: the kernel's passband ripple (80 dB stopband) is ~1e-4 inside, and the
    // broadband ringing of the record's kink at the wrap (the tone is not whole periods) is
    // attenuated near the ends.
    double d2 = 0, f2 = 0;
    for (std::size_t i = 0; i < n; ++i) {
      if (i > 100 && i < n - 100)
        EXPECT_NEAR(moving[i], fixed[i], 1e-4 * scale) << name << " " << i;
      d2 += std::pow(moving[i] - fixed[i], 2), f2 += fixed[i] * fixed[i];
    }
    EXPECT_LT(std::sqrt(d2 / f2), 1e-2) << name;
  }
}

TEST(Pressure, MovingSourceFollowsItsInstantGeometry) {
  // A breathing sphere swept from 2a to 40a while it sings at 2 kHz: each sample is the
  // frozen-geometry tone Re(H(ω; r_n) U e^{iωt_n}) computed from GSL's h₀, h₁ (transfer()).
  const std::size_t n = 4000;
  const double rate = 40000, f = 200 * rate / n, a = 2e-3;
  RealFft fft(n);
  const auto s = make_series_source("oscillating-sphere", a, kAir);
  SourcePath path;
  for (std::size_t i = 0; i < n; ++i) {
    const double phase = two_pi * i / n;
    path.distance.push_back(a * (21 - 19 * std::cos(phase)));
    path.cos_angle.push_back(std::cos(0.5 * phase));
  }
  const auto p = radiate_moving(*s, tone(n, rate, f, 1e-3, 0), rate, path, fft);
  for (std::size_t i = 0; i < n; i += 13) {
    const cd H = s->transfer(two_pi * f, path.distance[i], path.cos_angle[i]);
    EXPECT_NEAR(p[i], tone_pressure(H, i / rate, f, 1e-3, 0), 1e-4 * std::abs(H) * 1e-3) << i;
  }
}

TEST(Pressure, CoherentAndEnergeticSums) {
  std::vector<double> p1(1000), p2(1000);
  for (std::size_t i = 0; i < p1.size(); ++i) p1[i] = p2[i] = std::sin(two_pi * 7 * i / 1000.0);
  const double one = root_mean_square(p1);
  EXPECT_NEAR(root_mean_square(p1), std::sqrt(0.5), 1e-12);
  // Two equal sources in phase: +6.02 dB coherent, +3.01 dB energetic.
  EXPECT_NEAR(20 * std::log10(root_mean_square(sum_pressures({p1, p2}, Summation::coherent)) / one),
              6.0206, 1e-4);
  EXPECT_NEAR(
      20 * std::log10(root_mean_square(sum_pressures({p1, p2}, Summation::energetic)) / one),
      3.0103, 1e-4);
  // In antiphase: silence coherently, still +3.01 dB energetically.
  for (double& v : p2) v = -v;
  EXPECT_NEAR(root_mean_square(sum_pressures({p1, p2}, Summation::coherent)), 0.0, 1e-15);
  EXPECT_NEAR(root_mean_square(sum_pressures({p1, p2}, Summation::energetic)), std::sqrt(2) * one,
              1e-12);
  EXPECT_THROW(parse_summation("incoherent", "acoustics.summation"), InputError);
}

TEST(Microphones, BallPathDistancesAndAngles) {
  // A ball on the +x axis vibrating radially, a microphone straight above it and one beyond it.
  const std::vector<double> t{0.0}, r{1e-6};
  const auto above = ball_path({0.05, 0.02}, 0.05, 0.0, 10.0, t, r);
  EXPECT_NEAR(above.distance[0], std::hypot(1e-6, 0.02), 1e-15);
  EXPECT_NEAR(above.cos_angle[0], -1e-6 / above.distance[0], 1e-12);
  const auto beyond = ball_path({0.08, 0.0}, 0.05, 0.0, 10.0, t, r);
  EXPECT_NEAR(beyond.distance[0], 0.03 - 1e-6, 1e-15);
  EXPECT_NEAR(beyond.cos_angle[0], 1.0, 1e-15);
  // A quarter cage turn later the ball is on +y.
  const auto later = ball_path({0.0, 0.08}, 0.05, 0.0, 10.0, {pi / 20}, {0.0});
  EXPECT_NEAR(later.distance[0], 0.03, 1e-12);
}

}  // namespace
}  // namespace bearing
