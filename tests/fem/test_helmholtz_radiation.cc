// The Helmholtz radiation reference (issue 6) against independent references: the exact fields
// of lumped's acoustics/sources.h (GSL Hankel functions), the convergence under refinement, and
// the small-scatterer limit of the bearing section (a rigid cylinder of radius b scatters
// O(b²) of an incident field at low frequency).

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <complex>
#include <filesystem>
#include <string>

#include "bearing/acoustics/sources.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "radiation/helmholtz_radiation.h"

namespace {

using bearing::Air;
using bearing::InputError;
using bearing::make_source;
using bearing::pi;
using bearing::two_pi;
using namespace bearing::fem;
using cplx = std::complex<double>;

// The band's ends fix the default mesh (λ_min from 20 kHz) and layer (γ from 100 Hz), so these
// four frequencies see the mesh the CLI's full-band run uses.
const std::vector<double> kFrequencies{100, 630, 4000, 20000};

struct SingleSource {
  const char* name;
  bool cylinder, breathing;
  double radius;
};

void PrintTo(const SingleSource& s, std::ostream* os) {
  *os << s.name;
}

// A single source with microphones at distances rs [m], all at `angle` [rad] from the motion.
HelmholtzParameters single(const SingleSource& s, std::vector<double> rs, double angle) {
  HelmholtzParameters p;
  p.geometry = s.cylinder ? RadiationGeometry::planar : RadiationGeometry::axisymmetric;
  p.bodies = {RadiatingBody{0, 0, s.radius, s.breathing, 0}};
  p.motions = {SurfaceMotion{0, s.breathing, 0, s.name}};
  for (double r : rs)
    p.microphones.push_back(s.cylinder
                                ? std::array<double, 2>{r * std::cos(angle), r * std::sin(angle)}
                                : std::array<double, 2>{r * std::sin(angle), r * std::cos(angle)});
  p.frequencies = kFrequencies;
  return p;
}
HelmholtzParameters single(const SingleSource& s, double r, double angle) {
  return single(s, std::vector<double>{r}, angle);
}

class SingleSourceAccuracy : public ::testing::TestWithParam<SingleSource> {};

// The acceptance bound at the default (coarse) resolution: 0.1 dB and 1 degree, 100 Hz - 20 kHz,
// at 10 mm (inside the mesh for the cylinder; for the sphere, 5a away, by the outgoing-mode
// continuation) and at 1 m (continued for both).
TEST_P(SingleSourceAccuracy, MatchesTheExactFieldWithinATenthOfADecibelAndOneDegree) {
  const SingleSource s = GetParam();
  const std::vector<double> rs{10e-3, 1.0};
  const double angle = 30 * pi / 180;
  const HelmholtzResult fe = solve_helmholtz(single(s, rs, angle), MPI_COMM_WORLD);
  const auto exact = make_source(s.name, s.radius, Air{});
  for (std::size_t f = 0; f < kFrequencies.size(); ++f)
    for (std::size_t i = 0; i < rs.size(); ++i) {
      const cplx ex = exact->transfer(two_pi * kFrequencies[f], rs[i], std::cos(angle));
      const cplx ratio = fe.pressure[f][0][i] / ex;
      EXPECT_LT(std::abs(20 * std::log10(std::abs(ratio))), 0.1)
          << s.name << " " << kFrequencies[f] << " Hz, r = " << rs[i];
      EXPECT_LT(std::abs(std::arg(ratio)) * 180 / pi, 1.0)
          << s.name << " " << kFrequencies[f] << " Hz, r = " << rs[i];
    }
}

INSTANTIATE_TEST_SUITE_P(AllFour, SingleSourceAccuracy,
                         ::testing::Values(SingleSource{"cylinder-monopole", true, true, 5.79e-3},
                                           SingleSource{"cylinder-dipole", true, false, 5.79e-3},
                                           SingleSource{"sphere-monopole", false, true, 1.98e-3},
                                           SingleSource{"sphere-dipole", false, false, 1.98e-3}),
                         [](const auto& info) {
                           std::string n = info.param.name;
                           for (char& c : n)
                             if (c == '-') c = '_';
                           return n;
                         });

// One refinement of the degree-2 mesh cuts the error at 100 Hz (60 cells per wavelength: the
// asymptotic range, where the near field and the layer set the error) by more than 2^(p+1) = 8.
// At 20 kHz the coarse degree-2 mesh has 2 cells per wavelength, the pre-asymptotic range of
// Helmholtz's phase (pollution) error, so no rate is claimed there.
TEST(HelmholtzRadiation, ErrorFallsUnderRefinementAtLeastAtTheElementsOrder) {
  const SingleSource s{"cylinder-dipole", true, false, 5.79e-3};
  const double r = 20e-3, angle = 0;
  const auto exact = make_source(s.name, s.radius, Air{});
  double error[2];
  for (unsigned int level = 0; level < 2; ++level) {
    HelmholtzParameters p = single(s, r, angle);
    p.frequencies = {100, 20000};
    p.degree = 2;
    p.refinements = level;
    const HelmholtzResult fe = solve_helmholtz(p, MPI_COMM_WORLD);
    const cplx ex = exact->transfer(two_pi * 100, r, 1.0);
    error[level] = std::abs(fe.pressure[0][0][0] / ex - 1.0);
  }
  EXPECT_GT(error[0], 1e-4);  // measurable
  EXPECT_GT(error[0] / error[1], 8.0) << error[0] << " -> " << error[1];
}

// The layer is exact for the continuous problem, so its parameters may move the answer only by
// the discretisation's reflection: a thinner and a thicker layer, a weaker and a stronger decay
// all give the same pressure to 1e-4 (0.001 dB; measured spread ~1e-5), at both ends of the band.
TEST(HelmholtzRadiation, TheLayersParametersDoNotChangeTheAnswer) {
  const SingleSource s{"sphere-dipole", false, false, 1.98e-3};
  auto solve = [&](double thickness, double attenuation) {
    HelmholtzParameters p = single(s, 5e-3, 0.5);
    p.frequencies = {100, 20000};
    p.pml_thickness = thickness;
    p.pml_attenuation = attenuation;
    return solve_helmholtz(p, MPI_COMM_WORLD);
  };
  const HelmholtzResult base = solve(0, 12);
  for (const auto& [thickness, attenuation] :
       std::vector<std::pair<double, double>>{{1e-3, 12}, {6e-3, 12}, {0, 8}, {0, 16}}) {
    const HelmholtzResult other = solve(thickness, attenuation);
    for (std::size_t f = 0; f < 2; ++f)
      EXPECT_LT(std::abs(other.pressure[f][0][0] / base.pressure[f][0][0] - 1.0), 1e-4)
          << "L = " << thickness << ", sigma0 = " << attenuation << ", f index " << f;
  }
}

// The bearing section's path (gmsh mesh, several bodies, transfinite cells): a ring translating
// among Z small rigid cylinders. At low frequency each scatters a field ∝ b² of the ring's, so
// the FE's difference from the free ring's exact field falls by 4 when b is halved.
TEST(HelmholtzRadiation, ScatteringBySmallNeighboursFallsAsTheirRadiusSquared) {
  const double ring = 3e-3, pitch = 7.5e-3, f = 500;
  const std::array<double, 2> mic{10e-3, 0};
  const auto exact = make_source("cylinder-dipole", ring, Air{});
  const cplx free = exact->transfer(two_pi * f, 10e-3, 1.0);
  const std::string dir = std::filesystem::temp_directory_path() / "bearing_fem_radiation_test";
  std::filesystem::create_directories(dir);
  double difference[2];
  const double radii[2] = {1.0e-3, 0.5e-3};
  for (int i = 0; i < 2; ++i) {
    HelmholtzParameters p;
    p.bodies.push_back({0, 0, ring, false, 0});
    for (int j = 0; j < 7; ++j) {
      const double t = -pi / 2 + two_pi * j / 7;
      p.bodies.push_back({pitch * std::cos(t), pitch * std::sin(t), radii[i], false, t});
    }
    p.motions = {SurfaceMotion{0, false, 0, "ring-x"}};
    p.microphones = {mic};
    p.frequencies = {f};
    p.work_dir = dir;
    const HelmholtzResult fe = solve_helmholtz(p, MPI_COMM_WORLD);
    difference[i] = std::abs(fe.pressure[0][0][0] / free - 1.0);
  }
  EXPECT_GT(difference[0], 1e-3);
  EXPECT_NEAR(difference[0] / difference[1], 4.0, 0.4) << difference[0] << " -> " << difference[1];
}

// The planar continuation with several bodies: a microphone beyond the mesh (continued from the
// circle R_c) against the same point inside a mesh made large enough to hold it. Two meshes, two
// discretisation errors of ~1e-4 each: they must agree to 1.2e-3 (0.01 dB).
TEST(HelmholtzRadiation, ContinuedAndMeshedMicrophonesAgreeAroundABearingSection) {
  HelmholtzParameters p;
  p.bodies.push_back({0, 0, 5.5e-3, false, 0});
  for (int j = 0; j < 7; ++j) {
    const double t = -pi / 2 + two_pi * j / 7;
    p.bodies.push_back({7.775e-3 * std::cos(t), 7.775e-3 * std::sin(t), 1.98e-3, false, t});
  }
  p.motions = {SurfaceMotion{0, false, pi / 2, "ring-y"},
               SurfaceMotion{1, false, -pi / 2, "ball1"}};
  p.microphones = {{40e-3 * std::cos(0.3), 40e-3 * std::sin(0.3)}};
  p.frequencies = {2000, 8000};
  p.work_dir = std::filesystem::temp_directory_path() / "bearing_fem_radiation_test";
  std::filesystem::create_directories(p.work_dir);
  const HelmholtzResult continued = solve_helmholtz(p, MPI_COMM_WORLD);
  p.physical_radius = 44e-3;
  const HelmholtzResult meshed = solve_helmholtz(p, MPI_COMM_WORLD);
  for (std::size_t f = 0; f < p.frequencies.size(); ++f)
    for (std::size_t m = 0; m < p.motions.size(); ++m)
      EXPECT_LT(std::abs(continued.pressure[f][m][0] / meshed.pressure[f][m][0] - 1.0), 1.2e-3)
          << p.frequencies[f] << " Hz, " << p.motions[m].name;
}

TEST(HelmholtzRadiation, RejectsMicrophonesInsideABodyAndATooSmallPhysicalZone) {
  const SingleSource s{"cylinder-dipole", true, false, 5e-3};
  HelmholtzParameters inside = single(s, 4e-3, 0);
  EXPECT_THROW(solve_helmholtz(inside, MPI_COMM_WORLD), InputError);
  HelmholtzParameters tight = single(s, 20e-3, 0);
  tight.physical_radius = 5.5e-3;  // not room for the layer's start beyond the body
  EXPECT_THROW(solve_helmholtz(tight, MPI_COMM_WORLD), InputError);
  HelmholtzParameters no_frequency = single(s, 20e-3, 0);
  no_frequency.frequencies = {-1};
  EXPECT_THROW(solve_helmholtz(no_frequency, MPI_COMM_WORLD), InputError);
}

}  // namespace

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
  MPI_Finalize();
  return result;
}
