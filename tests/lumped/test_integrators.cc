// The integrators on small mechanical systems with known behaviour: analytic solutions,
// convergence orders, energy conservation, stiffness, exact output times, dense output of the
// adaptive methods, blow-up and settings errors. Each test model is defined here; none depends on
// the bearing models.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/solvers/integrator.h"
#include "bearing/solvers/mechanical_system.h"

#include "../../lumped/src/solvers/integrator_detail.h"  // HermiteStep, the dense-output interpolant

namespace bearing {
namespace {

// ---------------------------------------------------------------------------------------------
// Test systems

/// m q̈ = −k q − c q̇ (k < 0 makes it unstable). Uses the default finite-difference Jacobian.
class LinearOscillator : public MechanicalSystem {
 public:
  LinearOscillator(double m, double k, double c) : m_(m), k_(k), c_(c) {}
  int dofs() const override { return 1; }
  void mass(double* m) const override { m[0] = m_; }
  void force(double, const double* q, const double* v, double* f) const override {
    f[0] = -k_ * q[0] - c_ * v[0];
  }
  double m() const { return m_; }
  double k() const { return k_; }
  double c() const { return c_; }

  /// Exact q(t), v(t) for the underdamped case from q(0) = q0, v(0) = v0.
  void exact(double t, double q0, double v0, double* q, double* v) const {
    const double wn = std::sqrt(k_ / m_);
    const double zeta = c_ / (2.0 * std::sqrt(k_ * m_));
    const double wd = wn * std::sqrt(1.0 - zeta * zeta);
    const double s = zeta * wn;
    const double A = q0;
    const double B = (v0 + s * q0) / wd;
    const double e = std::exp(-s * t);
    const double cs = std::cos(wd * t), sn = std::sin(wd * t);
    *q = e * (A * cs + B * sn);
    *v = e * (-s * (A * cs + B * sn) + wd * (-A * sn + B * cs));
  }

 private:
  double m_, k_, c_;
};

/// m q̈ = F0 − K [q]₊^{3/2} − c q̇: a preloaded Hertz contact, with an analytic Jacobian.
class HertzOscillator : public MechanicalSystem {
 public:
  HertzOscillator(double m, double K, double F0, double c) : m_(m), K_(K), F0_(F0), c_(c) {}
  int dofs() const override { return 1; }
  void mass(double* m) const override { m[0] = m_; }
  void force(double, const double* q, const double* v, double* f) const override {
    const double d = std::max(q[0], 0.0);
    f[0] = F0_ - K_ * d * std::sqrt(d) - c_ * v[0];
  }
  void force_jacobian(double, const double* q, const double*, double* dfdq,
                      double* dfdv) const override {
    dfdq[0] = -1.5 * K_ * std::sqrt(std::max(q[0], 0.0));
    dfdv[0] = -c_;
  }
  double equilibrium() const { return std::cbrt((F0_ / K_) * (F0_ / K_)); }
  double energy(double q, double v) const {
    return 0.5 * m_ * v * v + 0.4 * K_ * std::pow(q, 2.5) - F0_ * q;
  }

 private:
  double m_, K_, F0_, c_;
};

/// A heavy slow mass M on a soft spring k1, carrying a light mass m on a stiff spring k2 with a
/// damper c2 between them: natural frequencies ~10 Hz and ~10 kHz.
class StiffPair : public MechanicalSystem {
 public:
  double M = 1.0, k1 = M * (two_pi * 10) * (two_pi * 10);
  double m = 1e-6, k2 = m * (two_pi * 1e4) * (two_pi * 1e4), c2 = 2.0 * std::sqrt(k2 * m);
  int dofs() const override { return 2; }
  void mass(double* mm) const override {
    mm[0] = M;
    mm[1] = m;
  }
  void force(double, const double* q, const double* v, double* f) const override {
    const double spring = k2 * (q[1] - q[0]) + c2 * (v[1] - v[0]);
    f[0] = -k1 * q[0] + spring;
    f[1] = -spring;
  }
};

/// A linear oscillator whose force becomes NaN after t_bad, like a model evaluated outside its
/// domain.
class PoisonedOscillator : public LinearOscillator {
 public:
  PoisonedOscillator(double t_bad) : LinearOscillator(0.6, 1e7, 200.0), t_bad_(t_bad) {}
  void force(double t, const double* q, const double* v, double* f) const override {
    LinearOscillator::force(t, q, v, f);
    if (t > t_bad_) f[0] = std::numeric_limits<double>::quiet_NaN();
  }

 private:
  double t_bad_;
};

/// An oscillator q[0] (the 50 Hz LinearOscillator `oscillator`) beside a flywheel whose angle
/// q[1] = φ [rad] is a cyclic DOF: J φ̈ = T(t) − b φ̇ − d φ̇|φ̇|, with T(t) = T from t_on on (0
/// before) and NaN from t_nan on. No force depends on φ. With d = 0 and t_on = 0, φ̇ spins up to
/// Ω = T/b with time constant τ = J/b:
///     φ̇(t) = Ω (1 − e^{−t/τ}),   φ(t) = φ(0) + Ω (t − τ (1 − e^{−t/τ}))   (φ̇(0) = 0),
/// so φ passes 1 mm-as-a-number after ~0.1 ms and reaches ~490 rad at 0.5 s.
class OscillatorAndFlywheel : public MechanicalSystem {
 public:
  static constexpr double kOmegaN = two_pi * 50;                     // [rad/s]
  static constexpr double kStiffness = kOmegaN * kOmegaN;            // [N/m] on 1 kg
  LinearOscillator oscillator{1.0, kStiffness, 2 * 0.01 * kOmegaN};  // ζ = 0.01
  double J = 2e-4, b = 2e-2, T = 20.0, d = 0.0;  // [kg m², N m s, N m, N m s²]: τ = 10 ms
  double t_on = 0.0, t_nan = std::numeric_limits<double>::infinity();  // [s]
  bool angle_is_cyclic = true;

  int dofs() const override { return 2; }
  void mass(double* m) const override {
    m[0] = oscillator.m();
    m[1] = J;
  }
  void force(double t, const double* q, const double* v, double* f) const override {
    oscillator.force(t, q, v, f);
    const double torque = t < t_on ? 0.0 : T;
    f[1] = torque - b * v[1] - d * v[1] * std::abs(v[1]);
    if (t >= t_nan) f[1] = std::numeric_limits<double>::quiet_NaN();
  }
  bool cyclic(int i) const override { return angle_is_cyclic && i == 1; }

  double omega() const { return T / b; }  ///< Ω [rad/s] (d = 0)
  double tau() const { return J / b; }    ///< τ [s]
  /// φ̇(t) and φ(t) − φ(0) for d = 0, t_on = 0, φ̇(0) = 0.
  double spin(double t) const { return omega() * -std::expm1(-t / tau()); }
  double turned(double t) const { return omega() * (t + tau() * std::expm1(-t / tau())); }
};

// ---------------------------------------------------------------------------------------------
// Helpers

struct Trajectory {
  std::vector<double> t, q, v, a;  // flattened, dofs() entries per output
  IntegrationStats stats;
};

IntegratorSettings settings(const std::string& method, double dt, double rtol = 1e-10,
                            double atol = 1e-18) {
  IntegratorSettings s;
  s.method = find_named(kIntegratorMethods, method).value();
  s.dt = dt;
  s.rtol = rtol;
  s.atol = atol;
  return s;
}

Trajectory run(const IntegratorSettings& s, const MechanicalSystem& system, double t0,
               const std::vector<double>& q0, const std::vector<double>& v0,
               const std::vector<double>& times) {
  Trajectory r;
  const int n = system.dofs();
  r.stats = make_integrator(s)->integrate(
      system, t0, q0, v0, times, [&](double t, const double* q, const double* v, const double* a) {
        r.t.push_back(t);
        r.q.insert(r.q.end(), q, q + n);
        r.v.insert(r.v.end(), v, v + n);
        r.a.insert(r.a.end(), a, a + n);
      });
  return r;
}

/// t0 + k·step for k = 1..count.
std::vector<double> grid(double t0, double step, int count) {
  std::vector<double> times;
  for (int k = 1; k <= count; ++k) times.push_back(t0 + k * step);
  return times;
}

double max_difference(const std::vector<double>& a, const std::vector<double>& b) {
  EXPECT_EQ(a.size(), b.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(a.size(), b.size()); ++i)
    worst = std::max(worst, std::abs(a[i] - b[i]));
  return worst;
}

/// Observed orders log2(e(dt)/e(dt/2)) and log2(e(dt/2)/e(dt/4)).
std::vector<double> observed_orders(const std::vector<double>& errors) {
  std::vector<double> p;
  for (std::size_t i = 0; i + 1 < errors.size(); ++i)
    p.push_back(std::log2(errors[i] / errors[i + 1]));
  return p;
}

// The linear oscillator of the tests: 650 Hz, ζ = 0.04, like a 0.6 kg rotor on a bearing.
const LinearOscillator kLinear(0.6, 1e7, 200.0);
constexpr double kQ0 = 1e-5;  // [m]

double linear_error(const Trajectory& r, double q0, double v0, const LinearOscillator& sys) {
  double worst = 0.0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    double q, v;
    sys.exact(r.t[k], q0, v0, &q, &v);
    worst = std::max(worst, std::abs(r.q[k] - q));
  }
  return worst;
}

// ---------------------------------------------------------------------------------------------
// (1) Linear oscillator against the analytic solution

TEST(IntegratorLinear, AllMethodsMatchAnalyticSolution) {
  const std::vector<double> times = grid(0.0, 2e-4, 20);  // 4 ms, 2.6 periods
  struct Case {
    std::string method;
    double dt, rtol, bound;  // bound on max |q − q_exact| relative to q0
  };
  for (const Case& c : {Case{"rk4", 5e-6, 1e-10, 1e-7}, Case{"newmark", 1e-6, 1e-10, 1e-3},
                        Case{"rkf45", 1e-6, 1e-9, 1e-7}, Case{"rk8pd", 1e-6, 1e-9, 1e-7},
                        Case{"bdf", 1e-6, 1e-9, 1e-6}}) {
    const Trajectory r = run(settings(c.method, c.dt, c.rtol), kLinear, 0.0, {kQ0}, {0.0}, times);
    ASSERT_EQ(r.t.size(), times.size()) << c.method;
    const double error = linear_error(r, kQ0, 0.0, kLinear);
    EXPECT_LT(error, c.bound * kQ0) << c.method;
    // The observer's acceleration is f/M at the output state.
    for (std::size_t k = 0; k < r.t.size(); ++k)
      EXPECT_NEAR(r.a[k], (-kLinear.k() * r.q[k] - kLinear.c() * r.v[k]) / kLinear.m(),
                  1e-12 * kLinear.k() * kQ0 / kLinear.m())
          << c.method;
  }
}

TEST(IntegratorLinear, Rk4IsFourthOrder) {
  const std::vector<double> times = grid(0.0, 2e-4, 20);
  std::vector<double> errors;
  for (const double dt : {2e-5, 1e-5, 5e-6})
    errors.push_back(linear_error(run(settings("rk4", dt), kLinear, 0.0, {kQ0}, {0.0}, times), kQ0,
                                  0.0, kLinear));
  for (const double p : observed_orders(errors)) EXPECT_NEAR(p, 4.0, 0.3);
}

TEST(IntegratorLinear, NewmarkIsSecondOrder) {
  const std::vector<double> times = grid(0.0, 2e-4, 20);
  std::vector<double> errors;
  for (const double dt : {2e-5, 1e-5, 5e-6})
    errors.push_back(linear_error(run(settings("newmark", dt), kLinear, 0.0, {kQ0}, {0.0}, times),
                                  kQ0, 0.0, kLinear));
  for (const double p : observed_orders(errors)) EXPECT_NEAR(p, 2.0, 0.3);
}

TEST(IntegratorLinear, AdaptiveMethodsReachTheirTolerance) {
  // The global error of a tolerance-controlled method is not bounded by the local tolerance, but
  // over a few periods it should stay within a multiple of rtol times the amplitude, and fall
  // when the tolerance does. The embedded Runge–Kutta pairs advance the higher-order solution
  // (local extrapolation) and land well inside (observed 0.94 and 1.5 rtol q0 for rkf45, 0.18 and
  // 0.10 for rk8pd, at rtol 1e-5 and 1e-8); msbdf's error estimate is that of the solution it
  // advances, and 200–800 steps accumulate (observed 32 and 139 rtol q0). The outputs (every
  // 200 µs) are dense output, interpolated inside steps, since the steps no longer land on them.
  const std::vector<double> times = grid(0.0, 2e-4, 20);
  struct Case {
    std::string method;
    double factor;
  };
  for (const Case& c : {Case{"rkf45", 10.0}, Case{"rk8pd", 10.0}, Case{"bdf", 300.0}}) {
    std::vector<double> errors;
    for (const double rtol : {1e-5, 1e-8}) {
      const Trajectory r =
          run(settings(c.method, 1e-6, rtol, 1e-6 * rtol * kQ0), kLinear, 0.0, {kQ0}, {0.0}, times);
      errors.push_back(linear_error(r, kQ0, 0.0, kLinear));
      EXPECT_LT(errors.back(), c.factor * rtol * kQ0) << c.method << " rtol " << rtol;
    }
    EXPECT_GT(errors[0] / errors[1], 30.0) << c.method;
  }
}

// ---------------------------------------------------------------------------------------------
// (2) A preloaded Hertz contact: smooth and nonlinear (q stays > 0)

// K = 1e10 N/m^1.5 and F0 = 100 N: q_eq = 4.6 µm, linearised frequency ~1.2 kHz.
const HertzOscillator kHertz(0.6, 1e10, 100.0, 0.0);

struct HertzFixture {
  double q0 = 1.3 * kHertz.equilibrium();
  std::vector<double> times = grid(0.0, 1e-4, 30);  // 3 ms, 3.5 periods
  Trajectory reference = run(settings("rk4", 1e-5 / 64), kHertz, 0.0, {q0}, {0.0}, times);
};

const HertzFixture& hertz() {
  static const HertzFixture fixture;
  return fixture;
}

TEST(IntegratorHertz, StaysLoaded) {
  const auto& q = hertz().reference.q;
  EXPECT_GT(*std::min_element(q.begin(), q.end()), 0.5 * kHertz.equilibrium());
}

TEST(IntegratorHertz, Rk4IsFourthOrder) {
  const HertzFixture& h = hertz();
  std::vector<double> errors;
  for (const double dt : {2e-5, 1e-5, 5e-6})
    errors.push_back(max_difference(run(settings("rk4", dt), kHertz, 0.0, {h.q0}, {0.0}, h.times).q,
                                    h.reference.q));
  for (const double p : observed_orders(errors)) EXPECT_NEAR(p, 4.0, 0.3);
}

TEST(IntegratorHertz, NewmarkIsSecondOrder) {
  const HertzFixture& h = hertz();
  std::vector<double> errors;
  for (const double dt : {2e-5, 1e-5, 5e-6})
    errors.push_back(max_difference(
        run(settings("newmark", dt), kHertz, 0.0, {h.q0}, {0.0}, h.times).q, h.reference.q));
  for (const double p : observed_orders(errors)) EXPECT_NEAR(p, 2.0, 0.3);
}

TEST(IntegratorHertz, AdaptiveMethodsMatchFineRk4) {
  const HertzFixture& h = hertz();
  for (const std::string method : {"rkf45", "rk8pd", "bdf"}) {
    const Trajectory r =
        run(settings(method, 1e-6, 1e-10, 1e-20), kHertz, 0.0, {h.q0}, {0.0}, h.times);
    EXPECT_LT(max_difference(r.q, h.reference.q), 1e-7 * h.q0) << method;
    EXPECT_GT(r.stats.jacobian_evaluations, 0) << method;  // the velocity scale, at least
  }
}

// ---------------------------------------------------------------------------------------------
// (3) Energy

TEST(IntegratorEnergy, Rk8pdConservesHertzEnergy) {
  const double q0 = 1.3 * kHertz.equilibrium();
  const double rtol = 1e-10;
  const std::vector<double> times = grid(0.0, 1e-4, 430);  // 43 ms, 50 periods
  const Trajectory r =
      run(settings("rk8pd", 1e-6, rtol, rtol * 1e-6 * q0), kHertz, 0.0, {q0}, {0.0}, times);
  const double e0 = kHertz.energy(q0, 0.0);
  const double swing = e0 - kHertz.energy(kHertz.equilibrium(), 0.0);  // vibration energy
  double drift = 0.0;
  for (std::size_t k = 0; k < r.t.size(); ++k)
    drift = std::max(drift, std::abs(kHertz.energy(r.q[k], r.v[k]) - e0));
  // Observed 14 rtol at these interpolated outputs (2 rtol at the step ends): the degree-8
  // interpolant's error is ~1 rtol·|q| here, and the vibration energy (the swing) is a small part
  // of q, so the drift relative to it is the most sensitive measure of it.
  EXPECT_LT(drift / swing, 20.0 * rtol);
}

TEST(IntegratorEnergy, NewmarkConservesLinearEnergyExactly) {
  // Average acceleration is the trapezoidal rule: it conserves ½mv² + ½kq² of an undamped linear
  // system at any step size, here ω dt = 0.4 over 100 periods.
  const LinearOscillator sys(0.6, 1e7, 0.0);
  const double dt = 0.4 / std::sqrt(sys.k() / sys.m());
  const std::vector<double> times = grid(0.0, 50 * dt, 310);  // ~100 periods
  const Trajectory r = run(settings("newmark", dt, 1e-12), sys, 0.0, {kQ0}, {0.3}, times);
  const auto energy = [&](double q, double v) {
    return 0.5 * sys.m() * v * v + 0.5 * sys.k() * q * q;
  };
  const double e0 = energy(kQ0, 0.3);
  double drift = 0.0;
  for (std::size_t k = 0; k < r.t.size(); ++k)
    drift = std::max(drift, std::abs(energy(r.q[k], r.v[k]) - e0));
  EXPECT_LT(drift / e0, 1e-11);
  // Whereas RK4 at the same step loses energy steadily.
  const Trajectory rk = run(settings("rk4", dt), sys, 0.0, {kQ0}, {0.3}, times);
  EXPECT_GT(std::abs(energy(rk.q.back(), rk.v.back()) - e0) / e0, 1e-4);
}

// ---------------------------------------------------------------------------------------------
// (4) Stiffness

TEST(IntegratorStiff, BdfTakesFarFewerStepsThanRkf45) {
  const StiffPair sys;
  const std::vector<double> q0 = {1e-4, 1e-4}, v0 = {0.0, 0.0};
  const std::vector<double> times = grid(0.0, 0.02, 10);  // 0.2 s: two slow periods
  const double rtol = 1e-6, atol = 1e-12;
  const Trajectory bdf = run(settings("bdf", 1e-6, rtol, atol), sys, 0.0, q0, v0, times);
  const Trajectory rkf = run(settings("rkf45", 1e-6, rtol, atol), sys, 0.0, q0, v0, times);
  const Trajectory ref = run(settings("rk8pd", 1e-6, 1e-11, 1e-17), sys, 0.0, q0, v0, times);
  RecordProperty("bdf_steps", static_cast<int>(bdf.stats.steps));
  RecordProperty("rkf45_steps", static_cast<int>(rkf.stats.steps));
  EXPECT_GT(rkf.stats.steps, 8 * bdf.stats.steps);  // observed 3411 vs 180
  // Both still follow the slow mass.
  for (std::size_t k = 0; k < ref.q.size(); k += 2) {
    EXPECT_NEAR(bdf.q[k], ref.q[k], 1e-3 * q0[0]) << "t = " << ref.t[k / 2];
    EXPECT_NEAR(rkf.q[k], ref.q[k], 1e-3 * q0[0]) << "t = " << ref.t[k / 2];
  }
}

// ---------------------------------------------------------------------------------------------
// (5) Output times

TEST(IntegratorOutput, TimesLandExactly) {
  // Output interval 7.3 µs with dt = 5 µs, starting at an awkward t0, and the first output at t0.
  // The fixed-step methods land steps on the times; the adaptive ones interpolate at them.
  const double t0 = 0.0123;
  std::vector<double> times = {t0};
  for (int k = 1; k <= 40; ++k) times.push_back(t0 + k * 7.3e-6);
  for (const std::string& method : integrator_names()) {
    const Trajectory r = run(settings(method, 5e-6, 1e-8, 1e-16), kLinear, t0, {kQ0}, {0.0}, times);
    ASSERT_EQ(r.t.size(), times.size()) << method;
    for (std::size_t k = 0; k < times.size(); ++k) EXPECT_EQ(r.t[k], times[k]) << method;
    EXPECT_EQ(r.q[0], kQ0) << method;  // the initial state, untouched
    EXPECT_EQ(r.v[0], 0.0) << method;
  }
}

TEST(IntegratorOutput, FixedStepsKeepDtBetweenOutputs) {
  // Each 7.3 µs interval is one full 5 µs step and one shortened 2.3 µs step.
  const std::vector<double> times = grid(0.0, 7.3e-6, 40);
  for (const std::string method : {"rk4", "newmark"}) {
    const Trajectory r = run(settings(method, 5e-6), kLinear, 0.0, {kQ0}, {0.0}, times);
    EXPECT_EQ(r.stats.steps, 80) << method;
  }
  // Output on the step grid (up to rounding of the times) adds no steps.
  const Trajectory r = run(settings("rk4", 5e-6), kLinear, 0.0, {kQ0}, {0.0}, grid(0.0, 2e-5, 100));
  EXPECT_EQ(r.stats.steps, 400);
  // and, with the output-point evaluation reused as the next step's first stage, costs 4 per step
  EXPECT_EQ(r.stats.force_evaluations, 4 * 400 + 1);
}

// max_step caps the adaptive methods' steps (what keeps them from stepping over a local defect):
// at a loose tolerance they would take a few hundred steps over 4 ms, capped at 2 µs at least
// 2000.
TEST(IntegratorStepControl, AdaptiveStepsNeverExceedMaxStep) {
  const std::vector<double> times = grid(0.0, 2e-4, 20);
  for (const std::string method : {"rkf45", "rk8pd", "rk8pd-events", "bdf"}) {
    IntegratorSettings s = settings(method, 1e-6, 1e-6, 1e-12);
    const long free_steps = run(s, kLinear, 0.0, {kQ0}, {0.0}, times).stats.steps;
    s.max_step = 2e-6;
    const Trajectory r = run(s, kLinear, 0.0, {kQ0}, {0.0}, times);
    EXPECT_LT(free_steps, 1000) << method;
    EXPECT_GE(r.stats.steps, 2000) << method;
  }
}

TEST(IntegratorOutput, NoOutputTimesNoWork) {
  for (const std::string& method : integrator_names()) {
    const Trajectory r = run(settings(method, 5e-6), kLinear, 0.0, {kQ0}, {0.0}, {});
    EXPECT_EQ(r.stats.steps, 0) << method;
    EXPECT_TRUE(r.t.empty()) << method;
  }
}

TEST(IntegratorOutput, ProgressIsThrottled) {
  const std::vector<double> times = grid(0.0, 1e-6, 5000);
  for (const std::string& method : integrator_names()) {
    std::vector<double> fractions;
    make_integrator(settings(method, 1e-6, 1e-6, 1e-14))
        ->integrate(kLinear, 0.0, {kQ0}, {0.0}, times, {},
                    [&](double f) { fractions.push_back(f); });
    ASSERT_FALSE(fractions.empty()) << method;
    EXPECT_LE(fractions.size(), 102u) << method;
    EXPECT_GE(fractions.size(), 50u) << method;
    EXPECT_TRUE(std::is_sorted(fractions.begin(), fractions.end())) << method;
    EXPECT_EQ(fractions.front(), 0.0) << method;
    EXPECT_EQ(fractions.back(), 1.0) << method;
    // the fraction of the span done: the report before the last is within its final percent
    ASSERT_GE(fractions.size(), 2u) << method;
    EXPECT_GE(fractions[fractions.size() - 2], 0.98) << method;
  }
}

// ---------------------------------------------------------------------------------------------
// (6) Dense output of the adaptive methods (rkf45, rk8pd, bdf)

TEST(IntegratorDense, InterpolatesInsideStepsWithinTheTolerance) {
  // An output every 1 µs for 4 ms on the linear oscillator: the steps average 3–170 µs, so most
  // of the 4000 outputs fall inside steps and are interpolated. They must stay within the bounds
  // of AdaptiveMethodsReachTheirTolerance (whose outputs, before dense output, were step ends):
  // 10 rtol q0 for the Runge–Kutta pairs, 300 rtol q0 for msbdf. Observed for q: rkf45 1.2 and
  // 1.6, rk8pd 0.04 and 0.11 (a quintic would give 6 and 113), bdf 53 and 224 rtol q0 at rtol
  // 1e-6 and 1e-9: the interpolation adds nothing visible to the step-end error. Velocities, the
  // derivative of the same interpolant, against rtol ω q0 with the same factors and 50 % more
  // room (observed 1.1/1.5, 0.15/0.67, 67/295).
  const std::vector<double> times = grid(0.0, 1e-6, 4000);
  const double omega = std::sqrt(kLinear.k() / kLinear.m());
  struct Case {
    std::string method;
    double factor;
  };
  for (const Case& c : {Case{"rkf45", 10.0}, Case{"rk8pd", 10.0}, Case{"bdf", 300.0}}) {
    for (const double rtol : {1e-6, 1e-9}) {
      const Trajectory r =
          run(settings(c.method, 1e-6, rtol, 1e-6 * rtol * kQ0), kLinear, 0.0, {kQ0}, {0.0}, times);
      ASSERT_EQ(r.t.size(), times.size()) << c.method;
      EXPECT_LT(2 * r.stats.steps, static_cast<long>(times.size())) << c.method << " " << rtol;
      double q_error = 0.0, v_error = 0.0;
      for (std::size_t k = 0; k < r.t.size(); ++k) {
        EXPECT_EQ(r.t[k], times[k]);
        double q, v;
        kLinear.exact(r.t[k], kQ0, 0.0, &q, &v);
        q_error = std::max(q_error, std::abs(r.q[k] - q));
        v_error = std::max(v_error, std::abs(r.v[k] - v));
        EXPECT_NEAR(r.a[k], (-kLinear.k() * r.q[k] - kLinear.c() * r.v[k]) / kLinear.m(),
                    1e-12 * kLinear.k() * kQ0 / kLinear.m());
      }
      EXPECT_LT(q_error, c.factor * rtol * kQ0) << c.method << " rtol " << rtol;
      EXPECT_LT(v_error, 1.5 * c.factor * rtol * omega * kQ0) << c.method << " rtol " << rtol;
      // One force evaluation per output for the observer's acceleration, on top of the steps.
      EXPECT_GT(r.stats.force_evaluations, static_cast<long>(times.size())) << c.method;
    }
  }
}

TEST(IntegratorDense, StepEndsAreReproducedExactly) {
  // Two step ends are known from outside: the last output time, which every run lands on, and
  // t0 + dt when the first step (solver.dt) is accepted, as a run with that single output shows
  // (1 step, none rejected). The steps do not depend on the output times, so a run with a fine
  // grid through both must give the step values there bit for bit, as must a run with only them.
  const double dt = 1e-8;  // short enough for msbdf's first-order start to be accepted
  std::vector<double> fine = {dt};
  for (const double t : grid(0.0, 1e-5, 200)) fine.push_back(t);
  const std::vector<double> ends = {dt, fine.back()};
  for (const std::string method : {"rkf45", "rk8pd", "bdf"}) {
    const IntegratorSettings s = settings(method, dt, 1e-6, 1e-14);
    const Trajectory one = run(s, kLinear, 0.0, {kQ0}, {0.0}, {dt});
    ASSERT_EQ(one.stats.steps, 1) << method;
    ASSERT_EQ(one.stats.rejected_steps, 0) << method;
    const Trajectory sparse = run(s, kLinear, 0.0, {kQ0}, {0.0}, ends);
    const Trajectory dense = run(s, kLinear, 0.0, {kQ0}, {0.0}, fine);
    ASSERT_EQ(dense.t.size(), fine.size()) << method;
    EXPECT_EQ(dense.stats.steps, sparse.stats.steps) << method;
    EXPECT_EQ(dense.q.front(), one.q.front()) << method;
    EXPECT_EQ(dense.v.front(), one.v.front()) << method;
    EXPECT_EQ(dense.a.front(), one.a.front()) << method;
    EXPECT_EQ(dense.q.front(), sparse.q.front()) << method;
    EXPECT_EQ(dense.v.front(), sparse.v.front()) << method;
    EXPECT_EQ(dense.q.back(), sparse.q.back()) << method;
    EXPECT_EQ(dense.v.back(), sparse.v.back()) << method;
    EXPECT_EQ(dense.a.back(), sparse.a.back()) << method;
  }
}

TEST(IntegratorDense, StepsDoNotDependOnTheOutputRate) {
  // 1 s of the preloaded Hertz oscillator (smooth, ~1.2 kHz) with output at 1 kHz and at 20 kHz.
  // Landing on every output used to cap the step at the output interval (≥ 20 000 steps at
  // 20 kHz); now the steps, rejections and their force evaluations are the same for both rates,
  // exactly, and the only extra cost of the finer output is its one evaluation per output for
  // the observer's acceleration (the totals differ by exactly 19 000: 6.5 %, 15 % and 6.6 % of
  // the 1 kHz totals 293 633, 129 636 and 289 044 for rkf45, rk8pd and bdf).
  const double q0 = 1.3 * kHertz.equilibrium();
  const double rtol = 1e-6;
  for (const std::string method : {"rkf45", "rk8pd", "bdf"}) {
    IntegrationStats stats[2];
    long outputs[2];
    int i = 0;
    for (const int count : {1000, 20000}) {
      const std::vector<double> times = grid(0.0, 1.0 / count, count);
      stats[i] = make_integrator(settings(method, 1e-6, rtol, 1e-6 * rtol * q0))
                     ->integrate(kHertz, 0.0, {q0}, {0.0}, times, {});
      outputs[i++] = count;
    }
    EXPECT_EQ(stats[1].steps, stats[0].steps) << method;
    EXPECT_EQ(stats[1].rejected_steps, stats[0].rejected_steps) << method;
    EXPECT_EQ(stats[1].jacobian_evaluations, stats[0].jacobian_evaluations) << method;
    EXPECT_EQ(stats[1].force_evaluations - outputs[1], stats[0].force_evaluations - outputs[0])
        << method;
    if (method == "rk8pd") EXPECT_LT(stats[1].steps, 10000);  // observed 7 753
  }
}

TEST(IntegratorDense, HermiteStepReproducesPolynomials) {
  // The quintic reproduces degree 5 and, with a third node before or after the step, degree 8,
  // to rounding; at the step's ends it returns the given values exactly.
  const auto poly = [](int degree, double t, double* q, double* v, double* a) {
    *q = *v = *a = 0.0;
    for (int k = degree; k >= 0; --k) {  // Σ c_k t^k with c_k = (−1)^k (k + 1) / 3
      const double c = (k % 2 ? -1.0 : 1.0) * (k + 1) / 3.0;
      *a = *a * t + *v * 2.0;
      *v = *v * t + *q;
      *q = *q * t + c;
    }
  };
  const double t0 = 0.3, t1 = 0.7;
  double q0, v0, a0, q1, v1, a1;
  for (const double t2 : {0.0, 0.1, 0.9}) {  // 0: no third node
    const int degree = t2 == 0.0 ? 5 : 8;
    poly(degree, t0, &q0, &v0, &a0);
    poly(degree, t1, &q1, &v1, &a1);
    solvers_detail::HermiteStep step;
    step.set(1, t0, t1, &q0, &v0, &a0, &q1, &v1, &a1);
    if (t2 != 0.0) {
      double q2, v2, a2;
      poly(degree, t2, &q2, &v2, &a2);
      step.add_node(t2, &q2, &v2, &a2);
    }
    for (int k = 0; k <= 20; ++k) {
      const double t = t0 + (t1 - t0) * k / 20.0;
      double q, v, a, qi, vi;
      poly(degree, t, &q, &v, &a);
      step.at(t, &qi, &vi);
      EXPECT_NEAR(qi, q, 1e-14) << "t2 = " << t2 << ", t = " << t;
      EXPECT_NEAR(vi, v, 1e-13) << "t2 = " << t2 << ", t = " << t;
    }
    double q, v;
    step.at(t0, &q, &v);
    EXPECT_EQ(q, q0);
    EXPECT_EQ(v, v0);
    step.at(t1, &q, &v);
    EXPECT_EQ(q, q1);
    EXPECT_EQ(v, v1);
  }
  // Degree 6 is beyond the quintic: its error is q⁽⁶⁾/6! (t − t0)³ (t − t1)³.
  const auto sixth = [](double t) { return std::pow(t, 6); };
  const double ends[2] = {t0, t1};
  double qq[2], vv[2], aa[2];
  for (int e = 0; e < 2; ++e) {
    qq[e] = sixth(ends[e]);
    vv[e] = 6.0 * std::pow(ends[e], 5);
    aa[e] = 30.0 * std::pow(ends[e], 4);
  }
  solvers_detail::HermiteStep step;
  step.set(1, t0, t1, &qq[0], &vv[0], &aa[0], &qq[1], &vv[1], &aa[1]);
  const double tm = 0.5 * (t0 + t1);
  double q, v;
  step.at(tm, &q, &v);
  EXPECT_NEAR(sixth(tm) - q, std::pow((tm - t0) * (tm - t1), 3), 1e-15);
}

// ---------------------------------------------------------------------------------------------
// (7) Blow-up

void expect_blow_up(const MechanicalSystem& sys, const std::string& what) {
  const std::vector<double> times = grid(0.0, 1e-4, 100);  // 10 ms
  for (const std::string& method : integrator_names()) {
    IntegratorSettings s = settings(method, 5e-6, 1e-6, 1e-14);
    bool all_finite = true;
    double largest = 0.0;
    std::string message;
    try {
      make_integrator(s)->integrate(
          sys, 0.0, {1e-6}, {0.0}, times,
          [&](double t, const double* q, const double* v, const double* a) {
            all_finite = all_finite && std::isfinite(t) && std::isfinite(q[0]) &&
                         std::isfinite(v[0]) && std::isfinite(a[0]);
            largest = std::max(largest, std::abs(q[0]));
          });
    } catch (const SolverError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("t = "), std::string::npos) << what << " " << method << ": " << message;
    EXPECT_NE(message.find("solver.dt"), std::string::npos)
        << what << " " << method << ": " << message;
    EXPECT_NE(message.find(method), std::string::npos) << what << " " << method << ": " << message;
    EXPECT_TRUE(all_finite) << what << " " << method;
    EXPECT_LE(largest, s.max_displacement) << what << " " << method;
  }
}

TEST(IntegratorBlowUp, NegativeStiffnessThrows) {
  // q grows like e^{4082 t}: past 1 mm after ~1.7 ms.
  expect_blow_up(LinearOscillator(0.6, -1e7, 0.0), "negative stiffness");
}

TEST(IntegratorBlowUp, NonFiniteForceThrows) {
  expect_blow_up(PoisonedOscillator(1.05e-3), "NaN force");
}

TEST(IntegratorBlowUp, MessageNamesTheStep) {
  try {
    run(settings("rk4", 1e-5), LinearOscillator(0.6, -1e7, 0.0), 0.0, {1e-6}, {0.0},
        grid(0.0, 1e-3, 10));
    FAIL() << "no SolverError";
  } catch (const SolverError& e) {
    const std::string message = e.what();
    EXPECT_NE(message.find("(step 1"), std::string::npos) << message;
    EXPECT_NE(message.find("dt = 1e-05 s"), std::string::npos) << message;
    EXPECT_NE(message.find("|q[0]|"), std::string::npos) << message;
  }
}

// ---------------------------------------------------------------------------------------------
// (8) Cyclic DOFs: a flywheel's angle beside an oscillator

/// The time [s] a blow-up message reports ("… at t = 0.2001 s …"), NaN if none.
double reported_time(const std::string& message) {
  const std::size_t at = message.find("t = ");
  return at == std::string::npos ? std::nan("") : std::stod(message.substr(at + 4));
}

TEST(IntegratorCyclic, AllMethodsFollowTheFlywheel) {
  // 0.5 s: the flywheel spins up to Ω = 1000 rad/s (τ = 10 ms) and turns ~490 rad, 4.9e5 times
  // max_displacement as a number, while the oscillator (50 Hz, ζ = 0.01) rings down from q0.
  // The fixed-step bounds are the methods' leading error terms at dt = 1e-4 s (z = dt/τ = 0.01,
  // ω_n dt = 0.031), times 1.5 for the next order (observed at 1.0–1.01 of the leading term for
  // the spin speed and the oscillator):
  // - newmark (trapezoidal rule): u = φ̇ − Ω decays by (1 − z/2)/(1 + z/2) = e^{−z − z³/12 − …}
  //   per step, so |δφ̇| ≈ Ω (t/τ) e^{−t/τ} z²/12 ≤ Ω z²/(12e). φ is the trapezoidal quadrature of
  //   that φ̇: ≤ dt²/12 |φ̈(t) − φ̈(0)| + ∫|δφ̇| ≤ τΩz²/12 + τΩz²/12 (no 1.5 needed: observed 0.18
  //   of it). The oscillator's phase error ω_n t (ω_n dt)²/12 on the decaying q0 e^{−ζω_n t}:
  //   ≤ q0 (ω_n dt)²/(12ζe).
  // - rk4: R(−z) = e^{−z} (1 + z⁵/120 + …): |δφ̇| ≤ Ω z⁴/(120e); φ gets the local errors
  //   dt⁵|φ⁽⁵⁾|/120 summed plus ∫|δφ̇|, ≤ 2τΩz⁴/120, and the rounding of 5000 additions to
  //   |φ| ≤ 490 rad, 5000 ε |φ| (observed 0.14 of both); the oscillator: ≤ q0 (ω_n dt)⁴/(120ζe).
  // The adaptive methods control φ̇'s error locally to rtol |φ̇| (a few rtol Ω globally) and φ is
  // its integral, so 10 rtol Ω for the spin speed and 10 rtol Ω t for the angle (observed at most
  // 1.3 and 0.46 of rtol Ω and rtol Ω t, bdf). Their oscillator is compared with the same
  // oscillator integrated alone (the accuracy of the methods on an oscillator is tested above).
  const OscillatorAndFlywheel sys;
  const double q0 = 1e-4, omega = sys.omega(), tau = sys.tau();
  const double wn = OscillatorAndFlywheel::kOmegaN, zeta = 0.01;
  const std::vector<double> times = grid(0.0, 1e-3, 500);
  const double dt = 1e-4, z = dt / tau, wh = wn * dt, e = std::exp(1.0);
  const double eps = std::numeric_limits<double>::epsilon();
  const double turns = sys.turned(times.back());
  for (const std::string& method : integrator_names()) {
    const bool fixed = method == "rk4" || method == "newmark";
    for (const double rtol : {1e-6, 1e-8}) {
      if (fixed && rtol == 1e-6) continue;  // rtol is only Newmark's Newton tolerance
      const IntegratorSettings s = settings(method, dt, rtol, 1e-6 * rtol * q0);
      const std::string what = method + " rtol " + solvers_detail::format_brief(rtol);
      Trajectory r;
      ASSERT_NO_THROW(r = run(s, sys, 0.0, {q0, 0.0}, {0.0, 0.0}, times)) << what;
      ASSERT_EQ(r.t.size(), times.size()) << what;
      EXPECT_GT(r.q.back(), 1e5 * s.max_displacement) << what;  // the angle ran far past the bound
      const Trajectory alone = run(s, sys.oscillator, 0.0, {q0}, {0.0}, times);
      double spin_bound = 10 * rtol * omega, angle_bound = 10 * rtol * omega, q_bound = 0.0;
      bool angle_grows = false;  // the adaptive angle bound grows with t
      if (method == "rk4") {
        spin_bound = 1.5 * omega * std::pow(z, 4) / (120 * e);
        angle_bound = 2 * tau * omega * std::pow(z, 4) / 120 + 5000 * eps * turns;
        q_bound = 1.5 * q0 * std::pow(wh, 4) / (120 * zeta * e);
      } else if (method == "newmark") {
        spin_bound = 1.5 * omega * z * z / (12 * e);
        angle_bound = tau * omega * z * z / 6;
        q_bound = 1.5 * q0 * wh * wh / (12 * zeta * e);
      } else {
        angle_grows = true;
      }
      double spin_error = 0, angle_excess = 0, q_error = 0, alone_error = 0, q_change = 0;
      for (std::size_t k = 0; k < r.t.size(); ++k) {
        const double t = r.t[k];
        double q, v;
        sys.oscillator.exact(t, q0, 0.0, &q, &v);
        q_error = std::max(q_error, std::abs(r.q[2 * k] - q));
        alone_error = std::max(alone_error, std::abs(alone.q[k] - q));
        q_change = std::max(q_change, std::abs(r.q[2 * k] - alone.q[k]));
        spin_error = std::max(spin_error, std::abs(r.v[2 * k + 1] - sys.spin(t)));
        angle_excess = std::max(angle_excess, std::abs(r.q[2 * k + 1] - sys.turned(t)) /
                                                  (angle_grows ? angle_bound * t : angle_bound));
      }
      EXPECT_LT(spin_error, spin_bound) << what;
      EXPECT_LT(angle_excess, 1.0) << what;
      if (q_bound > 0) EXPECT_LT(q_error, q_bound) << what;
      // The flywheel leaves the oscillator as it is alone (identical for all but bdf, whose step
      // and order choice see both DOFs: 3 % of its error).
      EXPECT_LE(q_change, 0.1 * alone_error) << what;
    }
  }
}

TEST(IntegratorCyclic, WithoutTheFlagTheAngleBlowsUp) {
  // The same system with cyclic() false: the angle passes 1 mm-as-a-number after ~0.14 ms, and
  // every method stops there, before the first output (1 ms), naming the DOF and the bound.
  OscillatorAndFlywheel sys;
  sys.angle_is_cyclic = false;
  for (const std::string& method : integrator_names()) {
    int outputs = 0;
    std::string message;
    try {
      make_integrator(settings(method, 1e-4, 1e-6, 1e-16))
          ->integrate(sys, 0.0, {1e-4, 0.0}, {0.0, 0.0}, grid(0.0, 1e-3, 500),
                      [&](double, const double*, const double*, const double*) { ++outputs; });
    } catch (const SolverError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find("|q[1]|"), std::string::npos) << method << ": " << message;
    EXPECT_NE(message.find("exceeds the blow-up bound 0.001 m"), std::string::npos)
        << method << ": " << message;
    EXPECT_LT(reported_time(message), 1e-3) << method << ": " << message;
    EXPECT_EQ(outputs, 0) << method;
  }
}

TEST(IntegratorCyclic, NonFiniteTorqueIsCaught) {
  // The exemption is from the bound only: a torque that turns NaN at 0.2 s (when φ ≈ 190 rad)
  // still stops every method at that time, before the observer sees a non-finite value.
  OscillatorAndFlywheel sys;
  sys.t_nan = 0.2;
  for (const std::string& method : integrator_names()) {
    bool all_finite = true;
    double last = -1.0, last_angle = 0.0;
    std::string message;
    try {
      make_integrator(settings(method, 1e-4, 1e-6, 1e-16))
          ->integrate(sys, 0.0, {1e-4, 0.0}, {0.0, 0.0}, grid(0.0, 1e-3, 500),
                      [&](double t, const double* q, const double* v, const double* a) {
                        for (int i = 0; i < 2; ++i)
                          all_finite = all_finite && std::isfinite(q[i]) && std::isfinite(v[i]) &&
                                       std::isfinite(a[i]);
                        last = t;
                        last_angle = q[1];
                      });
    } catch (const SolverError& e) {
      message = e.what();
    }
    EXPECT_NE(message.find(method), std::string::npos) << method << ": " << message;
    EXPECT_NE(message.find("solver.dt"), std::string::npos) << method << ": " << message;
    const double t_bad = reported_time(message);
    EXPECT_GE(t_bad, sys.t_nan) << method << ": " << message;
    EXPECT_LT(t_bad, sys.t_nan + 0.01) << method << ": " << message;
    EXPECT_TRUE(all_finite) << method;
    EXPECT_GE(last, 0.19) << method;  // the outputs went on until the NaN
    EXPECT_LT(last, sys.t_nan) << method;
    EXPECT_GT(last_angle, 100.0) << method;
  }
}

TEST(IntegratorCyclic, AngleOffsetChangesNothing) {
  // No force depends on the angle, so starting it at 1e4 or 1e7 rad instead of 0 must leave the
  // steps and the spin speed as they are, up to the rounding of the larger angle (ulp ≤ ε φ0).
  // The flywheel here has quadratic drag (J φ̈ = T − d φ̇|φ̇|, Ω = 1000 rad/s), so Newmark's
  // Newton takes more than one iteration; the fixed-step methods also get the torque switched on
  // abruptly at 20.5 ms, where Newton's first correction is large. The oscillator rests, so the
  // flywheel alone decides when Newton has converged. Newmark derives φ̇ = 2/h (x − qₙ) − φ̇ₙ from
  // the angle's increment: rounding ε φ0 in x gives 2ε φ0/dt per step, ~√steps of them adding up,
  // so the spin speeds may differ by 10 · 2ε φ0/dt · √1000 (1.4e-5 rad/s at 1e4 rad; observed
  // 3e-7), and the angle increments by that times the 0.1 s plus 1000 roundings ε φ0. Testing
  // Newton's correction against the accumulated angle (rtol |x|, 0.01 rad at 1e4 rad) instead of
  // the increment gave 9.5e-3 rad/s and 8e-5 rad; without the rounding floor 8ε|x| the increment
  // test could not be met at 1e7 rad (Newton stalled at the torque switch).
  OscillatorAndFlywheel sys;
  sys.b = 0.0;
  sys.d = sys.T / 1e6;
  const double dt = 1e-4;
  const std::vector<double> times = grid(0.0, 1e-3, 100);
  const double eps = std::numeric_limits<double>::epsilon();
  for (const std::string& method : integrator_names()) {
    const bool fixed = method == "rk4" || method == "newmark";
    for (const double t_on : {0.0, 0.0205}) {
      if (t_on > 0 && !fixed) continue;  // a force step is not for error-controlled methods
      sys.t_on = t_on;
      const IntegratorSettings s = settings(method, dt, 1e-6, 1e-12);
      const Trajectory base = run(s, sys, 0.0, {0.0, 0.0}, {0.0, 0.0}, times);
      ASSERT_GT(base.v.back(), 0.99 * 1000.0) << method;  // spun up
      for (const double phi0 : {1e4, 1e7}) {
        const std::string what = method + " t_on " + solvers_detail::format_brief(t_on) + " phi0 " +
                                 solvers_detail::format_brief(phi0);
        Trajectory r;
        ASSERT_NO_THROW(r = run(s, sys, 0.0, {0.0, phi0}, {0.0, 0.0}, times)) << what;
        ASSERT_EQ(r.t.size(), base.t.size()) << what;
        EXPECT_EQ(r.stats.steps, base.stats.steps) << what;
        if (!fixed) EXPECT_EQ(r.stats.rejected_steps, base.stats.rejected_steps) << what;
        const double spin_bound = 10 * 2 * eps * phi0 / dt * std::sqrt(1000.0);
        const double angle_bound = spin_bound * times.back() + 1000 * eps * phi0;
        double spin_change = 0, angle_change = 0;
        for (std::size_t k = 0; k < r.t.size(); ++k) {
          spin_change = std::max(spin_change, std::abs(r.v[2 * k + 1] - base.v[2 * k + 1]));
          angle_change =
              std::max(angle_change, std::abs((r.q[2 * k + 1] - phi0) - base.q[2 * k + 1]));
          EXPECT_EQ(r.q[2 * k], 0.0) << what;
        }
        EXPECT_LT(spin_change, spin_bound) << what;
        EXPECT_LT(angle_change, angle_bound) << what;
      }
    }
  }
}

TEST(IntegratorCyclic, AngleDoesNotDriveTheSteps) {
  // The adaptive methods with the flag against the same run without it but with the bound raised
  // to 1e6, so that the angle enters the error control as a displacement (atol + rtol |φ|): never
  // more steps, or attempts, with the flag. Both runs spin up from φ = 0, where the angle's
  // tolerance is atol. (a) Beside the ringing oscillator of AllMethodsFollowTheFlywheel, which
  // limits the steps anyway: observed 1002/1002, 2475/2475 (rkf45), 202/202, 302/302 (rk8pd),
  // 2524/2566, 6127/6180 (bdf) steps at rtol 1e-6/1e-8. (b) The quadratic-drag flywheel of
  // AngleOffsetChangesNothing with the oscillator at rest, so nothing else limits the steps:
  // 30/31, 64/66, 14/14, 20/21, and for bdf 82/149 and 158/245, where the angle's error alone
  // cost it 55–80 % more steps.
  for (const bool alone : {false, true}) {
    OscillatorAndFlywheel sys;
    double q0 = 1e-4;
    std::vector<double> times = grid(0.0, 1e-3, 500);
    if (alone) {
      sys.b = 0.0;
      sys.d = sys.T / 1e6;
      q0 = 0.0;
      times = grid(0.0, 1e-3, 100);
    }
    for (const std::string method : {"rkf45", "rk8pd", "bdf"}) {
      for (const double rtol : {1e-6, 1e-8}) {
        IntegratorSettings s = settings(method, 1e-4, rtol, alone ? 1e-12 : 1e-6 * rtol * q0);
        const std::string what = method + (alone ? " alone" : " beside the oscillator") + " rtol " +
                                 solvers_detail::format_brief(rtol);
        sys.angle_is_cyclic = true;
        const Trajectory cyclic = run(s, sys, 0.0, {q0, 0.0}, {0.0, 0.0}, times);
        s.max_displacement = 1e6;
        sys.angle_is_cyclic = false;
        const Trajectory plain = run(s, sys, 0.0, {q0, 0.0}, {0.0, 0.0}, times);
        EXPECT_LE(cyclic.stats.steps, plain.stats.steps) << what;
        EXPECT_LE(cyclic.stats.steps + cyclic.stats.rejected_steps,
                  plain.stats.steps + plain.stats.rejected_steps)
            << what;
        if (alone && method == "bdf") EXPECT_LT(cyclic.stats.steps, plain.stats.steps) << what;
        RecordProperty(
            method + (alone ? "_alone_" : "_beside_") + solvers_detail::format_brief(rtol) +
                "_steps",
            std::to_string(cyclic.stats.steps) + "/" + std::to_string(plain.stats.steps));
      }
    }
  }
}

TEST(IntegratorCyclic, BlowUpCheckBoundsOnlyTheOthers) {
  // check_state directly: the cyclic DOF passes any finite value and fails ±Inf and NaN, which no
  // integration above can hand it; the other DOF keeps the bound and its message.
  using solvers_detail::check_state;
  const OscillatorAndFlywheel sys;
  const std::vector<double> bound = solvers_detail::displacement_bounds(sys, 1e-3);
  ASSERT_EQ(bound.size(), 2u);
  EXPECT_EQ(bound[0], 1e-3);
  const double v[2] = {0.0, 0.0};
  const auto message = [&](double q0, double q1) -> std::string {
    const double q[2] = {q0, q1};
    try {
      check_state("rk4", 0.5, 7, 1e-5, q, v, 2, bound.data());
    } catch (const SolverError& e) {
      return e.what();
    }
    return "";
  };
  EXPECT_EQ(message(0.0, 1e300), "");
  EXPECT_EQ(message(0.0, -1e300), "");
  EXPECT_NE(message(0.0, std::numeric_limits<double>::infinity()).find("q[1] = inf"),
            std::string::npos);
  EXPECT_NE(message(0.0, -std::numeric_limits<double>::infinity()).find("q[1] = -inf"),
            std::string::npos);
  EXPECT_NE(message(0.0, std::nan("")).find("q[1] = nan"), std::string::npos);
  const std::string bounded = message(2e-3, 1e300);
  EXPECT_NE(bounded.find("|q[0]| = 0.002 m exceeds the blow-up bound 0.001 m"), std::string::npos)
      << bounded;
  EXPECT_NE(bounded.find("t = 0.5 s (step 7, dt = 1e-05 s)"), std::string::npos) << bounded;
  // Without the flag both DOFs keep the bound.
  OscillatorAndFlywheel plain;
  plain.angle_is_cyclic = false;
  EXPECT_EQ(solvers_detail::displacement_bounds(plain, 1e-3), (std::vector<double>{1e-3, 1e-3}));
}

// ---------------------------------------------------------------------------------------------
// (9) Settings and call errors

std::string input_error(const IntegratorSettings& s) {
  try {
    make_integrator(s);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(IntegratorFactory, UnknownMethodNamesKeyValueAndChoices) {
  std::string message;
  try {
    parse_named(kIntegratorMethods, "euler", "solver.method", "method");
  } catch (const InputError& e) {
    message = e.what();
  }
  EXPECT_NE(message.find("solver.method"), std::string::npos) << message;
  EXPECT_NE(message.find("euler"), std::string::npos) << message;
  for (const std::string& name : integrator_names())
    EXPECT_NE(message.find(name), std::string::npos) << message;
}

TEST(IntegratorFactory, BadStepNamesSolverDt) {
  for (const double dt : {0.0, -1e-6, std::numeric_limits<double>::quiet_NaN(),
                          std::numeric_limits<double>::infinity()})
    EXPECT_NE(input_error(settings("rk4", dt)).find("solver.dt"), std::string::npos) << dt;
}

TEST(IntegratorFactory, BadTolerancesNameSolverTolerance) {
  for (const double rtol : {0.0, -1e-6, 0.2, std::numeric_limits<double>::quiet_NaN()})
    EXPECT_NE(input_error(settings("rkf45", 5e-6, rtol)).find("solver.tolerance"),
              std::string::npos)
        << rtol;
  for (const double atol : {0.0, -1e-12, std::numeric_limits<double>::infinity()})
    EXPECT_NE(input_error(settings("bdf", 5e-6, 1e-6, atol)).find("solver.tolerance"),
              std::string::npos)
        << atol;
  EXPECT_EQ(input_error(settings("newmark", 5e-6, 0.1)), "");  // the upper end is allowed
}

TEST(IntegratorFactory, EveryNameMakesThatMethod) {
  EXPECT_EQ(integrator_names(),
            (std::vector<std::string>{"rk4", "rkf45", "rk8pd", "rk8pd-events", "newmark", "bdf"}));
  for (const std::string& name : integrator_names())
    EXPECT_EQ(make_integrator(settings(name, 5e-6))->name(), name);
}

TEST(IntegratorFactory, BadCallsAreInputErrors) {
  const auto integrator = make_integrator(settings("rk4", 5e-6));
  const Observer none;
  EXPECT_THROW(integrator->integrate(kLinear, 0.0, {kQ0, 0.0}, {0.0}, {1e-3}, none), InputError);
  EXPECT_THROW(integrator->integrate(kLinear, 0.0, {kQ0}, {0.0}, {2e-3, 1e-3}, none), InputError);
  EXPECT_THROW(integrator->integrate(kLinear, 1.0, {kQ0}, {0.0}, {0.5}, none), InputError);
  EXPECT_THROW(integrator->integrate(kLinear, 0.0, {std::nan("")}, {0.0}, {1e-3}, none),
               InputError);
}

// ---------------------------------------------------------------------------------------------
// The default Jacobian

TEST(IntegratorJacobian, CentralDifferencesMatchAnalytic) {
  // The Hertz oscillator's analytic Jacobian against the base-class default; the stiff pair
  // (linear, coupled, with damping) against its exact matrix.
  const HertzOscillator& h = kHertz;
  const double q = 0.8 * h.equilibrium(), v = 0.01;
  double dfdq = 0, dfdv = 0, fd_q = 0, fd_v = 0;
  h.force_jacobian(0.0, &q, &v, &dfdq, &dfdv);
  h.MechanicalSystem::force_jacobian(0.0, &q, &v, &fd_q, &fd_v);
  EXPECT_NEAR(fd_q, dfdq, 1e-8 * std::abs(dfdq));
  EXPECT_NEAR(fd_v, dfdv, 1e-12);

  const StiffPair p;
  const double qq[2] = {1e-4, -2e-5}, vv[2] = {0.1, -0.3};
  double jq[4], jv[4];
  p.force_jacobian(0.0, qq, vv, jq, jv);
  const double exact_q[4] = {-p.k1 - p.k2, p.k2, p.k2, -p.k2};
  const double exact_v[4] = {-p.c2, p.c2, p.c2, -p.c2};
  for (int i = 0; i < 4; ++i) {
    EXPECT_NEAR(jq[i], exact_q[i], 1e-8 * p.k2) << i;
    EXPECT_NEAR(jv[i], exact_v[i], 1e-8 * p.c2) << i;
  }
}

// RK4's step limit on the linearised system: 2√2/ω for an undamped oscillator (the imaginary
// axis), 2.7853/|λ| for a pure relaxation (the real axis, where 1 + z + z²/2 + z³/6 + z⁴/24 = −1),
// and for the two-mass chain the higher of the roots of det(K − λM) = 0,
// M m λ² − (M k₂ + m (k₁ + k₂)) λ + k₁ k₂ = 0, with its damping (the Jacobian by central
// differences).
TEST(IntegratorStability, Rk4StepLimitOfOscillationsAndRelaxations) {
  const double q[2] = {0, 0}, v[2] = {0, 0};
  const LinearOscillator osc(0.5, 2e6, 0.0);
  const StepLimit a = rk4_step_limit(osc, 0.0, q, v);
  EXPECT_NEAR(a.step, 2 * std::sqrt(2.0) / std::sqrt(2e6 / 0.5), 1e-9 * a.step);
  EXPECT_NEAR(a.imag, std::sqrt(2e6 / 0.5), 1e-6 * a.imag);
  const LinearOscillator drag(2.0, 0.0, 5e3);  // λ = −c/m = −2500 1/s
  const StepLimit b = rk4_step_limit(drag, 0.0, q, v);
  EXPECT_NEAR(b.step * 2500, 2.785293563405282, 1e-9);
  EXPECT_NEAR(b.real, -2500, 1e-6);
  const StiffPair s;
  const double bq = s.M * s.k2 + s.m * (s.k1 + s.k2), aq = s.M * s.m, cq = s.k1 * s.k2;
  const double omega = std::sqrt((bq + std::sqrt(bq * bq - 4 * aq * cq)) / (2 * aq));
  const StepLimit c = rk4_step_limit(s, 0.0, q, v);
  EXPECT_GT(c.step * omega, 1.0);  // damped (ζ ≈ 1 on the light mass): inside the region
  EXPECT_LT(c.step * omega, 2 * std::sqrt(2.0) + 1e-9);
  // Stable just below the limit and unstable just above: RK4 on the chain itself.
  for (double factor : {0.98, 1.02}) {
    IntegratorSettings set;
    set.dt = factor * c.step;
    set.max_displacement = 1e300;
    std::vector<double> times = {2000 * c.step};
    double end = 0;
    make_integrator(set)->integrate(
        s, 0.0, {1e-3, 1e-3}, {0, 0}, times,
        [&](double, const double* qq, const double*, const double*) { end = std::abs(qq[1]); });
    if (factor < 1)
      EXPECT_LT(end, 1e-3);
    else
      EXPECT_GT(end, 1.0);
  }
}
}  // namespace
}  // namespace bearing
