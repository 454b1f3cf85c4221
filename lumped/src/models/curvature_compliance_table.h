#pragma once
// Private to the lumped models (not installed): TVDS's relative compliance g(Δ) of a race contact
// whose rolling-direction curvature changed by Δ (race_stiffness.h derives Δ from the waviness),
// tabulated once. Per contact, with Δ = Δρ_II1, Σρ = Σρ₀ + Δ and
// F = (ρ_II1 − ρ_II2)/Σρ = (num₀ + Δ)/(Σρ₀ + Δ) (the ball terms cancel in the numerator), and
// K = 2^{5/2} / (3η δ*^{3/2} Σρ^{1/2}) gives
//     K^{−2/3} = K₀^{−2/3} · g(Δ),   g(Δ) = [δ*(F(Δ))/δ*(F₀)] · (1 + Δ/Σρ₀)^{1/3},
// scaled from the race's own constant K₀ so that zero waviness reproduces TVD exactly (and a
// calibrated K₀ keeps its calibration). g depends on Δ alone: it is tabulated once, with the
// case's Hertz method, over every Δ the waviness can reach (|Π + Π''| ≤ Σ A_s |N_s² − 1|), so
// the hot loop does one table lookup per race contact — no root finding, no cbrt.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/units.h"

namespace bearing::detail {

/// The relative compliance g(Δ) = K(Δ)^{−2/3} / K₀^{−2/3} = [δ*(F(Δ))/δ*(F₀)] · (1 + Δ/Σρ₀)^{1/3}
/// of one race contact whose rolling-direction curvature changed by Δ [1/m], with
/// F(Δ) = (num₀ + Δ)/(Σρ₀ + Δ): a function of Δ alone, tabulated once on a uniform grid through
/// Δ = 0 (where it is exactly 1) and interpolated by cubic Hermite with fourth-order difference
/// slopes, so the hot loop needs neither root finding nor cbrt.
class CurvatureComplianceTable {
 public:
  CurvatureComplianceTable() = default;
  CurvatureComplianceTable(const HertzSolution& method, double num0, double sum0, double bound,
                           const std::string& key) {
    // 32 intervals on each side of Δ = 0 up to ±bound (a floor on h for bound → 0).
    h_ = std::max(bound / 32.0, 1e-9 * sum0);
    const int side = static_cast<int>(std::ceil(bound / h_)) + 1;
    const int ghost = 2;  // extra nodes for the difference slopes at the ends
    const int nodes = 2 * (side + ghost) + 1;
    std::vector<double> g(nodes);
    const double f0 = num0 / sum0;
    const double ds0 = method.shape(f0).delta_star;
    for (int k = 0; k < nodes; ++k) {
      const int i = k - side - ghost;
      if (i == 0) {
        g[k] = 1.0;
        continue;
      }
      const double d = i * h_;
      const double sum = sum0 + d, f = (num0 + d) / sum;
      if (!(sum > 0 && f >= 0 && f < 1))
        throw InputError(key +
                         " with model.waviness_stiffness (TVDS): the waviness changes the "
                         "raceway curvature by up to " +
                         format_number(bound) +
                         " 1/m, which takes the contact's curvature sum to " + format_number(sum) +
                         " 1/m and F(rho) to " + format_number(f) +
                         ": too large for the first-order curvature model");
      g[k] = method.shape(f).delta_star / ds0 * std::cbrt(sum / sum0);
    }
    first_ = -side * h_;
    const int n = 2 * side + 1;
    y_.resize(n);
    m_.resize(n);
    for (int i = 0; i < n; ++i) {
      const int k = i + ghost;
      y_[i] = g[k];
      m_[i] = (g[k - 2] - 8.0 * g[k - 1] + 8.0 * g[k + 1] - g[k + 2]) / 12.0;  // dg/du, u = Δ/h
    }
  }

  /// dg/dΔ [m], the derivative of the same cubic Hermite interpolant.
  double derivative(double d) const {
    const double u = (d - first_) / h_;
    const int last = static_cast<int>(y_.size()) - 2;
    int i = static_cast<int>(std::floor(u));
    i = std::min(std::max(i, 0), last);
    const double t = u - i;
    const double t2 = t * t;
    return ((6 * t2 - 6 * t) * y_[i] + (3 * t2 - 4 * t + 1) * m_[i] +
            (-6 * t2 + 6 * t) * y_[i + 1] + (3 * t2 - 2 * t) * m_[i + 1]) /
           h_;
  }

  /// g(Δ); exact at the nodes (1 at Δ = 0).
  double operator()(double d) const {
    const double u = (d - first_) / h_;
    const int last = static_cast<int>(y_.size()) - 2;
    int i = static_cast<int>(std::floor(u));
    i = std::min(std::max(i, 0), last);
    const double t = u - i;
    const double t2 = t * t, t3 = t2 * t;
    return (2 * t3 - 3 * t2 + 1) * y_[i] + (t3 - 2 * t2 + t) * m_[i] +
           (-2 * t3 + 3 * t2) * y_[i + 1] + (t3 - t2) * m_[i + 1];
  }

 private:
  double first_ = 0, h_ = 1;
  std::vector<double> y_, m_;
};

}  // namespace bearing::detail
