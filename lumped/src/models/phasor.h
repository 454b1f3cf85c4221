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

inline Phasor phasor(double theta) {
  constexpr int kN = 1024;
  // Δ = 2π/N split as hi + lo: hi has 33 significant bits so k·hi is exact for |k| < 2^20.
  constexpr double kStep = two_pi / kN;
  static const double kStepHi = [] {
    const double scale = std::ldexp(1.0, 33 - std::ilogb(kStep));
    return std::nearbyint(kStep * scale) / scale;
  }();
  static const double kStepLo = [] {
    const double scale = std::ldexp(1.0, 33 - std::ilogb(kStep));
    // 2π/N − hi to double precision, from the long-double value of 2π.
    const long double exact = 2 * pi_long / kN;
    return static_cast<double>(exact - std::nearbyint(kStep * scale) / scale);
  }();
  static const std::array<Phasor, kN> kTable = [] {
    std::array<Phasor, kN> t{};
    for (int i = 0; i < kN; ++i) {
      const long double a = 2 * pi_long * i / kN;
      t[static_cast<std::size_t>(i)] = {static_cast<double>(std::cos(a)),
                                        static_cast<double>(std::sin(a))};
    }
    return t;
  }();

  // k = round(θ/Δ) by the 1.5·2^52 shifter (exact for |θ/Δ| < 2^51; std::nearbyint is a libm
  // call here, ~10 % of a frame); then i = k mod N by masking (N is a power of two).
  constexpr double kShifter = 6755399441055744.0;  // 1.5 · 2^52
  static_assert((kN & (kN - 1)) == 0, "the table length must be a power of two");
  const double k = (theta / kStep + kShifter) - kShifter;
  const double r = (theta - k * kStepHi) - k * kStepLo;
  const double r2 = r * r;
  const double cr = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24 + r2 * (-1.0 / 720 + r2 * (1.0 / 40320))));
  const double sr =
      r * (1.0 + r2 * (-1.0 / 6 + r2 * (1.0 / 120 + r2 * (-1.0 / 5040 + r2 * (1.0 / 362880)))));
  const auto i = static_cast<std::size_t>(static_cast<long long>(k) & (kN - 1));
  const Phasor& p = kTable[i];
  return {p.c * cr - p.s * sr, p.s * cr + p.c * sr};
}

}  // namespace bearing::detail
