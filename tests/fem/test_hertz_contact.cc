// FE Hertz contact (fem/contact): the power-law fit, and a coarse Hertz-reduced run of both 6308
// contacts checked against the analytic Hertz solution with the error this resolution has.
//
// The coarse mesh is level 0 of fem/scripts/hertz_convergence.py (N_b = 4 cells per semi-minor
// axis, grading 3): its errors against exact Hertz are about +1.1 % in K (the FE block is too
// stiff, as a displacement method must be), −0.6 % in a and −2.1 % in b at Q_max; the finer levels
// of the study in fem/README.md bring K within 0.3 %. The bounds below are that level's errors with margin, so
// a regression in the solver (a wrong sign, a lost constraint, a bad force sum) fails loudly.

#include <deal.II/base/mpi.h>
#include <gtest/gtest.h>

#include <cmath>

#include "bearing/contact.h"
#include "bearing/hertz.h"
#include "bearing/presets.h"
#include "contact/hertz_contact.h"

namespace {

using namespace bearing;

TEST(PowerLawFit, RecoversAnExactPowerLaw) {
  std::vector<double> d, f;
  for (int k = 0; k < 5; ++k) {
    d.push_back(1e-7 * std::pow(2.0, k));
    f.push_back(3.5e10 * std::pow(d.back(), 1.5));
  }
  const auto fit = fem::fit_power_law(d, f);
  EXPECT_NEAR(fit.exponent, 1.5, 1e-12);
  EXPECT_NEAR(fit.K / 3.5e10, 1.0, 1e-9);
  EXPECT_NEAR(fit.K_three_halves / 3.5e10, 1.0, 1e-12);
  EXPECT_LT(fit.residual, 1e-12);
}

TEST(PowerLawFit, ReportsTheResidualOfANonPowerLaw) {
  const std::vector<double> d = {1, 2, 4}, f = {1, 3, 7};
  const auto fit = fem::fit_power_law(d, f);
  EXPECT_GT(fit.residual, 1e-3);
  EXPECT_THROW(fem::fit_power_law({1.0}, {1.0}), std::invalid_argument);
}

// The Hertz-reduced problem of one race at the coarse level, loads 2–20 N (Q_max of the seed
// 002/003 case is 20 N).
struct Coarse {
  RaceContact rc;
  fem::HertzContactResult r;
  fem::PowerLawFit fit;
};

Coarse solve_coarse(Race race) {
  const Bearing b = preset("6308");
  const auto exact = make_exact_hertz();
  Coarse c;
  c.rc = race_contact(b, race, *exact);
  const Curvatures rho = race_curvatures(b, race);
  fem::HertzContactParameters p;
  p.contact_modulus = 1 / c.rc.compliance;
  p.radius_x = 1 / (rho.ball_1 + rho.race_1);
  p.radius_y = 1 / (rho.ball_2 + rho.race_2);
  for (const double q : {2.0, 6.3, 20.0}) p.approaches.push_back(c.rc.approach(q));
  p.design_semi_minor = c.rc.semi_minor(20.0);
  p.design_semi_major = c.rc.semi_major(20.0);
  p.finest_cell_fraction = 1.0 / 4;
  p.grading = 3;
  c.r = fem::solve_hertz_contact(p, MPI_COMM_WORLD);
  std::vector<double> d, f;
  for (const auto& s : c.r.steps) {
    d.push_back(s.approach);
    f.push_back(s.force);
  }
  c.fit = fem::fit_power_law(d, f);
  return c;
}

void check_against_hertz(const Coarse& c) {
  const double k_error = c.fit.K_three_halves / c.rc.K - 1;
  EXPECT_GT(k_error, 0.0) << "a displacement FE model must be too stiff";
  EXPECT_LT(k_error, 0.035);
  // Three steps at this resolution: n ≈ 1.507–1.510 (6 steps and finer meshes: README.md).
  EXPECT_NEAR(c.fit.exponent, 1.5, 0.015);
  // Semi-axes and peak pressure at Q_max (b has 4 cells there), as in the acceptance criteria.
  const auto& last = c.r.steps.back();
  EXPECT_NEAR(last.semi_major / c.rc.semi_major(last.force), 1.0, 0.01);
  EXPECT_NEAR(last.semi_minor / c.rc.semi_minor(last.force), 1.0, 0.03);
  EXPECT_NEAR(last.peak_pressure / c.rc.peak_pressure(last.force), 1.0, 0.01);
  // At the lightest load b spans only ~2 cells: the error is larger, and must fall as the
  // contact grows over more cells (the resolution study inside one run).
  double previous_error = 1;
  for (const auto& s : c.r.steps) {
    EXPECT_GE(s.active_set_iterations, 1u);
    const double b_error = std::abs(s.semi_minor / c.rc.semi_minor(s.force) - 1);
    EXPECT_LT(b_error, 0.16);
    EXPECT_LT(b_error, previous_error);
    previous_error = b_error;
    EXPECT_NEAR(s.semi_major / c.rc.semi_major(s.force), 1.0, 0.03);
    // The active set's extent brackets Hertz's semi-axes within one node spacing.
    EXPECT_NEAR(s.semi_major_edge, c.rc.semi_major(s.force), s.edge_spacing_major);
    EXPECT_NEAR(s.semi_minor_edge, c.rc.semi_minor(s.force), s.edge_spacing_minor);
  }
}

TEST(HertzContactFE, Coarse6308InnerAgreesWithHertz) { check_against_hertz(solve_coarse(Race::inner)); }
TEST(HertzContactFE, Coarse6308OuterAgreesWithHertz) { check_against_hertz(solve_coarse(Race::outer)); }

}  // namespace

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
