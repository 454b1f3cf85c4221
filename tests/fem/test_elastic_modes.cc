// The natural modes of fem/modes/ (solve_elastic_modes) on beams built here as meshes (no gmsh):
// a clamped-free beam of hexahedra and of tetrahedra against Timoshenko's beam (ν = 0), the
// mass-normalised shapes' orthogonality and Bessel's inequality, a free-free beam's six
// rigid-body modes left out, the seat's rigid fit against the tip, and the direct harmonic
// response against the modal sum with the residual flexibility of the modes left out.
// Label `fem`; each test solves a few thousand unknowns (a second or two).

#include <gtest/gtest.h>

#include <deal.II/base/mpi.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "../../verification/src/checks/structure_reference.h"
#include "bearing/errors.h"
#include "modes/elastic_modes.h"

namespace bearing::fem {
namespace {

namespace ref = bearing::verify::structure_reference;
constexpr double kPi = 3.14159265358979323846;

// A box [-bx/2, bx/2] x [-hy/2, hy/2] x [0, L] [m] of nx x ny x nz hexahedra (or each split into
// six tetrahedra about its diagonal 0-7), the face z = 0 physical surface 1 ("root"), z = L 2
// ("tip").
GmshMesh beam(double bx, double hy, double L, int nx, int ny, int nz, bool tetrahedra) {
  GmshMesh m;
  m.file = "beam";
  m.version = "2.2";
  m.cell_type = tetrahedra ? GmshMesh::CellType::tetrahedron : GmshMesh::CellType::hexahedron;
  m.names = {{2, 1, "root"}, {2, 2, "tip"}};
  const auto id = [&](int i, int j, int k) {
    return static_cast<unsigned>((k * (ny + 1) + j) * (nx + 1) + i);
  };
  for (int k = 0; k <= nz; ++k)
    for (int j = 0; j <= ny; ++j)
      for (int i = 0; i <= nx; ++i)
        m.vertices.push_back({{-bx / 2 + bx * i / nx, -hy / 2 + hy * j / ny, L * k / nz}});
  const auto det = [&](const std::vector<unsigned>& t) {
    const auto& a = m.vertices[t[0]];
    double e[3][3];
    for (int r = 1; r < 4; ++r)
      for (int d = 0; d < 3; ++d) e[r - 1][d] = m.vertices[t[r]][d] - a[d];
    return e[0][0] * (e[1][1] * e[2][2] - e[1][2] * e[2][1]) -
           e[0][1] * (e[1][0] * e[2][2] - e[1][2] * e[2][0]) +
           e[0][2] * (e[1][0] * e[2][1] - e[1][1] * e[2][0]);
  };
  constexpr int kuhn[6][4] = {{0, 1, 3, 7}, {0, 1, 5, 7}, {0, 2, 3, 7},
                              {0, 2, 6, 7}, {0, 4, 5, 7}, {0, 4, 6, 7}};
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i) {
        std::vector<unsigned> h;
        for (int c = 0; c < 8; ++c) h.push_back(id(i + (c & 1), j + ((c >> 1) & 1), k + (c >> 2)));
        if (!tetrahedra) {
          m.cells.push_back(h);
        } else {
          for (const auto& t : kuhn) {
            std::vector<unsigned> tet = {h[t[0]], h[t[1]], h[t[2]], h[t[3]]};
            if (det(tet) < 0) std::swap(tet[2], tet[3]);
            m.cells.push_back(tet);
          }
        }
        for (int end = 0; end < 2; ++end) {
          if ((end == 0 && k != 0) || (end == 1 && k != nz - 1)) continue;
          const unsigned* q = end == 0 ? &h[0] : &h[4];
          if (!tetrahedra)
            m.faces.push_back({{q[0], q[1], q[2], q[3]}, {end + 1}});
          else  // the Kuhn tetrahedra's faces on z = 0: (0, 1, 3), (0, 2, 3); on z = L: (4, 5, 7),
                // (4, 6, 7)
            m.faces.push_back({{q[0], q[1], q[3]}, {end + 1}}),
                m.faces.push_back({{q[0], q[2], q[3]}, {end + 1}});
        }
      }
  return m;
}

ElasticModesParameters steel(bool clamped, unsigned count) {
  ElasticModesParameters p;
  p.young = 210e9, p.poisson = 0.0, p.density = 7850;
  if (clamped) p.fixed = {1};
  p.seat = 2, p.seat_name = "tip";
  p.sensors = {Vec3{{0, 0, 0.1}}};
  p.count = count;
  return p;
}

// The bending frequencies along y: modes whose tip translation is mostly along y.
std::vector<double> bending_y(const ElasticModesResult& r) {
  std::vector<double> f;
  for (std::size_t k = 0; k < r.frequencies.size(); ++k) {
    const Vec3& t = r.seat[k].translation;
    if (std::fabs(t[1]) > 3 * (std::fabs(t[0]) + std::fabs(t[2]))) f.push_back(r.frequencies[k]);
  }
  return f;
}

TEST(ElasticModes, ACantileverBendsAsTimoshenkosBeam) {
  // 100 x 10 x 6 mm, ν = 0: the 3-D beam and Timoshenko's with Cowper's k = 5/6 agree to the
  // shear coefficient's uncertainty (5/6 against π²/12: 2e-5 of mode 1, 1.5e-4 of mode 2), the
  // FE error of this mesh bounded by its difference to one refinement (order >= 2: /3).
  const ref::Section y{210e9, 0.0, 7850, 0.010, 0.006};
  const std::vector<double> t = ref::timoshenko_cantilever(y, 0.1, 5.0 / 6, 2);
  const std::vector<double> m = ref::timoshenko_cantilever(y, 0.1, kPi * kPi / 12, 2);
  for (bool tets : {false, true}) {
    ElasticModesParameters p = steel(true, 6);
    const GmshMesh mesh = beam(0.010, 0.006, 0.1, 2, 2, 20, tets);
    const auto f0 = bending_y(solve_elastic_modes(mesh, p, MPI_COMM_WORLD));
    p.refinements = 1;
    const auto f1 = bending_y(solve_elastic_modes(mesh, p, MPI_COMM_WORLD));
    ASSERT_GE(std::min(f0.size(), f1.size()), 2u);
    for (int k = 0; k < 2; ++k) {
      EXPECT_LE(f1[k], f0[k]);  // nested meshes: from above
      const double bound = std::fabs(m[k] / t[k] - 1) + (f0[k] - f1[k]) / (3 * f1[k]);
      EXPECT_NEAR(f1[k] / t[k] - 1, 0, bound) << (tets ? "tetrahedra" : "hexahedra") << " mode "
                                              << k + 1 << ": " << f1[k] << " Hz, " << t[k];
    }
  }
}

TEST(ElasticModes, ShapesAreMassOrthonormalAndObeyBessel) {
  const ElasticModesResult r =
      solve_elastic_modes(beam(0.010, 0.006, 0.1, 2, 2, 12, true), steel(true, 15), MPI_COMM_WORLD);
  ASSERT_EQ(r.frequencies.size(), 15u);
  EXPECT_TRUE(std::is_sorted(r.frequencies.begin(), r.frequencies.end()));
  EXPECT_LT(r.orthogonality_mass, 1e-10);
  EXPECT_LT(r.orthogonality_stiffness, 1e-10);
  EXPECT_NEAR(r.total_mass, 7850 * 0.010 * 0.006 * 0.1, 1e-12);
  for (int d = 0; d < 3; ++d) {
    double sum = 0;
    for (double e : r.effective_mass[d]) sum += e;
    EXPECT_LE(sum, r.total_mass * (1 + 1e-12));  // Bessel: Σ (φᵀMr)² ≤ rᵀMr
    EXPECT_GT(sum, 0.8 * r.total_mass);          // 15 modes hold most of it
  }
  EXPECT_EQ(r.rigid_body_modes, 0u);
}

TEST(ElasticModes, AFreeBeamsSixRigidBodyModesAreLeftOut) {
  const ElasticModesResult r =
      solve_elastic_modes(beam(0.010, 0.006, 0.1, 2, 2, 12, true), steel(false, 4), MPI_COMM_WORLD);
  EXPECT_EQ(r.rigid_body_modes, 6u);
  EXPECT_LT(r.rigid_body_span, 1e-10);
  ASSERT_EQ(r.frequencies.size(), 4u);
  EXPECT_GT(r.frequencies[0], 100 * r.near_zero);
  // Elastic modes are M-orthogonal to the rigid translations: no effective mass.
  for (int d = 0; d < 3; ++d)
    for (double e : r.effective_mass[d]) EXPECT_LT(e, 1e-12 * r.total_mass);
  // The free-free beam's first bending (β L = 4.730) lies near Euler–Bernoulli's, below it.
  const ref::Section y{210e9, 0.0, 7850, 0.010, 0.006};
  const double eb =
      std::pow(4.730041 / 1.875104, 2) * ref::euler_bernoulli_cantilever(y, 0.1, 1)[0];
  EXPECT_NEAR(bending_y(r).front() / eb, 1, 0.02);
}

TEST(ElasticModes, TheSeatFitAndTheSensorSeeTheTip) {
  const ElasticModesResult r =
      solve_elastic_modes(beam(0.010, 0.006, 0.1, 2, 2, 12, false), steel(true, 4), MPI_COMM_WORLD);
  EXPECT_NEAR(r.seat_centre[2], 0.1, 1e-15);
  EXPECT_NEAR(r.seat_area, 6e-5, 1e-18);
  ASSERT_EQ(r.sensors.size(), 1u);
  EXPECT_LT(r.sensors[0].distance, 1e-15);  // the tip's centre is a vertex
  for (std::size_t k = 0; k < r.frequencies.size(); ++k) {
    // A bending mode's tip section moves nearly rigidly: its centre is the fit's centre.
    if (r.seat[k].residual > 0.05) continue;
    for (int d = 0; d < 2; ++d)
      EXPECT_NEAR(r.sensors[0].displacement[k][d], r.seat[k].translation[d],
                  0.05 * std::hypot(r.seat[k].translation[0], r.seat[k].translation[1]));
  }
  // A mass-normalised cantilever's tip moves 2/√m per unit modal coordinate (Euler–Bernoulli).
  EXPECT_NEAR(std::fabs(r.seat[0].translation[1]) * std::sqrt(r.total_mass), 2.0, 0.05);
}

TEST(ElasticModes, TheDirectResponseIsTheModalSumPlusTheModesLeftOut) {
  ElasticModesParameters p = steel(true, 9);
  p.frf_frequencies = {700, 3200};
  const ElasticModesResult r =
      solve_elastic_modes(beam(0.010, 0.006, 0.1, 2, 2, 12, true), p, MPI_COMM_WORLD);
  ASSERT_TRUE(r.frf.has_static);
  const std::size_t kept = 8;  // the 9th bounds the ones left out
  const double w9 = 2 * kPi * r.frequencies[kept];
  for (int d = 0; d < 2; ++d) {
    double modal_static = 0;
    for (std::size_t k = 0; k < kept; ++k)
      modal_static += std::pow(r.seat[k].translation[d] / (2 * kPi * r.frequencies[k]), 2);
    const double residual = r.frf.static_response[d].translation[d] - modal_static;
    EXPECT_GT(residual, 0);
    for (std::size_t i = 0; i < 2; ++i) {
      const double w = 2 * kPi * p.frf_frequencies[i];
      double modal = 0;
      for (std::size_t k = 0; k < kept; ++k) {
        const double wk = 2 * kPi * r.frequencies[k];
        modal += std::pow(r.seat[k].translation[d], 2) / (wk * wk - w * w);
      }
      const double left_out = r.frf.direct[d][i].translation[d] - modal;
      EXPECT_GE(left_out, residual * (1 - 1e-6));
      EXPECT_LE(left_out, residual * w9 * w9 / (w9 * w9 - w * w) * (1 + 1e-6));
    }
  }
}

}  // namespace
}  // namespace bearing::fem

int main(int argc, char** argv) {
  dealii::Utilities::MPI::MPI_InitFinalize mpi(argc, argv, 1);
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
