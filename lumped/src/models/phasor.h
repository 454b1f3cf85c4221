#pragma once
// cos θ and sin θ by rotation instead of libm (private to lumped/src/models).
//
// The ball-set kernel needs (cos, sin) of the cage angle ω_c t at every force evaluation. Instead
// of calling sincos (≈ 20 ns, a quarter of a 2-DOF force call), the angle is split as
// θ = k·Δ + r with Δ = 2π/1024 and |r| ≤ Δ/2, the table entry for k·Δ is rotated by the small
// angle r, and cos r, sin r come from their Taylor series to r⁸ and r⁹ (remainder < 1e-25 for
// |r| ≤ 3.1e-3). The reduction subtracts k·Δ in two parts (Cody–Waite), so the result is within
// a few ulp of libm for |θ| up to ~1e6 rad — far beyond a simulated run. Stateless and
// thread-safe: the table is a function-local constant.

#include <array>
#include <cmath>

#include "bearing/constants.h"

namespace bearing::detail {

struct Phasor {
  double c;  ///< cos θ
  double s;  ///< sin θ
};

/// The constants of phasor(): Δ = 2π/N split as hi + lo (hi has 33 significant bits, so k·hi is
/// exact for |k| < 2^20) and the N (cos, sin) of k·Δ. One instance (phasor_constants()), shared
/// with the vectorised phasors of contact_kernels.h, which must give phasor()'s bits.
struct PhasorConstants {
  static constexpr int kN = 1024;
  static constexpr double kStep = two_pi / kN;
  // k = round(θ/Δ) by the 1.5·2^52 shifter (exact for |θ/Δ| < 2^51; std::nearbyint is a libm
  // call here, ~10 % of a frame); then i = k mod N by masking (N is a power of two).
  static constexpr double kShifter = 6755399441055744.0;  // 1.5 · 2^52
  static_assert((kN & (kN - 1)) == 0, "the table length must be a power of two");
  double step_hi;
  double step_lo;
  std::array<Phasor, kN> table;
};

inline const PhasorConstants& phasor_constants() {
  static const PhasorConstants kConstants = [] {
    PhasorConstants p{};
    const double step = PhasorConstants::kStep;
    const double scale = std::ldexp(1.0, 33 - std::ilogb(step));
    p.step_hi = std::nearbyint(step * scale) / scale;
    // 2π/N − hi to double precision, from the long-double value of 2π.
    const long double exact = 2 * pi_long / PhasorConstants::kN;
    p.step_lo = static_cast<double>(exact - p.step_hi);
    for (int i = 0; i < PhasorConstants::kN; ++i) {
      const long double a = 2 * pi_long * i / PhasorConstants::kN;
      p.table[static_cast<std::size_t>(i)] = {static_cast<double>(std::cos(a)),
                                              static_cast<double>(std::sin(a))};
    }
    return p;
  }();
  return kConstants;
}

inline Phasor phasor(double theta) {
  using C = PhasorConstants;
  const PhasorConstants& p = phasor_constants();
  const double k = (theta / C::kStep + C::kShifter) - C::kShifter;
  const double r = (theta - k * p.step_hi) - k * p.step_lo;
  const double r2 = r * r;
  const double cr = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320))));
  const double sr =
      r * (1.0 + r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880)))));
  const auto i = static_cast<std::size_t>(static_cast<long long>(k) & (C::kN - 1));
  const Phasor& t = p.table[i];
  return {t.c * cr - t.s * sr, t.s * cr + t.c * sr};
}

}  // namespace bearing::detail
