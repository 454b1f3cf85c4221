// The bearing's sound from a run (noise.h): every model kind radiates, and the levels obey what
// is known independently — a breathing sphere's 1/r, the ball-pass periodicity of a perfect
// bearing, the geometry of the balls passing a microphone, the sign of a dipole's two lobes.

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/acoustics/pressure.h"
#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/errors.h"
#include "bearing/signal/spectrum.h"
#include "bearing/simulation.h"

namespace bearing {
namespace {

std::vector<Override> sets(const std::vector<std::string>& s) {
  std::vector<Override> o;
  for (const auto& t : s) o.push_back(parse_override(t));
  return o;
}

// Seed 000's 608 at 720 rpm and 50 N with its example's waviness and ball errors, 0.5 s.
Case noisy_608(const std::string& acoustics, const std::vector<std::string>& more = {}) {
  return parse_case(
      "[bearing]\npreset = \"608\"\n[operation]\nspeed = \"720 rpm\"\nload = [0, -50]\n"
      "[[waviness.inner]]\norder = 7\namplitude = \"0.5 um\"\n"
      "[[waviness.outer]]\norder = 7\namplitude = \"0.5 um\"\nphase = \"180 deg\"\n"
      "[ball_errors]\nband = \"2 um\"\nseed = 1\n[model]\nkind = \"quasistatic\"\n"
      "[solver]\nduration = 0.5\ntransient = 0.1\n[acoustics]\n" +
          acoustics,
      "noisy_608.toml", sets(more));
}

RunSummary run(const Case& c) {
  return summarize(c, simulate(c));
}

TEST(Noise, EveryModelKindRadiates) {
  for (const char* kind : {"quasistatic", "2dof", "3dof"}) {
    const Case c = noisy_608("microphones = [[\"10 mm\", \"-90 deg\"], [\"0.2 m\", \"30 deg\"]]\n",
                             {std::string("model.kind=") + kind, "solver.method=rk8pd"});
    const RunSummary s = run(c);
    ASSERT_TRUE(s.noise) << kind;
    const BearingNoise& n = *s.noise;
    ASSERT_EQ(n.microphones.size(), 2u);
    // The analysis window: 0.4 s at 20 kHz, from t = 0.1 s.
    ASSERT_EQ(n.time.size(), 8000u) << kind;
    EXPECT_DOUBLE_EQ(n.time.front(), 0.1);
    EXPECT_DOUBLE_EQ(n.band_low, 2.5);
    EXPECT_DOUBLE_EQ(n.band_high, 8000.0);
    for (std::size_t i = 0; i < 2; ++i) {
      const MicrophoneLevels& m = n.microphones[i];
      ASSERT_TRUE(m.spl_total && m.spl_ring && m.spl_balls) << kind;
      EXPECT_TRUE(std::isfinite(*m.spl_total));
      EXPECT_NEAR(root_mean_square(n.pressure[i]), m.p_rms, 1e-15);
      EXPECT_NEAR(*m.spl_total, 20 * std::log10(m.p_rms / 20e-6), 1e-12);
    }
    // Closer is louder.
    EXPECT_GT(*n.microphones[0].spl_total, *n.microphones[1].spl_total + 10) << kind;
  }
}

TEST(Noise, BreathingBallsFallBySixDecibelsPerDoublingOfDistance) {
  // A pulsating sphere's |p| is exactly ρc u (a/r) ka/√(1+(ka)²): 1/r at every frequency. Far
  // from the bearing (r ≫ d_m) each ball is at nearly the same distance, so the set falls by
  // 20 log10 2 = 6.02 dB from 10 m to 20 m; the ring is off.
  const Case c = noisy_608(
      "ring_source = \"none\"\nball_source = \"pulsating-sphere\"\n"
      "microphones = [[\"10 m\", \"20 deg\"], [\"20 m\", \"20 deg\"]]\n");
  const RunSummary s = run(c);
  ASSERT_TRUE(s.noise);
  const auto& m = s.noise->microphones;
  EXPECT_FALSE(m[0].spl_ring);  // ring "none": no level
  EXPECT_NEAR(*m[0].spl_balls - *m[1].spl_balls, 20 * std::log10(2.0), 0.01);
  EXPECT_EQ(*m[0].spl_total, *m[0].spl_balls);
}

TEST(Noise, PerfectBearingSoundsAtTheBallPassFrequency) {
  // No waviness, no ball errors: the quasi-static orbit repeats every ball pass, so the sound at
  // a microphone has lines at multiples of BPFO only. 1 s of record: bins 1 Hz apart.
  const Case c = parse_case(
      "[bearing]\npreset = \"608\"\n[operation]\nspeed = \"720 rpm\"\nload = [0, -50]\n"
      "[model]\nkind = \"quasistatic\"\n[solver]\nduration = 1.2\ntransient = 0.2\n"
      "[acoustics]\nmicrophones = [[\"12 mm\", \"-60 deg\"]]\n",
      "perfect_608.toml");
  const SimulationResult r = simulate(c);
  const RunSummary s = summarize(c, r);
  ASSERT_TRUE(s.noise);
  const Spectrum p =
      amplitude_spectrum(s.noise->pressure[0], c.solver.output_rate, Window::flattop);
  const double bpfo = r.frequencies.bpfo;
  std::vector<std::size_t> order(p.amplitude.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::partial_sort(order.begin(), order.begin() + 5, order.end(),
                    [&](std::size_t a, std::size_t b) { return p.amplitude[a] > p.amplitude[b]; });
  // The five largest lines are ball-pass harmonics (within the flattop's ±5-bin main lobe).
  for (int i = 0; i < 5; ++i) {
    const double f = p.frequency[order[i]];
    const double harmonic = std::round(f / bpfo);
    EXPECT_GE(harmonic, 1);
    EXPECT_LT(std::fabs(f - harmonic * bpfo), 5 * p.resolution) << f;
  }
}

TEST(Noise, NearestBallSurfaceIsTheGeometryOfPointA) {
  // Seed 000's point A, 10 mm below the centre of the 608: the balls' outer surfaces pass at
  // d_m/2 + D/2 (+ r_j, micrometres), so the gap is 10 mm − (15.55 + 3.969)/2 mm = 0.2405 mm.
  const Case c = noisy_608("microphones = [[\"10 mm\", \"-90 deg\"]]\n");
  const RunSummary s = run(c);
  const double gap = 0.010 - 0.5 * (c.bearing.pitch_diameter + c.bearing.ball_diameter);
  ASSERT_TRUE(s.noise->microphones[0].nearest_ball_surface);
  EXPECT_NEAR(*s.noise->microphones[0].nearest_ball_surface, gap, 5e-6);
  EXPECT_NEAR(gap, 0.2405e-3, 1e-7);
}

TEST(Noise, RingDipoleLobesAreOpposite) {
  // A cylinder dipole on its own: microphones at the same distance on opposite sides of the ring
  // centre hear opposite pressures. The ring source sits at the centre's mean position, so the
  // microphones are placed symmetrically about it by offsetting them in the case.
  Case c = noisy_608("ball_source = \"none\"\nmicrophones = [[\"0.1 m\", \"0 deg\"]]\n");
  const SimulationResult r = simulate(c);
  const RunSummary first = summarize(c, r);
  const Eigen::Vector2d o = first.noise->ring_centre;
  const Eigen::Vector2d d(0.06, 0.08);  // 0.1 m from the ring centre
  c.acoustics.microphones = {{(o + d).norm(), std::atan2((o + d).y(), (o + d).x())},
                             {(o - d).norm(), std::atan2((o - d).y(), (o - d).x())}};
  const RunSummary s = summarize(c, r);
  const auto& p = s.noise->pressure;
  double scale = 0;
  for (double v : p[0]) scale = std::max(scale, std::fabs(v));
  for (std::size_t k = 0; k < p[0].size(); ++k) EXPECT_NEAR(p[0][k], -p[1][k], 1e-9 * scale);
}

TEST(Noise, EnergeticSumIsTheSquareRootOfSummedSquares) {
  // Seed 000 eq. (26): p_e² = p_ring² + Σ_j p_ball,j²: the energetic total is at or above each
  // part and its square the sum of the parts' squares; the coherent total differs from it.
  const std::string mics =
      "microphones = [[\"10 mm\", \"-90 deg\"]]\nball_source = "
      "\"pulsating-sphere\"\n";
  const RunSummary e = run(noisy_608(mics + "summation = \"energetic\"\n"));
  const RunSummary k = run(noisy_608(mics));
  const MicrophoneLevels& me = e.noise->microphones[0];
  const MicrophoneLevels& mk = k.noise->microphones[0];
  EXPECT_NEAR(me.p_rms * me.p_rms, me.p_rms_ring * me.p_rms_ring + me.p_rms_balls * me.p_rms_balls,
              1e-12 * me.p_rms * me.p_rms);
  EXPECT_DOUBLE_EQ(me.p_rms_ring, mk.p_rms_ring);           // one source: no sum
  EXPECT_NE(me.p_rms_balls, mk.p_rms_balls);                // seven balls: the sums differ
  for (double v : e.noise->pressure[0]) EXPECT_GE(v, 0.0);  // an envelope, not a pressure
}

TEST(Noise, QuasiStaticRingLevelRisesTwelveDecibelsPerDoublingOfSpeed) {
  // The quasi-static orbit is a function of the shaft angle alone, so doubling the speed doubles
  // every velocity and every frequency; the ring's near field at low ka is p ≈ ρ a² (v̇ · n)/r,
  // hence p ∝ n²: +20 log10 4 = 12.04 dB (the (ka)² terms add 0.007 dB here: ka < 0.1 up to 1 kHz).
  // The record holds the same shaft revolutions at both speeds.
  const std::string mic = "ball_source = \"none\"\nmicrophones = [[\"10 mm\", \"-90 deg\"]]\n";
  const RunSummary slow = run(noisy_608(mic, {"solver.duration=1.1", "solver.transient=0.1"}));
  const RunSummary fast =
      run(noisy_608(mic, {"operation.speed=1440rpm", "solver.duration=0.55",
                          "solver.transient=0.05", "solver.output_rate=40kHz"}));
  const double rise = *fast.noise->microphones[0].spl_ring - *slow.noise->microphones[0].spl_ring;
  EXPECT_NEAR(rise, 20 * std::log10(4.0), 0.03);
  EXPECT_GT(rise, 20 * std::log10(4.0));  // the next term of H raises the higher frequencies
}

TEST(Noise, StillBearingIsSilentWithoutANumber) {
  // No speed: the quasi-static ring stays where the static solution puts it and no ball moves:
  // p = 0 exactly, and SPL = −∞ is reported as no level (JSON null), never as a number or NaN.
  const Case c = noisy_608("microphones = [[\"10 mm\", \"-90 deg\"]]\n",
                           {"operation.speed=0rpm", "ball_errors.band=0um"});
  const RunSummary s = run(c);
  const MicrophoneLevels& m = s.noise->microphones[0];
  EXPECT_EQ(m.p_rms, 0.0);
  EXPECT_FALSE(m.spl_total);
  EXPECT_FALSE(m.spl_ring);
  EXPECT_FALSE(m.spl_balls);
}

TEST(Noise, BallAnglesAreTheModelsAngles) {
  // The acoustics places ball j at θ_j = 2πj/Z + ω_c t with the run's FTF. In a perfect bearing
  // under a downward load a ball's load peaks when it is straight below the centre: at those
  // instants the acoustics' angle must be −90°. Quasi-static and 3-DOF (whose cage turns at the
  // loaded contact angle under an axial load).
  for (const char* kind : {"quasistatic", "3dof"}) {
    const Case c = parse_case(
        "[bearing]\npreset = \"608\"\n[operation]\nspeed = \"720 rpm\"\nload = [0, -50]\n"
        "axial_load = " +
            std::string(std::string(kind) == "3dof" ? "20" : "0") + "\n[model]\nkind = \"" +
            std::string(kind) +
            "\"\n[solver]\nmethod = \"rk8pd\"\nduration = 0.6\ntransient = 0.1\n"
            "tolerance = 1e-9\n[output]\nball_loads = true\n",
        "angles.toml");
    const SimulationResult r = simulate(c);
    const double wc = two_pi * r.frequencies.ftf;
    const int Z = c.bearing.balls;
    for (int j = 0; j < Z; j += 3) {
      const auto& Q = r.response.channel("Q" + std::to_string(j + 1));
      int peaks = 0;
      for (std::size_t k = 1; k + 1 < Q.size(); ++k) {
        if (!(Q[k] > Q[k - 1] && Q[k] >= Q[k + 1] && Q[k] > 0.5 * 50)) continue;
        const double theta = two_pi * j / Z + wc * r.response.time[k];
        const double off = std::remainder(theta + pi / 2, two_pi);
        // One output interval turns the cage by ω_c/20 kHz = 1.4e-3 rad.
        EXPECT_LT(std::fabs(off), 2e-3) << kind << " ball " << j + 1 << " t " << r.response.time[k];
        ++peaks;
      }
      EXPECT_GE(peaks, 2) << kind << " ball " << j + 1;
    }
  }
}

TEST(Noise, MicrophoneInsideABallIsRejectedByName) {
  Case c = noisy_608("microphones = [[\"1 m\", \"0 deg\"]]\n");
  const SimulationResult r = simulate(c);
  c.acoustics.microphones = {{1.0, 0.0}, {0.5 * c.bearing.pitch_diameter, 0.3}};
  try {
    summarize(c, r);
    FAIL();
  } catch (const InputError& e) {
    const std::string m = e.what();
    EXPECT_NE(m.find("acoustics.microphones[1]"), std::string::npos) << m;
    EXPECT_NE(m.find("inside ball"), std::string::npos) << m;
  }
}

}  // namespace
}  // namespace bearing
