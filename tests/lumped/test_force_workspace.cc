// MechanicalSystem::force_with (mechanical_system.h) for the bearing models, whose workspace keeps
// the ball set at the last t asked for: the force is force()'s to the bit whatever sequence of
// times and states the caller passes (RK4's repeated times, jumps back, a workspace new or used),
// and workspaces used on several threads at once do not disturb each other.

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "bearing/contact.h"
#include "bearing/hertz.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"
#include "bearing/presets.h"
#include "bearing/traction.h"

namespace bearing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// The 6304 of seed 004 at 2000 rpm under 2000 N with waviness on both races, ball-size errors
// and TVDS: every part of the ball set's frame varies with t.
ModelInputs wavy_6304() {
  ModelInputs in;
  in.bearing = preset("6304");
  in.bearing.clearance = 30e-6;
  in.contact = contact_constants(in.bearing, *make_exact_hertz());
  in.hertz_method = HertzMethod::exact;
  in.inner_speed = 2000 * 2 * kPi / 60;
  in.load = Eigen::Vector2d(2000, -300);
  in.mass = 0.4;
  in.damping = 350;
  in.unbalance = 1e-5;
  in.waviness_stiffness = true;
  in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}, {16, 0.2e-6, 1.1}};
  in.inner_waviness.harmonics = {{5, 0.3e-6, 2.0}, {23, 0.05e-6, 0.7}};
  in.ball_size_errors = {0.5e-6, -0.3e-6, 0, 0.2e-6, 0, -0.6e-6, 0.1e-6};
  in.cage_slip = 0.02;
  in.traction = make_traction_curve(0.05, 0.1);
  in.ball_damping = 350;
  return in;
}

std::vector<std::unique_ptr<BearingModel>> models() {
  std::vector<std::unique_ptr<BearingModel>> m;
  ModelInputs in = wavy_6304();
  m.push_back(make_two_dof_model(in));
  m.push_back(make_ball_dof_model(in));
  in.axial_load = 300;
  m.push_back(make_three_dof_model(in));
  m.push_back(make_ball_dof_model(in));
  return m;
}

// Call k's time: RK4's pattern t, t + h/2, t + h/2, t + h (the next step's t), with a jump back
// every 11 calls.
double time_of(int k) {
  const double h = 5e-6;
  if (k % 11 == 10) return 0.5 * h * (k / 7);
  const int step = k / 4, stage = k % 4;
  return h * step + (stage == 0 ? 0.0 : stage == 3 ? h : 0.5 * h);
}

// Call k's state: the model's initial state, moved a little differently each call.
void state_of(const BearingModel& m, int k, std::vector<double>& q, std::vector<double>& v) {
  q = m.initial_displacement();
  v.assign(q.size(), 0.0);
  for (std::size_t i = 0; i < q.size(); ++i) {
    q[i] += 0.3e-6 * std::sin(0.7 * k + 1.3 * i);
    v[i] = 0.01 * std::cos(0.4 * k + 0.9 * i);
  }
}

TEST(ForceWorkspace, SameBitsAsForce) {
  for (const auto& m : models()) {
    SCOPED_TRACE(std::to_string(m->dofs()) + " DOFs");
    const std::unique_ptr<MechanicalSystem::Workspace> ws = m->make_workspace();
    ASSERT_NE(ws, nullptr);
    std::vector<double> q, v, f(m->dofs()), g(m->dofs()), h(m->dofs());
    for (int k = 0; k < 60; ++k) {
      const double t = time_of(k);
      state_of(*m, k, q, v);
      m->force(t, q.data(), v.data(), f.data());
      m->force_with(ws.get(), t, q.data(), v.data(), g.data());
      m->force_with(nullptr, t, q.data(), v.data(), h.data());
      EXPECT_EQ(f, g) << "call " << k << ", t = " << t;
      EXPECT_EQ(f, h) << "call " << k << ", t = " << t;
    }
  }
}

TEST(ForceWorkspace, OneWorkspacePerThread) {
  for (const auto& m : models()) {
    SCOPED_TRACE(std::to_string(m->dofs()) + " DOFs");
    const int calls = 200;
    std::vector<std::vector<double>> serial(calls, std::vector<double>(m->dofs()));
    std::vector<double> q, v;
    for (int k = 0; k < calls; ++k) {
      state_of(*m, k, q, v);
      m->force(time_of(k), q.data(), v.data(), serial[k].data());
    }
    std::vector<int> mismatches(4, 0);
    std::vector<std::thread> threads;
    for (int th = 0; th < 4; ++th)
      threads.emplace_back([&, th] {
        const std::unique_ptr<MechanicalSystem::Workspace> ws = m->make_workspace();
        std::vector<double> qt, vt, f(m->dofs());
        for (int rep = 0; rep < 5; ++rep)
          for (int k = 0; k < calls; ++k) {
            const int kk = (k + 37 * th) % calls;  // each thread in its own order
            state_of(*m, kk, qt, vt);
            m->force_with(ws.get(), time_of(kk), qt.data(), vt.data(), f.data());
            if (f != serial[kk]) ++mismatches[th];
          }
      });
    for (auto& t : threads) t.join();
    for (int c : mismatches) EXPECT_EQ(c, 0);
  }
}

}  // namespace
}  // namespace bearing
