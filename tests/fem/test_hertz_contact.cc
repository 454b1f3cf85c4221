// FE Hertz contact (fem/contact): the power-law fit, and a coarse Hertz-reduced run of both 6308
// contacts checked against the analytic Hertz solution with the error this resolution has.
//
// The coarse mesh is level 0 of fem/scripts/hertz_convergence.py (N_b = 4 cells per semi-minor
// axis, grading 3): its errors against exact Hertz are about +1.1 % in K (the FE block is too
// stiff, as a displacement method must be), −0.6 % in a and −2.1 % in b at Q_max; the finer levels
// of the study in fem/README.md bring K within 0.3 %. The bounds below are that level's errors with
// margin, so a regression in the solver (a wrong sign, a lost constraint, a bad force sum) fails
// loudly.

#include <deal.II/base/mpi.h>
#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <iostream>
#include <string>

#include "bearing/constants.h"
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

TEST(HertzContactFE, Coarse6308InnerAgreesWithHertz) {
  check_against_hertz(solve_coarse(Race::inner));
}
TEST(HertzContactFE, Coarse6308OuterAgreesWithHertz) {
  check_against_hertz(solve_coarse(Race::outer));
}

// --- The real groove geometry (RacewaySegment) -------------------------------------------------
// The 6308 inner ring segment (ISO 15: bore 40 mm, width 23 mm; land 0.2 D below the groove
// edge), at the coarse level, three approach steps up to a design load Q.
struct GrooveRun {
  RaceContact rc;
  fem::HertzContactResult r;
};

GrooveRun solve_groove(double q, bool paraboloid, const std::string& name) {
  const Bearing b = preset("6308");
  const auto exact = make_exact_hertz();
  GrooveRun g;
  g.rc = race_contact(b, Race::inner, *exact);
  const Curvatures rho = race_curvatures(b, Race::inner);
  fem::HertzContactParameters p;
  p.geometry = "groove";
  p.contact_modulus = 1 / g.rc.compliance;
  p.radius_x = 1 / (rho.ball_1 + rho.race_1);
  p.radius_y = 1 / (rho.ball_2 + rho.race_2);
  for (const double f : {0.5, 0.7, 1.0}) p.approaches.push_back(g.rc.approach(f * q));
  p.design_semi_minor = g.rc.semi_minor(q);
  p.design_semi_major = g.rc.semi_major(q);
  p.finest_cell_fraction = 1.0 / 4;
  p.grading = 3;
  fem::RacewaySegment& r = p.raceway;
  r.outer = false;
  r.ball_radius = b.ball_diameter / 2;
  r.groove_radius = b.inner_conformity * b.ball_diameter;
  r.groove_bottom = b.inner_raceway_diameter() / 2;
  r.back_radius = 20e-3;
  r.half_width = 11.5e-3;
  r.paraboloid_gap = paraboloid;
  const std::string msh =
      (std::filesystem::temp_directory_path() / ("bearing_fem_test_" + name + ".msh")).string();
  fem::mesh_raceway_segment(r, 0.2 * b.ball_diameter, pi / b.balls, msh, msh + ".log",
                            MPI_COMM_WORLD);
  g.r = fem::solve_hertz_contact(p, MPI_COMM_WORLD);
  return g;
}

// F_FE / F_Hertz − 1 at the design approach (the last step).
double stiffening(const GrooveRun& g) {
  const auto& s = g.r.steps.back();
  return s.force / (g.rc.K * std::pow(s.approach, 1.5)) - 1;
}

// The exact gap (sphere against the torus) differs from Hertz's paraboloid by the quartic terms
// y⁴/8 (1/R³ − 1/r³) (likewise in x): relative to the paraboloid's y²/2 (1/R − 1/r) that is
// (y²/4)(1/R² + 1/(Rr) + 1/r²) < 0.75 (y/R)², at most 0.75 (a/R)² inside the contact (R the ball's,
// r the groove's radius). So at 20 N (a = 0.45 mm, R = 7.5 mm: 0.27 %) the two gaps must give the
// same force on the same mesh to within that bound, and at 3 GPa (a ≈ 2.8 mm, 45 % of the groove's
// half-width: ~10 %) they must differ far more: the large-contact effect Hertz's theory
// neglects. On the ring, the clamped bore makes both stiffer than the half-space.
TEST(GrooveContactFE, ExactGapTendsToHertzsParaboloidAtLightLoad) {
  const GrooveRun exact_light = solve_groove(20.0, false, "exact_light");
  const GrooveRun parab_light = solve_groove(20.0, true, "parab_light");
  const double light = exact_light.r.steps.back().force / parab_light.r.steps.back().force - 1;
  const double a = exact_light.rc.semi_major(20.0), R = preset("6308").ball_diameter / 2;
  EXPECT_LT(std::abs(light), 0.75 * (a / R) * (a / R)) << light;
  // Hertz's semi-axes at the FE force, within this resolution's errors (as for the block).
  const auto& s = exact_light.r.steps.back();
  EXPECT_NEAR(s.semi_major / exact_light.rc.semi_major(s.force), 1.0, 0.02);
  EXPECT_NEAR(s.semi_minor / exact_light.rc.semi_minor(s.force), 1.0, 0.03);
  // The ring segment is stiffer than Hertz's half-space (clamped 5 mm under the groove), but by
  // only a few per cent at this load.
  EXPECT_GT(stiffening(parab_light), 0.0);
  EXPECT_LT(stiffening(parab_light), 0.06);

  const double q_heavy = std::pow(3e9 / exact_light.rc.peak_pressure(1.0), 3.0);  // p0 = 3 GPa
  const GrooveRun exact_heavy = solve_groove(q_heavy, false, "exact_heavy");
  const GrooveRun parab_heavy = solve_groove(q_heavy, true, "parab_heavy");
  const double heavy = exact_heavy.r.steps.back().force / parab_heavy.r.steps.back().force - 1;
  EXPECT_GT(std::abs(heavy), 5 * std::abs(light)) << heavy << " vs " << light;
  std::cout << "exact/paraboloid gap - 1: " << light << " at 20 N (bound "
            << 0.75 * (a / R) * (a / R) << "), " << heavy << " at " << q_heavy
            << " N; ring/Hertz - 1 at 20 N: " << stiffening(parab_light) << '\n';
}

}  // namespace

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
