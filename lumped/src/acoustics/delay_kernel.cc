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

// Eight doubles: one AVX-512 register, two AVX2, four SSE2; the arithmetic is element-wise
// (GCC's and Clang's vector extension), so every clone computes the same lanes.
typedef double Lanes __attribute__((vector_size(8 * sizeof(double))));
static_assert(kDelayTaps % 8 == 0, "whole vectors of taps");

// Samples per block: each pass over a block is one short loop whose iterations do not wait on
// each other (a whole sample in one iteration was a chain of ~50 cycles: position, table row,
// weights, sums, geometry); the block's arrays stay in the L1 cache.
constexpr std::size_t kBlock = 128;

// Where the taps of one delayed sample are: table row p, fraction w, first sample.
struct TapSpot {
  int p;
  double w;
  std::size_t first;
};

// The first tap's sample, floor(s) − kHalfWidth + 1 modulo N (one wrap at most for a delay
// shorter than the record; the remainder otherwise).
BEARING_KERNEL_INLINE std::size_t first_tap(double floor_s, std::size_t n) {
  long first = static_cast<long>(floor_s) - kHalfWidth + 1;
  const long length = static_cast<long>(n);
  if (first < 0) first += length;
  if (first < 0 || first >= length) first = ((first % length) + length) % length;
  return static_cast<std::size_t>(first);
}

BEARING_KERNEL_INLINE TapSpot tap_spot(double s, std::size_t n) {
  const double floor_s = std::floor(s);
  const double phase = (s - floor_s) * kPhases;
  const int p = std::min(static_cast<int>(phase), kPhases - 1);
  return {p, phase - p, first_tap(floor_s, n)};
}

// value[m] = Σ_t w_t q_m(first + t), the weights interpolated linearly between the table's rows
// (PeriodicInterpolator::taps' formula); the 32 products in 8 partial sums (t mod 8), added
// pairwise at the end.
template <int M>
BEARING_KERNEL_INLINE void tap_sums(const DelayedPlacement& pl, const TapSpot& at, double* value) {
  alignas(64) double weight[kDelayTaps];
  interpolate_rows(pl.table, at.p, at.w, weight);
  Lanes acc[M] = {};
  for (int b = 0; b < kDelayTaps; b += 8) {
    Lanes wb, x;  // no function returning Lanes: its ABI differs between the clones
    std::memcpy(&wb, weight + b, sizeof wb);
    for (int m = 0; m < M; ++m) {
      std::memcpy(&x, pl.terms[m] + at.first + b, sizeof x);
      acc[m] += wb * x;
    }
  }
  for (int m = 0; m < M; ++m)
    value[m] = ((acc[m][0] + acc[m][1]) + (acc[m][2] + acc[m][3])) +
               ((acc[m][4] + acc[m][5]) + (acc[m][6] + acc[m][7]));
}

// Samples i0 … i0 + k − 1 in three passes: where each delayed position falls, the tap sums, then
// p_i = Θ_i Σ_m (a/r_i)^m (value_m + ramp_m) (each (a/r)^m as repeated products of a/r).
template <int M>
BEARING_KERNEL_INLINE void place_block(const DelayedPlacement& pl, std::size_t i0, std::size_t k,
                                       double* p) {
  TapSpot spot[kBlock];
  bool on_sample[kBlock];
  for (std::size_t j = 0; j < k; ++j) {
    const double i = static_cast<double>(i0 + j);
    const double s = i - (pl.distance[i0 + j] - pl.a) * pl.samples_per_metre;
    on_sample[j] = s == i;  // the record's own value, exactly
    spot[j] = tap_spot(s, pl.n);
  }
  double value[M][kBlock];
  for (std::size_t j = 0; j < k; ++j) {
    double v[M];
    if (on_sample[j]) {
      for (int m = 0; m < M; ++m) v[m] = pl.terms[m][i0 + j];
    } else {
      tap_sums<M>(pl, spot[j], v);
    }
    for (int m = 0; m < M; ++m) value[m][j] = v[m];
  }
  double ratio[kBlock], sum[kBlock] = {};
  for (std::size_t j = 0; j < k; ++j) ratio[j] = pl.a / pl.distance[i0 + j];
  for (int m = 0; m < M; ++m) {
    double power[kBlock];
    for (std::size_t j = 0; j < k; ++j) power[j] = 1;
    for (int e = 0; e < pl.powers[m]; ++e)
      for (std::size_t j = 0; j < k; ++j) power[j] *= ratio[j];
    for (std::size_t j = 0; j < k; ++j) sum[j] += power[j] * (value[m][j] + pl.ramp[m]);
  }
  for (std::size_t j = 0; j < k; ++j)
    p[i0 + j] = (pl.cos_angle ? pl.cos_angle[i0 + j] : 1.0) * sum[j];
}

template <int M>
BEARING_KERNEL_INLINE void place(const DelayedPlacement& pl, double* p) {
  for (std::size_t i = 0; i < pl.n; i += kBlock)
    place_block<M>(pl, i, std::min(kBlock, pl.n - i), p);
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
