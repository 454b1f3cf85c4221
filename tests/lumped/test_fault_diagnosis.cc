// Issue 17's acceptance: simulated spalls, their envelope spectra and the diagnosis. Each line is
// checked against the frequency the textbook kinematics give for the bearing's geometry, written
// here (f_r (Z/2)(1 ∓ g), g = D cos α / d_m), and the CWRU data set's published defect frequencies
// for its 6205 (multiples of the shaft speed); the sidebands against f_r and the FTF.

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "bearing/analysis.h"
#include "bearing/case_file.h"
#include "bearing/constants.h"
#include "bearing/diagnosis.h"
#include "bearing/kinematics.h"
#include "bearing/simulation.h"

namespace bearing {
namespace {

// The CWRU-like example (0.533 mm outer spall at the bottom, 1797 rpm, 500 N down), 1 s analysed
// (1 Hz bins), the envelope band by the kurtogram, with `sets` applied.
Case cwru(std::vector<std::string> sets = {}) {
  std::vector<Override> o{parse_override("output.envelope_band=auto")};
  for (const auto& s : sets) o.push_back(parse_override(s));
  return read_case_file(std::string(BEARING_SOURCE_DIR) + "/examples/cwru_6205_outer.toml", o);
}

struct Analysed {
  Case c;
  RunSummary summary;
  const EnvelopeSummary& envelope(const std::string& channel) const {
    for (const EnvelopeSummary& e : summary.envelopes)
      if (e.channel == channel) return e;
    throw std::runtime_error("no envelope of " + channel);
  }
};

Analysed analysed(const Case& c) {
  return {c, summarize(c, simulate(c))};
}

// The textbook frequencies [Hz] of the case's geometry (outer ring fixed, cage slip s).
struct Textbook {
  double fr, ftf, bpfo, bpfi, bsf;
};
Textbook textbook(const Case& c, double slip = 0) {
  const Bearing& b = c.bearing;
  const double fr = c.operation.speed / two_pi;
  const double g = b.ball_diameter * std::cos(b.contact_angle) / b.pitch_diameter;
  const double ftf = (1 - slip) * 0.5 * fr * (1 - g);
  return {fr, ftf, b.balls * ftf, b.balls * (fr - ftf),
          b.pitch_diameter / b.ball_diameter * (1 + g) * ftf};
}

// The envelope peak labelled `label`; fails the test if absent.
Peak peak(const EnvelopeSummary& e, const std::string& label) {
  for (const Peak& p : e.peaks)
    if (p.label == label) return p;
  ADD_FAILURE() << "no envelope peak " << label << " in " << e.channel;
  return {};
}

double resolution(const EnvelopeSummary& e) {
  return e.spectrum.resolution;
}

TEST(FaultDiagnosis, TheCwruBearingsFrequenciesAreThePublishedOnes) {
  // CWRU Bearing Data Center, drive-end bearing 6205-2RS JEM SKF: defect frequencies in multiples
  // of the running speed (printed to 5 digits).
  const Case c = cwru();
  const BearingFrequencies f = bearing_frequencies(c.bearing, c.operation.speed);
  EXPECT_NEAR(f.shaft, 1797.0 / 60, 1e-12);
  EXPECT_NEAR(f.bpfi / f.shaft, 5.4152, 1e-4);
  EXPECT_NEAR(f.bpfo / f.shaft, 3.5848, 1e-4);
  EXPECT_NEAR(f.ftf / f.shaft, 0.39828, 1e-4);
  EXPECT_NEAR(2 * f.bsf / f.shaft, 4.7135, 1e-4);  // CWRU's "rolling element" is 2 x BSF
}

TEST(FaultDiagnosis, AnOuterRaceSpallShowsBpfoHarmonicsAndIsNamed) {
  const Analysed a = analysed(cwru());
  const Textbook t = textbook(a.c);
  const EnvelopeSummary& e = a.envelope("ay");
  EXPECT_NEAR(peak(e, "BPFO").frequency, t.bpfo, resolution(e));
  EXPECT_NEAR(peak(e, "2xBPFO").frequency, 2 * t.bpfo, resolution(e));
  for (const Peak& p : e.peaks)  // every fault line of the envelope is a BPFO harmonic
    EXPECT_TRUE(fault_family(p.label) == FaultFamily::outer ||
                fault_family(p.label) == FaultFamily::none)
        << p.label;
  ASSERT_TRUE(a.summary.diagnosis);
  EXPECT_EQ(a.summary.diagnosis->family, FaultFamily::outer) << a.summary.diagnosis->reason;
  EXPECT_GE(a.summary.diagnosis->spectral_kurtosis, 5);
  ASSERT_FALSE(a.summary.diagnosis->evidence.empty());
  EXPECT_EQ(a.summary.diagnosis->evidence.front().label, "BPFO");
}

TEST(FaultDiagnosis, AnInnerRaceSpallShowsBpfiWithShaftSidebandsAndIsNamed) {
  const Analysed a = analysed(cwru({"defects.0.location=inner", "defects.0.position=0"}));
  const Textbook t = textbook(a.c);
  const EnvelopeSummary& e = a.envelope("ay");
  const double bpfi = peak(e, "BPFI").frequency;
  EXPECT_NEAR(bpfi, t.bpfi, resolution(e));
  // The spall passes the load zone once per turn of the shaft: the impacts are modulated at f_r.
  EXPECT_NEAR(peak(e, "BPFI+fr").frequency - bpfi, t.fr, 2 * resolution(e));
  EXPECT_NEAR(bpfi - peak(e, "BPFI-fr").frequency, t.fr, 2 * resolution(e));
  EXPECT_NEAR(peak(e, "fr").frequency, t.fr, resolution(e));
  ASSERT_TRUE(a.summary.diagnosis);
  EXPECT_EQ(a.summary.diagnosis->family, FaultFamily::inner) << a.summary.diagnosis->reason;
}

TEST(FaultDiagnosis, ABallSpallShowsTwiceBsfWithCageSidebandsAndIsNamed) {
  const Analysed a =
      analysed(cwru({"defects.0.location=ball", "defects.0.ball=0", "defects.0.position=0"}));
  const Textbook t = textbook(a.c);
  const EnvelopeSummary& e = a.envelope("ay");
  // The defect strikes each race once per ball turn: the impact rate is 2 x BSF, and the ball
  // carries it around the load zone at the cage speed.
  const double two_bsf = peak(e, "2xBSF").frequency;
  EXPECT_NEAR(two_bsf, 2 * t.bsf, resolution(e));
  EXPECT_NEAR(peak(e, "2xBSF+FTF").frequency - two_bsf, t.ftf, 2 * resolution(e));
  EXPECT_NEAR(two_bsf - peak(e, "2xBSF-FTF").frequency, t.ftf, 2 * resolution(e));
  EXPECT_NEAR(peak(e, "FTF").frequency, t.ftf, resolution(e));
  ASSERT_TRUE(a.summary.diagnosis);
  EXPECT_EQ(a.summary.diagnosis->family, FaultFamily::ball) << a.summary.diagnosis->reason;
}

// In the ball-DOF model the cage, and the balls with it, turn at (1 − s_c) ω_c: the outer spall's
// line moves from BPFO to (1 − s_c)·BPFO, 5.4 Hz (5 bins) away at s_c = 0.05, and is named BPFO
// still (the named frequencies turn with the cage).
TEST(FaultDiagnosis, CageSlipMovesTheOuterRaceLine) {
  const double slip = 0.05;
  const Analysed a = analysed(cwru({"model.kind=balls", "cage.slip=0.05"}));
  const Textbook t = textbook(a.c, slip), rolling = textbook(a.c);
  const EnvelopeSummary& e = a.envelope("ay");
  const double line = peak(e, "BPFO").frequency;
  EXPECT_NEAR(line, t.bpfo, resolution(e));
  EXPECT_NEAR(t.bpfo, (1 - slip) * rolling.bpfo, 1e-12);
  EXPECT_GT(std::abs(line - rolling.bpfo), 4 * resolution(e));
  ASSERT_TRUE(a.summary.diagnosis);
  EXPECT_EQ(a.summary.diagnosis->family, FaultFamily::outer) << a.summary.diagnosis->reason;
}

// Healthy bearings with waviness vibrate at deterministic lines (BPFO harmonics among them), but
// without impacts: no family is named. The CWRU bearing under its 500 N, and the default 6308.
TEST(FaultDiagnosis, AHealthyBearingWithWavinessIsNotDiagnosed) {
  Case healthy = cwru({"solver.duration=0.6"});
  healthy.excitation.defects.clear();
  healthy.excitation.inner_waviness = {{8, 0.3e-6, 0.0}};
  healthy.excitation.outer_waviness = {{10, 0.5e-6, 0.0}};
  const Analysed a = analysed(healthy);
  ASSERT_TRUE(a.summary.diagnosis);
  EXPECT_EQ(a.summary.diagnosis->family, FaultFamily::none) << a.summary.diagnosis->reason;
  EXPECT_TRUE(a.summary.diagnosis->evidence.empty());

  Case light = default_case({parse_override("output.envelope_band=auto")});
  light.excitation.outer_waviness = {{9, 0.5e-6, 0.0}};
  const Analysed b = analysed(light);
  ASSERT_TRUE(b.summary.diagnosis);
  EXPECT_EQ(b.summary.diagnosis->family, FaultFamily::none) << b.summary.diagnosis->reason;
}

}  // namespace
}  // namespace bearing
