// The contact kernels (lumped/src/models/contact_kernels.h) of every instruction set this build
// holds that this CPU runs (AVX-512, AVX2, SSE4, the emulated 128-bit one...) against the scalar
// loop, on random balls: the same bits, so a run is reproducible across CPUs. The whole models
// are compared in test_contact_loop.cc.

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <initializer_list>
#include <random>
#include <string>
#include <vector>

#include "../../lumped/src/models/contact_kernels.h"
#include "../../lumped/src/models/phasor.h"
#include "bearing/contact_loop.h"

namespace bearing {
namespace {

constexpr double kPi = 3.14159265358979323846;

TEST(ContactKernels, EveryInstructionSetGivesTheScalarBits) {
  const detail::ContactKernels scalar = detail::contact_kernels(ContactLoop::scalar, 8);
  const std::vector<detail::NamedKernels> targets = detail::kernels_per_target();
  if (simd_target().rfind("scalar", 0) == 0) GTEST_SKIP() << "built without Highway";
  ASSERT_GE(targets.size(), 2u);  // at least the best one and Highway's portable fallback
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const detail::NamedKernels& t : targets)
    for (int Z : {1, 3, 7, 8, 9, 15, 16, 17, 33}) {
      SCOPED_TRACE(t.target + ", Z = " + std::to_string(Z));
      const int n = detail::padded_balls(Z);
      std::vector<double> bc(n), bs(n), e(n), K(n);
      for (int j = 0; j < Z; ++j) {
        bc[j] = std::cos(2 * kPi * j / Z + 0.3);
        bs[j] = std::sin(2 * kPi * j / Z + 0.3);
        e[j] = 1e-6 * u(rng);
        K[j] = 1e10 * (1 + 0.1 * u(rng));
      }
      for (int k = 0; k < 50; ++k) {
        const double phi = 10 * u(rng), x = 2e-5 * u(rng), y = 2e-5 * u(rng), gap = 5e-6;
        std::vector<double> c1(n), s1(n), c2(n), s2(n);
        t.kernels.rotate(bc.data(), bs.data(), std::cos(phi), std::sin(phi), Z, c1.data(),
                         s1.data());
        scalar.rotate(bc.data(), bs.data(), std::cos(phi), std::sin(phi), Z, c2.data(), s2.data());
        for (int j = 0; j < Z; ++j) {
          ASSERT_EQ(c1[j], c2[j]) << j;
          ASSERT_EQ(s1[j], s2[j]) << j;
        }
        double fx1 = 3.0, fy1 = -2.0, fx2 = 3.0, fy2 = -2.0;
        t.kernels.radial(c1.data(), s1.data(), e.data(), K.data(), Z, x, y, gap, &fx1, &fy1);
        scalar.radial(c2.data(), s2.data(), e.data(), K.data(), Z, x, y, gap, &fx2, &fy2);
        ASSERT_EQ(fx1, fx2);
        ASSERT_EQ(fy1, fy2);
      }
    }
}

// The static RK4 computes a segment's phasors ahead with these kernels (static_rk4.h) where the
// interface RK4 calls phasor() one at a time: they must agree to the bit, for angles of either
// sign, up to a long run's ~1e5 rad, on the table's nodes and half-way between them (where the
// rounding of θ/Δ decides the node), and for every count (the last vector partly used).
TEST(ContactKernels, PhasorsInEveryInstructionSetGivePhasorsBits) {
  std::vector<double> theta;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const double step = detail::PhasorConstants::kStep;
  for (int i = 0; i < 200; ++i) theta.push_back(1e5 * u(rng));
  for (int i = 0; i < 200; ++i) theta.push_back(10 * u(rng));
  for (int k = -3000; k <= 3000; k += 7) {
    theta.push_back(k * step);
    theta.push_back((k + 0.5) * step);
    theta.push_back(std::nextafter((k + 0.5) * step, 0.0));
  }
  theta.push_back(0.0);
  theta.push_back(-0.0);
  std::vector<detail::NamedKernels> targets = detail::kernels_per_target();
  targets.push_back({"scalar", detail::contact_kernels(ContactLoop::scalar, 8)});
  for (const detail::NamedKernels& t : targets)
    for (const int n : {1, 7, 8, 9, static_cast<int>(theta.size())}) {
      SCOPED_TRACE(t.target + ", n = " + std::to_string(n));
      const int padded = detail::padded_balls(n);
      std::vector<double> in(theta.begin(), theta.begin() + n), c(padded), s(padded);
      in.resize(padded, 0.5);
      t.kernels.phasors(in.data(), n, c.data(), s.data());
      for (int i = 0; i < n; ++i) {
        const detail::Phasor p = detail::phasor(in[i]);
        ASSERT_EQ(c[i], p.c) << "theta = " << in[i];
        ASSERT_EQ(s[i], p.s) << "theta = " << in[i];
      }
    }
}

TEST(ContactKernels, PlanarBallsInEveryInstructionSetGiveTheScalarBits) {
  const detail::ContactKernels scalar = detail::contact_kernels(ContactLoop::scalar, 8);
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const detail::NamedKernels& t : detail::kernels_per_target())
    for (int Z : {4, 5, 7, 8, 9, 12, 13}) {
      for (bool friction : {false, true}) {
        SCOPED_TRACE(t.target + ", Z = " + std::to_string(Z) + (friction ? ", friction" : ""));
        const int n = detail::padded_balls(Z);
        std::vector<double> c(n), s(n), ei(n), eo(n), Ki(n), Ko(n);
        // The ball DOFs exactly Z long, as at the end of the integrator's state vector.
        std::vector<double> pos(Z), speed(Z), spin(Z);
        for (int j = 0; j < Z; ++j) {
          c[j] = std::cos(2 * kPi * j / Z + 0.3);
          s[j] = std::sin(2 * kPi * j / Z + 0.3);
          ei[j] = 1e-7 * u(rng), eo[j] = 1e-7 * u(rng);
          Ki[j] = 1e10 * (1 + 0.1 * u(rng)), Ko[j] = 1.1e10 * (1 + 0.1 * u(rng));
        }
        for (int k = 0; k < 50; ++k) {
          for (int j = 0; j < Z; ++j) {
            pos[j] = 3e-6 * u(rng);
            speed[j] = 1e-3 * u(rng);
            spin[j] = 2000 * (1 + 0.01 * u(rng));
          }
          detail::PlanarBalls in;
          in.cos_theta = c.data(), in.sin_theta = s.data();
          in.inner_excitation = ei.data(), in.outer_excitation = eo.data();
          in.inner_stiffness = Ki.data(), in.outer_stiffness = Ko.data();
          in.position = pos.data(), in.speed = speed.data(), in.spin = spin.data();
          in.balls = Z;
          const double x = 2e-5 * u(rng), y = 2e-5 * u(rng);
          in.vx = 1e-3 * u(rng), in.vy = 1e-3 * u(rng);
          in.gap = 5e-6, in.centrifugal = 3.0, in.ball_damping = 200, in.lever = 3e-3;
          in.drive_inner = 6.0, in.drive_outer = 6.1, in.traction_gain = 0.1,
          in.traction_cap = 0.01;
          in.friction = friction;
          std::vector<double> r1(Z), t1(Z), r2(Z), t2(Z);
          in.fx = 3.0, in.fy = -2.0;
          double ring1[2], ring2[2];
          t.kernels.planar_balls(in, x, y, ring1, r1.data(), t1.data());
          scalar.planar_balls(in, x, y, ring2, r2.data(), t2.data());
          ASSERT_EQ(ring1[0], ring2[0]);
          ASSERT_EQ(ring1[1], ring2[1]);
          for (int j = 0; j < Z; ++j) {
            ASSERT_EQ(r1[j], r2[j]) << j;
            ASSERT_EQ(t1[j], t2[j]) << j;
          }
        }
      }
    }
}

}  // namespace
}  // namespace bearing

namespace bearing {
namespace {

// The dispatch (lumped/src/models/highway_runtime.cc) picks the best target whose instruction
// sets the CPU has; the reference here is the kernel's own list in /proc/cpuinfo, read
// independently of __builtin_cpu_supports.
TEST(ContactKernels, DispatchPicksTheBestTargetTheCpuHas) {
  if (simd_target().rfind("scalar", 0) == 0) GTEST_SKIP() << "built without Highway";
  std::ifstream in("/proc/cpuinfo");
  std::string line, flags;
  while (std::getline(in, line))
    if (line.rfind("flags", 0) == 0) {
      flags = " " + line.substr(line.find(':') + 1) + " ";
      break;
    }
  // The toolkit is built and tested on Linux (Debian): its /proc/cpuinfo always has the flags.
  ASSERT_FALSE(flags.empty()) << "no flags line in /proc/cpuinfo";
  const auto has = [&](std::initializer_list<const char*> sets) {
    for (const char* s : sets)
      if (flags.find(" " + std::string(s) + " ") == std::string::npos) return false;
    return true;
  };
  const bool ssse3 = has({"sse2", "ssse3"});
  const bool sse4 = ssse3 && has({"sse4_1", "sse4_2", "pclmulqdq", "aes"});
  const bool avx2 = sse4 && has({"avx", "avx2", "bmi1", "bmi2", "fma", "f16c"});
  const bool avx3 = avx2 && has({"avx512f", "avx512vl", "avx512dq", "avx512bw"});
  const std::string expected = avx3    ? "AVX3"
                               : avx2  ? "AVX2"
                               : sse4  ? "SSE4"
                               : ssse3 ? "SSSE3"
                                       : "EMU128";
  EXPECT_EQ(simd_target(), expected) << "cpuinfo flags:" << flags;
}

}  // namespace
}  // namespace bearing
