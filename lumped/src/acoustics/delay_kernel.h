#pragma once
// The hot loop of a moving source's pressure (pressure.h, pressure_from): at every sample the
// delayed values q_m(t_n − τ_n) by the Kaiser-windowed sinc of PeriodicInterpolator, weighted by
// the geometry. Private to the acoustics library.

#include <cstddef>

namespace bearing::detail {

// The interpolation kernel: 2·kHalfWidth taps, tabulated at kPhases fractional positions per
// sample: row p holds the kDelayTaps weights at phase p / kPhases. The kernel is even, so row
// kPhases − p is row p reversed: PeriodicInterpolator's table holds rows 0 … kPhases/2 only
// (kTableRows; 264 kB, half the cache the whole table would take).
constexpr int kHalfWidth = 16;
constexpr int kDelayTaps = 2 * kHalfWidth;
constexpr int kPhases = 2048;
constexpr int kTableRows = kPhases / 2 + 1;

// Inlined into each instruction set's clone of the kernel (an out-of-line helper would be
// compiled for the baseline only).
#if defined(__GNUC__)
#define BEARING_KERNEL_INLINE inline __attribute__((always_inline))
#else
#define BEARING_KERNEL_INLINE inline
#endif

// The weights at phase (p + w) / kPhases, 0 ≤ p < kPhases, 0 ≤ w ≤ 1: rows p and p + 1 of the
// kernel interpolated linearly, (1 − w) row_p + w row_{p+1}, from the half table.
BEARING_KERNEL_INLINE void interpolate_rows(const double* table, int p, double w, double* weight) {
  const double v = 1 - w;
  if (p < kPhases / 2) {
    const double* k0 = table + static_cast<std::size_t>(p) * kDelayTaps;
    const double* k1 = k0 + kDelayTaps;
    for (int i = 0; i < kDelayTaps; ++i) weight[i] = v * k0[i] + w * k1[i];
  } else {  // rows kPhases − p and kPhases − p − 1, reversed
    const double* k0 = table + static_cast<std::size_t>(kPhases - p) * kDelayTaps + kDelayTaps - 1;
    const double* k1 = k0 - kDelayTaps;
    for (int i = 0; i < kDelayTaps; ++i) weight[i] = v * k0[-i] + w * k1[-i];
  }
}

// What place_delayed needs: one source's filtered terms (each N + kDelayTaps − 1 samples, continued
// periodically: FilteredRecord::term) and its path seen from one point.
struct DelayedPlacement {
  const double* const* terms;  // M records
  std::size_t n;               // samples N
  const double* distance;      // r_n [m]
  const double* cos_angle;     // cos ψ_n, or nullptr for a breathing body (Θ = 1)
  const int* powers;           // of (a/r), one per term
  const double* ramp;          // one per term [Pa]
  double a;                    // the body's radius [m]
  double samples_per_metre;    // rate / c₀, or 0 for a field without delay
  const double* table;         // the kernel table, kTableRows rows of kDelayTaps
};

// p_n = Θ_n Σ_m (a/r_n)^m (q_m(t_n − τ_n) + ramp_m), n = 0 … N − 1, for M = 1, 2 or 3 terms.
void place_delayed(const DelayedPlacement& placement, int terms, double* p);

}  // namespace bearing::detail
