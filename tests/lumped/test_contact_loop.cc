// The SIMD contact loop (solver.contact_loop = "simd", lumped/src/models/contact_kernels.h)
// against the scalar one it replaced, kept for this check: every model kind gives the same force
// to the bit at any time and state, for ball counts that fill SIMD vectors exactly and that leave
// a partial vector, with and without waviness, size errors and defects; and a whole run gives the
// same response. Bitwise equality is asked for (stronger than the 1e-12): both loops do
// each ball's arithmetic as the same IEEE operations and sum the ring force in ball order.

#include <gtest/gtest.h>

#include <cstring>
#include <memory>
#include <random>
#include <string>
#include <vector>

#include "bearing/case_file.h"
#include "bearing/contact.h"
#include "bearing/contact_loop.h"
#include "bearing/hertz.h"
#include "bearing/models/ball_dofs.h"
#include "bearing/models/three_dof.h"
#include "bearing/models/two_dof.h"
#include "bearing/presets.h"
#include "bearing/simulation.h"
#include "bearing/traction.h"

namespace bearing {
namespace {

constexpr double kPi = 3.14159265358979323846;

// A 6304-like bearing with Z balls (the ball diameter scaled so that they fit), at 2000 rpm under
// 2000 N; `rich`: waviness on both races, size errors and an outer-race spall as well.
ModelInputs bearing_with(int Z, bool rich) {
  ModelInputs in;
  in.bearing = preset("6304");
  in.bearing.balls = Z;
  in.bearing.ball_diameter = std::min(in.bearing.ball_diameter, 0.9 * kPi * 0.034 / Z);
  in.bearing.clearance = 30e-6;
  in.contact = contact_constants(in.bearing, *make_exact_hertz());
  in.inner_speed = 2000 * 2 * kPi / 60;
  in.load = Eigen::Vector2d(2000, -300);
  in.mass = 0.4;
  in.damping = 350;
  in.cage_slip = 0.02;
  in.traction = make_traction_curve(0.05, 0.1);
  in.ball_damping = 350;
  in.centrifugal = true;
  if (rich) {
    in.unbalance = 1e-5;
    in.outer_waviness.harmonics = {{9, 0.4e-6, 0.3}, {16, 0.2e-6, 1.1}};
    in.inner_waviness.harmonics = {{5, 0.3e-6, 2.0}, {23, 0.05e-6, 0.7}};
    for (int j = 0; j < Z; ++j) in.ball_size_errors.push_back(0.1e-6 * ((j * 7) % 5 - 2));
    LocalDefect spall;
    spall.location = DefectLocation::outer;
    spall.position = 0.3;
    spall.width = 1e-3;
    spall.depth = 50e-6;
    in.defects = {spall};
  }
  return in;
}

using Factory = std::unique_ptr<BearingModel> (*)(const ModelInputs&);

std::unique_ptr<BearingModel> make_balls(const ModelInputs& in) {
  return make_ball_dof_model(in);
}

struct Variant {
  std::string name;
  Factory make;
  double axial_load;  // [N]
  double friction;    // μ_m
};

const Variant kVariants[] = {
    {"2dof", &make_two_dof_model, 0, 0},
    {"3dof", &make_three_dof_model, 300, 0},
    {"balls", &make_balls, 0, 0},
    {"balls+traction", &make_balls, 0, 0.05},
    {"balls+axial", &make_balls, 300, 0.05},
};

bool same_bits(const std::vector<double>& a, const std::vector<double>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0;
}

TEST(ContactLoop, SimdAndScalarGiveTheSameForceToTheBit) {
  std::mt19937_64 rng(18);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Variant& variant : kVariants)
    for (int Z : {3, 7, 8, 9, 16, 17, 31})
      for (bool rich : {false, true}) {
        SCOPED_TRACE(variant.name + ", Z = " + std::to_string(Z) + (rich ? ", rich" : ""));
        ModelInputs in = bearing_with(Z, rich);
        in.axial_load = variant.axial_load;
        in.traction = make_traction_curve(variant.friction, 0.1);
        in.contact_loop = ContactLoop::simd;
        const auto simd = variant.make(in);
        in.contact_loop = ContactLoop::scalar;
        const auto scalar = variant.make(in);
        const int n = simd->dofs();
        const std::vector<double> q0 = simd->initial_displacement();
        const auto ws_simd = simd->make_workspace(), ws_scalar = scalar->make_workspace();
        int loaded_states = 0;
        for (int k = 0; k < 200; ++k) {
          // Around the static state, out to several times its deflection (many balls loaded).
          std::vector<double> q(q0), v(static_cast<std::size_t>(n));
          const double spread = k < 100 ? 1e-6 : 2e-5;
          for (int i = 0; i < n; ++i) {
            q[i] += spread * u(rng);
            v[i] = 0.01 * u(rng);
          }
          const double t = (k % 4 == 3) ? 0.0 : 0.05 * (1 + u(rng));
          std::vector<double> f_simd(static_cast<std::size_t>(n)), f_scalar(f_simd.size());
          simd->force_with(ws_simd.get(), t, q.data(), v.data(), f_simd.data());
          scalar->force_with(ws_scalar.get(), t, q.data(), v.data(), f_scalar.data());
          ASSERT_TRUE(same_bits(f_simd, f_scalar))
              << "state " << k << ": f_x " << f_simd[0] << " vs " << f_scalar[0];
          if (f_simd[0] != in.load.x()) ++loaded_states;
        }
        EXPECT_GT(loaded_states, 150);  // the contacts were exercised, not only the loads
      }
}

TEST(ContactLoop, AWholeRunIsTheSameToTheBit) {
  for (const char* kind : {"2dof", "3dof", "balls"}) {
    SCOPED_TRACE(kind);
    std::vector<Override> o = {{"model.kind", kind},
                               {"solver.duration", "0.05 s"},
                               {"solver.transient", "0.01 s"},
                               {"waviness.outer", "[{order=12, amplitude=\"0.5 um\"}]"}};
    if (std::string(kind) == "3dof") o.push_back({"operation.axial_load", "100 N"});
    o.push_back({"solver.contact_loop", "simd"});
    const SimulationResult a = simulate(default_case(o));
    o.back().value = "scalar";
    const SimulationResult b = simulate(default_case(o));
    ASSERT_FALSE(a.response.time.empty());
    ASSERT_EQ(a.response.values.size(), b.response.values.size());
    for (std::size_t c = 0; c < a.response.values.size(); ++c)
      EXPECT_TRUE(same_bits(a.response.values[c], b.response.values[c]))
          << a.response.channels[c].name;
  }
}

TEST(ContactLoop, NamesTheInstructionSetItRunsWith) {
  const std::string target = simd_target();
  EXPECT_FALSE(target.empty());
  EXPECT_EQ(target.find('?'), std::string::npos) << target;
}

TEST(ContactLoop, CaseFilesKeepTheChoiceAndOmitTheDefault) {
  // The default changes no result, so case.toml written without it stays as before the key.
  EXPECT_EQ(case_to_toml(default_case()).find("contact_loop"), std::string::npos);
  const Case scalar = default_case({{"solver.contact_loop", "scalar"}});
  const std::string text = case_to_toml(scalar);
  EXPECT_NE(text.find("contact_loop = \"scalar\""), std::string::npos);
  EXPECT_EQ(parse_case(text, "case.toml", {}, ".").solver.contact_loop, ContactLoop::scalar);
}

}  // namespace
}  // namespace bearing
