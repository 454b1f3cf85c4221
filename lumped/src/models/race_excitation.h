#pragma once
// Private to the lumped models (not installed): one race's waviness at the balls, Π(φ_j) and, for
// TVDS, Π + Π'' — for the hot loop folded by order mod Z (RaceExcitation), for the output
// instants by direct sums with the derivatives (profile_derivatives).
//
// Waviness (docs/model.md §5): Π(φ) = Σ_s A_s sin(N_s φ + ψ_s) at the race-fixed contact angle,
// φ_j = θ_j on the outer race and θ_j − ω_i t on the inner race. Written per order n as
//     Π(φ) = Σ_n a_n sin nφ + b_n cos nφ,   a_n = Σ_{N_s = n} A_s cos ψ_s,  b_n = Σ A_s sin ψ_s.
// The balls are evenly spaced on each race, φ_j = φ_ref + 2πj/Z, so with β_nj = 2π n j / Z
//     a_n sin(nφ_j) + b_n cos(nφ_j) = P_n cos β_nj + Q_n sin β_nj,
//     P_n = a_n sin nφ_ref + b_n cos nφ_ref,   Q_n = a_n cos nφ_ref − b_n sin nφ_ref,
// and β_nj depends on n only through k = n mod Z. Hence, per instant,
//   1. sin nφ_ref, cos nφ_ref for n = 1…N_max by the Chebyshev recurrence
//      sin((n+1)φ) = 2 cos φ sin(nφ) − sin((n−1)φ) (likewise cos) from the one (cos, sin) of φ_ref
//      (run as Z independent chains of step Zφ, one per bin: RaceExcitation);
//   2. fold the orders into Z bins, U_k = Σ_{n≡k} P_n, V_k = Σ_{n≡k} Q_n;
//   3. Π(φ_j) = Σ_k U_k cos(2πkj/Z) + V_k sin(2πkj/Z) with a precomputed Z×Z table.
// That is ~8 flops per order plus 4 per (ball, bin), instead of one recurrence per ball (for the
// 6308 with seed 003's 97 orders: ~1000 instead of ~5000 flops). It is also the physics of
// waviness seen by Z balls: orders N and N ± Z act alike on the ball set.

#include <algorithm>
#include <cmath>
#include <vector>

#include "bearing/excitation.h"
#include "max_balls.h"

namespace bearing::detail {

/// One race's waviness, folded by order mod Z (see the top of this file), for all balls at once.
///
/// Layout: order n = mZ + k sits in row m, column k (k = 0…Z−1, m = 0…rows−1); the columns are the
/// bins. Column k is one Chebyshev chain with step Zφ,
///     sin((n+Z)φ) = 2 cos(Zφ) sin(nφ) − sin((n−Z)φ)   (likewise cos),
/// started from sin(kφ) and sin((k−Z)φ) = −sin((Z−k)φ), which come from the step-φ recurrence
/// over the first Z orders. Each row is then a loop over contiguous arrays with no dependence
/// between columns (it vectorises), and each column accumulates its own bin. When N_max < Z there
/// is one row of N_max + 1 columns and no chain step.
class RaceExcitation {
 public:
  RaceExcitation() = default;
  RaceExcitation(const Waviness& w, int balls, bool curvature) : balls_(balls) {
    const int order_max = w.max_order();
    if (order_max == 0) return;
    rows_ = order_max / balls + 1;
    width_ = rows_ == 1 ? order_max + 1 : balls;
    a_.assign(rows_ * width_, 0.0);
    b_.assign(rows_ * width_, 0.0);
    for (const WavinessHarmonic& h : w.harmonics) {
      const int i = (h.order / balls) * width_ + h.order % balls;
      a_[i] += h.amplitude * std::cos(h.phase);
      b_[i] += h.amplitude * std::sin(h.phase);
    }
    curvature_ = curvature;
    if (curvature) {
      weight_.resize(rows_ * width_);
      for (int m = 0; m < rows_; ++m)
        for (int k = 0; k < width_; ++k) {
          const double n = double(m) * balls + k;
          weight_[m * width_ + k] = 1.0 - n * n;
        }
    }
  }

  bool empty() const { return rows_ == 0; }

  /// Adds Π(φ_ref + 2πj/Z) to profile[j] and, with curvature, writes (Π + Π'')(φ_j) to
  /// curv[j]; (c, s) = (cos φ_ref, sin φ_ref); table[j*Z + k] = (cos, sin)(2πkj/Z).
  void evaluate(double c, double s, const double* table_cos, const double* table_sin,
                double* profile, double* curv) const {
    if (rows_ == 0) return;
    if (curvature_)
      evaluate_impl<true>(c, s, table_cos, table_sin, profile, curv);
    else
      evaluate_impl<false>(c, s, table_cos, table_sin, profile, curv);
  }

 private:
  template <bool kCurvature>
  void evaluate_impl(double c, double s, const double* table_cos, const double* table_sin,
                     double* profile, double* curv) const {
    const int Z = balls_, W = width_;
    // sin(kφ), cos(kφ) for k = 0…W−1 (the chains' first row), and for k = Z if rows follow.
    double sn[kMaxBalls], cn[kMaxBalls], sp[kMaxBalls], cp[kMaxBalls];
    sn[0] = 0.0, cn[0] = 1.0;
    if (W > 1) sn[1] = s, cn[1] = c;
    const double two_c = 2.0 * c;
    for (int k = 2; k < W; ++k) {
      sn[k] = two_c * sn[k - 1] - sn[k - 2];
      cn[k] = two_c * cn[k - 1] - cn[k - 2];
    }
    double two_cz = 0.0;
    if (rows_ > 1) {  // W == Z: the previous row, orders k − Z, and cos Zφ
      const double sz = two_c * sn[Z - 1] - (Z >= 2 ? sn[Z - 2] : 0.0);
      const double cz = two_c * cn[Z - 1] - (Z >= 2 ? cn[Z - 2] : 1.0);
      sp[0] = -sz, cp[0] = cz;
      for (int k = 1; k < Z; ++k) sp[k] = -sn[Z - k], cp[k] = cn[Z - k];
      two_cz = 2.0 * cz;
    }
    double U[kMaxBalls], V[kMaxBalls], U2[kMaxBalls], V2[kMaxBalls];
    std::fill(U, U + W, 0.0);
    std::fill(V, V + W, 0.0);
    if (kCurvature) {
      std::fill(U2, U2 + W, 0.0);
      std::fill(V2, V2 + W, 0.0);
    }
    for (int m = 0; m < rows_; ++m) {
      const double* a = a_.data() + m * W;
      const double* b = b_.data() + m * W;
      const double* wt = kCurvature ? weight_.data() + m * W : nullptr;
      for (int k = 0; k < W; ++k) {
        const double p = a[k] * sn[k] + b[k] * cn[k];
        const double q = a[k] * cn[k] - b[k] * sn[k];
        U[k] += p;
        V[k] += q;
        if (kCurvature) {
          U2[k] += wt[k] * p;
          V2[k] += wt[k] * q;
        }
      }
      if (m + 1 == rows_) break;
      for (int k = 0; k < W; ++k) {
        const double s_next = two_cz * sn[k] - sp[k];
        const double c_next = two_cz * cn[k] - cp[k];
        sp[k] = sn[k], cp[k] = cn[k];
        sn[k] = s_next, cn[k] = c_next;
      }
    }
    for (int j = 0; j < Z; ++j) {
      const double* tc = table_cos + j * Z;
      const double* ts = table_sin + j * Z;
      double sum = 0.0;
      for (int k = 0; k < W; ++k) sum += U[k] * tc[k] + V[k] * ts[k];
      profile[j] += sum;
      if (kCurvature) {
        double sum2 = 0.0;
        for (int k = 0; k < W; ++k) sum2 += U2[k] * tc[k] + V2[k] * ts[k];
        curv[j] = sum2;
      }
    }
  }

  int balls_ = 0;
  int rows_ = 0;   // 0: no waviness
  int width_ = 0;  // columns per row: Z, or N_max + 1 < Z for a single row
  bool curvature_ = false;
  std::vector<double> a_, b_, weight_;  // row-major, rows_ × width_
};

/// Π, Π', Π + Π'' and Π' + Π''' of one race at the race-fixed angle φ, by direct sums over the
/// harmonics (for output instants; the hot loop uses RaceExcitation).
struct ProfileDerivatives {
  double profile = 0;     ///< Π [m]
  double slope = 0;       ///< dΠ/dφ [m/rad]
  double curv = 0;        ///< Π + Π'' [m] (TVDS curvature term)
  double curv_slope = 0;  ///< Π' + Π''' [m/rad]
};

inline ProfileDerivatives profile_derivatives(const Waviness& w, double phi) {
  ProfileDerivatives d;
  for (const WavinessHarmonic& h : w.harmonics) {
    const double N = h.order, a = N * phi + h.phase;
    const double s = h.amplitude * std::sin(a), c = h.amplitude * std::cos(a);
    d.profile += s;
    d.slope += N * c;
    d.curv += (1.0 - N * N) * s;
    d.curv_slope += N * (1.0 - N * N) * c;
  }
  return d;
}

}  // namespace bearing::detail
