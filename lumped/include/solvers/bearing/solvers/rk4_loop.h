#pragma once
// The loop of the classic fixed-step RK4 (rk4.cc, where the method and its cost are described) as
// a template on the force, so that a model whose force is hot can instantiate it with its own
// force inlined in the stages (a statically dispatched path: models/static_rk4.h), while
// make_integrator's RK4 instantiates it with MechanicalSystem::force_with behind a virtual call.
// One loop, so both give the same steps and the same arithmetic in the same order: the same
// bits.
//
// The stage arithmetic is element by element, no sums across DOFs and no fused multiply–add at
// the baseline x86-64. It is compiled twice: inline (rk4_inline), used for 2 or 3 DOFs, where
// rk4.cc is built without the loop vectoriser (its packed loads of what the force has just stored
// one DOF at a time would miss store forwarding: ~1 ms of a 45 ms run), and vectorised in
// rk4_wide.cc for the ball-DOF model's 2Z + 2 or 3 DOFs. Both give the same bits.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "bearing/solvers/fixed_step.h"
#include "bearing/solvers/integrator.h"
#include "bearing/solvers/mechanical_system.h"

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

// The arrays never overlap (one allocation, n apart): restrict on the loops' parameters lets the
// vectoriser widen them in rk4_wide.cc without runtime overlap checks (GCC honours it on
// parameters, not on local pointers). The arithmetic is unchanged.

/// a ← M⁻¹ a (w = 1/m per DOF).
inline void scale(double* __restrict a, const double* __restrict w, int n) {
  for (int i = 0; i < n; ++i) a[i] *= w[i];
}
inline void stage2_loop(const double* __restrict q, const double* __restrict v,
                        const double* __restrict a, double* __restrict qs, double* __restrict vs,
                        int n, double hh) {
  for (int i = 0; i < n; ++i) {
    qs[i] = q[i] + hh * v[i];
    vs[i] = v[i] + hh * a[i];
  }
}
inline void stage3_loop(const double* __restrict q, const double* __restrict v,
                        const double* __restrict a, const double* __restrict as,
                        double* __restrict qs, double* __restrict vs, double* __restrict sq,
                        double* __restrict sv, int n, double hh) {
  for (int i = 0; i < n; ++i) {
    sq[i] = v[i] + 2.0 * vs[i];
    sv[i] = a[i] + 2.0 * as[i];
    qs[i] = q[i] + hh * vs[i];
    vs[i] = v[i] + hh * as[i];
  }
}
inline void stage4_loop(const double* __restrict q, const double* __restrict v,
                        const double* __restrict as, double* __restrict qs, double* __restrict vs,
                        double* __restrict sq, double* __restrict sv, int n, double h) {
  for (int i = 0; i < n; ++i) {
    sq[i] += 2.0 * vs[i];
    sv[i] += 2.0 * as[i];
    qs[i] = q[i] + h * vs[i];
    vs[i] = v[i] + h * as[i];
  }
}
inline void finish_loop(const double* __restrict sq, const double* __restrict sv,
                        const double* __restrict vs, const double* __restrict as,
                        double* __restrict q, double* __restrict v, int n, double h6) {
  for (int i = 0; i < n; ++i) {
    q[i] += h6 * (sq[i] + vs[i]);
    v[i] += h6 * (sv[i] + as[i]);
  }
}

/// The second stage's state from a₁.
inline void stage2(const Rk4Arrays& r, double hh) {
  stage2_loop(r.q, r.v, r.a, r.qs, r.vs, r.n, hh);
}
/// The third stage's state from a₂.
inline void stage3(const Rk4Arrays& r, double hh) {
  stage3_loop(r.q, r.v, r.a, r.as, r.qs, r.vs, r.sq, r.sv, r.n, hh);
}
/// The fourth stage's state from a₃.
inline void stage4(const Rk4Arrays& r, double h) {
  stage4_loop(r.q, r.v, r.as, r.qs, r.vs, r.sq, r.sv, r.n, h);
}
/// The step's end from a₄.
inline void finish(const Rk4Arrays& r, double h6) {
  finish_loop(r.sq, r.sv, r.vs, r.as, r.q, r.v, r.n, h6);
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

/// One step of a segment between output times, planned before the segment runs (its times
/// depend on t alone): it starts at t with size h, evaluates the force at t (unless already
/// known), at mid = t + h/2 (twice) and at end = t + h, and the next step starts at `next`
/// (the output time for the segment's last step, else the segment's start + k dt).
struct Rk4Step {
  double t, h, mid, end, next;
};

/// The steps from t [s] to the output time t_out [s] with step dt [s] (Rk4Step), into `plan`.
inline void plan_segment(double t, double dt, double t_out, std::vector<Rk4Step>& plan) {
  plan.clear();
  const double segment_start = t;
  long k = 0;  // steps in this segment: times are segment_start + k dt, not a running sum
  while (t < t_out) {
    const bool last = final_step_to(t, dt, t_out);
    const double h = last ? t_out - t : dt;
    ++k;
    const double next = last ? t_out : segment_start + static_cast<double>(k) * dt;
    // Field by field: a whole Rk4Step built on the stack and copied in 16-byte moves had those
    // loads wait for the 8-byte stores they straddle (a failed store forwarding per step).
    Rk4Step& s = plan.emplace_back();
    s.t = t;
    s.h = h;
    s.mid = t + 0.5 * h;
    s.end = t + h;
    s.next = next;
    t = next;
  }
}

/// check_state's test alone, inline (rk4_loop calls check_state, which names what failed, on a
/// copy of the state only when it fails).
inline bool state_good(const double* q, const double* v, int n, const double* bound) {
  bool good = true;
  for (int i = 0; i < n; ++i) good &= (std::abs(q[i]) <= bound[i]) & (v[i] - v[i] == 0.0);
  return good;
}

/// q, v, a (n each) into the arrays of the same names prefixed by `to_`.
inline void copy_state(const double* q, const double* v, const double* a, int n, double* to_q,
                       double* to_v, double* to_a) {
  std::copy(q, q + n, to_q);
  std::copy(v, v + n, to_v);
  std::copy(a, a + n, to_a);
}

/// The force of make_integrator's RK4: the system's force_with() behind the interface, with the
/// system's workspace; nothing to prepare ahead.
struct InterfaceForce {
  const MechanicalSystem& system;
  MechanicalSystem::Workspace* workspace;
  void operator()(double t, const double* q, const double* v, double* f) const {
    system.force_with(workspace, t, q, v, f);
  }
  void ahead(const std::vector<Rk4Step>& /*plan*/, double /*t_out*/) const {}
  int wide_from(int n) const { return n >= kRk4WideDofs ? 0 : n; }
};

/// One integrate() of RK4 with step `dt` [s] and the blow-up bound `max_displacement` [m]
/// (IntegratorSettings), as Integrator::integrate describes it; `method` names it in messages.
/// force(t, q, v, f) writes the generalised force f(t, q, v) [N per DOF], as
/// MechanicalSystem::force_with does for `system`, whose dofs() and mass() are used; before each
/// segment between output times, force.ahead(plan, t_out) is told the segment's steps (and may
/// prepare what depends on t alone; InterfaceForce does nothing). kDofs > 0: the system's DOF
/// count known at compile time (the stage loops unrolled); 0: system.dofs(), and
/// force.wide_from(n) says from which DOF on the stage loops run vectorised (rk4_wide), the DOFs
/// before it one at a time (rk4_inline): where the force stores its entries one by one, a vector
/// load across several of them would miss store forwarding, and where it stores them a vector at
/// a time (the housed model's support), the stage loops' vectors must start where the force's
/// do. The arithmetic is element by element either way: the same bits.
template <int kDofs, class Force>
IntegrationStats rk4_loop(const std::string& method, double dt, double max_displacement,
                          const MechanicalSystem& system, double t0, const std::vector<double>& q0,
                          const std::vector<double>& v0, const std::vector<double>& output_times,
                          const Observer& observe, const Progress& progress, Force& force) {
  const std::vector<double> inv_mass = check_call(method, system, t0, q0, v0, output_times);
  const int n = kDofs > 0 ? kDofs : system.dofs();
  const std::vector<double> bounds = displacement_bounds(system, max_displacement);
  const double* const bound = bounds.data();
  IntegrationStats stats;

  // With kDofs known, the state lives in a local array, and only copies of it leave the loop
  // (`shown`: the observer, the checks' messages), so the compiler may keep it in registers
  // across the inlined force (issue 42); else on the heap.
  std::vector<double> heap(kDofs > 0 ? 0 : 8 * static_cast<std::size_t>(n));
  double local[kDofs > 0 ? 8 * kDofs : 1];
  double shown_q[kDofs > 0 ? kDofs : 1], shown_v[kDofs > 0 ? kDofs : 1],
      shown_a[kDofs > 0 ? kDofs : 1];
  double* const q = kDofs > 0 ? local : heap.data();  // state
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
  if (!state_good(q, v, n, bound)) check_state(method, t0, 0, dt, q0.data(), v0.data(), n, bound);
  if (output_times.empty()) return stats;

  const int head = kDofs > 0 ? n : force.wide_from(n);  // [0, head) inline, [head, n) wide
  const Rk4Arrays r{q, v, a, qs, vs, as, sq, sv, head};
  const Rk4Arrays tail{q + head,  v + head,  a + head,  qs + head, vs + head,
                       as + head, sq + head, sv + head, n - head};
  const bool wide = kDofs == 0 && tail.n > 0;  // never for a fixed count: nothing opaque
  // Inlined at its four calls: a call would take the arrays' addresses out of the loop, so they
  // could not stay in registers (the force itself is inline for the kinds' own RK4).
  const auto acceleration = [&](double t, const double* qq, const double* vv, double* aa)
      __attribute__((always_inline)) {
    force(t, qq, vv, aa);
    rk4_inline::scale(aa, w, head);
    if (wide) rk4_wide::scale(aa + head, w + head, tail.n);
  };

  ProgressThrottle report(progress, t0, output_times.back());
  double t = t0;
  bool a_current = false;  // whether a holds a(t, q, v) already
  long evaluations = 0;
  std::vector<Rk4Step> plan;
  for (const double t_out : output_times) {
    plan_segment(t, dt, t_out, plan);
    force.ahead(plan, t_out);
    for (const Rk4Step& s : plan) {
      const double h = s.h;
      const double hh = 0.5 * h;
      if (!a_current) {
        acceleration(t, q, v, a);
        ++evaluations;
      }
      rk4_inline::stage2(r, hh);
      if (wide) rk4_wide::stage2(tail, hh);
      acceleration(s.mid, qs, vs, as);
      rk4_inline::stage3(r, hh);
      if (wide) rk4_wide::stage3(tail, hh);
      acceleration(s.mid, qs, vs, as);
      rk4_inline::stage4(r, h);
      if (wide) rk4_wide::stage4(tail, h);
      acceleration(s.end, qs, vs, as);
      const double h6 = h / 6.0;
      rk4_inline::finish(r, h6);
      if (wide) rk4_wide::finish(tail, h6);
      evaluations += 3;
      a_current = false;
      t = s.next;
      ++stats.steps;
      if (!state_good(q, v, n, bound)) {
        if constexpr (kDofs > 0) {  // the copies hold kDofs values: the state itself otherwise
          copy_state(q, v, a, n, shown_q, shown_v, shown_a);
          check_state(method, t, stats.steps, h, shown_q, shown_v, n, bound);
        } else {
          check_state(method, t, stats.steps, h, q, v, n, bound);
        }
      }
      report.update(t);
    }
    acceleration(t, q, v, a);
    ++evaluations;
    a_current = true;
    if constexpr (kDofs > 0) {
      copy_state(q, v, a, n, shown_q, shown_v, shown_a);
      check_acceleration(method, t, stats.steps, dt, shown_a, n);
      if (observe) observe(t, shown_q, shown_v, shown_a);
    } else {
      check_acceleration(method, t, stats.steps, dt, a, n);
      if (observe) observe(t, q, v, a);
    }
  }
  stats.force_evaluations = evaluations;
  report.finish();
  return stats;
}

}  // namespace bearing::solvers_detail
