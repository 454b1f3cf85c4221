// The housing support's kernels (support_kernels.cc): every instruction set gives the scalar
// reference's bits, for mode counts around the 8 partial sums' blocks.

#include <gtest/gtest.h>

#include <random>
#include <string>
#include <vector>

#include "../../lumped/src/models/housed_model.h"
#include "bearing/contact_loop.h"

namespace bearing {
namespace {

TEST(SupportKernels, EveryInstructionSetGivesTheScalarBits) {
  const detail::SupportKernels scalar = detail::support_kernels(ContactLoop::scalar);
  auto targets = detail::support_kernels_per_target();
  if (targets.empty()) GTEST_SKIP() << "built without Highway";
  targets.emplace_back("simd", detail::support_kernels(ContactLoop::simd));
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const auto& [name, kernels] : targets)
    for (int M : {1, 2, 3, 7, 8, 9, 15, 16, 17, 20, 41}) {
      SCOPED_TRACE(name + ", M = " + std::to_string(M));
      const int padded = (M + 7) / 8 * 8;
      std::vector<double> sx(padded, 0.0), sy(padded, 0.0), k(M), c(M), p(M), pv(M);
      for (int i = 0; i < M; ++i) {
        sx[i] = u(rng), sy[i] = u(rng), k[i] = 1e9 * (1.5 + u(rng)), c[i] = 300 * (1 + u(rng));
        p[i] = 1e-6 * u(rng), pv[i] = 1e-3 * u(rng);
      }
      double a[4], b[4];
      kernels.seat_sums(sx.data(), sy.data(), p.data(), pv.data(), M, a);
      scalar.seat_sums(sx.data(), sy.data(), p.data(), pv.data(), M, b);
      for (int i = 0; i < 4; ++i) ASSERT_EQ(a[i], b[i]) << "sum " << i;
      // The sums are the plain sums to rounding (a wrong lane or a lost block is not).
      double x = 0;
      for (int i = 0; i < M; ++i) x += sx[i] * p[i];
      EXPECT_NEAR(a[0], x, 1e-13 * 1e-6 * M);
      std::vector<double> f1(M), f2(M);
      kernels.forces(sx.data(), sy.data(), k.data(), c.data(), 3.5, -20.25, p.data(), pv.data(), M,
                     f1.data());
      scalar.forces(sx.data(), sy.data(), k.data(), c.data(), 3.5, -20.25, p.data(), pv.data(), M,
                    f2.data());
      for (int i = 0; i < M; ++i) {
        ASSERT_EQ(f1[i], f2[i]) << i;
        EXPECT_EQ(f2[i], (sx[i] * -3.5 + sy[i] * 20.25) - k[i] * p[i] - c[i] * pv[i]);
      }
    }
}

}  // namespace
}  // namespace bearing
