// The load–approach law with the EHL film in series (film_law.h, issue 43): load(δ) inverts
// δ(Q) = (Q/K)^{1/n} − H Q^−e, its tangent is dQ/dδ, its energy's derivative in δ is the load, and
// H = 0 is Hertz's law. The constants are the 6205's (exact Hertz, ball between both races) and
// its two films at 1800 rpm, 0.02 Pa s, 2e-8 1/Pa (H = C_i + C_o).

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "bearing/contact.h"
#include "bearing/ehl_film.h"
#include "bearing/film_law.h"
#include "bearing/hertz.h"
#include "bearing/lubricant.h"
#include "bearing/presets.h"

namespace {

using namespace bearing;

constexpr double kE = kCentralFilmLoadExponent;

FilmLaw law_6205() {
  const Bearing b = preset("6205");
  const ContactConstants cc = contact_constants(b, *make_exact_hertz());
  Lubricant l;
  l.viscosity = 0.02;
  l.pressure_viscosity = 2e-8;
  l.roughness = 1e-7;
  const double w = 1800.0 * 2 * M_PI / 60, g = b.ball_diameter / b.pitch_diameter;
  const BallFilms f = ball_films(b, cc, l, w, 0.5 * w * (1 - g));
  return {cc.K, cc.exponent, f.inner.central_coefficient() + f.outer.central_coefficient()};
}

double approach_of(const FilmLaw& f, double q) {
  return std::pow(q / f.K, 1 / f.exponent) - f.H * std::pow(q, -kE);
}

// load(δ) is the root of δ(Q): over δ from −10 µm (a gap of ~20 film thicknesses, Q ~ 1e-20 N) to
// +50 µm (Q ~ 30 kN), δ(load(δ)) = δ to the root's accuracy. The solver stops at a step of
// 1e-15 |ln Q| (|ln Q| < 50 here), which moves δ by (δ_H/n + e h_c) Δln Q ≤ 5e-14 (δ_H + h_c);
// with the few ulps of evaluating the two terms, 1e-13 (δ_H + h_c) bounds it.
TEST(FilmLaw, LoadInvertsTheApproach) {
  const FilmLaw f = law_6205();
  ASSERT_GT(f.H, 0);
  for (int i = 0; i <= 600; ++i) {
    const double delta = -10e-6 + i * 0.1e-6;
    const double q = f.load(delta);
    ASSERT_GT(q, 0) << delta;
    const double hertz = std::pow(q / f.K, 1 / f.exponent), film = f.H * std::pow(q, -kE);
    EXPECT_NEAR(approach_of(f, q), delta, 1e-13 * (hertz + film)) << delta;
    EXPECT_NEAR(f.film(q), film, 1e-14 * film);
  }
  // Monotone: a larger approach carries a larger load.
  EXPECT_LT(f.load(-1e-6), f.load(0.0));
  EXPECT_LT(f.load(0.0), f.load(1e-6));
}

// The tangent against a central difference of load(δ): D_Δ = (Q(δ+Δ) − Q(δ−Δ))/(2Δ) has the
// truncation error Δ² Q'''/6 + O(Δ⁴), estimated by Richardson as |D_Δ − D_2Δ|/3; the loads' own
// error (1e-13 relative, above) adds 1e-13 Q/Δ. Bound: twice the Richardson estimate (for its own
// O(Δ⁴) error) plus the round-off term.
TEST(FilmLaw, TangentIsTheDerivativeOfTheLoad) {
  const FilmLaw f = law_6205();
  for (double delta : {-2e-6, -0.5e-6, 0.0, 0.3e-6, 2e-6, 10e-6, 40e-6}) {
    const double q = f.load(delta);
    const double step = 1e-3 * (std::pow(q / f.K, 1 / f.exponent) + f.film(q));
    auto d = [&](double h) { return (f.load(delta + h) - f.load(delta - h)) / (2 * h); };
    const double d1 = d(step), d2 = d(2 * step);
    const double bound = 2 * std::fabs(d1 - d2) / 3 + 1e-13 * q / step;
    EXPECT_NEAR(f.tangent(q), d1, bound) << delta;
    // The series of Hertz's and the film's springs.
    const double k_hertz = f.exponent * q / std::pow(q / f.K, 1 / f.exponent);
    const double k_film = q / (kE * f.film(q));
    EXPECT_NEAR(f.tangent(q), 1 / (1 / k_hertz + 1 / k_film), 1e-13 * f.tangent(q));
  }
}

// dU/dδ = Q: the central difference of U(load(δ)) against load(δ), the same bound as above (U's
// terms are evaluated to a few ulps: 1e-13 U/Δ covers them and the loads' error).
TEST(FilmLaw, EnergyDerivativeIsTheLoad) {
  const FilmLaw f = law_6205();
  for (double delta : {-2e-6, -0.5e-6, 0.0, 0.3e-6, 2e-6, 10e-6, 40e-6}) {
    const double q = f.load(delta);
    const double step = 1e-3 * (std::pow(q / f.K, 1 / f.exponent) + f.film(q));
    auto u = [&](double x) { return f.energy(f.load(x)); };
    auto d = [&](double h) { return (u(delta + h) - u(delta - h)) / (2 * h); };
    const double d1 = d(step), d2 = d(2 * step);
    const double bound = 2 * std::fabs(d1 - d2) / 3 + 1e-13 * f.energy(q) / step;
    EXPECT_NEAR(d1, q, bound) << delta;
    EXPECT_GT(f.energy(q), 0);
  }
  EXPECT_EQ(f.energy(0.0), 0.0);
}

// H = 0: Hertz's Q = K [δ]_+^n, its tangent n K δ^(n−1) and energy K δ^(n+1)/(n+1).
TEST(FilmLaw, WithoutFilmItIsHertz) {
  FilmLaw f = law_6205();
  f.H = 0;
  for (double delta : {1e-7, 5e-6, 30e-6}) {
    const double q = f.K * std::pow(delta, f.exponent);
    EXPECT_DOUBLE_EQ(f.load(delta), q);
    EXPECT_NEAR(f.tangent(q), f.exponent * f.K * std::pow(delta, f.exponent - 1),
                1e-13 * f.tangent(q));
    EXPECT_NEAR(f.energy(q), f.K * std::pow(delta, f.exponent + 1) / (f.exponent + 1),
                1e-13 * f.energy(q));
  }
  EXPECT_EQ(f.load(-1e-6), 0.0);
  EXPECT_EQ(f.load(0.0), 0.0);
  EXPECT_EQ(f.film(100.0), 0.0);
}

// The film law lies between Hertz at δ and Hertz at δ + h_c(K δ^n): Q = K (δ + h_c(Q))^n.
TEST(FilmLaw, TheFilmAddsItsThicknessToTheApproach) {
  const FilmLaw f = law_6205();
  for (double delta : {1e-6, 5e-6, 20e-6}) {
    const double q = f.load(delta);
    EXPECT_NEAR(q, f.K * std::pow(delta + f.film(q), f.exponent), 1e-12 * q);
    EXPECT_GT(q, f.K * std::pow(delta, f.exponent));
  }
  // No load, no film (the header's promise; not H 0^−e = inf).
  EXPECT_EQ(f.film(0.0), 0.0);
  EXPECT_EQ(f.film(-1.0), 0.0);
  // An open gap of 10 film thicknesses leaves a vanishing load (h_c ∝ Q^−0.067).
  const double h1 = f.film(1.0);
  EXPECT_LT(f.load(-10 * h1), 1e-12);
}

TEST(FilmLaw, RefusesANonFiniteApproach) {
  const FilmLaw f = law_6205();
  EXPECT_ANY_THROW(f.load(std::numeric_limits<double>::quiet_NaN()));
  EXPECT_ANY_THROW(f.load(std::numeric_limits<double>::infinity()));
}

}  // namespace
