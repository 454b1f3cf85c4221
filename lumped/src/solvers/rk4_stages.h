#pragma once
// The O(n) arithmetic of one RK4 step (rk4.cc), apart so that it is compiled twice: inline in
// rk4.cc, which is built without the loop vectoriser (for 2 or 3 DOFs its packed loads of what
// force() has just stored one DOF at a time miss store forwarding: ~1 ms of a 45 ms run), and
// vectorised in rk4_wide.cc for the ball-DOF model's 2Z + 2 or 3 DOFs. Element by element, no
// sums across DOFs and no fused multiply–add at the baseline x86-64: the two give the same bits.

namespace bearing::solvers_detail {

/// The arrays of one integrate() call (n doubles each).
struct Rk4Arrays {
  double* q;   ///< state displacement
  double* v;   ///< state velocity
  double* a;   ///< a₁ = M⁻¹ f(t, q, v)
  double* qs;  ///< stage displacement
  double* vs;  ///< stage velocity v₂, v₃, v₄
  double* as;  ///< stage acceleration a₂, a₃, a₄
  double* sq;  ///< v + 2v₂ + 2v₃ (+ v₄)
  double* sv;  ///< a₁ + 2a₂ + 2a₃ (+ a₄)
  int n;
};

namespace rk4_inline {

/// a ← M⁻¹ a (w = 1/m per DOF).
inline void scale(double* a, const double* w, int n) {
  for (int i = 0; i < n; ++i) a[i] *= w[i];
}
/// The second stage's state from a₁.
inline void stage2(const Rk4Arrays& r, double hh) {
  for (int i = 0; i < r.n; ++i) {
    r.qs[i] = r.q[i] + hh * r.v[i];
    r.vs[i] = r.v[i] + hh * r.a[i];
  }
}
/// The third stage's state from a₂.
inline void stage3(const Rk4Arrays& r, double hh) {
  for (int i = 0; i < r.n; ++i) {
    r.sq[i] = r.v[i] + 2.0 * r.vs[i];
    r.sv[i] = r.a[i] + 2.0 * r.as[i];
    r.qs[i] = r.q[i] + hh * r.vs[i];
    r.vs[i] = r.v[i] + hh * r.as[i];
  }
}
/// The fourth stage's state from a₃.
inline void stage4(const Rk4Arrays& r, double h) {
  for (int i = 0; i < r.n; ++i) {
    r.sq[i] += 2.0 * r.vs[i];
    r.sv[i] += 2.0 * r.as[i];
    r.qs[i] = r.q[i] + h * r.vs[i];
    r.vs[i] = r.v[i] + h * r.as[i];
  }
}
/// The step's end from a₄.
inline void finish(const Rk4Arrays& r, double h6) {
  for (int i = 0; i < r.n; ++i) {
    r.q[i] += h6 * (r.sq[i] + r.vs[i]);
    r.v[i] += h6 * (r.sv[i] + r.as[i]);
  }
}

}  // namespace rk4_inline

/// The same, vectorised (rk4_wide.cc).
namespace rk4_wide {
void scale(double* a, const double* w, int n);
void stage2(const Rk4Arrays& r, double hh);
void stage3(const Rk4Arrays& r, double hh);
void stage4(const Rk4Arrays& r, double h);
void finish(const Rk4Arrays& r, double h6);
}  // namespace rk4_wide

/// From this many DOFs on, rk4.cc uses rk4_wide (the ball-DOF model; not the 2- and 3-DOF ones).
inline constexpr int kRk4WideDofs = 4;

}  // namespace bearing::solvers_detail
