// The 5-DOF static solution with the EHL film (issue 43; five_dof_static.h, film_law.h): the
// stiffness with the film in series against each ball's series spring computed by hand from
// ehl_film.h's formulas, the squeeze-film damping against Σ c_j g_j g_jᵀ from the balls' loads,
// K with the film tending to the dry K under heavy load, the dry case untouched (no entrainment
// at rest: bit for bit the dry solution), and the pipeline's StiffnessPoint carrying C.

#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/case_file.h"
#include "bearing/ehl_film.h"
#include "bearing/five_dof_static.h"
#include "bearing/kinematics.h"
#include "bearing/stiffness.h"

namespace bearing {
namespace {

// The acceptance case of issue 43: a 6205 at 1800 rpm under 2 kN radial, 0.02 Pa s, 2e-8 1/Pa.
Case film_case(const std::string& load = "[\"0 N\", \"-2000 N\"]",
               const std::string& speed = "1800 rpm", bool lubricated = true) {
  std::vector<Override> sets = {parse_override("bearing.preset=6205"),
                                parse_override("operation.speed=" + speed),
                                parse_override("operation.load=" + load)};
  if (lubricated) {
    sets.push_back(parse_override("lubricant.viscosity=0.02 Pa s"));
    sets.push_back(parse_override("lubricant.pressure_viscosity=2e-8 1/Pa"));
    sets.push_back(parse_override("lubricant.roughness=0.1 um"));
  }
  Case c = default_case(sets);
  // The one-contact form (the balls on the line of centres), where the hand formulas below hold;
  // the races apart have their own test.
  c.ball.centrifugal = false;
  return c;
}

// The films of the case's balls, from the library's ehl_film.h alone.
BallFilms films_of(const Case& c) {
  return ball_films(c.bearing, contact_constants(c), c.lubricant, c.operation.speed,
                    cage_speed(c.bearing, c.operation.speed));
}

struct Hand {
  Matrix5 K = Matrix5::Zero(), C = Matrix5::Zero();
  double max_hertz_over_film = 0;  // max_j k_H / k_f (both films in series) over loaded balls
  double max_film_over_hertz = 0;  // max_j (h_ci + h_co) / δ_H
};

// K and C from the balls' loads and angles of `s`, each ball's springs and dampers from the
// formulas: k_H = n Q/δ_H, k_f = Q/(0.067 h_c) of each race (FilmContact::stiffness), in series;
// c_i, c_o the squeeze films (FilmContact::damping), in series; g = Bᵀ e, h = Bᵀ t.
Hand by_hand(const Case& c, const FiveDofSolution& s, const BallFilms& f) {
  const ContactConstants cc = contact_constants(c);
  const FiveDofBearing b = five_dof_bearing(c.bearing, cc);
  Hand r;
  for (std::size_t j = 0; j < s.at.ball_loads.size(); ++j) {
    const double Q = s.at.ball_loads[j];
    if (!(Q > 0)) continue;
    const double psi = s.at.ball_angles[j], a = s.at.contact_angles[j];
    const double dH = std::pow(Q / cc.K, 1 / cc.exponent);
    const double kH = cc.exponent * Q / dH;
    const double kf = 1 / (1 / f.inner.stiffness(Q) + 1 / f.outer.stiffness(Q));
    const double k = 1 / (1 / kH + 1 / kf);
    const double ci = f.inner.damping(Q), co = f.outer.damping(Q);
    const double R = b.groove_radius, L = b.A0 + s.at.approaches[j];
    Vector5 g, h;
    g << std::cos(a) * std::cos(psi), std::cos(a) * std::sin(psi), std::sin(a),
        std::sin(a) * R * std::sin(psi), -std::sin(a) * R * std::cos(psi);
    h << -std::sin(a) * std::cos(psi), -std::sin(a) * std::sin(psi), std::cos(a),
        std::cos(a) * R * std::sin(psi), -std::cos(a) * R * std::cos(psi);
    r.K += k * g * g.transpose() + (Q / L) * h * h.transpose();
    r.C += ci * co / (ci + co) * g * g.transpose();
    if (s.at.approaches[j] > 0) {
      r.max_hertz_over_film = std::max(r.max_hertz_over_film, kH / kf);
      r.max_film_over_hertz =
          std::max(r.max_film_over_hertz,
                   (f.inner.central_thickness(Q) + f.outer.central_thickness(Q)) / dH);
    }
  }
  return r;
}

double max_abs(const Matrix5& m) {
  return m.cwiseAbs().maxCoeff();
}

TEST(FilmStiffness, BallLoadsFollowTheFilmLawAndKIsTheSeriesSprings) {
  const Case c = film_case();
  ASSERT_TRUE(c.lubricant.enabled);
  const BallFilms f = films_of(c);
  const StiffnessPoint p = stiffness_point(c, 0);
  const FiveDofSolution& s = p.solution;
  const ContactConstants cc = contact_constants(c);
  // Each ball's approach is its Hertz deflection less both films at its load (film_law.h).
  for (std::size_t j = 0; j < s.at.ball_loads.size(); ++j) {
    const double Q = s.at.ball_loads[j];
    if (Q < 1e-6 * p.q_max()) continue;
    const double approach = std::pow(Q / cc.K, 1 / cc.exponent) - f.inner.central_thickness(Q) -
                            f.outer.central_thickness(Q);
    EXPECT_NEAR(s.at.approaches[j], approach, 1e-12) << "ball " << j;
  }
  const Hand hand = by_hand(c, s, f);
  EXPECT_LT(max_abs(s.at.stiffness - hand.K), 1e-9 * max_abs(hand.K));
  EXPECT_NEAR(s.at.stiffness(1, 1), hand.K(1, 1), 1e-10 * hand.K(1, 1));
  // The film softens K: the dry solution's k_yy is larger.
  const StiffnessPoint dry =
      stiffness_point(film_case("[\"0 N\", \"-2000 N\"]", "1800 rpm", false), 0);
  EXPECT_LT(s.at.stiffness(1, 1), dry.solution.at.stiffness(1, 1));
}

TEST(FilmStiffness, DampingIsTheSeriesSqueezeFilmsOfTheBalls) {
  const Case c = film_case();
  const BallFilms f = films_of(c);
  const StiffnessPoint p = stiffness_point(c, 0);
  const Hand hand = by_hand(c, p.solution, f);
  ASSERT_GT(hand.C(1, 1), 0);
  EXPECT_LT(max_abs(p.solution.at.damping - hand.C), 1e-9 * max_abs(hand.C));
  EXPECT_EQ(p.solution.at.damping, p.solution.at.damping.transpose());
  // A radial load along y: the y damping is the largest, and c_yy = Σ c_j sin²ψ_j.
  EXPECT_GT(p.solution.at.damping(1, 1), p.solution.at.damping(0, 0));
}

TEST(FilmStiffness, HeavyLoadTendsToTheDryStiffness) {
  // Under a heavy load k_f ≫ k_H and h_c ≪ δ_H: K with the film tends to the dry K. Each ball's
  // spring is k_H/(1 + k_H/k_f) ≥ k_H (1 − k_H/k_f), and the film's gap shifts its approach by
  // h_c, which redistributes the loads by about h_c/δ_H; the bound is twice the sum of both
  // ratios at their largest over the loaded balls.
  std::vector<double> relative, bounds;
  for (const char* load : {"[\"0 N\", \"-2000 N\"]", "[\"0 N\", \"-20000 N\"]"}) {
    const Case c = film_case(load);
    const StiffnessPoint wet = stiffness_point(c, 0);
    const StiffnessPoint dry = stiffness_point(film_case(load, "1800 rpm", false), 0);
    const Hand hand = by_hand(c, wet.solution, films_of(c));
    const double kw = wet.solution.at.stiffness(1, 1), kd = dry.solution.at.stiffness(1, 1);
    relative.push_back((kd - kw) / kd);
    bounds.push_back(2 * (hand.max_hertz_over_film + hand.max_film_over_hertz));
    EXPECT_GT(relative.back(), 0) << load;  // the film softens
    EXPECT_LT(relative.back(), bounds.back()) << load;
  }
  // The heavier load: a smaller bound and a smaller difference (K_film → K_dry).
  EXPECT_LT(bounds[1], bounds[0]);
  EXPECT_LT(relative[1], relative[0]);
  EXPECT_LT(relative[1], 0.05);
}

TEST(FilmStiffness, AtRestTheLubricatedCaseIsTheDryOneBitForBit) {
  // No entrainment at rest, no film: K, the balls and C = 0 exactly as without [lubricant].
  const StiffnessPoint wet = stiffness_point(film_case("[\"0 N\", \"-2000 N\"]", "0 rpm"), 8);
  const StiffnessPoint dry =
      stiffness_point(film_case("[\"0 N\", \"-2000 N\"]", "0 rpm", false), 8);
  EXPECT_EQ(wet.solution.at.stiffness, dry.solution.at.stiffness);
  EXPECT_EQ(wet.solution.displacement, dry.solution.displacement);
  EXPECT_EQ(wet.solution.at.ball_loads, dry.solution.at.ball_loads);
  EXPECT_EQ(wet.solution.at.damping, Matrix5::Zero());
  EXPECT_EQ(wet.loaded_balls(), dry.loaded_balls());
  ASSERT_TRUE(wet.ball_pass && dry.ball_pass);
  EXPECT_EQ(wet.ball_pass->mean, dry.ball_pass->mean);
  EXPECT_EQ(wet.ball_pass->damping_mean, Matrix5::Zero());
}

TEST(FilmStiffness, DryBearingHasNoFilmAndNoDamping) {
  const Case dry = film_case("[\"0 N\", \"-2000 N\"]", "1800 rpm", false);
  const FiveDofBearing b = five_dof_bearing_of(dry);
  EXPECT_EQ(b.film_H, 0.0);
  EXPECT_EQ(b.inner_squeeze, 0.0);
  const StiffnessPoint p = stiffness_point(dry, 0);
  EXPECT_EQ(p.solution.at.damping, Matrix5::Zero());
}

TEST(FilmStiffness, LoadedBallsCountThoseWhoseHertzDeflectionExceedsTheFilm) {
  const Case c = film_case();
  const StiffnessPoint p = stiffness_point(c, 0);
  // Every ball carries some load through the film, but only the load zone's count.
  int positive = 0, approach = 0;
  for (std::size_t j = 0; j < p.solution.at.ball_loads.size(); ++j) {
    positive += p.solution.at.ball_loads[j] > 0;
    approach += p.solution.at.approaches[j] > 0;
  }
  EXPECT_EQ(p.loaded_balls(), approach);
  EXPECT_LT(p.loaded_balls(), positive);
  EXPECT_GE(p.loaded_balls(), 3);
}

TEST(FilmStiffness, RacesApartDampingIsSymmetricPositiveAndBallPassAveragesIt) {
  // At speed with the centrifugal load (races apart): C symmetric, positive semi-definite, of the
  // one-contact form's size, and the ball pass's damping_mean the mean of its samples.
  Case c = film_case();
  c.ball.centrifugal = true;
  const StiffnessPoint p = stiffness_point(c, 8);
  const Matrix5& C = p.solution.at.damping;
  EXPECT_LT(max_abs(C - C.transpose()), 1e-12 * max_abs(C));
  const Eigen::SelfAdjointEigenSolver<Matrix5> eig(C);
  EXPECT_GE(eig.eigenvalues().minCoeff(), -1e-9 * max_abs(C));
  const StiffnessPoint one = stiffness_point(film_case(), 0);
  EXPECT_NEAR(C(1, 1), one.solution.at.damping(1, 1), 0.5 * one.solution.at.damping(1, 1));
  ASSERT_TRUE(p.ball_pass);
  Matrix5 mean = Matrix5::Zero();
  for (const Matrix5& s : p.ball_pass->damping_samples) mean += s / 8;
  EXPECT_LT(max_abs(p.ball_pass->damping_mean - mean), 1e-12 * max_abs(mean));
  EXPECT_EQ(p.ball_pass->damping_samples[0], C);
}

}  // namespace
}  // namespace bearing
