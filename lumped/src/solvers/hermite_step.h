#pragma once
// Private to the solvers (not installed): the adaptive methods' dense-output interpolant
// (gsl_adaptive.cc, event_adaptive.cc).

#include <algorithm>
#include <cstddef>
#include <vector>

namespace bearing {
namespace solvers_detail {

/// Dense output of the adaptive methods on one accepted step [t₀, t₁], h = t₁ − t₀, from q,
/// v = q' and a = q'' at the step's ends and, optionally, at one or two more nodes outside the
/// step (the start of the previous step, the end of the next one). With s = (t − t₀)/h:
///
/// Quintic Hermite (two nodes, six conditions per DOF):
///     p₅(s) = q₀ + h v₀ s + ½h² a₀ s² + s³ (c₃ + c₄ s + c₅ s²),
///     c₃ = 10 D₀ − 4 D₁ + ½ D₂,   c₄ = −15 D₀ + 7 D₁ − D₂,   c₅ = 6 D₀ − 3 D₁ + ½ D₂,
///     D₀ = q₁ − q₀ − h v₀ − ½h² a₀,   D₁ = h (v₁ − v₀ − h a₀),   D₂ = h² (a₁ − a₀),
/// matches q, h q', h² q'' at s = 0 and 1 and reproduces polynomials of degree ≤ 5. For a smooth
/// solution q − p₅ = q⁽⁶⁾(ξ)/6! · (t − t₀)³ (t − t₁)³: O(h⁶) in q (interpolation order 5),
/// at most h⁶ max|q⁽⁶⁾| / 46 080, and, from its derivative, O(h⁵) in v (≲ h⁵ max|q⁽⁶⁾| / 13 400).
/// For a mode ω, amplitude A: 2.2e-5 (ωh)⁶ A in q and 7.5e-5 (ωh)⁵ ωA in v.
///
/// Degree 8 (three nodes, nine conditions; Hermite–Birkhoff with the third node at σ = (t₂ − t₀)/h,
/// σ < 0 or σ > 1):
///     p₈(s) = p₅(s) + w(s) g(s),   w(s) = s³ (s − 1)³,   g(s) = g₀ + g₁ (s − σ) + ½ g₂ (s − σ)²,
/// where w keeps the six conditions at s = 0, 1, and g₀, g₁, g₂ make p₈, p₈', p₈'' equal q₂, h v₂,
/// h² a₂ at σ:
///     g₀ = E₀/w,   g₁ = (E₁ − w' g₀)/w,   g₂ = (E₂ − w'' g₀ − 2 w' g₁)/w   (w and its
///     derivatives at σ),   E₀ = q₂ − p₅(σ),   E₁ = h v₂ − p₅'(σ),   E₂ = h² a₂ − p₅''(σ).
/// It reproduces polynomials of degree ≤ 8: q − p₈ = q⁽⁹⁾(ξ)/9! · (t − t₂)³ (t − t₀)³ (t − t₁)³,
/// O(h⁹) in q (interpolation order 8) and O(h⁸) in v; with equal steps at most
/// 0.057 h⁹ max|q⁽⁹⁾| / 9! = 1.6e-7 (ωh)⁹ A.
///
/// Degree 11 (four nodes, rk8pd-events, issue 42; the fourth at τ = (t₃ − t₀)/h on the other
/// side of the step from σ), the same construction once more:
///     p₁₁(s) = p₈(s) + W(s) m(s),   W(s) = w(s) (s − σ)³,   m(s) = m₀ + m₁ (s − τ) + ½ m₂ (s −
///     τ)²,
/// m₀, m₁, m₂ from the fourth node's q₃, h v₃, h² a₃ as g₀, g₁, g₂ above (W for w, p₈ for p₅).
/// q − p₁₁ = q⁽¹²⁾(ξ)/12! · (t − t₂)³ (t − t₀)³ (t − t₁)³ (t − t₃)³; with equal steps at most
/// 0.178 h¹² max|q⁽¹²⁾| / 12! = 3.7e-10 (ωh)¹² A, 50× below p₈ at ωh = 2.
///
/// In all, v = p'(s)/h, the derivative of the same polynomial, so the interpolated (q, v) are
/// consistent (v = dq/dt along the interpolant) and no third derivative (jerk, which would take
/// the Jacobian) is needed. At s = 0 and s = 1 the step's own values are returned exactly.
/// Optionally also a = p''(s)/h² (rk8pd-events' outputs): it matches a at every node; O(h⁴) for
/// the quintic, O(h⁷) for p₈, O(h¹⁰) for p₁₁.
class HermiteStep {
 public:
  /// q, v, a at t₀ (q0, v0, a0) and at t₁ (q1, v1, a1), n entries each; read now, not kept.
  void set(int n, double t0, double t1, const double* q0, const double* v0, const double* a0,
           const double* q1, const double* v1, const double* a1) {
    n_ = n;
    t0_ = t0;
    t1_ = t1;
    h_ = t1 - t0;
    third_ = false;
    fourth_ = false;
    c_.resize(kRows * static_cast<std::size_t>(n));
    const double h = h_;
    for (int i = 0; i < n; ++i) {
      const double hv0 = h * v0[i], hha0 = h * h * a0[i];
      const double d0 = q1[i] - q0[i] - hv0 - 0.5 * hha0;
      const double d1 = h * (v1[i] - v0[i]) - hha0;
      const double d2 = h * h * a1[i] - hha0;
      coef(kQ0)[i] = q0[i];
      coef(kV0)[i] = v0[i];
      coef(kHv0)[i] = hv0;
      coef(kC2)[i] = 0.5 * hha0;
      coef(kC3)[i] = 10.0 * d0 - 4.0 * d1 + 0.5 * d2;
      coef(kC4)[i] = -15.0 * d0 + 7.0 * d1 - d2;
      coef(kC5)[i] = 6.0 * d0 - 3.0 * d1 + 0.5 * d2;
      coef(kQ1)[i] = q1[i];
      coef(kV1)[i] = v1[i];
      coef(kA0)[i] = a0[i];
      coef(kA1)[i] = a1[i];
    }
  }

  /// Raises the interpolant to degree 8 with q, v, a at a third node t2 outside [t₀, t₁].
  void add_node(double t2, const double* q2, const double* v2, const double* a2) {
    const int n = n_;
    const double h = h_;
    const double sg = (t2 - t0_) / h;
    sigma_ = sg;
    const double u = sg * (sg - 1.0), du = 2.0 * sg - 1.0;
    const double w = u * u * u, dw = 3.0 * u * u * du, ddw = 6.0 * u * (du * du + u);
    for (int i = 0; i < n; ++i) {
      const double c2 = coef(kC2)[i], c3 = coef(kC3)[i], c4 = coef(kC4)[i], c5 = coef(kC5)[i];
      const double hv0 = coef(kHv0)[i];
      const double p = coef(kQ0)[i] + sg * (hv0 + sg * (c2 + sg * (c3 + sg * (c4 + sg * c5))));
      const double dp = hv0 + sg * (2.0 * c2 + sg * (3.0 * c3 + sg * (4.0 * c4 + sg * 5.0 * c5)));
      const double ddp = 2.0 * c2 + sg * (6.0 * c3 + sg * (12.0 * c4 + sg * 20.0 * c5));
      const double e0 = q2[i] - p, e1 = h * v2[i] - dp, e2 = h * h * a2[i] - ddp;
      const double g0 = e0 / w;
      const double g1 = (e1 - dw * g0) / w;
      coef(kG0)[i] = g0;
      coef(kG1)[i] = g1;
      coef(kG2)[i] = (e2 - ddw * g0 - 2.0 * dw * g1) / w;
    }
    third_ = true;
  }

  /// Raises the degree-8 interpolant (add_node first) to degree 11 with q, v, a at a fourth
  /// node t3 outside [t₀, t₁], on the other side of the step from the third.
  void add_fourth_node(double t3, const double* q3, const double* v3, const double* a3) {
    const double h = h_;
    const double tau = (t3 - t0_) / h;
    double big_w, dbig_w, ddbig_w;
    fourth_weight(tau, &big_w, &dbig_w, &ddbig_w);
    for (int i = 0; i < n_; ++i) {
      double p, dp, ddp;
      degree8(i, tau, &p, &dp, &ddp);
      const double e0 = q3[i] - p, e1 = h * v3[i] - dp, e2 = h * h * a3[i] - ddp;
      const double m0 = e0 / big_w;
      const double m1 = (e1 - dbig_w * m0) / big_w;
      coef(kM0)[i] = m0;
      coef(kM1)[i] = m1;
      coef(kM2)[i] = (e2 - ddbig_w * m0 - 2.0 * dbig_w * m1) / big_w;
    }
    tau_ = tau;
    fourth_ = true;
  }

  /// Whether add_node() raised the interpolant to degree 8 (or more).
  bool has_third_node() const { return third_; }
  /// Whether add_fourth_node() raised it to degree 11.
  bool has_fourth_node() const { return fourth_; }

  /// q(t) and v(t) for t in [t₀, t₁] (n entries each), and a(t) too unless a is null.
  void at(double t, double* q, double* v, double* a = nullptr) const {
    const int n = n_;
    if (t == t0_ || t == t1_) {
      const bool first = t == t0_;
      std::copy(coef(first ? kQ0 : kQ1), coef(first ? kQ0 : kQ1) + n, q);
      std::copy(coef(first ? kV0 : kV1), coef(first ? kV0 : kV1) + n, v);
      if (a) std::copy(coef(first ? kA0 : kA1), coef(first ? kA0 : kA1) + n, a);
      return;
    }
    const double s = (t - t0_) / h_;
    const double inv_h = 1.0 / h_;
    double big_w = 0.0, dbig_w = 0.0, ddbig_w = 0.0;
    if (fourth_) fourth_weight(s, &big_w, &dbig_w, &ddbig_w);
    const double y = s - tau_;
    for (int i = 0; i < n; ++i) {
      double p, dp, ddp;
      degree8(i, s, &p, &dp, &ddp);
      if (fourth_) {
        const double m1 = coef(kM1)[i], m2 = coef(kM2)[i];
        const double m = coef(kM0)[i] + y * (m1 + 0.5 * m2 * y), dm = m1 + m2 * y;
        p += big_w * m;
        dp += dbig_w * m + big_w * dm;
        ddp += ddbig_w * m + 2.0 * dbig_w * dm + big_w * m2;
      }
      q[i] = p;
      v[i] = dp * inv_h;
      if (a) a[i] = ddp * (inv_h * inv_h);
    }
  }

 private:
  // clang-format off
  enum Row { kQ0, kV0, kHv0, kC2, kC3, kC4, kC5, kQ1, kV1, kG0, kG1, kG2, kA0, kA1, kM0, kM1, kM2,
             kRows };
  // clang-format on
  double* coef(Row r) { return c_.data() + static_cast<std::size_t>(r) * n_; }
  const double* coef(Row r) const { return c_.data() + static_cast<std::size_t>(r) * n_; }

  // p, p', p'' (derivatives in s) of DOF i at s: the quintic, plus w g with the third node.
  void degree8(int i, double s, double* p, double* dp, double* ddp) const {
    const double c2 = coef(kC2)[i], c3 = coef(kC3)[i], c4 = coef(kC4)[i], c5 = coef(kC5)[i];
    const double hv0 = coef(kHv0)[i];
    *p = coef(kQ0)[i] + s * (hv0 + s * (c2 + s * (c3 + s * (c4 + s * c5))));
    *dp = hv0 + s * (2.0 * c2 + s * (3.0 * c3 + s * (4.0 * c4 + s * 5.0 * c5)));
    *ddp = 2.0 * c2 + s * (6.0 * c3 + s * (12.0 * c4 + s * 20.0 * c5));
    if (!third_) return;
    const double u = s * (s - 1.0), du = 2.0 * s - 1.0;
    const double w = u * u * u, dw = 3.0 * u * u * du, ddw = 6.0 * u * (du * du + u);
    const double x = s - sigma_;
    const double g1 = coef(kG1)[i], g2 = coef(kG2)[i];
    const double g = coef(kG0)[i] + x * (g1 + 0.5 * g2 * x), dg = g1 + g2 * x;
    *p += w * g;
    *dp += dw * g + w * dg;
    *ddp += ddw * g + 2.0 * dw * dg + w * g2;
  }

  // W(s) = s³ (s − 1)³ (s − σ)³ and its first two derivatives.
  void fourth_weight(double s, double* big_w, double* dbig_w, double* ddbig_w) const {
    const double u = s * (s - 1.0), du = 2.0 * s - 1.0;
    const double w = u * u * u, dw = 3.0 * u * u * du, ddw = 6.0 * u * (du * du + u);
    const double x = s - sigma_, x2 = x * x, x3 = x2 * x;
    *big_w = w * x3;
    *dbig_w = dw * x3 + 3.0 * w * x2;
    *ddbig_w = ddw * x3 + 6.0 * dw * x2 + 6.0 * w * x;
  }

  int n_ = 0;
  double t0_ = 0.0, t1_ = 0.0, h_ = 0.0, sigma_ = 0.0, tau_ = 0.0;
  bool third_ = false, fourth_ = false;
  // rows of n: q₀, v₀, h v₀, ½h²a₀, c₃, c₄, c₅, q₁, v₁, g₀, g₁, g₂, a₀, a₁, m₀, m₁, m₂
  std::vector<double> c_;
};

}  // namespace solvers_detail
}  // namespace bearing
