// TVDS's relative compliance table g(Δ) (lumped/src/models/curvature_compliance_table.h): its
// slope is what the rates of TVDS (dK/dt) use, so it is tested directly here, against the slope
// of its own value interpolant and against the closed form it tabulates, over the whole range
// and in the end intervals (where the difference slopes need the ghost nodes).

#include <cmath>
#include <memory>

#include <gtest/gtest.h>

#include "../../lumped/src/models/curvature_compliance_table.h"
#include "bearing/hertz.h"

namespace {

// A 6308-like inner-race contact: Σρ₀ = 188 1/m, num₀ = ρ_II1 − ρ_II2 = 178 1/m (F₀ = 0.947),
// and waviness that changes the curvature by up to ±5 1/m.
constexpr double kSum0 = 188.0, kNum0 = 178.0, kBound = 5.0;

// The closed form the table holds: g(Δ) = [δ*(F(Δ))/δ*(F₀)] (1 + Δ/Σρ₀)^{1/3}.
double closed_form(const bearing::HertzSolution& m, double d) {
  const double sum = kSum0 + d, f = (kNum0 + d) / sum;
  return m.shape(f).delta_star / m.shape(kNum0 / kSum0).delta_star * std::cbrt(sum / kSum0);
}

}  // namespace

TEST(CurvatureComplianceTable, SlopeIsTheDerivativeOfItsValue) {
  const auto method = bearing::make_hamrock_brewe_hertz();
  const bearing::detail::CurvatureComplianceTable g(*method, kNum0, kSum0, kBound, "test");
  // Central differences of the cubic value interpolant inside one interval: the step 1e-6 1/m
  // is ~1e-5 of an interval (h = 5/32 1/m), so the difference is exact for the cubic to
  // ~(1e-5)^2 and its rounding is ~1e-16/1e-6 = 1e-10 against slopes ~2e-3 m: 1e-6 relative is a
  // bound with a margin of ~100.
  const double e = 1e-6;
  for (int k = -99; k <= 99; ++k) {
    const double d = k * 0.0499;  // off the nodes (h = 5/32), up to ±0.99 of the bound
    const double fd = (g(d + e) - g(d - e)) / (2 * e);
    EXPECT_NEAR(g.derivative(d), fd, 1e-6 * std::abs(fd)) << "Δ = " << d << " 1/m";
  }
}

TEST(CurvatureComplianceTable, SlopeMatchesTheClosedFormToTheEnds) {
  const auto method = bearing::make_hamrock_brewe_hertz();
  const bearing::detail::CurvatureComplianceTable g(*method, kNum0, kSum0, kBound, "test");
  // Cubic Hermite with fourth-order difference slopes: the slope's error is O(h³ g⁗) with
  // h/Σρ₀ ≈ 8e-4, i.e. ~1e-9 of the slope; the reference's central difference (step 0.01 1/m)
  // is good to ~(0.01/Σρ₀)² ≈ 3e-9. 1e-6 relative bounds both with a margin of ~100.
  const double s = 0.01;
  for (const double d : {-kBound, -0.999 * kBound, -0.97 * kBound, -1.3, 0.0, 0.37, 2.2,
                         0.97 * kBound, 0.999 * kBound, kBound}) {
    const double exact = (closed_form(*method, d + s) - closed_form(*method, d - s)) / (2 * s);
    EXPECT_NEAR(g.derivative(d), exact, 1e-6 * std::abs(exact)) << "Δ = " << d << " 1/m";
    EXPECT_NEAR(g(d), closed_form(*method, d), 1e-9) << "Δ = " << d << " 1/m";
  }
}
