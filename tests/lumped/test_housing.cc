// The housing carrying the outer ring (models/housing.h) against closed forms and conservation
// laws: driven by a prescribed ring force it is the single-DOF oscillator (amplitude, phase, peak,
// free decay); on a linear bearing the two-mass chain; on the 2-DOF and 3-DOF models its energy
// balance, the whole system's conservation, its Jacobian, the limit k_h → ∞ and RK4's order; and
// the [housing] table's rules.

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/models/housing.h"
#include "bearing/models/model_registry.h"
#include "bearing/models/two_dof.h"
#include "bearing/simulation.h"
#include "bearing/solvers/integrator.h"
#include "housing_helpers.h"

namespace bearing {
namespace {

// The steady housing response to the ring force F sin ω t: the housing takes −F sin ω t, so its
// displacement is −(F/k_h) A(r) sin(ω t − φ), A = 1/sqrt((1 − r²)² + (2ζr)²),
// φ = atan2(2ζr, 1 − r²), r = ω/ω_h. Returns the simulated (amplitude, phase φ).
std::pair<double, double> simulated_response(double ratio, double zeta, double* accel_amplitude) {
  const double fh = 2000.0, mh = 0.5;
  StubBearing stub;
  stub.amplitude = 3.0;
  stub.omega = ratio * two_pi * fh;
  const auto model = on_housing(stub, housing(mh, fh, zeta));
  // The free transient decays as exp(−ζ ω_h t): 30 time constants before the fit window.
  const double settle = 30.0 / (zeta * two_pi * fh), window = 10.0 / fh;
  const double dt = 1.0 / (400.0 * fh * std::max(1.0, ratio));  // ω h ≤ 2π/400
  const Samples r = integrate(*model, IntegratorMethod::rk4, dt, 1e-6, {0, 0, 0, 0}, {0, 0, 0, 0},
                              settle + window, dt);
  const Eigen::Vector2d sc = fit_sine(r, 3, false, stub.omega, settle);
  if (accel_amplitude) *accel_amplitude = fit_sine(r, 3, true, stub.omega, settle).norm();
  // y_h = s sin + c cos = −X (sin ω t cos φ − cos ω t sin φ): −s = X cos φ, c = X sin φ.
  return {sc.norm(), std::atan2(sc.y(), -sc.x())};
}

// Forced by a prescribed ring force, the housing is the single-DOF oscillator m_h ÿ + c_h ẏ + k_h
// y = −F sin ω t, with k_h = m_h (2π f_h)² and c_h = 2ζ m_h 2π f_h: amplitude and phase at five
// frequency ratios, and the sensor's acceleration ω² times the displacement. RK4 at ωh ≤ 2π/400
// errs by ~(ωh)⁴ ≈ 6e-8 relative; the tolerances, 1e-5, are far below what a wrong sign (phase off
// by π) or a missing 2π (f_h 6.3 times too low) would give.
TEST(Housing, ForcedByTheRingItIsTheSingleDofOscillator) {
  const double zeta = 0.05, k = 0.5 * std::pow(two_pi * 2000.0, 2), F = 3.0;
  for (double r : {0.5, 0.9, 1.0, 1.1, 2.0}) {
    double accel = 0;
    const auto [amplitude, phase] = simulated_response(r, zeta, &accel);
    const double A = 1.0 / std::hypot(1 - r * r, 2 * zeta * r);
    EXPECT_NEAR(amplitude, F / k * A, 1e-5 * F / k * A) << "r = " << r;
    EXPECT_NEAR(phase, std::atan2(2 * zeta * r, 1 - r * r), 1e-5) << "r = " << r;
    const double omega = r * two_pi * 2000.0;
    EXPECT_NEAR(accel, omega * omega * amplitude, 1e-5 * omega * omega * amplitude);
  }
}

// The displacement's resonance peak lies at f_h sqrt(1 − 2ζ²), not at f_h or at the damped
// f_h sqrt(1 − ζ²): ζ = 0.2 puts them at 0.959, 1 and 0.980 f_h. A golden-section search on the
// simulated amplitude; near the peak A(r) ≈ A₀(1 − 12 (r − r_p)²), so an amplitude good to 1e-7
// places the peak to ~1e-4, and 1e-3 separates the three candidates by 20 tolerances.
TEST(Housing, ResonancePeakOfTheDisplacement) {
  const double zeta = 0.2;
  const auto amplitude = [&](double r) { return simulated_response(r, zeta, nullptr).first; };
  const double golden = 0.5 * (std::sqrt(5.0) - 1.0);
  double lo = 0.9, hi = 1.0;
  double x1 = hi - golden * (hi - lo), x2 = lo + golden * (hi - lo);
  double a1 = amplitude(x1), a2 = amplitude(x2);
  while (hi - lo > 1e-5) {
    if (a1 > a2) {
      hi = x2, x2 = x1, a2 = a1, x1 = hi - golden * (hi - lo), a1 = amplitude(x1);
    } else {
      lo = x1, x1 = x2, a1 = a2, x2 = lo + golden * (hi - lo), a2 = amplitude(x2);
    }
  }
  EXPECT_NEAR(0.5 * (lo + hi), std::sqrt(1 - 2 * zeta * zeta), 1e-3);
}

// Released from a displaced rest, the housing rings at f_d = f_h sqrt(1 − ζ²), each period smaller
// by the logarithmic decrement 2πζ/sqrt(1 − ζ²), in x and in y alike (isotropic). Upward zero
// crossings by linear interpolation (error ~ h² ζ ω/4 in time, 1e-7 of a period at h = T/1000).
TEST(Housing, FreeDecayFrequencyAndDecrement) {
  for (double zeta : {0.05, 0.3}) {
    const double fh = 2000.0;
    StubBearing stub;  // no force on the ring: the housing is alone
    const auto model = on_housing(stub, housing(0.5, fh, zeta));
    const double dt = 1.0 / (1000.0 * fh);
    const Samples r = integrate(*model, IntegratorMethod::rk4, dt, 1e-6, {0, 0, -0.5e-6, 1e-6},
                                {0, 0, 0, 0}, 6.0 / fh, dt);
    for (int dof : {2, 3}) {
      std::vector<double> crossing, speed;  // the times y = 0 upward, and ẏ there
      for (std::size_t k = 1; k < r.t.size(); ++k) {
        const double y0 = r.q[k - 1][dof], y1 = r.q[k][dof];
        if (y0 < 0 && y1 >= 0) {
          const double w = -y0 / (y1 - y0);
          crossing.push_back(r.t[k - 1] + w * (r.t[k] - r.t[k - 1]));
          speed.push_back(r.v[k - 1][dof] + w * (r.v[k][dof] - r.v[k - 1][dof]));
        }
      }
      ASSERT_GE(crossing.size(), 3u);
      const double periods = static_cast<double>(crossing.size() - 1);
      const double fd = periods / (crossing.back() - crossing.front());
      EXPECT_NEAR(fd, fh * std::sqrt(1 - zeta * zeta), 1e-6 * fh) << "zeta " << zeta;
      const double decrement = std::log(speed.front() / speed.back()) / periods;
      const double expected = two_pi * zeta / std::sqrt(1 - zeta * zeta);
      EXPECT_NEAR(decrement, expected, 1e-5 * expected) << "zeta " << zeta;
    }
  }
}

// On a linear bearing (k_b between the rings) the undamped modes are the two-mass chain's:
// m m_h ω⁴ − (m (k_b + k_h) + m_h k_b) ω² + k_b k_h = 0, each twice (x and y); the housing's
// share of the kinetic energy of the lower mode is m_h φ_h²/(m φ_r² + m_h φ_h²) with
// φ_h/φ_r = (k_b − m ω²)/k_b.
TEST(Housing, ModesOfTheTwoMassChain) {
  StubBearing stub;
  stub.stiffness = 4e7;
  const double m = stub.ring_mass, mh = 0.5, kb = stub.stiffness;
  const Housing h = housing(mh, 3000.0, 0.05);
  const double kh = h.stiffness();
  const auto modes = housing_modes(*on_housing(stub, h));
  ASSERT_EQ(modes.size(), 4u);
  const double b = m * (kb + kh) + mh * kb, disc = std::sqrt(b * b - 4 * m * mh * kb * kh);
  const double w_lo = std::sqrt((b - disc) / (2 * m * mh)),
               w_hi = std::sqrt((b + disc) / (2 * m * mh));
  for (int i : {0, 1}) EXPECT_NEAR(modes[i].frequency, w_lo / two_pi, 1e-9 * w_lo);
  for (int i : {2, 3}) EXPECT_NEAR(modes[i].frequency, w_hi / two_pi, 1e-9 * w_hi);
  const double ratio = (kb - m * w_lo * w_lo) / kb;
  const double share = mh * ratio * ratio / (m + mh * ratio * ratio);
  EXPECT_NEAR(modes[0].housing_share, share, 1e-9);
  EXPECT_NEAR(modes[2].housing_share, 1 - share, 1e-9);
}

// ---------------------------------------------------------------------------------------------
// On the bearing models.

Case case_with(std::vector<std::string> sets) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return default_case(o);
}

// The 6308 under 500 N at 2000 rpm on a 1 kg housing at 3 kHz.
std::vector<std::string> loaded_on_housing(const std::string& frequency = "3kHz") {
  return {"operation.load=[0, -500]", "housing.mass=1kg", "housing.frequency=" + frequency,
          "housing.damping_ratio=0.05"};
}

// What the bearing exerts on the inner ring, from the 2-DOF model itself built without the
// housing and without the ring loads, at the rings' relative state.
Eigen::Vector2d bearing_force(const BearingModel& bearing, double t, const std::vector<double>& q,
                              const std::vector<double>& v) {
  const std::vector<double> qr{q[0] - q[2], q[1] - q[3]}, vr{v[0] - v[2], v[1] - v[3]};
  double f[2];
  bearing.force(t, qr.data(), vr.data(), f);
  return {f[0], f[1]};
}

ModelInputs without_ring_loads(ModelInputs in) {
  in.housing = Housing{};
  in.load = Eigen::Vector2d::Zero();
  in.unbalance = 0.0;
  in.gravity = false;
  return in;
}

// The housing's energy E_h = ½ m_h |v_h|² + ½ k_h |q_h|² changes by the work of the bearing's
// reaction −f_b minus what its damper dissipates: ΔE_h = ∫ (−f_b·v_h − c_h |v_h|²) dt, over 10 ms
// of the turning, loaded 6308. f_b comes from a separately built 2-DOF model; k_h, c_h from m_h,
// f_h, ζ here. The integral by Simpson's rule on 0.5 µs samples: (ωh)⁴/180 ≈ 1e-7 for the
// ~20 kHz content, so 1e-5 of the gross energy flow is a bound, not a fit.
TEST(Housing, EnergyOfTheHousingChangesByTheReactionsWork) {
  const Case c = case_with(loaded_on_housing());
  const auto model = make_model(c);
  const auto bearing = make_two_dof_model(without_ring_loads(model_inputs(c)));
  const double mh = 1.0, wh = two_pi * 3000.0, kh = mh * wh * wh, ch = 2 * 0.05 * mh * wh;
  const double h = 0.5e-6;
  const Samples r = integrate(*model, IntegratorMethod::rk4, h, 1e-6, model->initial_displacement(),
                              model->initial_velocity(), 0.01, h);
  std::vector<double> power(r.t.size());
  double gross = 0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const Eigen::Vector2d vh(r.v[k][2], r.v[k][3]);
    const Eigen::Vector2d reaction = -bearing_force(*bearing, r.t[k], r.q[k], r.v[k]);
    power[k] = reaction.dot(vh) - ch * vh.squaredNorm();
    gross += h * (std::fabs(reaction.dot(vh)) + ch * vh.squaredNorm());
  }
  ASSERT_EQ(r.t.size() % 2, 1u);  // Simpson needs an even number of intervals
  double work = 0;
  for (std::size_t k = 0; k + 2 < r.t.size(); k += 2)
    work += h / 3 * (power[k] + 4 * power[k + 1] + power[k + 2]);
  const auto energy = [&](std::size_t k) {
    const auto& q = r.q[k];
    const auto& v = r.v[k];
    return 0.5 * mh * (v[2] * v[2] + v[3] * v[3]) + 0.5 * kh * (q[2] * q[2] + q[3] * q[3]);
  };
  EXPECT_GT(gross, 1e-3 * energy(0));  // energy flows through the housing
  EXPECT_NEAR(energy(r.t.size() - 1) - energy(0), work, 1e-5 * gross);
}

// At rest without damping the bearing on its housing is conservative: the kinetic energy of ring
// and housing, the contacts' energy at the relative position, the housing's spring and the work of
// the ring's load add up to a constant (the reaction acts on the housing as on the ring, or the
// sum would drift). Released off equilibrium so the balls part and re-impact; rk8pd at 1e-11.
TEST(Housing, BearingOnItsHousingConservesEnergyAtRest) {
  const Case c =
      case_with({"operation.speed=0rpm", "rotor.damping=0", "operation.load=[0, -300]",
                 "housing.mass=1kg", "housing.frequency=3kHz", "housing.damping_ratio=0"});
  const auto model = make_model(c);
  const auto bearing = make_two_dof_model(without_ring_loads(model_inputs(c)));
  const double m = c.rotor.mass, mh = 1.0, kh = mh * std::pow(two_pi * 3000.0, 2);
  std::vector<double> q0 = model->initial_displacement();
  q0[1] += 2e-6;
  q0[0] += 1e-6;
  q0[3] -= 0.5e-6;
  const Samples r =
      integrate(*model, IntegratorMethod::rk8pd, 1e-6, 1e-11, q0, {0, 0, 0, 0}, 0.02, 4e-5);
  const auto energy = [&](std::size_t k) {
    const auto& q = r.q[k];
    const auto& v = r.v[k];
    const double qr[2] = {q[0] - q[2], q[1] - q[3]};
    return 0.5 * m * (v[0] * v[0] + v[1] * v[1]) + 0.5 * mh * (v[2] * v[2] + v[3] * v[3]) +
           bearing->potential_energy(0.0, qr) + 0.5 * kh * (q[2] * q[2] + q[3] * q[3]) -
           c.operation.load.x() * q[0] - c.operation.load.y() * q[1];
  };
  double exchanged = 0, drift = 0;
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const auto& v = r.v[k];
    exchanged = std::max(exchanged, 0.5 * mh * (v[2] * v[2] + v[3] * v[3]));
    drift = std::max(drift, std::fabs(energy(k) - energy(0)));
  }
  EXPECT_GT(exchanged, 0.0);
  EXPECT_LT(drift / exchanged, 1e-6);
}

// With the housing at rest (q_h = v_h = 0) the ring feels the model without the housing exactly
// (loads, gravity, unbalance, waviness), and the housing takes what the bearing exerts on the ring
// with the opposite sign; the static start is an equilibrium of every DOF.
TEST(Housing, HousingAtRestIsTheFixedOuterRing) {
  const std::string wavy =
      std::string(default_case_toml()) + "[[waviness.inner]]\norder = 3\namplitude = \"0.5 um\"\n";
  const auto read = [&](std::vector<std::string> sets) {
    std::vector<Override> o;
    for (const auto& s : sets) o.push_back(parse_override(s));
    return parse_case(wavy, "test", o);
  };
  for (const char* kind : {"2dof", "3dof"}) {
    const std::vector<std::string> plain_sets{
        std::string("model.kind=") + kind, "operation.load=[40, -300]", "operation.gravity=true",
        "operation.unbalance=2e-4",
        "operation.axial_load=" + std::string(kind == std::string("3dof") ? "150" : "0")};
    auto sets = plain_sets;
    for (const char* h : {"housing.mass=1kg", "housing.frequency=3kHz"}) sets.push_back(h);
    const Case c = read(sets);
    const auto model = make_model(c);
    const auto plain = make_model(read(plain_sets));
    const auto bearing = make_dynamic_model(c.model.kind, without_ring_loads(model_inputs(c)));
    const int n = plain->dofs();
    ASSERT_EQ(model->dofs(), n + 2);
    std::vector<double> q = plain->initial_displacement(), v(n);
    q[0] += 0.3e-6;
    for (int i = 0; i < n; ++i) v[i] = 2e-3 * (i + 1);
    std::vector<double> qf = q, vf = v, f(n + 2), g(n), b(n);
    qf.insert(qf.end(), {0.0, 0.0});
    vf.insert(vf.end(), {0.0, 0.0});
    const double t = 1.7e-3;
    model->force(t, qf.data(), vf.data(), f.data());
    plain->force(t, q.data(), v.data(), g.data());
    bearing->force(t, q.data(), v.data(), b.data());
    for (int i = 0; i < n; ++i) EXPECT_NEAR(f[i], g[i], 1e-12 * 300) << kind << " dof " << i;
    EXPECT_NEAR(f[n], -b[0], 1e-12 * 300) << kind;
    EXPECT_NEAR(f[n + 1], -b[1], 1e-12 * 300) << kind;
    // The static start: no force anywhere (without unbalance and waviness, as the start assumes).
    sets.push_back("operation.unbalance=0");
    sets.push_back("waviness.inner.0.amplitude=0um");
    const auto still = make_model(read(sets));
    const std::vector<double> q0 = still->initial_displacement(), v0(n + 2, 0.0);
    still->force(0.0, q0.data(), v0.data(), f.data());
    for (int i = 0; i < n + 2; ++i) EXPECT_NEAR(f[i], 0.0, 1e-7 * 300) << kind << " dof " << i;
  }
}

// The analytic Jacobian of the bearing on its housing against central differences, for both kinds
// that carry it, at a state off equilibrium with every velocity nonzero (newmark and bdf use it).
TEST(Housing, JacobianMatchesDifferences) {
  for (const char* kind : {"2dof", "3dof"}) {
    std::vector<std::string> sets = loaded_on_housing();
    sets.push_back(std::string("model.kind=") + kind);
    sets.push_back("operation.axial_load=200");
    if (std::string(kind) == "2dof") sets.back() = "operation.unbalance=1e-4";
    const auto model = make_model(case_with(sets));
    const int n = model->dofs();
    std::vector<double> q = model->initial_displacement(), v(n);
    for (int i = 0; i < n; ++i) v[i] = 1e-3 * (i + 1);
    q[n - 1] += 0.3e-6;
    q[0] -= 0.2e-6;
    std::vector<double> dfdq(n * n), dfdv(n * n), fp(n), fm(n);
    model->force_jacobian(1e-3, q.data(), v.data(), dfdq.data(), dfdv.data());
    double scale = 0;
    for (double x : dfdq) scale = std::max(scale, std::fabs(x));
    for (int j = 0; j < n; ++j) {
      for (int which : {0, 1}) {
        auto qp = q, qm = q, vp = v, vm = v;
        const double h = which == 0 ? 1e-10 : 1e-4;
        (which == 0 ? qp : vp)[j] += h;
        (which == 0 ? qm : vm)[j] -= h;
        model->force(1e-3, qp.data(), vp.data(), fp.data());
        model->force(1e-3, qm.data(), vm.data(), fm.data());
        for (int i = 0; i < n; ++i) {
          const double d = (fp[i] - fm[i]) / (2 * h);
          if (which == 0)
            EXPECT_NEAR(dfdq[i * n + j], d, 1e-6 * scale) << kind << " df" << i << "/dq" << j;
          else
            EXPECT_NEAR(dfdv[i * n + j], d, 1e-9 * (1 + std::fabs(d)))
                << kind << " df" << i << "/dv" << j;
        }
      }
    }
  }
}

// As the housing stiffens (f_h → ∞ at fixed m_h) the ring moves as on a fixed outer ring: the
// housing yields by O(f_b/k_h), so the difference is O(1/k_h) = O(f_h⁻²), order 2 in f_h. The
// largest difference of y over 10 ms against the model without the housing, at f_h = 10, 20 and
// 40 kHz (well above the ring's ~2 kHz resonance, where the quasi-static yield dominates); rk8pd
// at 1e-12 keeps its own error far below the nanometres compared.
TEST(Housing, StiffHousingGivesBackTheFixedOuterRing) {
  const auto largest_y = [](const Samples& a, const Samples& b) {
    double d = 0;
    for (std::size_t k = 0; k < a.t.size(); ++k) d = std::max(d, std::fabs(a.q[k][1] - b.q[k][1]));
    return d;
  };
  const Case fixed = case_with({"operation.load=[0, -500]"});
  const auto plain = make_model(fixed);
  const Samples reference = integrate(*plain, IntegratorMethod::rk8pd, 1e-6, 1e-12,
                                      plain->initial_displacement(), {0, 0}, 0.01, 1e-5);
  std::vector<double> difference;
  for (const char* f : {"10kHz", "20kHz", "40kHz"}) {
    const auto model = make_model(case_with(loaded_on_housing(f)));
    const Samples r = integrate(*model, IntegratorMethod::rk8pd, 1e-7, 1e-12,
                                model->initial_displacement(), {0, 0, 0, 0}, 0.01, 1e-5);
    difference.push_back(largest_y(r, reference));
  }
  for (int i : {0, 1}) {
    const double order = std::log2(difference[i] / difference[i + 1]);
    EXPECT_NEAR(order, 2.0, 0.15) << "from f_h = " << (10 << i) << " kHz to twice that";
  }
}

// RK4 keeps its fourth order with the housing on: the 3-DOF model under an axial preload keeps
// every ball loaded (smooth forces), on a housing at 3 kHz; p = log2(d(h)/d(h/2)), d(h) the largest
// difference over 2 ms between the runs at h and h/2, for the ring's y and the housing's y, at
// h = 8, 4, 2 µs (test_dynamics.cc does the same without the housing).
TEST(Housing, Rk4KeepsItsOrderWithTheHousing) {
  const auto model = make_model(
      case_with({"model.kind=3dof", "operation.axial_load=500", "operation.load=[0, -300]",
                 "housing.mass=0.5kg", "housing.frequency=3kHz"}));
  std::vector<double> q0 = model->initial_displacement();
  q0[1] += 0.5e-6;
  q0[4] -= 0.2e-6;
  const std::vector<double> v0(q0.size(), 0.0);
  const Samples check = integrate(*model, IntegratorMethod::rk4, 1e-6, 1e-9, q0, v0, 2e-3, 1e-5);
  std::vector<double> loads(static_cast<std::size_t>(model->balls()));
  for (std::size_t k = 0; k < check.t.size(); ++k) {
    model->ball_loads(check.t[k], check.q[k].data(), loads.data());
    for (double Q : loads) ASSERT_GT(Q, 0.0);
  }
  std::vector<Samples> runs;
  for (double dt : {8e-6, 4e-6, 2e-6, 1e-6})
    runs.push_back(integrate(*model, IntegratorMethod::rk4, dt, 1e-9, q0, v0, 2e-3, 8e-6));
  for (int dof : {1, 4}) {
    std::vector<double> d;
    for (std::size_t i = 0; i + 1 < runs.size(); ++i) {
      double most = 0;
      for (std::size_t k = 0; k < runs[i].t.size(); ++k)
        most = std::max(most, std::fabs(runs[i].q[k][dof] - runs[i + 1].q[k][dof]));
      d.push_back(most);
    }
    for (std::size_t i = 0; i + 1 < d.size(); ++i)
      EXPECT_NEAR(std::log2(d[i] / d[i + 1]), 4.0, 0.2) << "dof " << dof << ", step halving " << i;
  }
}

// ---------------------------------------------------------------------------------------------
// The [housing] table.

std::string input_error(const std::vector<std::string>& sets) {
  try {
    const Case c = case_with(sets);
    make_model(c);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Housing, TableRulesNameTheKey) {
  EXPECT_NE(input_error({"housing.mass=1kg"}).find("housing.frequency is missing"),
            std::string::npos);
  EXPECT_NE(input_error({"housing.frequency=3kHz"}).find("housing.mass is missing"),
            std::string::npos);
  EXPECT_NE(input_error({"housing.mas=1kg", "housing.frequency=3kHz"}).find("did you mean"),
            std::string::npos);
  EXPECT_NE(input_error({"housing.mass=0", "housing.frequency=3kHz"}).find("housing.mass = 0"),
            std::string::npos);
  EXPECT_NE(input_error({"housing.mass=1kg", "housing.frequency=-3kHz"}).find("housing.frequency"),
            std::string::npos);
  EXPECT_NE(input_error({"housing.mass=1kg", "housing.frequency=3kHz", "housing.damping_ratio=1"})
                .find("housing.damping_ratio = 1"),
            std::string::npos);
  for (const char* kind : {"balls", "quasistatic"})
    EXPECT_NE(input_error(
                  {"housing.mass=1kg", "housing.frequency=3kHz", std::string("model.kind=") + kind})
                  .find("[housing]: model.kind = \"" + std::string(kind) + "\""),
              std::string::npos)
        << kind;
  ModelInputs in = model_inputs(case_with({}));
  in.housing = housing(1.0, 3000.0, 0.05);
  EXPECT_THROW(make_dynamic_model(ModelKind::balls, in), InputError);  // from code, too
  in.housing.mass = -1;
  EXPECT_THROW(make_dynamic_model(ModelKind::two_dof, in), InputError);
}

// Absent, the housing is off and case.toml has no [housing]; present, it is written back whole
// (damping ratio default 0.05) and reads back to the same values.
TEST(Housing, TableIsOffByDefaultAndRoundTrips) {
  const Case off = case_with({});
  EXPECT_FALSE(off.housing.enabled);
  EXPECT_EQ(case_to_toml(off).find("[housing]"), std::string::npos);
  EXPECT_EQ(make_model(off)->dofs(), 2);
  const Case on = case_with({"housing.mass=1.5kg", "housing.frequency=2.5kHz"});
  ASSERT_TRUE(on.housing.enabled);
  EXPECT_EQ(on.housing.damping_ratio, 0.05);
  const Case back = parse_case(case_to_toml(on), "written");
  EXPECT_TRUE(back.housing.enabled);
  EXPECT_EQ(back.housing.mass, 1.5);
  EXPECT_EQ(back.housing.frequency, 2500.0);
  EXPECT_EQ(back.housing.damping_ratio, 0.05);
  const auto model = make_model(on);
  EXPECT_EQ(model->dof_names(), (std::vector<std::string>{"x", "y", "x_housing", "y_housing"}));
  // The static start: the housing carries the whole load, k_h y_h = F_y.
  const std::vector<double> q0 = model->initial_displacement();
  EXPECT_DOUBLE_EQ(q0[3], on.operation.load.y() / on.housing.stiffness());
}

}  // namespace
}  // namespace bearing
