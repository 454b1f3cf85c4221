// The statically dispatched RK4 of the dynamic models (models/static_rk4.h, issue 31): the same
// steps and the same bits as make_integrator's RK4 through the MechanicalSystem interface, for
// every part of each model's force (waviness on both races, TVDS, ball-size errors, unbalance,
// a local defect, the scalar contact loop, an exponent other than 3/2, an axial load, cage slip
// and traction), over output times that make it shorten and stretch steps; and it is the path
// the registry gives each dynamic kind.

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "bearing/contact.h"
#include "bearing/errors.h"
#include "bearing/hertz.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/model_registry.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"
#include "bearing/presets.h"
#include "bearing/traction.h"

namespace bearing {
namespace {

constexpr double kPi = 3.14159265358979323846;

ModelInputs plain_6308() {
  ModelInputs in;
  in.bearing = preset("6308");
  in.contact = contact_constants(in.bearing, *make_exact_hertz());
  in.hertz_method = HertzMethod::exact;
  in.inner_speed = 2000 * 2 * kPi / 60;
  in.load = Eigen::Vector2d(0, -20);
  in.mass = 0.6;
  in.damping = 200;
  return in;
}

// Each variant switches on one more part of the force.
std::vector<std::pair<std::string, ModelInputs>> variants() {
  std::vector<std::pair<std::string, ModelInputs>> v;
  ModelInputs in = plain_6308();
  v.emplace_back("plain 6308 (the frame's angles only)", in);
  in.contact_loop = ContactLoop::scalar;
  v.emplace_back("scalar contact loop", in);
  in = plain_6308();
  in.unbalance = 2e-5;
  in.outer_waviness.harmonics = {{8, 0.4e-6, 0.3}, {17, 0.2e-6, 1.1}};
  in.inner_waviness.harmonics = {{5, 0.3e-6, 2.0}};
  in.ball_size_errors = {0.5e-6, -0.3e-6, 0, 0.2e-6, 0, -0.6e-6, 0.1e-6, 0};
  v.emplace_back("waviness, size errors, unbalance", in);
  in.waviness_stiffness = true;
  v.emplace_back("with TVDS", in);
  in = plain_6308();
  LocalDefect spall;
  spall.location = DefectLocation::outer;
  spall.position = -kPi / 2;
  spall.width = 1e-3;
  spall.depth = 20e-6;
  in.defects = {spall};
  v.emplace_back("an outer-race spall", in);
  in = plain_6308();
  in.contact.exponent = 10.0 / 9.0;
  v.emplace_back("exponent 10/9", in);
  return v;
}

struct Trace {
  std::vector<double> values;  // t, q, v, a at each output time
  IntegrationStats stats;
};

Trace integrate(const Integrator& integrator, const BearingModel& model,
                const std::vector<double>& times) {
  Trace tr;
  const int n = model.dofs();
  tr.stats =
      integrator.integrate(model, 0.0, model.initial_displacement(), model.initial_velocity(),
                           times, [&](double t, const double* q, const double* v, const double* a) {
                             tr.values.push_back(t);
                             tr.values.insert(tr.values.end(), q, q + n);
                             tr.values.insert(tr.values.end(), v, v + n);
                             tr.values.insert(tr.values.end(), a, a + n);
                           });
  return tr;
}

// Output times every 50 µs with dt = 5 µs, then a few off the step grid: full steps, a step
// shortened to land on an output time, a sliver within kLandingSlack, a repeated start.
std::vector<double> output_times() {
  std::vector<double> t;
  for (int k = 0; k <= 400; ++k) t.push_back(k * 5e-5);
  for (const double extra : {0.0200031, 0.02000310000001, 0.0200401, 0.021}) t.push_back(extra);
  return t;
}

// Each kind's integrator against make_integrator's on the same model, to the bit.
void expect_same_bits(const Integrator& inlined, const BearingModel& model) {
  IntegratorSettings s;
  s.method = IntegratorMethod::rk4;
  s.dt = 5e-6;
  const std::unique_ptr<Integrator> interface = make_integrator(s);
  EXPECT_EQ(inlined.name(), interface->name());
  const std::vector<double> times = output_times();
  const Trace a = integrate(*interface, model, times);
  const Trace b = integrate(inlined, model, times);
  ASSERT_EQ(a.values.size(), b.values.size());
  EXPECT_EQ(std::memcmp(a.values.data(), b.values.data(), a.values.size() * sizeof(double)), 0);
  EXPECT_EQ(a.stats.steps, b.stats.steps);
  EXPECT_EQ(a.stats.force_evaluations, b.stats.force_evaluations);
  // The run moved: the comparison is not of two idle states.
  const std::size_t row = 1 + 3 * static_cast<std::size_t>(model.dofs());
  EXPECT_NE(a.values[1], a.values[a.values.size() - row + 1]);
}

IntegratorSettings rk4_settings() {
  IntegratorSettings s;
  s.method = IntegratorMethod::rk4;
  s.dt = 5e-6;
  return s;
}

TEST(StaticRk4, TwoDofSameBitsAsTheInterfaceRk4ForEveryPartOfTheForce) {
  const std::unique_ptr<Integrator> inlined = make_two_dof_rk4(rk4_settings());
  for (const auto& [name, in] : variants()) {
    SCOPED_TRACE(name);
    expect_same_bits(*inlined, *make_two_dof_model(in));
  }
}

TEST(StaticRk4, ThreeDofSameBitsAsTheInterfaceRk4) {
  const std::unique_ptr<Integrator> inlined = make_three_dof_rk4(rk4_settings());
  for (auto [name, in] : variants()) {
    SCOPED_TRACE(name);
    in.axial_load = 150;
    expect_same_bits(*inlined, *make_three_dof_model(in));
  }
}

TEST(StaticRk4, BallDofSameBitsAsTheInterfaceRk4) {
  const std::unique_ptr<Integrator> inlined = make_ball_dof_rk4(rk4_settings());
  for (auto [name, in] : variants()) {
    if (in.contact.exponent != 1.5) continue;  // the ball-DOF model's contacts are Hertzian
    SCOPED_TRACE(name);
    in.cage_slip = 0.02;
    in.traction = make_traction_curve(0.05, 0.1);
    in.ball_damping = 350;
    expect_same_bits(*inlined, *make_ball_dof_model(in));
    in.axial_load = 150;
    expect_same_bits(*inlined, *make_ball_dof_model(in));
  }
}

TEST(StaticRk4, RefusesAModelOfAnotherKind) {
  IntegratorSettings s;
  const std::unique_ptr<Integrator> inlined = make_two_dof_rk4(s);
  ModelInputs in = plain_6308();
  in.axial_load = 100;
  const std::unique_ptr<BearingModel> three = make_three_dof_model(in);
  EXPECT_THROW(integrate(*inlined, *three, {0.0, 1e-4}), std::logic_error);
}

TEST(StaticRk4, ValidatesItsSettingsAsMakeIntegrator) {
  IntegratorSettings s;
  s.dt = -1e-6;
  EXPECT_THROW(make_two_dof_rk4(s), InputError);
}

TEST(StaticRk4, EachDynamicKindHasItsOwn) {
  EXPECT_EQ(model_descriptor(ModelKind::two_dof).rk4, &make_two_dof_rk4);
  EXPECT_EQ(model_descriptor(ModelKind::three_dof).rk4, &make_three_dof_rk4);
  EXPECT_EQ(model_descriptor(ModelKind::balls).rk4, &make_ball_dof_rk4);
  for (const ModelDescriptor& d : model_registry())
    EXPECT_EQ(d.rk4 != nullptr, d.dynamic != nullptr) << name_of(kModelKinds, d.kind);
}

}  // namespace
}  // namespace bearing
