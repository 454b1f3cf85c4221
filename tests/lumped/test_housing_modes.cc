// The modal transfer path (housing.h: `[housing] modes = "modes.json"`): the resonator as two
// modes gives the resonator's bits; driven by a prescribed ring force, the sensors follow the
// closed-form modal frequency response; the Jacobian against differences; the sensor channels;
// the table's rules and round trip.

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstdio>
#include <cstdlib>
#include <fstream>
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
#include "bearing/simulation.h"
#include "bearing/structure_modes.h"
#include "housing_helpers.h"

namespace bearing {
namespace {

// A folder of its own for the modes files of one test.
class TempDir {
 public:
  TempDir() {
    char name[] = "/tmp/housing_modes_test.XXXXXX";
    path_ = mkdtemp(name);
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

std::string list(const std::vector<double>& v) {
  std::string s = "[";
  for (std::size_t k = 0; k < v.size(); ++k) {
    char buf[40];
    std::snprintf(buf, sizeof buf, "%s%.17g", k ? ", " : "", v[k]);
    s += buf;
  }
  return s + "]";
}

// Writes a modes file (structure_modes.h) with one sensor of shapes (px, py, pz).
std::string write_modes(const std::string& path, const std::vector<double>& f,
                        const std::vector<double>& sx, const std::vector<double>& sy,
                        const std::vector<double>& px, const std::vector<double>& py,
                        const std::string& sensor = "housing", bool free = false) {
  const std::vector<double> zero(f.size(), 0.0);
  std::ofstream(path) << "{\"format\": \"bearing-fem modes\", \"version\": 1, \"boundary\": "
                      << "{\"free\": " << (free ? "true" : "false")
                      << "}, \"frequencies\": " << list(f) << ", \"seat\": {\"x\": " << list(sx)
                      << ", \"y\": " << list(sy) << ", \"z\": " << list(zero)
                      << "}, \"sensors\": [{\"name\": \"" << sensor
                      << "\", \"point\": [0, 0.05, 0], \"x\": " << list(px)
                      << ", \"y\": " << list(py) << ", \"z\": " << list(zero) << "}]}\n";
  return path;
}

Case case_of(const std::vector<std::string>& sets) {
  std::vector<Override> o;
  for (const auto& s : sets) o.push_back(parse_override(s));
  return default_case(o);
}

// The resonator (m_h, f_h) is the case of two modes at f_h with seat motion 1/√m_h in x and in y
// (housing.h): η = √m_h q_h. With m_h = 4 kg every operation of the modal path is the resonator's
// scaled by a power of two (k = ω² against m_h ω², c = 2ζω against 2ζ m_h ω, the seat 0.5 η
// against q_h; housing.cc), and such scaling is exact in binary floating point: the same bits, for
// the ring and for the sensor placed on the seat, on both kinds that carry a housing. Any slip of
// a factor, a transposed shape or a sign shows up as a difference.
TEST(HousingModes, TheResonatorAsTwoModesGivesItsBits) {
  TempDir dir;
  const std::string file = write_modes(dir.path() + "/two.json", {3000.0, 3000.0}, {0.5, 0.0},
                                       {0.0, 0.5}, {0.5, 0.0}, {0.0, 0.5});
  for (const char* kind : {"2dof", "3dof"}) {
    const std::vector<std::string> common{
        std::string("model.kind=") + kind,
        "operation.load=[30, -500]",
        "solver.duration=0.06",
        "solver.transient=0.01",
        "operation.unbalance=1e-4",
        std::string("operation.axial_load=") + (kind == std::string("3dof") ? "100" : "0")};
    auto resonator = common, modal = common;
    for (const char* s :
         {"housing.mass=4kg", "housing.frequency=3kHz", "housing.damping_ratio=0.04"})
      resonator.push_back(s);
    for (const std::string s : {"housing.modes=" + file, std::string("housing.damping_ratio=0.04")})
      modal.push_back(s);
    const Response a = simulate(case_of(resonator)).response;
    const Response b = simulate(case_of(modal)).response;
    for (const char* ch : {"x", "y", "vx", "vy", "ax", "ay", "x_housing", "y_housing", "vx_housing",
                           "vy_housing", "ax_housing", "ay_housing"}) {
      const std::vector<double>& va = a.channel(ch);
      const std::vector<double>& vb = b.channel(ch);
      ASSERT_EQ(va.size(), vb.size());
      std::size_t first = va.size();
      for (std::size_t k = 0; k < va.size() && first == va.size(); ++k)
        if (va[k] != vb[k]) first = k;
      EXPECT_EQ(first, va.size()) << kind << " " << ch << " differs first at sample " << first;
    }
    // The modal run has no DOF channels for its modes, and its sensor's z (zero here).
    EXPECT_THROW(b.channel("x_mode1"), std::out_of_range);
    for (double z : b.channel("az_housing")) EXPECT_EQ(z, 0.0);
  }
}

// Amplitude and phase of u(t) ≈ s sin ω t + c cos ω t over the samples from `from` on.
std::complex<double> fitted_phasor(const std::vector<double>& t, const std::vector<double>& u,
                                   double omega, double from) {
  Eigen::Matrix2d A = Eigen::Matrix2d::Zero();
  Eigen::Vector2d b = Eigen::Vector2d::Zero();
  for (std::size_t k = 0; k < t.size(); ++k) {
    if (t[k] < from) continue;
    const Eigen::Vector2d basis(std::sin(omega * t[k]), std::cos(omega * t[k]));
    A += basis * basis.transpose();
    b += basis * u[k];
  }
  const Eigen::Vector2d sc = A.ldlt().solve(b);
  return {sc.x(), sc.y()};  // u = Im[(s + i c) e^{iωt}]
}

// A structure of three modes, driven through the seat by the prescribed ring force F sin ω t ŷ
// (the stub bearing, uncoupled: the seat takes −F sin ω t ŷ). Each mode is the single-DOF
// oscillator η̈_k + 2ζ_k ω_k η̇_k + ω_k² η_k = −s_k,y F sin ω t, so a sensor ψ moves by
//     u = Im[ Σ_k ψ_k (−s_k,y F) e^{iωt} / (ω_k² − ω² + 2i ζ_k ω_k ω) ],
// the truncated modal sum, written here from the modes as given. Checked through the model's
// sensor rows (what response.csv writes) for x and y, at frequencies between two modes, at one,
// and above the last, with a different damping ratio per mode. RK4 at ω_max h ≤ 2π/400 errs by
// ~(ω h)⁴ ≈ 6e-8 relative; 1e-5 of the largest term is far below what a wrong shape, damping or
// sign gives (each moves a term by its whole size).
TEST(HousingModes, SensorsFollowTheModalFrequencyResponse) {
  StubBearing stub;
  stub.amplitude = 2.0;
  Housing h;
  h.enabled = true;
  StructureModes m;
  m.frequencies = {1500.0, 2600.0, 4100.0};
  m.seat = {std::vector<double>{0.3, -0.1, 0.05}, std::vector<double>{0.4, 0.25, -0.3},
            std::vector<double>{0.0, 0.0, 0.0}};
  StructureSensor top;
  top.name = "top";
  top.shape = {std::vector<double>{0.2, 0.1, -0.4}, std::vector<double>{0.5, -0.35, 0.15},
               std::vector<double>{0.1, 0.0, 0.2}};
  m.sensors = {top};
  h.modes = m;
  h.modes_file = "test";
  h.damping_ratios = {0.02, 0.05, 0.1};
  const double zeta_min = 0.02, f_min = 1500.0, f_max = 4100.0;
  for (double f : {2000.0, 2600.0, 6000.0}) {
    stub.omega = two_pi * f;
    const auto model =
        make_housing_model(std::make_unique<StubBearing>(stub), RingLoad{}, h, {0.0, 0.0});
    const std::vector<SensorRow> all = model->sensor_rows();
    ASSERT_EQ(all.size(), 5u);  // x_seat, y_seat, then the sensor's x, y, z
    EXPECT_EQ(all[0].name, "x_seat");
    EXPECT_EQ(all[2].name, "x_top");
    EXPECT_EQ(all[3].name, "y_top");
    const std::vector<SensorRow> rows(all.begin() + 2, all.end());
    const double settle = 30.0 / (zeta_min * two_pi * f_min),
                 dt = 1.0 / (400.0 * std::max(f, f_max));
    const Samples r =
        integrate(*model, IntegratorMethod::rk4, dt, 1e-6, std::vector<double>(5, 0.0),
                  std::vector<double>(5, 0.0), settle + 10.0 / f, dt);
    for (int axis : {0, 1}) {
      std::vector<double> u(r.t.size(), 0.0);
      for (std::size_t k = 0; k < r.t.size(); ++k)
        for (const auto& [dof, weight] : rows[static_cast<std::size_t>(axis)].terms)
          u[k] += weight * r.q[k][static_cast<std::size_t>(dof)];
      std::complex<double> expected = 0;
      double largest = 0;
      const double w = stub.omega;
      for (int k = 0; k < 3; ++k) {
        const double wk = two_pi * m.frequencies[k], zk = h.damping_ratios[k];
        const std::complex<double> term = top.shape[axis][k] * (-m.seat[1][k] * stub.amplitude) /
                                          std::complex<double>(wk * wk - w * w, 2 * zk * wk * w);
        expected += term;
        largest = std::max(largest, std::abs(term));
      }
      const std::complex<double> got = fitted_phasor(r.t, u, w, settle);
      EXPECT_NEAR(std::abs(got - expected), 0.0, 1e-5 * largest) << "f " << f << " axis " << axis;
    }
  }
}

// The analytic Jacobian of the bearing on the structure's modes against central differences
// (newmark and bdf use it), on both kinds, at a state off equilibrium with every velocity nonzero.
TEST(HousingModes, JacobianMatchesDifferences) {
  TempDir dir;
  const std::string file =
      write_modes(dir.path() + "/three.json", {1800.0, 3100.0, 5200.0}, {0.3, -0.2, 0.1},
                  {0.25, 0.4, -0.15}, {0.1, 0.2, 0.3}, {0.3, 0.2, 0.1}, "top");
  for (const char* kind : {"2dof", "3dof"}) {
    const auto model = make_model(
        case_of({std::string("model.kind=") + kind, "operation.load=[0, -500]",
                 "operation.axial_load=" + std::string(kind == std::string("3dof") ? "200" : "0"),
                 "housing.modes=" + file}));
    const int n = model->dofs();
    ASSERT_EQ(n, (kind == std::string("3dof") ? 3 : 2) + 3);
    std::vector<double> q = model->initial_displacement(), v(n);
    for (int i = 0; i < n; ++i) v[i] = 1e-3 * (i + 1);
    q[n - 1] += 0.3e-6;
    q[0] -= 0.2e-6;
    std::vector<double> dfdq(n * n), dfdv(n * n), fp(n), fm(n);
    model->force_jacobian(1e-3, q.data(), v.data(), dfdq.data(), dfdv.data());
    double scale = 0;
    for (double x : dfdq) scale = std::max(scale, std::fabs(x));
    for (int j = 0; j < n; ++j)
      for (int which : {0, 1}) {
        auto qp = q, qm = q, vp = v, vm = v;
        const double step = which == 0 ? 1e-10 : 1e-4;
        (which == 0 ? qp : vp)[j] += step;
        (which == 0 ? qm : vm)[j] -= step;
        model->force(1e-3, qp.data(), vp.data(), fp.data());
        model->force(1e-3, qm.data(), vm.data(), fm.data());
        for (int i = 0; i < n; ++i) {
          const double d = (fp[i] - fm[i]) / (2 * step);
          if (which == 0)
            EXPECT_NEAR(dfdq[i * n + j], d, 1e-6 * scale) << kind << " df" << i << "/dq" << j;
          else
            EXPECT_NEAR(dfdv[i * n + j], d, 1e-9 * (1 + std::fabs(d)))
                << kind << " df" << i << "/dv" << j;
        }
      }
  }
}

// The static start is an equilibrium of every DOF, the modes deflected by η_k = s_k · F / ω_k².
TEST(HousingModes, StaticStartIsAnEquilibrium) {
  TempDir dir;
  const std::string file =
      write_modes(dir.path() + "/three.json", {1800.0, 3100.0, 5200.0}, {0.3, -0.2, 0.1},
                  {0.25, 0.4, -0.15}, {0.1, 0.2, 0.3}, {0.3, 0.2, 0.1}, "top");
  const auto model = make_model(case_of({"operation.load=[40, -500]", "housing.modes=" + file}));
  const std::vector<double> q0 = model->initial_displacement(), v0(q0.size(), 0.0);
  std::vector<double> f(q0.size());
  model->force(0.0, q0.data(), v0.data(), f.data());
  for (std::size_t i = 0; i < f.size(); ++i) EXPECT_NEAR(f[i], 0.0, 1e-7 * 500) << "dof " << i;
  const double w1 = two_pi * 1800.0;
  EXPECT_NEAR(q0[2], (0.3 * 40 + 0.25 * -500) / (w1 * w1), 1e-15);
}

// The ball channels, the contacts' switching functions and the potential energy are the bearing's
// at the rings' relative position (with the support's springs' energy added), q − q_s with the seat
// displaced by its modes (housing.h), for the resonator and the modes alike: against the bearing
// model built without the housing, at that position.
TEST(HousingModes, BallChannelsAreTheBearingsAtTheRelativePosition) {
  TempDir dir;
  const std::string file =
      write_modes(dir.path() + "/three.json", {1800.0, 3100.0, 5200.0}, {0.3, -0.2, 0.1},
                  {0.25, 0.4, -0.15}, {0.1, 0.2, 0.3}, {0.3, 0.2, 0.1}, "top");
  for (const std::vector<std::string>& housing :
       {std::vector<std::string>{"housing.modes=" + file},
        std::vector<std::string>{"housing.mass=2kg", "housing.frequency=3kHz"}}) {
    std::vector<std::string> sets{"operation.load=[0, -500]", "operation.speed=0rpm"};
    sets.insert(sets.end(), housing.begin(), housing.end());
    const Case c = case_of(sets);
    const auto model = make_model(c);
    ModelInputs in = model_inputs(c);
    in.housing = Housing{};
    const auto bearing = make_dynamic_model(c.model.kind, in);
    std::vector<double> q = model->initial_displacement();
    for (std::size_t i = 2; i < q.size(); ++i) q[i] += 1e-7 * static_cast<double>(i);  // the seat
    const int Z = model->balls();
    std::vector<double> loads(Z), approaches(Z), expected(Z), expected_approaches(Z), g(Z), h(Z);
    model->ball_loads(0.0, q.data(), loads.data());
    model->ball_approaches(0.0, q.data(), approaches.data());
    model->switching_functions(0.0, q.data(), g.data());
    // q_r = q − q_s, the seat q_s = Σ_k s_k η_k (the modes, s_k as written to the file above) or
    // (x_h, y_h) (the resonator).
    double sx = 0, sy = 0;
    if (housing.size() == 1) {
      const double s_x[] = {0.3, -0.2, 0.1}, s_y[] = {0.25, 0.4, -0.15};
      for (int k = 0; k < 3; ++k) sx += s_x[k] * q[2 + k], sy += s_y[k] * q[2 + k];
    } else {
      sx = q[2], sy = q[3];
    }
    const std::vector<double> qr{q[0] - sx, q[1] - sy};
    if (housing.size() == 1) {  // the seat's channels are that seat motion
      const std::vector<SensorRow> rows = model->sensor_rows();
      double x = 0, y = 0;
      for (const auto& [dof, weight] : rows[0].terms)
        x += weight * q[static_cast<std::size_t>(dof)];
      for (const auto& [dof, weight] : rows[1].terms)
        y += weight * q[static_cast<std::size_t>(dof)];
      EXPECT_EQ(rows[0].name + rows[1].name, "x_seaty_seat");
      EXPECT_NEAR(x, sx, 1e-21);
      EXPECT_NEAR(y, sy, 1e-21);
    }
    bearing->ball_loads(0.0, qr.data(), expected.data());
    bearing->ball_approaches(0.0, qr.data(), expected_approaches.data());
    bearing->switching_functions(0.0, qr.data(), h.data());
    // The potential energy: the contacts' at q_r and the support's springs, ½ Σ k η² with
    // k = ω_k² for mass-normalised modes, ½ m_h ω_h² (x_h² + y_h²) for the resonator.
    double springs = 0.0;
    if (housing.size() == 1) {
      const double f[] = {1800.0, 3100.0, 5200.0};
      for (int k = 0; k < 3; ++k) springs += 0.5 * std::pow(two_pi * f[k] * q[2 + k], 2);
    } else {
      springs = 0.5 * 2.0 * std::pow(two_pi * 3000.0, 2) * (q[2] * q[2] + q[3] * q[3]);
    }
    const double energy = bearing->potential_energy(0.0, qr.data()) + springs;
    EXPECT_NEAR(model->potential_energy(0.0, q.data()), energy, 1e-12 * energy) << housing[0];
    for (int j = 0; j < Z; ++j) {
      EXPECT_NEAR(loads[j], expected[j], 1e-9 * (1 + expected[j])) << housing[0] << " ball " << j;
      EXPECT_NEAR(approaches[j], expected_approaches[j], 1e-18) << housing[0] << " ball " << j;
      EXPECT_NEAR(g[j], h[j], 1e-18) << housing[0] << " ball " << j;
    }
  }
}

std::string input_error(const std::vector<std::string>& sets) {
  try {
    make_model(case_of(sets));
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(HousingModes, TableRulesNameTheKey) {
  TempDir dir;
  const std::string file = write_modes(dir.path() + "/m.json", {1800.0, 3100.0}, {0.3, -0.2},
                                       {0.25, 0.4}, {0.1, 0.2}, {0.3, 0.2}, "top");
  const std::string free = write_modes(dir.path() + "/free.json", {1800.0, 3100.0}, {0.3, -0.2},
                                       {0.25, 0.4}, {0.1, 0.2}, {0.3, 0.2}, "top", true);
  const auto has = [](const std::string& message, const std::string& part) {
    return message.find(part) != std::string::npos;
  };
  const std::string modes = "housing.modes=" + file;
  EXPECT_TRUE(has(input_error({modes, "housing.mass=1kg"}),
                  "housing.mass = 1 kg: give either mass and frequency"));
  EXPECT_TRUE(has(input_error({"housing.modes=" + free}), "the structure is free-free"));
  EXPECT_TRUE(has(input_error({modes, "housing.damping_ratio=[0.01, 0.02, 0.03]"}),
                  "housing.damping_ratio has 3 entries: give one for all modes, or one per mode"));
  EXPECT_TRUE(has(input_error({modes, "housing.damping_ratio=[0.01, 1.5]"}),
                  "housing.damping_ratio[1] = 1.5"));
  EXPECT_TRUE(has(input_error({modes, "housing.sensors=[\"bottom\"]"}),
                  "housing.sensors: \"bottom\" is not a sensor of housing.modes"));
  EXPECT_TRUE(
      has(input_error({"housing.mass=1kg", "housing.frequency=3kHz", "housing.sensors=[\"top\"]"}),
          "housing.sensors: sensors are points of the structure's modes"));
  EXPECT_TRUE(has(input_error({"housing.mass=1kg", "housing.frequency=3kHz",
                               "housing.damping_ratio=[0.01, 0.02]"}),
                  "one per mode needs housing.modes"));
  EXPECT_TRUE(has(input_error({modes, "model.kind=balls"}), "[housing]: model.kind = \"balls\""));
  EXPECT_TRUE(has(input_error({"housing.modes=" + dir.path() + "/none.json"}), "cannot read"));
  EXPECT_TRUE(has(input_error({"housing.damping_ratio=0.02"}), "housing.mass is missing"));
  const std::string seat =
      write_modes(dir.path() + "/seat.json", {1800.0}, {0.3}, {0.25}, {0.1}, {0.3}, "seat");
  EXPECT_TRUE(has(input_error({"housing.modes=" + seat}), "a sensor is named \"seat\""));
}

// The sensors a run writes: all of the file's by default, or those named; x, y, z with their
// velocities and accelerations; the case writes the modes file, damping ratios and sensors back,
// and reads back to the same.
TEST(HousingModes, ChannelsAndRoundTrip) {
  TempDir dir;
  const std::string path = dir.path() + "/m.json";
  std::ofstream(path) << "{\"format\": \"bearing-fem modes\", \"version\": 1, \"boundary\": "
                         "{\"free\": false}, \"frequencies\": [2000, 4000], \"seat\": {\"x\": "
                         "[0.1, 0.2], \"y\": [0.3, 0.1], \"z\": [0, 0]}, \"sensors\": [{\"name\": "
                         "\"top\", \"point\": [0, 1, 0], \"x\": [1, 0], \"y\": [0, 1], \"z\": [0, "
                         "0]}, {\"name\": \"side\", \"point\": [1, 0, 0], \"x\": [0.5, 0.5], "
                         "\"y\": [0, 0], \"z\": [0.2, 0]}]}\n";
  const Case all = case_of({"housing.modes=" + path, "housing.damping_ratio=[0.02, 0.03]"});
  const std::vector<std::string> names = make_model(all)->dof_names();
  EXPECT_EQ(names, (std::vector<std::string>{"x", "y"}));
  const Response r = simulate(case_of({"housing.modes=" + path, "solver.duration=0.002",
                                       "solver.transient=0.001"}))
                         .response;
  for (const char* ch : {"x_top", "vy_top", "az_top", "x_side", "ay_side", "vz_side", "x_seat",
                         "vy_seat", "ay_seat"})
    EXPECT_NO_THROW(r.channel(ch)) << ch;
  // The seat's channels are its motion Σ s_k η_k: a sensor whose shapes are the seat's reads the
  // same (top's x is mode 1 alone, the seat's x 0.1 η_1 + 0.2 η_2, so they differ).
  EXPECT_NE(r.channel("x_seat"), r.channel("x_top"));
  const Response one = simulate(case_of({"housing.modes=" + path, "housing.sensors=[\"side\"]",
                                         "solver.duration=0.002", "solver.transient=0.001"}))
                           .response;
  EXPECT_THROW(one.channel("x_top"), std::out_of_range);
  EXPECT_EQ(one.channel("ay_side"), r.channel("ay_side"));

  const Case selected = case_of({"housing.modes=" + path, "housing.damping_ratio=[0.02, 0.03]",
                                 "housing.sensors=[\"side\"]"});
  const std::string text = case_to_toml(selected);
  EXPECT_NE(text.find("modes = \"" + path + "\""), std::string::npos) << text;
  EXPECT_NE(text.find("damping_ratio = [0.02, 0.029999999999999999]"), std::string::npos) << text;
  EXPECT_NE(text.find("sensors = [\"side\"]"), std::string::npos) << text;
  const std::string table =
      text.substr(text.find("[housing]"), text.find("[solver]") - text.find("[housing]"));
  EXPECT_EQ(table.find("mass ="), std::string::npos) << table;
  EXPECT_EQ(table.find("frequency ="), std::string::npos) << table;
  const Case back = parse_case(text, "round trip");
  EXPECT_EQ(back.housing.damping_ratios, selected.housing.damping_ratios);
  EXPECT_EQ(back.housing.sensors, selected.housing.sensors);
  ASSERT_TRUE(back.housing.modal());
  EXPECT_EQ(back.housing.modes->frequencies, selected.housing.modes->frequencies);
  const auto body = [](const std::string& toml) { return toml.substr(toml.find("[bearing]")); };
  EXPECT_EQ(body(case_to_toml(back)), body(text));  // the Source comment names where it came from
}

}  // namespace
}  // namespace bearing
