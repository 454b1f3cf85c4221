// The delayed placement of a moving source's filtered record (delay_kernel.h). Compiled per
// instruction set (bearing/target_clones.h) without fused multiply-adds: each tap sum runs in 8
// partial sums, lane by lane the same arithmetic in every clone, so every clone gives the same
// bits.

#include "delay_kernel.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <stdexcept>

#include "bearing/target_clones.h"

namespace bearing::detail {

namespace {

// Θ_n Σ_m (a/r_n)^m (value_m + ramp_m), in the order pressure_from always used.
template <int M>
inline double combine(const DelayedPlacement& pl, std::size_t i, const double* value) {
  const double r = pl.distance[i];
  double sum = 0;
  for (int m = 0; m < M; ++m) {
    double weight = 1;  // (a/r)^m, m a small whole number
    for (int e = 0; e < pl.powers[m]; ++e) weight *= pl.a / r;
    sum += weight * (value[m] + pl.ramp[m]);
  }
  return (pl.cos_angle ? pl.cos_angle[i] : 1.0) * sum;
}

// Eight doubles: one AVX-512 register, two AVX2, four SSE2; the arithmetic is element-wise
// (GCC's and Clang's vector extension), so every clone computes the same lanes.
typedef double Lanes __attribute__((vector_size(8 * sizeof(double))));
static_assert(kDelayTaps % 8 == 0, "whole vectors of taps");

// The first tap's sample, floor(s) − kHalfWidth + 1 modulo N (one wrap at most for a delay
// shorter than the record; the remainder otherwise).
inline std::size_t first_tap(double floor_s, std::size_t n) {
  long first = static_cast<long>(floor_s) - kHalfWidth + 1;
  const long length = static_cast<long>(n);
  if (first < 0) first += length;
  if (first < 0 || first >= length) first = ((first % length) + length) % length;
  return static_cast<std::size_t>(first);
}

// value[m] = Σ_t w_t q_m(first + t), the weights interpolated linearly between the table's rows
// (PeriodicInterpolator::taps' formula); the 32 products in 8 partial sums (t mod 8), added
// pairwise at the end.
template <int M>
inline void tap_sums(const DelayedPlacement& pl, double s, double* value) {
  const double floor_s = std::floor(s);
  const double phase = (s - floor_s) * kPhases;
  const int p = std::min(static_cast<int>(phase), kPhases - 1);
  alignas(64) double weight[kDelayTaps];
  interpolate_rows(pl.table, p, phase - p, weight);
  const std::size_t first = first_tap(floor_s, pl.n);
  Lanes acc[M] = {};
  for (int b = 0; b < kDelayTaps; b += 8) {
    Lanes wb, x;  // no function returning Lanes: its ABI differs between the clones
    std::memcpy(&wb, weight + b, sizeof wb);
    for (int m = 0; m < M; ++m) {
      std::memcpy(&x, pl.terms[m] + first + b, sizeof x);
      acc[m] += wb * x;
    }
  }
  for (int m = 0; m < M; ++m)
    value[m] = ((acc[m][0] + acc[m][1]) + (acc[m][2] + acc[m][3])) +
               ((acc[m][4] + acc[m][5]) + (acc[m][6] + acc[m][7]));
}

template <int M>
inline void place(const DelayedPlacement& pl, double* p) {
  for (std::size_t i = 0; i < pl.n; ++i) {
    const double s = static_cast<double>(i) - (pl.distance[i] - pl.a) * pl.samples_per_metre;
    double value[M];
    if (s == static_cast<double>(i)) {  // on a sample: the record's own value
      for (int m = 0; m < M; ++m) value[m] = pl.terms[m][i];
    } else {
      tap_sums<M>(pl, s, value);
    }
    p[i] = combine<M>(pl, i, value);
  }
}

BEARING_TARGET_CLONES void place1(const DelayedPlacement& pl, double* p) {
  place<1>(pl, p);
}
BEARING_TARGET_CLONES void place2(const DelayedPlacement& pl, double* p) {
  place<2>(pl, p);
}
BEARING_TARGET_CLONES void place3(const DelayedPlacement& pl, double* p) {
  place<3>(pl, p);
}

}  // namespace

void place_delayed(const DelayedPlacement& pl, int terms, double* p) {
  switch (terms) {
    case 1:
      return place1(pl, p);
    case 2:
      return place2(pl, p);
    case 3:
      return place3(pl, p);
    default:
      throw std::logic_error("place_delayed: a source of more than 3 terms");
  }
}

}  // namespace bearing::detail
