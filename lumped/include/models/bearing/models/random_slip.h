#pragma once
// Random slip of the cage (the case file's [slip] table; issue 40 §4; docs/model.md, "Random
// slip"). Off by default: every kind's balls then turn at exactly the kinematic cage speed, and
// nothing here runs.
//
// Why. A real bearing's balls do not roll perfectly: the load zone brakes and drives them, the
// lubricant film shears, the cage lags and catches up. The cage's speed fluctuates by 1–2 % about
// its kinematic mean, so the impacts of a local fault do not fall at exact multiples of the
// fault's period: their inter-arrival times jitter, and the error accumulates (Antoni & Randall,
// J. Vib. Acoust. 125, 2003: a "random slip" of 1–2 % of the period; Sawalhi & Randall, MSSP 22,
// 2008, Part I, put it into their simulated signals). The signal is then cyclostationary rather
// than periodic: the lines of its spectrum broaden and its squared envelope spectrum's harmonics
// fall off, and — what a diagnosis relies on — the impacts survive pre-whitening, which sets every
// bin's magnitude to one and so erases exactly periodic impacts (examples/cwru/README.md).
//
// The process. The cage angle is θ_c(t) = ω_c t + φ(t), with φ̇ = ω_c u(t) and u the cage
// speed's relative fluctuation: a stationary Ornstein–Uhlenbeck process of RMS σ (slip.rms) and
// autocorrelation
//     E[u(t) u(t + s)] = σ² exp(−|s|/τ)              (τ: slip.correlation_time),
// the Gaussian process with exponential memory. Its default τ is one ball pass of the cage,
// 2π/(Z ω_c) = 1/BPFO, the scale of the independent-interval model of Antoni & Randall: the time
// between two balls over a point of the outer race, T_b = 1/BPFO, then fluctuates by
// σ sqrt(2 (x − 1 + e^(−x)))/x = 0.86 σ at x = T_b/τ = 1 (from Var[φ(t + T) − φ(t)] =
// 2 σ² ω_c² τ² (T/τ − 1 + e^(−T/τ))), so σ of 1–2 % is the 1–2 % of the period they report, and
// consecutive intervals are nearly independent: the memory is that of the load zone each ball
// crosses once per pass.
//
// It is sampled exactly on a uniform grid of step Δ = τ/64 from t = 0: u₀ ~ N(0, σ²) (so the
// process is stationary from the start) and u_{k+1} = a u_k + σ sqrt(1 − a²) ξ_k, a = exp(−Δ/τ),
// ξ_k independent N(0, 1) from a 64-bit Mersenne twister seeded with slip.seed through a
// Box–Muller transform written here (std::normal_distribution's algorithm is the library's, so its
// bits would not be the same with another standard library). Between nodes u is linear, so
//     φ(t) = ω_c ∫₀ᵗ u = φ_k + ω_c (u_k s + (u_{k+1} − u_k) s²/(2Δ)),   s = t − kΔ,
// is continuous with a continuous derivative, exact to integrate, and evaluated at any t (the
// integrators ask at arbitrary times) by one index and a few flops. The linear interpolation
// lowers u's variance between nodes by at most Δ/(2τ) = 0.8 % (at the midpoints; its average over
// an interval by a third of that), which the stated RMS is judged with (tests/lumped/
// test_random_slip.cc). A run with a given seed is the same bits every time; another seed gives
// another path. The mean rate is ω_c: E[φ(t)] = 0, and φ(T)/T → 0 as the run lengthens (its
// standard deviation sqrt(2σ²ω_c²τ/T) for T ≫ τ).

#include <cstdint>
#include <vector>

namespace bearing {

/// The [slip] table, in SI.
struct RandomSlip {
  double rms = 0.0;               ///< σ, RMS of (θ̇_c − ω_c)/ω_c [-]; 0: off
  double correlation_time = 0.0;  ///< τ [s]; 0: one ball pass, 2π/(Z ω_c)
  int seed = 1;                   ///< the generator's seed, >= 0
  bool enabled() const { return rms > 0.0; }
};

/// The cage's angle error φ(t) of one run, over [0, end].
class SlipPath {
 public:
  /// Grid steps per correlation time.
  static constexpr int kStepsPerCorrelationTime = 64;
  /// The most grid points a path holds (a τ far below the run's length asks for too many).
  static constexpr double kMaxPoints = 5e7;

  /// σ = `rms` [-], τ = `correlation_time` [s] (> 0), `seed`, ω_c = `cage_speed` [rad/s] (the
  /// mean cage speed the error is relative to), the span [0, `end`] [s] it covers. Throws
  /// InputError for σ or τ out of range or a grid beyond kMaxPoints.
  SlipPath(double rms, double correlation_time, int seed, double cage_speed, double end);

  /// φ(t) [rad]; std::logic_error for t outside [0, end].
  double angle(double t) const;
  /// φ̇(t) = ω_c u(t) [rad/s].
  double rate(double t) const;
  /// Both at once (one lookup): {φ(t) [rad], φ̇(t) [rad/s]}.
  struct AngleRate {
    double angle, rate;
  };
  AngleRate at(double t) const;

  double step() const { return step_; }  ///< Δ [s]
  double end() const { return end_; }    ///< [s]
  /// u at the grid's nodes, u_k = u(kΔ) [-] (for the tests).
  const std::vector<double>& speed() const { return u_; }

 private:
  std::size_t index(double t, double& s) const;

  double cage_speed_;
  double step_, inv_step_, end_;
  std::vector<double> u_;    // u_k
  std::vector<double> phi_;  // φ_k = φ(kΔ) [rad]
};

}  // namespace bearing
