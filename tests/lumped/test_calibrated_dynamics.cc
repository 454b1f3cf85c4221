// The FE-calibrated contact law in the dynamics: it reaches the 2-DOF and 3-DOF models, a general
// exponent runs and settles where the static solution with that exponent says, and TVDS uses the
// file's per-race constants (or refuses a non-Hertz exponent with a clear message).

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/models/three_dof.h"
#include "bearing/simulation.h"
#include "bearing/static_load.h"
#include "calibration_files.h"

namespace bearing {
namespace {

Case case_with(std::vector<std::string> sets) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return default_case(o);
}

// Race constants for exponent n that agree with the exact Hertz law at the ball load q0 [N]:
// K_n = q0 / δ(q0)^n with δ(q0) = (q0/K_1.5)^{2/3}.
nlohmann::json calibration_with_exponent(const Bearing& b, double n, double q0) {
  const ContactConstants h = contact_constants(b, *make_exact_hertz());
  const auto k = [&](double k15) { return q0 / std::pow(std::pow(q0 / k15, 1 / 1.5), n); };
  return test::calibration_doc(b, k(h.inner.K), n, k(h.outer.K), n);
}

std::vector<std::string> calibrated(const std::string& path) {
  return {"model.contact=calibrated", "model.calibration=" + path};
}

template <class T>
std::vector<T> operator+(std::vector<T> a, const std::vector<T>& b) {
  a.insert(a.end(), b.begin(), b.end());
  return a;
}

// (a) The exact Hertz constants as a calibration run exactly like contact = "exact".
TEST(CalibratedDynamics, HertzConstantsRunLikeTheExactLaw) {
  const std::vector<std::string> base = {"solver.duration=0.3", "solver.transient=0.1",
                                         "waviness.inner=[{order=8, amplitude=\"0.3 um\"}]"};
  const Case exact = case_with(base);
  const std::string path =
      test::write_calibration("dyn_hertz.json", test::hertz_calibration_doc(exact.bearing));
  const Case cal = case_with(base + calibrated(path));
  for (const ModelKind kind : {ModelKind::two_dof, ModelKind::three_dof}) {
    Case a = exact, b = cal;
    a.model.kind = b.model.kind = kind;
    const RunSummary sa = summarize(a, simulate(a)), sb = summarize(b, simulate(b));
    ASSERT_EQ(sa.channels.size(), sb.channels.size());
    for (std::size_t i = 0; i < sa.channels.size(); ++i) {
      const double ra = sa.channels[i].statistics.rms, rb = sb.channels[i].statistics.rms;
      EXPECT_LE(std::abs(ra - rb), 1e-12 * std::abs(ra))
          << name_of(kModelKinds, kind) << " " << sa.channels[i].name;
    }
  }
}

// (g) A 2-DOF run with n = 1.45 on both races: the ball law is the closed-form series with
// n = 1.45, the mean deflection of a slow ball passage is the static solution with n = 1.45
// averaged over one ball-pass period, and that static solution balances the load when the ball
// loads are recomputed by hand. The 1.5 law, agreeing with it at 5 N per ball, gives a clearly
// different deflection at this load (Q_max ≈ 270 N), so the check resolves the exponent.
TEST(CalibratedDynamics, GeneralExponentMatchesTheStaticSolution) {
  const double n = 1.45;
  const std::vector<std::string> base = {"operation.load=[0, -500]", "solver.duration=1.0",
                                         "solver.transient=0.5"};
  const Case hertz = case_with(base);
  const std::string path =
      test::write_calibration("dyn_n145.json", calibration_with_exponent(hertz.bearing, n, 5.0));
  const Case c = case_with(base + calibrated(path));
  const ContactConstants cc = contact_constants(c);
  ASSERT_EQ(cc.exponent, n);
  EXPECT_EQ(cc.series_fit_residual, 0.0);

  const SimulationResult r = simulate(c);
  EXPECT_EQ(r.contact.exponent, n);
  double mean_y = 0;
  const auto y = r.response.steady("y");
  for (double v : y) mean_y += v / static_cast<double>(y.size());

  const int Z = c.bearing.balls;
  const double gap = c.bearing.ball_gap();
  const int m = 400;
  double static_y = 0;
  for (int k = 0; k < m; ++k) {
    StaticLoadOptions o;
    o.phase = two_pi / Z * k / m;
    o.exponent = n;
    static_y += solve_static_load(Z, cc.K, gap, c.operation.load, o).deflection.y() / m;
  }
  EXPECT_NEAR(mean_y / static_y, 1.0, 0.01);

  // The static solution at phase 0, checked by hand: Σ K δ_j^1.45 (cos θ_j, sin θ_j) = F.
  StaticLoadOptions o;
  o.exponent = n;
  const StaticLoadResult s = solve_static_load(Z, cc.K, gap, c.operation.load, o);
  double fx = 0, fy = 0;
  for (int j = 0; j < Z; ++j) {
    const double th = two_pi * j / Z;
    const double d = s.deflection.x() * std::cos(th) + s.deflection.y() * std::sin(th) - gap;
    if (d <= 0) continue;
    fx += cc.K * std::pow(d, n) * std::cos(th);
    fy += cc.K * std::pow(d, n) * std::sin(th);
  }
  EXPECT_NEAR(fx, c.operation.load.x(), 1e-8 * 500);
  EXPECT_NEAR(fy, c.operation.load.y(), 1e-8 * 500);

  const ContactConstants h = contact_constants(hertz);
  const double hertz_y = solve_static_load(Z, h.K, gap, c.operation.load).deflection.y();
  EXPECT_GT(std::abs(s.deflection.y() / hertz_y - 1), 0.03);  // 4.5 % here
}

// The 3-DOF model with n = 1.45 under an axial preload: the axial state satisfies Harris's
// closed form Z K [A₀ (cos α₀/cos α − 1)]^n sin α = F_z, and a run stays at it on average.
TEST(CalibratedDynamics, GeneralExponentIn3Dof) {
  const double n = 1.45;
  const std::vector<std::string> base = {"model.kind=3dof", "operation.axial_load=200",
                                         "operation.load=[0, 0]", "solver.duration=0.3",
                                         "solver.transient=0.1"};
  const Case hertz = case_with(base);
  const std::string path = test::write_calibration(
      "dyn_3dof_n145.json", calibration_with_exponent(hertz.bearing, n, 60.0));
  const Case c = case_with(base + calibrated(path));
  const ModelInputs in = model_inputs(c);
  ASSERT_EQ(in.contact.exponent, n);
  const AxialPreload p = solve_axial_preload(in);
  const Bearing& b = c.bearing;
  const double A0 = (b.inner_conformity + b.outer_conformity - 1) * b.ball_diameter;
  const double cos_a0 = 1 - b.clearance / (2 * A0);
  const double delta = A0 * (cos_a0 / std::cos(p.contact_angle) - 1);
  EXPECT_NEAR(b.balls * in.contact.K * std::pow(delta, n) * std::sin(p.contact_angle), 200.0,
              1e-8 * 200);
  EXPECT_NEAR(p.ball_load, in.contact.K * std::pow(delta, n), 1e-8 * p.ball_load);

  const SimulationResult r = simulate(c);
  double mean_z = 0;
  const auto z = r.response.steady("z");
  for (double v : z) mean_z += v / static_cast<double>(z.size());
  EXPECT_NEAR(mean_z, p.z, 1e-3 * std::abs(p.z));
}

// TVDS with a calibrated law: exponents other than 1.5 are refused with a message naming the
// option and the exponents; with 1.5 the file's per-race K are the K₀ that the curvature changes
// modify, so scaling both by s scales every ball load by s.
TEST(CalibratedDynamics, TvdsUsesTheFilesConstants) {
  const std::vector<std::string> base = {
      "model.waviness_stiffness=true", "waviness.inner=[{order=16, amplitude=\"1 um\"}]",
      "waviness.outer=[{order=9, amplitude=\"0.5 um\"}]", "operation.load=[0, -300]"};
  const Case hertz = case_with(base);

  const std::string p145 = test::write_calibration(
      "tvds_n145.json", calibration_with_exponent(hertz.bearing, 1.45, 60.0));
  try {
    make_model(case_with(base + calibrated(p145)));
    ADD_FAILURE() << "TVDS with n = 1.45 accepted";
  } catch (const InputError& e) {
    const std::string m = e.what();
    for (const char* s : {"waviness_stiffness", "TVDS", "1.45", "calibrat", "3/2"})
      EXPECT_NE(m.find(s), std::string::npos) << "lacks \"" << s << "\": " << m;
  }

  const double s = 1.21;
  const ContactConstants h = contact_constants(hertz);
  const std::string p15 = test::write_calibration(
      "tvds_scaled.json",
      test::calibration_doc(hertz.bearing, s * h.inner.K, 1.5, s * h.outer.K, 1.5));
  const auto exact_model = make_model(hertz);
  const auto cal_model = make_model(case_with(base + calibrated(p15)));
  const std::vector<double> q = exact_model->initial_displacement();
  std::vector<double> la(8), lb(8);
  int loaded = 0;
  for (double t : {0.0, 0.0013, 0.0171}) {
    exact_model->ball_loads(t, q.data(), la.data());
    cal_model->ball_loads(t, q.data(), lb.data());
    for (int j = 0; j < 8; ++j) {
      EXPECT_NEAR(lb[j], s * la[j], 1e-12 * s * la[j]) << "t = " << t << ", ball " << j;
      loaded += la[j] > 0;
    }
  }
  EXPECT_GT(loaded, 6);
}

}  // namespace
}  // namespace bearing
