// Classic fixed-step fourth-order Runge–Kutta on the first-order form y = [q, v],
//     q' = v,   v' = a(t, q, v) = M⁻¹ f(t, q, v),
// the seeds' method (dt = 5 or 10 µs). One step of size h from (t, q, v):
//     a₁ = a(t, q, v)
//     a₂ = a(t + h/2, q + h/2 v,  v + h/2 a₁)        with v₂ = v + h/2 a₁
//     a₃ = a(t + h/2, q + h/2 v₂, v + h/2 a₂)        with v₃ = v + h/2 a₂
//     a₄ = a(t + h,   q + h v₃,   v + h a₃)          with v₄ = v + h a₃
//     q ← q + h/6 (v + 2v₂ + 2v₃ + v₄),   v ← v + h/6 (a₁ + 2a₂ + 2a₃ + a₄).
// Global error O(h⁴). Every step is dt except the one that would pass an output time, which is
// shortened to end on it exactly; the next step starts there with dt again.
//
// Cost: four force evaluations per step and O(n) arithmetic, on eight arrays of n doubles
// allocated once per integrate() (and the system's force workspace, MechanicalSystem::force_with).
// At an output time the force is evaluated afresh for the observer's acceleration (counted in
// force_evaluations); that evaluation is at the state the next step starts from, so it doubles as
// that step's a₁ and costs nothing extra.

#include <memory>
#include <string>
#include <vector>

#include "bearing/solvers/integrator.h"
#include "integrator_detail.h"
#include "rk4_stages.h"

namespace bearing {
namespace solvers_detail {

namespace {

class Rk4 final : public Integrator {
 public:
  explicit Rk4(const IntegratorSettings& settings) : settings_(settings) {}

  IntegrationStats integrate(const MechanicalSystem& system, double t0,
                             const std::vector<double>& q0, const std::vector<double>& v0,
                             const std::vector<double>& output_times, const Observer& observe,
                             const Progress& progress) const override;

  std::string name() const override { return "rk4"; }

 private:
  IntegratorSettings settings_;
};

IntegrationStats Rk4::integrate(const MechanicalSystem& system, double t0,
                                const std::vector<double>& q0, const std::vector<double>& v0,
                                const std::vector<double>& output_times, const Observer& observe,
                                const Progress& progress) const {
  const std::string method = name();
  const std::vector<double> inv_mass = check_call(method, system, t0, q0, v0, output_times);
  const int n = system.dofs();
  const double dt = settings_.dt;
  const std::vector<double> bounds = displacement_bounds(system, settings_.max_displacement);
  const double* const bound = bounds.data();
  IntegrationStats stats;

  std::vector<double> work(8 * static_cast<std::size_t>(n));
  double* const q = work.data();  // state
  double* const v = q + n;
  double* const a = v + n;    // a₁ = M⁻¹ f at (t, q, v)
  double* const qs = a + n;   // stage displacement
  double* const vs = qs + n;  // stage velocity v₂, v₃, v₄
  double* const as = vs + n;  // stage acceleration a₂, a₃, a₄
  double* const sq = as + n;  // v + 2v₂ + 2v₃ (+ v₄)
  double* const sv = sq + n;  // a₁ + 2a₂ + 2a₃ (+ a₄)
  const double* const w = inv_mass.data();
  std::copy(q0.begin(), q0.end(), q);
  std::copy(v0.begin(), v0.end(), v);
  check_state(method, t0, 0, dt, q, v, n, bound);
  if (output_times.empty()) return stats;

  const Rk4Arrays r{q, v, a, qs, vs, as, sq, sv, n};
  const bool wide = n >= kRk4WideDofs;
  const std::unique_ptr<MechanicalSystem::Workspace> workspace = system.make_workspace();
  const auto acceleration = [&](double t, const double* qq, const double* vv, double* aa) {
    system.force_with(workspace.get(), t, qq, vv, aa);
    wide ? rk4_wide::scale(aa, w, n) : rk4_inline::scale(aa, w, n);
  };

  ProgressThrottle report(progress, t0, output_times.back());
  double t = t0;
  bool a_current = false;  // whether a holds a(t, q, v) already
  long evaluations = 0;
  for (const double t_out : output_times) {
    const double segment_start = t;
    long k = 0;  // steps in this segment: times are segment_start + k dt, not a running sum
    while (t < t_out) {
      const bool last = final_step_to(t, dt, t_out);
      const double h = last ? t_out - t : dt;
      const double hh = 0.5 * h;
      if (!a_current) {
        acceleration(t, q, v, a);
        ++evaluations;
      }
      wide ? rk4_wide::stage2(r, hh) : rk4_inline::stage2(r, hh);
      acceleration(t + hh, qs, vs, as);
      wide ? rk4_wide::stage3(r, hh) : rk4_inline::stage3(r, hh);
      acceleration(t + hh, qs, vs, as);
      wide ? rk4_wide::stage4(r, h) : rk4_inline::stage4(r, h);
      acceleration(t + h, qs, vs, as);
      const double h6 = h / 6.0;
      wide ? rk4_wide::finish(r, h6) : rk4_inline::finish(r, h6);
      evaluations += 3;
      a_current = false;
      ++k;
      t = last ? t_out : segment_start + static_cast<double>(k) * dt;
      ++stats.steps;
      check_state(method, t, stats.steps, h, q, v, n, bound);
      report.update(t);
    }
    acceleration(t, q, v, a);
    ++evaluations;
    a_current = true;
    check_acceleration(method, t, stats.steps, dt, a, n);
    if (observe) observe(t, q, v, a);
  }
  stats.force_evaluations = evaluations;
  report.finish();
  return stats;
}

}  // namespace

std::unique_ptr<Integrator> make_rk4(const IntegratorSettings& settings) {
  return std::make_unique<Rk4>(settings);
}

}  // namespace solvers_detail
}  // namespace bearing
