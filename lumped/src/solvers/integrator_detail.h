#pragma once
// What the integrators share (private to lumped/src/solvers): the per-method factories that
// make_integrator dispatches to, validation of an integrate() call, the blow-up check, the
// adaptive methods' dense-output interpolant, the rule that lands a fixed step on an output time,
// and the progress throttle.

#include <algorithm>
#include <cmath>
#include <exception>
#include <limits>
#include <memory>
#include <string>
#include <vector>

#include <gsl/gsl_odeiv2.h>

#include "bearing/solvers/fixed_step.h"
#include "bearing/solvers/integrator.h"

namespace bearing {
namespace solvers_detail {

// Factories for the concrete methods; the settings are already validated by make_integrator.
std::unique_ptr<Integrator> make_rk4(const IntegratorSettings& settings);
/// method is "rkf45" or "rk8pd".
std::unique_ptr<Integrator> make_gsl_adaptive(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_newmark(const IntegratorSettings& settings);
std::unique_ptr<Integrator> make_bdf(const IntegratorSettings& settings);
/// rk8pd with contact events located (event_adaptive.cc).
std::unique_ptr<Integrator> make_event_adaptive(const IntegratorSettings& settings);

/// What the GSL callbacks see through gsl_odeiv2_system::params: the model and its force
/// workspace, 1/m, counters, work arrays for force_jacobian, and an exception the model threw
/// inside a callback (it is carried across GSL's C frames and rethrown after
/// gsl_odeiv2_evolve_apply returns).
struct GslContext {
  const MechanicalSystem* system = nullptr;
  MechanicalSystem::Workspace* workspace = nullptr;  ///< the system's, for force_with()
  int n = 0;
  const double* inv_mass = nullptr;  ///< 1/m_i [1/kg]
  double* dfdq = nullptr;            ///< n×n work array
  double* dfdv = nullptr;            ///< n×n work array
  long force_evaluations = 0;
  long jacobian_evaluations = 0;
  std::exception_ptr error;
  // A non-finite force ends the step with GSL_EBADFUNC; where it happened:
  double bad_time = 0.0;
  int bad_dof = -1;
  double bad_value = 0.0;
};

/// A GslContext with what it points to, for one integrate() call: the system's force workspace and
/// the n×n Jacobian work arrays. Not copyable: the context points into it.
class GslContextData {
 public:
  GslContextData(const MechanicalSystem& system, const std::vector<double>& inv_mass)
      : workspace_(system.make_workspace()),
        dfdq_(static_cast<std::size_t>(system.dofs()) * static_cast<std::size_t>(system.dofs())),
        dfdv_(dfdq_.size()) {
    context.system = &system;
    context.workspace = workspace_.get();
    context.n = system.dofs();
    context.inv_mass = inv_mass.data();
    context.dfdq = dfdq_.data();
    context.dfdv = dfdv_.data();
  }
  GslContextData(const GslContextData&) = delete;
  GslContextData& operator=(const GslContextData&) = delete;

  MechanicalSystem::Workspace* workspace() const { return workspace_.get(); }
  GslContext context;

 private:
  std::unique_ptr<MechanicalSystem::Workspace> workspace_;
  std::vector<double> dfdq_, dfdv_;
};

/// The Jacobian callback of gsl_odeiv2_system (params is a GslContext*), or nullptr.
using GslJacobian = int (*)(double t, const double y[], double* dfdy, double dfdt[], void* params);

/// y' = [v, M⁻¹ f] for GSL (gsl_adaptive.cc; params is a GslContext*): counts the evaluation,
/// parks a model exception in the context and records a non-finite force there, either returned
/// as GSL_EBADFUNC.
int first_order_rhs(double t, const double y[], double dydt[], void* params);

/// The adaptive methods' absolute-tolerance scales s_i of y = [q, v] (gsl_adaptive.cc: 1 for a
/// displacement, 1e300 for a cyclic one, ω_i for a velocity), from force_jacobian at t0.
std::vector<double> tolerance_scales(const MechanicalSystem& system, double t0,
                                     const std::vector<double>& q0, const std::vector<double>& v0,
                                     const std::vector<double>& inv_mass, double dt,
                                     GslContext& context);

/// Throws for a failed GSL step (status ≠ GSL_SUCCESS): the model's exception, a blow-up (a
/// non-finite force), or a step-size control that cannot meet the tolerance.
void check_step(const std::string& method, int status, const GslContext& context, double t,
                long step, double h);

struct DriverFree {
  void operator()(gsl_odeiv2_driver* d) const { gsl_odeiv2_driver_free(d); }
};

/// integrate() for a GSL odeiv2 stepper with error control (gsl_adaptive.cc): rkf45, rk8pd, and
/// msbdf (bdf.cc, which passes the Jacobian callback). `method` names it in messages.
IntegrationStats integrate_gsl(const std::string& method, const gsl_odeiv2_step_type* type,
                               GslJacobian jacobian, const IntegratorSettings& settings,
                               const MechanicalSystem& system, double t0,
                               const std::vector<double>& q0, const std::vector<double>& v0,
                               const std::vector<double>& output_times, const Observer& observe,
                               const Progress& progress);

/// Dense output of the adaptive methods on one accepted step [t₀, t₁], h = t₁ − t₀, from q,
/// v = q' and a = q'' at the step's ends and, optionally, at one more node t₂ outside the step
/// (the start of the previous step, or the end of the next one). With s = (t − t₀)/h:
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
/// In both, v = p'(s)/h, the derivative of the same polynomial, so the interpolated (q, v) are
/// consistent (v = dq/dt along the interpolant) and no third derivative (jerk, which would take
/// the Jacobian) is needed. At s = 0 and s = 1 the step's own values are returned exactly.
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
    c_.resize(12 * static_cast<std::size_t>(n));
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

  /// q(t) and v(t) for t in [t₀, t₁] (n entries each).
  void at(double t, double* q, double* v) const {
    const int n = n_;
    if (t == t0_ || t == t1_) {
      const bool first = t == t0_;
      std::copy(coef(first ? kQ0 : kQ1), coef(first ? kQ0 : kQ1) + n, q);
      std::copy(coef(first ? kV0 : kV1), coef(first ? kV0 : kV1) + n, v);
      return;
    }
    const double s = (t - t0_) / h_;
    const double inv_h = 1.0 / h_;
    const double u = s * (s - 1.0), w = u * u * u, dw = 3.0 * u * u * (2.0 * s - 1.0);
    const double x = s - sigma_;
    for (int i = 0; i < n; ++i) {
      const double c2 = coef(kC2)[i], c3 = coef(kC3)[i], c4 = coef(kC4)[i], c5 = coef(kC5)[i];
      const double hv0 = coef(kHv0)[i];
      double p = coef(kQ0)[i] + s * (hv0 + s * (c2 + s * (c3 + s * (c4 + s * c5))));
      double dp = hv0 + s * (2.0 * c2 + s * (3.0 * c3 + s * (4.0 * c4 + s * 5.0 * c5)));
      if (third_) {
        const double g1 = coef(kG1)[i], g2 = coef(kG2)[i];
        const double g = coef(kG0)[i] + x * (g1 + 0.5 * g2 * x);
        p += w * g;
        dp += dw * g + w * (g1 + g2 * x);
      }
      q[i] = p;
      v[i] = dp * inv_h;
    }
  }

 private:
  enum Row { kQ0, kV0, kHv0, kC2, kC3, kC4, kC5, kQ1, kV1, kG0, kG1, kG2 };
  double* coef(Row r) { return c_.data() + static_cast<std::size_t>(r) * n_; }
  const double* coef(Row r) const { return c_.data() + static_cast<std::size_t>(r) * n_; }

  int n_ = 0;
  double t0_ = 0.0, t1_ = 0.0, h_ = 0.0, sigma_ = 0.0;
  bool third_ = false;
  std::vector<double> c_;  // rows of n: q₀, v₀, h v₀, ½h²a₀, c₃, c₄, c₅, q₁, v₁, g₀, g₁, g₂
};

}  // namespace solvers_detail
}  // namespace bearing
